# SPDX-License-Identifier: MIT
"""Knot-vector fairing (thesis 7.4) from a study file, with the faired curve saved.

    PYTHONPATH=build/ci/python /usr/bin/python3 examples/python/fair_knots.py [STUDY.json]
"""
import json
import pathlib
import sys

import hulahoops as hh

root = pathlib.Path(__file__).resolve().parents[1]
path = pathlib.Path(sys.argv[1]) if len(sys.argv) > 1 else root / "studies" / "fair-knots-7.4-example2.json"
setup = json.loads(path.read_text())
result = hh.fair_knots(setup)
print(f"{path.name}: energy {result.energy}")
print(f"  chord length  {result.chord_length.energy:.6g}  parameters {result.chord_length.parameters}")
for method in ("ga", "deterministic"):
    if method in result:
        r = result[method]
        print(f"  {method:13s} {r.energy:.6g}  parameters {r.parameters}  ({r.improvement:.1%} better)")
best = min((result[m] for m in ("ga", "deterministic") if m in result), key=lambda r: r.energy)
best.curve.save("faired.json")
