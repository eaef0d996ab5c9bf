// SPDX-License-Identifier: MIT
// Adaptive numerical integration of a scalar law of one parameter to a
// requested tolerance, with the achieved error estimate reported — also for
// improper integrals. The interval is cut at the law's kinks, switches and
// poles (singularities()); smooth pieces take adaptive Gauss–Kronrod
// (61-point, Boost.Math), pieces with a singular or infinitely steep end take
// tanh-sinh quadrature (Boost.Math, double exponential: it never evaluates the
// end and its nodes crowd towards it, so ∫₀¹ t^(−1/2), ∫₀¹ log t and ∫₀¹ √t
// converge to rounding), and infinite bounds exp-sinh or sinh-sinh. Before any
// of that, each singular end is classified from the integrand's growth
// |f| ≈ C |t − t0|^p: p ≤ −1 (to within 1e-3) is a non-integrable singularity
// and the integral is reported divergent, never computed. A singular end t0 ≠ 0
// is moved to 0 first (f(t0 + u) simplified, so that t − t0 becomes u exactly):
// the double-exponential nodes then resolve distances below the spacing of
// doubles at t0. This is the integration the thesis could not get from ACIS
// (10.2.3, natural equations).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "hula/law/expr.hpp"

namespace hula::law {

/// Options of integrate().
struct IntegrationOptions {
  /// Requested relative accuracy: stop when error ≤ relative_tolerance × ∫|f|. Default 1e-12;
  /// valid [1e-15, 0.1]. Below ~1e-14 rounding makes the request unreachable.
  double relative_tolerance = 1e-12;
  /// Maximum bisection depth of the adaptive Gauss–Kronrod rule per piece, and the number of
  /// refinement levels of the double-exponential rules (at most 15). Default 20; valid 1 … 40.
  int max_depth = 20;
  /// Cut [a, b] at kinks, switches, poles and knots found by singularities() before integrating.
  /// Default true. Infinite ranges are integrated in one piece either way.
  bool split_at_singularities = true;
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// How an end of a piece behaves (reported for every end that needed the improper treatment).
struct SingularPoint {
  /// Where: a point of [a, b], or ±infinity for an infinite bound.
  double t = 0.0;
  /// The subexpression responsible (from singularities()), or the integrand at an infinite bound or an
  /// end where it is not finite.
  std::string expression;
  /// Estimated exponent p of the growth: |f(t)| ≈ C |t − t0|^p approaching a finite point (the smaller of
  /// the two sides for an interior point), |f(t)| ≈ C |t|^p towards ±infinity. A function that vanishes
  /// faster than any power has +infinity at a point and −infinity at infinity (e^(−t)).
  double exponent = 0.0;
  /// p > −1 at a finite point (integrable), p < −1 at infinity; exponents within 1e-3 of −1 count as
  /// −1 (not integrable: a logarithmic divergence cannot be told from |t|^(−1 ± 1e-3)).
  bool integrable = true;
};

/// Result of integrate().
struct IntegrationResult {
  /// ∫_a^b f(t) dt; NaN when divergent.
  double value = 0.0;
  /// Estimated absolute error (Gauss–Kronrod difference, or the difference of the last two levels of a
  /// double-exponential rule, summed over pieces); +infinity when divergent.
  double error_estimate = 0.0;
  /// ∫_a^b |f(t)| dt (the scale of the relative tolerance).
  double l1_norm = 0.0;
  /// Number of pieces integrated separately.
  std::size_t pieces = 0;
  /// True when error_estimate ≤ relative_tolerance × l1_norm (or the integral is exactly 0).
  bool converged = false;
  /// True when a singular point is not integrable (singular_points says which): the integral diverges.
  bool divergent = false;
  /// True when some piece needed the improper treatment (a singular end or an infinite bound).
  bool improper = false;
  /// The ends that needed it, increasing in t.
  std::vector<SingularPoint> singular_points;
};

/// Integrates the scalar law f(parameter) over [a, b] (a > b gives the negated integral). a and b may
/// be ±infinity (the range is then one piece, by exp-sinh or sinh-sinh).
/// @returns the value with its error estimate; divergent = true (value NaN) when the singularity
///   analysis finds a non-integrable end; converged = false when the rule could not reach the tolerance
///   (the value is then the rule's best)
/// @throws hula::Error(Errc::InvalidArgument) if f is not a scalar or depends on another parameter,
///   or a or b is NaN
/// @throws hula::Error(Errc::NumericalFailure) naming the parameter where the integrand is undefined
///   inside the range (an undefined region, not an end)
/// @throws hula::Error(Errc::InvalidOption) if options are invalid
[[nodiscard]] IntegrationResult integrate(const Law& f, std::string_view parameter, double a, double b,
                                          const IntegrationOptions& options = {});

}  // namespace hula::law
