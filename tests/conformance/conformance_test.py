#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Conformance: the same analysis asked through every door gives the same
answer (DESIGN.md, "One engine, one answer"). Each curve of the seeded corpus
(tests/data/conformance, README.md there) is analysed by `hula analyse`
(the CLI), by POST /api/documents/{name}/entities/{label}/analysis of a real
`hula serve` (http.client; the body checked against the OpenAPI document) and
by hulahoops.analyse (Python, the curve file given as a dict), with the same
options. The answers must be equal value for value: every double bit for bit
(JSON null where Python has NaN), the feature lists identical. The page's
preview is checked against the same corpus by web/src/geometry/conformance.test.ts.

Also asserted on every door, as issue 22 asks: the space Bézier has no
inflection; the constant-κ helix has no curvature extremum and no knot.

Usage: conformance_test.py HULA_BINARY   (PYTHONPATH must reach hulahoops)
"""
import json
import math
import os
import pathlib
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
sys.path.insert(0, str(ROOT / "tests" / "server"))
from hula_server import OpenApi, Server  # noqa: E402

import numpy as np  # noqa: E402

import hulahoops as hh  # noqa: E402

CORPUS = ROOT / "tests" / "data" / "conformance"
SAMPLES = 33
FINS = ["curvature", "torsion"]
FIN_DENSITY = 17
# The options every door is given: the CLI always adds arc lengths and the Bishop frame.
REQUEST = {"samples": SAMPLES, "features": True, "fins": FINS, "fin_density": FIN_DENSITY,
           "arc_lengths": True, "bishop": True}


def cli(hula, path, by):
    r = subprocess.run([hula, "analyse", str(path), "--samples", str(SAMPLES), "--by", by, "--features",
                        "--fins", ",".join(FINS), "--fin-density", str(FIN_DENSITY)],
                       capture_output=True, text=True, timeout=300)
    if r.returncode != 0:
        raise AssertionError(f"hula analyse {path.name} failed ({r.returncode}): {r.stderr}")
    return json.loads(r.stdout)


def plain(value):
    """Python's answer in JSON's terms: StudyResult and dicts as dicts, arrays and tuples as lists, curves
    as their JSON, NaN as None (shared by study_conformance_test.py)."""
    if isinstance(value, hh.StudyResult):
        return {k: plain(value[k]) for k in value.keys()}
    if isinstance(value, dict):
        return {k: plain(v) for k, v in value.items()}
    if isinstance(value, hh.NurbsCurve):
        return json.loads(value.to_json())
    if isinstance(value, np.ndarray):
        return plain(value.tolist())
    if isinstance(value, (list, tuple)):
        return [plain(v) for v in value]
    if isinstance(value, float) and math.isnan(value):
        return None
    return value


def undefined_rows(value):
    """A vector written as [NaN, NaN, NaN] by Python is null in JSON."""
    if isinstance(value, list) and len(value) == 3 and all(v is None for v in value):
        return None
    if isinstance(value, list):
        return [undefined_rows(v) for v in value]
    if isinstance(value, dict):
        return {k: undefined_rows(v) for k, v in value.items()}
    return value


def first_difference(a, b, where="$"):
    """The path of the first value that differs (floats compared exactly), or None."""
    if isinstance(a, dict) and isinstance(b, dict):
        if list(a) != list(b) and set(a) != set(b):
            return f"{where}: members {sorted(a)} != {sorted(b)}"
        for k in a:
            d = first_difference(a[k], b[k], f"{where}.{k}")
            if d:
                return d
        return None
    if isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            return f"{where}: {len(a)} != {len(b)} entries"
        for i, (x, y) in enumerate(zip(a, b)):
            d = first_difference(x, y, f"{where}[{i}]")
            if d:
                return d
        return None
    if isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
        return None if float(a) == float(b) else f"{where}: {a!r} != {b!r}"
    return None if a == b else f"{where}: {a!r} != {b!r}"


def main():
    hula = sys.argv[1]
    names = (CORPUS / "corpus.txt").read_text().split()
    assert len(names) >= 15, names
    failures = []
    checked = 0
    with Server(hula) as server:
        api = OpenApi(json.loads(server.request("GET", "/api/openapi.json")[2]))
        status, _, body = server.request("POST", "/api/documents", {"name": "conformance.hula"})
        assert status == 201, body
        for name in names:
            path = CORPUS / f"{name}.json"
            curve = json.loads(path.read_text())
            status, _, body = server.request("POST", "/api/documents/conformance.hula/entities", {"curve": curve})
            assert status == 201, body
            label = json.loads(body)["label"]
            for by in ("parameter", "arclength"):
                from_cli = cli(hula, path, by)
                status, _, body = server.request(
                    "POST", f"/api/documents/conformance.hula/entities/{label}/analysis", dict(REQUEST, by=by))
                assert status == 200, body
                api.validate("POST", f"/api/documents/conformance.hula/entities/{label}/analysis", 200, body)
                from_http = json.loads(body)
                del from_http["revision"]
                from_python = undefined_rows(plain(hh.analyse(
                    curve, SAMPLES, by=by, features=True, fins=FINS, fin_density=FIN_DENSITY, arc_lengths=True,
                    bishop=True)))
                for door, answer in (("HTTP", from_http), ("Python", from_python)):
                    d = first_difference(from_cli, answer)
                    if d:
                        failures.append(f"{name} by {by}: CLI and {door} differ at {d}")
                for door, answer in (("CLI", from_cli), ("HTTP", from_http), ("Python", from_python)):
                    f = answer["features"]
                    if name == "space_bezier_issue22" and (f["inflections"] or answer["planarity"]["planar"]):
                        failures.append(f"{door}: the space Bézier has inflections {f['inflections']}")
                    if name == "law_helix" and (f["curvature_extrema"] or f["knots"] or f["torsion_extrema"]):
                        failures.append(f"{door}: the helix has extrema or knots: {f}")
                    if name == "planar_bezier_s" and len(f["inflections"]) != 1:
                        failures.append(f"{door}: the planar S-curve has {len(f['inflections'])} inflections")
                checked += 1
    for f in failures:
        print("FAIL:", f)
    print(f"conformance: {checked} analyses of {len(names)} curves through CLI, HTTP and Python, "
          f"{len(failures)} difference(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
