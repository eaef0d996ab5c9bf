// SPDX-License-Identifier: MIT
// Symbolic antiderivatives of laws where they exist in closed form for the
// supported functions — the symbolic integration the thesis could not get
// (6, 10.2.3: "it was not possible to proceed to symbolic integration"):
// polynomials (any expression that expands to one), piecewise laws whose
// switch is linear in the parameter (made continuous at the switch), |at+b|,
// and, for products k·P(t)·Π g_i^e_i (antiderivative.cpp lists the rules in
// the order tried):
//  - rational functions with a denominator of degree ≤ 2 (log, atan forms:
//    ∫1/(1+t²) = atan t) and polynomials times powers of a linear factor;
//  - substitution ∫g(u)·u' = G(u) for g = u^e, sin, cos, exp, sinh, cosh, tan,
//    tanh, log, atan, asin, acos (∫2t·cos t² = sin t², ∫f'/f = log|f|), which
//    includes every linear argument ∫sin(at+b), ∫(at+b)^n;
//  - integration by parts of a polynomial times exp, sin, cos, sinh, cosh of
//    a linear argument (∫t·eᵗ = (t − 1)eᵗ, ∫t·sin t = sin t − t cos t) and
//    times log, atan, asin, acos;
//  - e^(at+b)·sin/cos(ct+d); powers sin^m·cos^n of one linear argument
//    (∫cos² t = t/2 + sin t cos t/2) and products of two;
//  - (mt + n)/√Q and √Q for a quadratic Q (asin and log forms).
// Vector laws are integrated per component. Every rule is checked in the
// tests by differentiating back (law::simplify, then 100 points to 1e-12).
// Anything else has no closed form here; definite_integral() then integrates
// numerically (integrate(), improper integrals included) and says why.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hula/law/expr.hpp"
#include "hula/law/integrate.hpp"

namespace hula::law {

/// A closed-form F with dF/d(parameter) = f, or nullopt when none of the rules applies.
/// F is continuous across piecewise switches; its constant of integration is unspecified. F is an
/// antiderivative on every interval where f is defined and finite (log|u| forms span the roots of u
/// only as an improper integral's two sides).
/// @throws hula::Error(Errc::InvalidArgument) if f is empty
[[nodiscard]] std::optional<Law> antiderivative(const Law& f, std::string_view parameter);

/// antiderivative() with the reason when there is none.
struct AntiderivativeReport {
  /// F, or nullopt.
  std::optional<Law> antiderivative;
  /// Without F: the first term of f's sum (by linearity) that no rule applies to, e.g. sin(t^2) in
  /// t + sin(t^2); empty when F exists.
  Law blocking_term;
};

/// antiderivative() and, when there is none, the term that stops it.
/// @throws hula::Error(Errc::InvalidArgument) if f is empty
[[nodiscard]] AntiderivativeReport antiderivative_report(const Law& f, std::string_view parameter);

/// How definite_integral() obtained its value.
enum class IntegralMethod {
  Symbolic,  ///< F(b) − F(a) from antiderivative()
  Numeric,   ///< adaptive Gauss–Kronrod (integrate())
};

/// Result of definite_integral().
struct DefiniteIntegralResult {
  /// ∫_a^b f; NaN when divergent.
  double value = 0.0;
  /// Symbolic: rounding bound 16 ε (|F(a)| + |F(b)|); numeric: the quadrature's error estimate.
  double error_estimate = 0.0;
  IntegralMethod method = IntegralMethod::Symbolic;
  /// Symbolic: always true; numeric: the quadrature met the requested tolerance (false when the rule
  /// could not resolve the integrand: the value is then unreliable; false when divergent).
  bool converged = false;
  /// Numeric only: a singular end is not integrable (integrate()); value is NaN.
  bool divergent = false;
  /// The antiderivative used (empty handle for the numeric method).
  Law antiderivative{};
  /// Numeric only: why the closed form was not used, e.g. "no closed-form antiderivative of sin(t^2)",
  /// "the antiderivative log(abs(t)) has no finite limit at t = 0", "an infinite bound".
  std::string numeric_reason;
  /// Numeric only: the singular ends the quadrature treated (integrate()).
  std::vector<SingularPoint> singular_points;
};

/// The symbolic branch of definite_integral() alone: F(b) − F(a) when a closed form F exists, a ≠ b, f has no
/// undefined region inside [a, b] and F has a finite limit at every pole, boundary or undefined end of f in
/// [a, b], the same from both sides at an interior one (so ∫₀¹ t^(−1/2) = 2√t |₀¹ and ∫₀¹ log t = [t log t − t]₀¹
/// with the limit 0 at t = 0 are closed forms, ∫₋₁² 1/t is not). The limit at t0 is F(t0) when finite, else
/// F(t0 ± u) (re-expanded about t0 by law::simplify) at u = 1e-30, 1e-60 and 1e-120 times the interval's
/// length when those agree to 1e-14. Cheap and bounded (no quadrature), so callers that only need to decide
/// between a closed form and a numeric method use it instead of definite_integral().
/// @throws hula::Error(Errc::InvalidArgument) if f is not a scalar law or a bound is not finite
[[nodiscard]] std::optional<DefiniteIntegralResult> symbolic_definite_integral(const Law& f, std::string_view parameter,
                                                                               double a, double b);

/// ∫_a^b f d(parameter) for a scalar law: symbolic when symbolic_definite_integral() applies, else numeric
/// (integrate(): improper integrals with integrable end singularities and infinite bounds included, divergence
/// reported only where the growth at a singular end is not integrable) with its error estimate and the reason.
/// a and b may be ±infinity (numeric then).
/// @throws hula::Error(Errc::InvalidArgument) if f is not a scalar law or a bound is NaN
/// @throws as integrate() (the numeric path reports undefined integrands)
[[nodiscard]] DefiniteIntegralResult definite_integral(const Law& f, std::string_view parameter, double a, double b,
                                                       const IntegrationOptions& options = {});

}  // namespace hula::law
