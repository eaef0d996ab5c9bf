# SPDX-License-Identifier: MIT
# analyse() and reconstruct(): against `hula analyse` / `hula reconstruct`
# bit for bit, and against the closed forms of the circle and the helix.
import math

import numpy as np
import pytest

import hulahoops as hh
from conftest import hula, numbers


def column(values, width=None):
    """A JSON column as a float array, NaN where the JSON has null (rows of `width` for vectors)."""
    if width is None:
        return np.array([np.nan if v is None else v for v in values], dtype=float)
    return np.array([[np.nan] * width if v is None else v for v in values], dtype=float)


def test_analyse_matches_cli_bit_for_bit(space_curve, tmp_path):
    # checks every column, the features and the fins of analyse() against `hula analyse --at` at the same
    # parameters, bit for bit (one analysis, diffgeom::analyse_curve, behind both doors)
    a = hh.analyse(space_curve, 41, arc_lengths=True, bishop=True, fins=["curvature"], fin_density=120,
                   features=True)
    path = tmp_path / "c.json"
    space_curve.save(str(path))
    cli = hula("analyse", path, "--at", numbers(a["t"]), "--fins", "curvature", "--features")
    assert len(cli["t"]) == 41
    for key in ("t", "s", "curvature", "torsion", "speed", "curvature_derivative"):
        assert np.array_equal(a[key], column(cli[key]), equal_nan=True), key
    assert np.array_equal(a["points"], column(cli["points"], 3), equal_nan=True)
    for key in ("T", "N", "B"):
        assert np.array_equal(a["frames"][key], column(cli["frames"][key], 3), equal_nan=True), key
    for key in ("U", "V"):
        assert np.array_equal(a["bishop"][key], column(cli["bishop"][key], 3), equal_nan=True), key
    assert a["fins"][0]["scale"] == cli["fins"][0]["scale"]
    assert np.array_equal(a["fins"][0]["tip"], column(cli["fins"][0]["tip"], 3), equal_nan=True)
    assert a["planarity"] == cli["planarity"]
    for key in ("inflections", "curvature_extrema", "torsion_extrema"):
        assert [(f["t"], list(f["point"])) for f in a["features"][key]] == \
            [(f["t"], f["point"]) for f in cli["features"][key]], key
    assert [k["t"] for k in a["features"]["knots"]] == [k["t"] for k in cli["features"]["knots"]] == [0.3, 0.7]


def test_analyse_circle_closed_form(quarter_circle):
    # checks the unit circle: κ = 1, τ = 0, N points to the centre, fins P - 0.5 κN end outside, at radius 1.5
    a = hh.analyse(quarter_circle, 101, fins=["curvature"], fin_scale=0.5)
    assert set(a) >= {"t", "points", "frames", "curvature", "torsion", "speed", "fins", "planarity"}
    assert np.allclose(a["curvature"], 1.0, rtol=0, atol=1e-13)
    assert np.allclose(a["torsion"], 0.0, rtol=0, atol=1e-13)
    assert np.allclose(a["frames"]["N"], -a["points"], rtol=0, atol=1e-13)
    tips = a["fins"][0]["tip"]
    assert np.allclose(np.hypot(tips[:, 0], tips[:, 1]), 1.5, rtol=0, atol=1e-13)
    assert a["planarity"]["planar"] and a["planarity"]["normal"] == [0.0, 0.0, 1.0]


def test_analyse_undefined_frame_on_a_line():
    # checks that on a straight line N, B and τ are NaN (undefined, documented) while κ = 0 and T are defined
    a = hh.analyse(hh.NurbsCurve(1, [0, 0, 1, 1], [[0, 0, 0], [1, 1, 0]]), 5)
    assert np.all(a["curvature"] == 0) and np.all(np.isnan(a["torsion"])) and np.all(np.isnan(a["frames"]["N"]))
    assert np.allclose(a["frames"]["T"], [math.sqrt(0.5), math.sqrt(0.5), 0], rtol=0, atol=1e-15)


def test_analyse_law_curve_from_a_dict():
    # checks a curve file given as a dict (a law helix, converted as a value): constant κ = 16/17, no extremum,
    # no knot, no inflection (a space curve)
    helix = {"kind": "law", "expression": "vec(cos(t), sin(t), t/4)", "domain": [0, 4 * math.pi]}
    a = hh.analyse(helix, 50, features=True)
    assert np.allclose(a["curvature"], 16 / 17, rtol=0, atol=1e-12)
    f = a["features"]
    assert f["inflections"] == [] and f["curvature_extrema"] == [] and f["torsion_extrema"] == [] and f["knots"] == []
    with pytest.raises(hh.InvalidArgumentError, match="curve"):
        hh.analyse([1, 2, 3])


def test_reconstruct_helix_closed_form_and_cli():
    # checks κ = 0.4, τ = 0.2 against the closed-form helix (rotation about the Darboux vector) and `hula reconstruct`
    k, t, length = 0.4, 0.2, 10.0
    curve = hh.reconstruct("0.4", "0.2", length=length)
    s = np.linspace(0, length, 9)
    # T0 = x, N0 = y, B0 = z; the frame turns about A = (τT0 + κB0)/w at rate w = √(κ²+τ²):
    # T(s) = (τ/w)A + cos(ws)U + sin(ws)(A×U), U = T0 - (τ/w)A, so r(s) = ∫T.
    w = np.hypot(k, t)
    A = np.array([t, 0.0, k]) / w
    U = np.array([1.0, 0.0, 0.0]) - (t / w) * A
    V = np.cross(A, U)
    expected = (np.outer((t / w) * s, A) + np.outer(np.sin(w * s) / w, U) + np.outer((1 - np.cos(w * s)) / w, V))
    assert np.allclose(curve(s), expected, rtol=0, atol=1e-8)
    cli = hula("reconstruct", "--kappa", "0.4", "--tau", "0.2", "--length", length, "--at", numbers(s))
    assert np.array_equal(curve(s), np.array([p["position"] for p in cli["points"]]))
    fit = curve.to_nurbs(1e-9)
    assert fit.converged and fit.max_deviation <= 1e-9


def test_reconstruct_accepts_laws_from_other_contexts():
    # checks Law objects parsed separately combine (re-parsed in one context) into the planar circle of radius 2
    curve = hh.reconstruct(hh.Law("0.5", parameters=["s"]), 0, length=math.pi)
    end = curve(math.pi)
    assert np.allclose(end, [2.0, 2.0, 0.0], atol=1e-9)
    with pytest.raises(hh.InvalidArgumentError, match="kappa"):
        hh.reconstruct(hh.Law("t"), 0, length=1.0)
