#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the conformance corpus (README.md): named curves with known features
and random ones drawn from a fixed seed, one curve file each (docs/formats.md).
Usage: tests/data/conformance/generate.py   (rewrites the *.json files here)"""
import json
import math
import pathlib
import random

HERE = pathlib.Path(__file__).resolve().parent
SEED = 22


def rounded(x):
    # Short decimals, so the files read the same in every language's parser.
    return round(x, 6)


def clamped_knots(n, degree, rng, double=False):
    """n + degree + 1 clamped knots on [0, 1]; with `double`, one interior knot of multiplicity 2."""
    singles = n - degree - 1 - (2 if double else 0)
    inner = [rounded(rng.uniform(0.05, 0.95)) for _ in range(singles)]
    if double:
        k = rounded(rng.uniform(0.3, 0.7))
        inner += [k, k]
    return [0.0] * (degree + 1) + sorted(inner) + [1.0] * (degree + 1)


def main():
    rng = random.Random(SEED)
    corpus = {}
    # Named curves whose features are known in closed form (tests/diffgeom/analysis_test.cpp).
    corpus["planar_bezier_s"] = {"kind": "bezier", "control_points": [[0, 0], [1, 1], [2, -1], [3, 0]]}
    corpus["space_bezier_issue22"] = {
        "kind": "bezier",
        "control_points": [[-155.86, 108.91, 0], [-20, 60, 0], [-4.14, 88.22, 0], [85.52, 0, 115.21]],
    }
    w = math.sqrt(0.5)
    corpus["rational_circle"] = {
        "kind": "nurbs", "degree": 2, "knots": [0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1],
        "control_points": [[3, 0], [3, 3], [0, 3], [-3, 3], [-3, 0], [-3, -3], [0, -3], [3, -3], [3, 0]],
        "weights": [1, w, 1, w, 1, w, 1, w, 1],
    }
    corpus["law_helix"] = {"kind": "law", "expression": "vec(cos(t), sin(t), t/4)", "parameter": "t",
                           "domain": [0, 4 * math.pi]}
    corpus["law_cubic_zero_curvature"] = {"kind": "law", "expression": "vec(t, t^3, 0)", "parameter": "t",
                                          "domain": [-1, 1]}
    corpus["natural_sine"] = {"kind": "natural", "curvature": "sin(s)", "torsion": "0", "parameter": "s",
                              "length": 2 * math.pi}
    corpus["hermite_double_knots"] = {"kind": "hermite", "points": [[0, 0, 0], [2, 1, 0.5], [4, 0, 1]],
                               "tangents": [[2, 2, 0], [2, 0, 1], [2, -2, 0]]}
    # Random curves from the seed: planar and space NURBS (one with a double knot), rational ones,
    # a cubic spline through points, a planar NURBS with two double knots.
    for i in range(2):
        n = rng.randint(6, 9)
        corpus[f"random_planar_nurbs_{i}"] = {
            "kind": "nurbs", "degree": 3, "knots": clamped_knots(n, 3, rng),
            "control_points": [[rounded(rng.uniform(-10, 10)), rounded(rng.uniform(-10, 10))] for _ in range(n)]}
    for i in range(2):
        n = rng.randint(6, 9)
        corpus[f"random_space_nurbs_{i}"] = {
            "kind": "nurbs", "degree": 3, "knots": clamped_knots(n, 3, rng, double=i == 1),
            "control_points": [[rounded(rng.uniform(-10, 10)) for _ in range(3)] for _ in range(n)]}
    for i in range(2):
        n = rng.randint(5, 7)
        corpus[f"random_rational_{i}"] = {
            "kind": "nurbs", "degree": 2 + i, "knots": clamped_knots(n, 2 + i, rng),
            "control_points": [[rounded(rng.uniform(-5, 5)) for _ in range(3 - (1 - i))] for _ in range(n)],
            "weights": [rounded(rng.uniform(0.5, 2.0)) for _ in range(n)]}
    corpus["random_interpolated"] = {
        "kind": "interpolated", "parameterisation": "chord",
        "points": [[rounded(x + rng.uniform(-0.3, 0.3)), rounded(rng.uniform(-2, 2)), rounded(rng.uniform(-1, 1))]
                   for x in range(7)]}
    corpus["planar_nurbs_double_knots"] = {
        "kind": "nurbs", "degree": 3, "knots": [0, 0, 0, 0, 0.4, 0.4, 0.6, 0.6, 1, 1, 1, 1],
        "control_points": [[rounded(rng.uniform(-5, 5)), rounded(rng.uniform(-5, 5)), 0] for _ in range(8)]}
    for name, curve in corpus.items():
        (HERE / f"{name}.json").write_text(json.dumps(curve, indent=2) + "\n")
    (HERE / "corpus.txt").write_text("".join(f"{name}\n" for name in corpus))


if __name__ == "__main__":
    main()
