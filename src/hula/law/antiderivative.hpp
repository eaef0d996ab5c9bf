// SPDX-License-Identifier: MIT
// Symbolic antiderivatives of laws where they exist in closed form for the
// supported functions — the integration the thesis asked ACIS for (10.2.3):
// polynomials (any expression that expands to one: sums, products, integer
// powers), piecewise laws whose switch is linear in the parameter (made
// continuous at the switch), and linear-argument forms ∫sin(at+b), ∫cos,
// ∫exp, ∫sinh, ∫cosh, ∫tan, ∫(at+b)^n (n = −1 gives log|at+b|), ∫|at+b|,
// with linearity and constant factors. Vector laws are integrated per
// component. Anything else has no closed form here; definite_integral()
// then falls back to adaptive quadrature and says so.
#pragma once

#include <optional>
#include <string_view>

#include "hula/law/expr.hpp"
#include "hula/law/integrate.hpp"

namespace hula::law {

/// A closed-form F with dF/d(parameter) = f, or nullopt when none of the rules applies.
/// F is continuous across piecewise switches; its constant of integration is unspecified.
/// @throws hula::Error(Errc::InvalidArgument) if f is empty
[[nodiscard]] std::optional<Law> antiderivative(const Law& f, std::string_view parameter);

/// How definite_integral() obtained its value.
enum class IntegralMethod {
  Symbolic,  ///< F(b) − F(a) from antiderivative()
  Numeric,   ///< adaptive Gauss–Kronrod (integrate())
};

/// Result of definite_integral().
struct DefiniteIntegralResult {
  double value = 0.0;
  /// Symbolic: rounding bound 16 ε (|F(a)| + |F(b)|); numeric: the quadrature's error estimate.
  double error_estimate = 0.0;
  IntegralMethod method = IntegralMethod::Symbolic;
  /// Symbolic: always true; numeric: the quadrature met the requested tolerance (false for a
  /// divergent or non-smooth integrand the rule could not resolve: the value is then unreliable).
  bool converged = false;
  /// The antiderivative used (empty handle for the numeric method).
  Law antiderivative{};
};

/// The symbolic branch of definite_integral() alone: F(b) − F(a) when a closed form exists, a ≠ b and f has no
/// pole or undefined region on [a, b], else nullopt. Cheap and bounded (no quadrature), so callers that only need to
/// decide between a closed form and a numeric method use it instead of definite_integral().
/// @throws hula::Error(Errc::InvalidArgument) if f is not a scalar law or a bound is not finite
[[nodiscard]] std::optional<DefiniteIntegralResult> symbolic_definite_integral(const Law& f, std::string_view parameter,
                                                                               double a, double b);

/// ∫_a^b f d(parameter) for a scalar law: symbolic when a closed form exists and f has no pole or
/// undefined region in [a, b], else numeric with its error estimate.
/// @throws as integrate() (the numeric path reports undefined integrands)
[[nodiscard]] DefiniteIntegralResult definite_integral(const Law& f, std::string_view parameter, double a, double b,
                                                       const IntegrationOptions& options = {});

}  // namespace hula::law
