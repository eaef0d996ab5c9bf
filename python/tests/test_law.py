# SPDX-License-Identifier: MIT
# Law: parse, evaluate, derive, integrate, roots against closed forms and the
# `hula law` CLI (bit for bit where the computation is the same).
import json
import math

import numpy as np
import pytest

import hulahoops as hh
from conftest import hula, numbers


def test_evaluate_matches_cli_bit_for_bit():
    # checks Law(t) over an array against `hula law --at`, bit for bit, scalar and vector laws
    t = np.linspace(-1, 2, 17)
    for text in ("exp(-t^2) * sin(3*t) + t/7", "vec(2*cos(t), 2*sin(t), 0.5*t)"):
        law = hh.Law(text)
        cli = hula("law", text, "--at", numbers(t))
        expected = np.array([r["derivatives"][0] for r in cli["results"]]).squeeze()
        assert np.array_equal(law(t), expected)


def test_derivative_closed_form_and_cli():
    # checks derive() against the closed form d/dt sin(t^2) = 2t cos(t^2) and `hula law --derivatives 2`
    law = hh.Law("sin(t^2)")
    d = law.derive()
    t = np.linspace(0, 2, 11)
    assert np.allclose(d(t), 2 * t * np.cos(t * t), rtol=0, atol=1e-14)
    cli = hula("law", "sin(t^2)", "--at", numbers(t), "--derivatives", 2)
    assert np.array_equal(law.derive(order=2)(t), np.array([r["derivatives"][2][0] for r in cli["results"]]))


def test_integrate_and_roots_closed_forms():
    # checks ∫_0^π sin = 2 and the roots of cos(t) on [0, 10]: π/2, 3π/2, 5π/2
    assert hh.Law("sin(t)").integrate(0, math.pi) == pytest.approx(2.0, abs=1e-13)
    r = hh.Law("cos(t)").roots(0, 10)
    assert np.allclose(r, np.pi / 2 + np.pi * np.arange(3), atol=1e-12)


def test_several_parameters_and_broadcasting():
    # checks a law of two parameters with broadcast arguments and keyword arguments against NumPy
    law = hh.Law("u*v + sin(u)", parameters=["u", "v"])
    u = np.linspace(0, 1, 5)[:, None]
    v = np.linspace(0, 2, 4)[None, :]
    assert np.allclose(law(u, v), u * v + np.sin(u), rtol=0, atol=1e-15)
    assert law(v=2.0, u=0.5) == pytest.approx(1.0 + math.sin(0.5), abs=1e-15)
    assert law.derive("v")(0.3, 9.0) == pytest.approx(0.3, abs=1e-15)


def test_undefined_values_are_nan_and_parse_errors_are_positioned():
    # checks log of a negative number is NaN (documented undefined) and a parse error names line and column
    assert np.isnan(hh.Law("log(t)")(np.array([-1.0]))[0])
    with pytest.raises(hh.ParseError) as e:
        hh.Law("sin(t")
    assert e.value.where["line"] == 1 and e.value.where["column"] >= 1


def test_improper_integrals_and_antiderivatives():
    # checks (issue 26) the improper integrals the CLI refused as divergent against their closed forms, a
    # divergent one (nan), an infinite range, and antiderivatives differentiating back (F' = f at 50 points)
    assert hh.Law("sqrt(t)").integrate(0, 1) == pytest.approx(2 / 3, rel=1e-12)
    assert hh.Law("log(t)").integrate(0, 1) == pytest.approx(-1.0, rel=1e-12)
    assert hh.Law("t^(-1/2)").integrate(0, 1) == pytest.approx(2.0, rel=1e-12)
    assert hh.Law("exp(-t^2)").integrate(-math.inf, math.inf) == pytest.approx(math.sqrt(math.pi), rel=1e-12)
    assert math.isnan(hh.Law("1/t").integrate(0, 1))
    t = np.linspace(0.1, 2, 50)
    for text in ("t*exp(t)", "t*sin(t)", "2*t*cos(t^2)", "1/(1+t^2)", "cos(t)^2"):
        f = hh.Law(text)
        F = f.antiderivative()
        assert F is not None, text
        assert np.allclose(F.derive()(t), f(t), rtol=1e-12, atol=1e-12), text
    assert hh.Law("sin(t^2)").antiderivative() is None


def test_nurbs_to_law_evaluates_as_the_curve(tmp_path):
    # checks NurbsCurve.to_law on seeded random curves (degrees 1-5, rational or not, a double knot): the law equals
    # the curve to 1e-12 (relative to the control points' size) at 1,000 parameters, and the answer is
    # `hula edit to-law`'s (the report bit for bit, the written law curve's expression the same text)
    rng = np.random.default_rng(26)
    for degree in range(1, 6):
        for rational in (False, True):
            n = degree + 4
            interior = np.sort(rng.uniform(0.0, 2.0, n - degree - 1))
            if degree > 1:
                interior[1] = interior[0]  # a double knot
            knots = [0.0] * (degree + 1) + list(interior) + [2.0] * (degree + 1)
            points = rng.uniform(-5, 5, (n, 3)).tolist()
            weights = rng.uniform(0.3, 3.0, n).tolist() if rational else None
            c = hh.NurbsCurve(degree, knots, points, weights)
            answer = c.to_law()
            t = np.linspace(0.0, 2.0, 1000)
            size = max(1.0, float(np.max(np.linalg.norm(points, axis=1))))
            assert np.max(np.linalg.norm(answer["law"](t) - c(t), axis=-1)) <= 1e-12 * size
            assert answer["max_difference"] <= 1e-12 * size
            c.save(str(tmp_path / "c.json"))
            cli = hula("edit", "to-law", tmp_path / "c.json", "-o", tmp_path / "law.json")
            assert {k: v for k, v in answer.items() if k not in ("law", "expression")} == \
                {k: v for k, v in cli.items() if k not in ("operation", "curve")}
            written = hh.NurbsCurve.load(str(tmp_path / "law.json"))  # resolved to its stand-in NURBS
            assert written.domain == (0.0, 2.0)
            assert json.loads((tmp_path / "law.json").read_text())["expression"] == answer["expression"]
