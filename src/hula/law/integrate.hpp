// SPDX-License-Identifier: MIT
// Adaptive numerical integration of a scalar law of one parameter to a
// requested tolerance, with the achieved error estimate reported. Adaptive
// Gauss–Kronrod (61-point, Boost.Math) on pieces of [a, b] cut at the law's
// kinks and switches (singularities()), so non-smooth laws converge as fast
// as smooth ones. This is the integration the thesis could not get from ACIS
// (10.2.3, natural equations).
#pragma once

#include <cstddef>
#include <string_view>

#include "hula/law/expr.hpp"

namespace hula::law {

/// Options of integrate().
struct IntegrationOptions {
  /// Requested relative accuracy: stop when error ≤ relative_tolerance × ∫|f|. Default 1e-12;
  /// valid [1e-15, 0.1]. Below ~1e-14 rounding makes the request unreachable.
  double relative_tolerance = 1e-12;
  /// Maximum bisection depth of the adaptive rule per piece. Default 20; valid 1 … 40.
  int max_depth = 20;
  /// Cut [a, b] at kinks, switches and knots found by singularities() before integrating. Default true.
  bool split_at_singularities = true;
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// Result of integrate().
struct IntegrationResult {
  /// ∫_a^b f(t) dt.
  double value = 0.0;
  /// Estimated absolute error (Gauss–Kronrod difference, summed over pieces).
  double error_estimate = 0.0;
  /// ∫_a^b |f(t)| dt (the scale of the relative tolerance).
  double l1_norm = 0.0;
  /// Number of pieces integrated separately.
  std::size_t pieces = 0;
  /// True when error_estimate ≤ relative_tolerance × l1_norm (or the integral is exactly 0).
  bool converged = false;
};

/// Integrates the scalar law f(parameter) over [a, b] (a > b gives the negated integral).
/// @throws hula::Error(Errc::InvalidArgument) if f is not a scalar or depends on another parameter,
///   or a, b are not finite
/// @throws hula::Error(Errc::NumericalFailure) naming the parameter where the integrand is undefined
/// @throws hula::Error(Errc::InvalidOption) if options are invalid
[[nodiscard]] IntegrationResult integrate(const Law& f, std::string_view parameter, double a, double b,
                                          const IntegrationOptions& options = {});

}  // namespace hula::law
