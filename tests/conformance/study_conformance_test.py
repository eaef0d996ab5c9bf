#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Study conformance: the same seeded study run through every door gives the
same result (DESIGN.md, "One engine, one answer"; every door runs it through
oli::run_study). Each study below is run by its `hula` command (the CLI), as a
study job of a real `hula serve` (POST /api/jobs, the job's "result" member
once done) and by hulahoops (Python); the result documents must be equal value
for value, every double bit for bit. Wall-clock members ("seconds") are the
only ones left out. Python may add members the others do not have (arrays of
the convergence graph, the map's grid); those are not compared.

Usage: study_conformance_test.py HULA_BINARY   (PYTHONPATH must reach hulahoops)
"""
import json
import pathlib
import subprocess
import sys
import tempfile

HERE = pathlib.Path(__file__).resolve().parent
ROOT = HERE.parent.parent
sys.path.insert(0, str(ROOT / "tests" / "server"))
from hula_server import Server, read_events, open_events  # noqa: E402

import hulahoops as hh  # noqa: E402
from conformance_test import plain  # noqa: E402  (Python's answer in JSON's terms)

# Thesis 8.2.1 Example 1 (examples/studies/match-curvature-example1.json) with a small binary GA, then
# the hybrid (GA + Levenberg-Marquardt) and the direct method on the same setup.
MATCH = {"format": "hula-study", "version": 1, "study": "match-curvature", "seed": 5,
         "points": [[0, 0], [5, 20], [40, 0]],
         "lower": [[0, 0], [30, 30], [0, 0]], "upper": [[0, 0], [35, 30], [0, 0]],
         "target": {"of_points": [[0, 0], [5, 20], [40, 0]], "mirror": True},
         "samples": 50, "method": "ga",
         "ga": {"algorithm": "binary", "population": 12, "generations": 15, "boost_start": 3,
                "boost_end": 5, "crossover_probability": 1.0, "mutation_probability": 0.01, "precision": 0.001}}
# Thesis 7.3 Example 2's points; both optimisers, so the GA's re-centring and Nelder-Mead both run.
FAIR = {"format": "hula-study", "version": 1, "study": "fair-knots", "seed": 3,
        "points": [[0, 0], [1, 2], [3, 3], [4, 1], [6, 0], [7, 2]], "method": "both",
        "ga": {"population": 16, "generations": 12}}

STUDIES = [
    ("match-curvature ga", MATCH, lambda s: hh.match_curvature(s)),
    ("match-curvature hybrid", dict(MATCH, seed=11, method="hybrid"), lambda s: hh.match_curvature(s)),
    ("fair-knots both", FAIR, lambda s: hh.fair_knots(s)),
]


def first_difference(a, b, where="$", subset=False):
    """The path of the first value that differs (floats compared exactly, "seconds" skipped), or None.
    With subset, b may have members a has not."""
    if isinstance(a, dict) and isinstance(b, dict):
        if not subset and set(a) != set(b):
            return f"{where}: members {sorted(a)} != {sorted(b)}"
        for k in a:
            if k == "seconds":
                continue
            if k not in b:
                return f"{where}: no member {k!r}"
            d = first_difference(a[k], b[k], f"{where}.{k}", subset)
            if d:
                return d
        return None
    if isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            return f"{where}: {len(a)} != {len(b)} entries"
        for i, (x, y) in enumerate(zip(a, b)):
            d = first_difference(x, y, f"{where}[{i}]", subset)
            if d:
                return d
        return None
    if isinstance(a, (int, float)) and isinstance(b, (int, float)) and not isinstance(a, bool):
        return None if float(a) == float(b) else f"{where}: {a!r} != {b!r}"
    return None if a == b else f"{where}: {a!r} != {b!r}"


def cli(hula, study, folder):
    path = pathlib.Path(folder) / f"{study['study']}-{study['seed']}.json"
    path.write_text(json.dumps(study))
    r = subprocess.run([hula, study["study"], str(path)], capture_output=True, text=True, timeout=300)
    if r.returncode != 0:
        raise AssertionError(f"hula {study['study']} failed ({r.returncode}): {r.stderr}")
    return json.loads(r.stdout)


def http(server, study, document):
    status, _, body = server.request("POST", "/api/documents", {"name": document})
    assert status == 201, body
    status, _, body = server.request("POST", "/api/jobs", {"document": document, "study": study})
    assert status == 202, body
    job = json.loads(body)["job"]
    conn, response = open_events(server, f"/api/jobs/{job}/events")
    events = list(read_events(response))
    conn.close()
    event, data = events[-1]
    assert event == "done" and data["state"] == "done", events[-1]
    return data["result"]["result"]


def main():
    hula = sys.argv[1]
    failures = []
    with tempfile.TemporaryDirectory() as folder, Server(hula) as server:
        for i, (name, study, python) in enumerate(STUDIES):
            from_cli = cli(hula, study, folder)
            from_http = http(server, study, f"study{i}.hula")
            from_python = plain(python(study))
            # The CLI and the job hold the same members; Python adds arrays (convergence, the map's grid).
            d = first_difference(from_cli, from_http)
            if d:
                failures.append(f"{name}: CLI and HTTP differ at {d}")
            d = first_difference(from_cli, from_python, subset=True)
            if d:
                failures.append(f"{name}: CLI and Python differ at {d}")
            # The study ran: the optimisers evaluated something and found a finite answer.
            text = json.dumps(from_cli)
            if "evaluations" not in text:
                failures.append(f"{name}: no evaluations in {text[:200]}")
    for f in failures:
        print("FAIL:", f)
    print(f"study conformance: {len(STUDIES)} studies through CLI, HTTP and Python, {len(failures)} difference(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
