# SPDX-License-Identifier: MIT
# analyse() and reconstruct(): against `hula analyse` / `hula reconstruct`
# bit for bit, and against the closed forms of the circle and the helix.
import math

import numpy as np
import pytest

import hulahoops as hh
from conftest import hula, numbers


def test_analyse_matches_cli_bit_for_bit(space_curve, tmp_path):
    # checks κ, τ, T, N, B, speed of analyse() against `hula analyse --at` at the same parameters, bit for bit
    a = hh.analyse(space_curve, 41)
    path = tmp_path / "c.json"
    space_curve.save(str(path))
    cli = hula("analyse", path, "--at", numbers(a["t"]))["points"]
    assert len(cli) == 41
    for key in ("kappa", "tau", "speed", "kappa_prime"):
        expected = np.array([np.nan if p[key] is None else p[key] for p in cli])
        assert np.array_equal(a[key], expected, equal_nan=True), key
    for key in ("position", "T", "N", "B"):
        expected = np.array([[np.nan] * 3 if p[key] is None else p[key] for p in cli])
        assert np.array_equal(a[key], expected, equal_nan=True), key


def test_analyse_circle_closed_form(quarter_circle):
    # checks the unit circle: κ = 1, τ = 0, N points to the centre, fins P - 0.5 κN end outside, at radius 1.5
    a = hh.analyse(quarter_circle, 101, fin_scale=0.5)
    assert set(a) >= {"t", "position", "T", "N", "B", "kappa", "tau", "speed", "fins"}
    assert np.allclose(a["kappa"], 1.0, rtol=0, atol=1e-13)
    assert np.allclose(a["tau"], 0.0, rtol=0, atol=1e-13)
    assert np.allclose(a["N"], -a["position"], rtol=0, atol=1e-13)
    assert np.allclose(np.hypot(*a["fins"].T), 1.5, rtol=0, atol=1e-13)
    assert a["frame_defined"].all()


def test_analyse_undefined_frame_on_a_line():
    # checks that on a straight line N, B and τ are NaN (undefined, documented) while κ = 0 and T are defined
    a = hh.analyse(hh.NurbsCurve(1, [0, 0, 1, 1], [[0, 0, 0], [1, 1, 0]]), 5)
    assert np.all(a["kappa"] == 0) and np.all(np.isnan(a["tau"])) and np.all(np.isnan(a["N"]))
    assert np.allclose(a["T"], [math.sqrt(0.5), math.sqrt(0.5), 0], rtol=0, atol=1e-15)
    assert not a["frame_defined"].any() and a["tangent_defined"].all()


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
