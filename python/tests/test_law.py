# SPDX-License-Identifier: MIT
# Law: parse, evaluate, derive, integrate, roots against closed forms and the
# `hula law` CLI (bit for bit where the computation is the same).
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
