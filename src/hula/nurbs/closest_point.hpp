// SPDX-License-Identifier: MIT
// Global closest point on a NURBS curve (point inversion / projection, The
// NURBS Book 6.1, eqs. 6.3–6.5): every knot span is sampled with a density
// that grows with the degree, Newton's method on f(t) = C'(t)·(C(t) - P),
// safeguarded by bisection, is run in every sample interval where f changes
// sign from - to + (each holds a local minimum of the distance) and around
// every sample that is a local minimum of the distance, and in every sample
// interval whose speed-based lower bound on the distance is below the best so
// far (narrow hairpins); iterates stay in the domain, and the best result is
// compared with both ends.
#pragma once

#include "hula/core/tolerance.hpp"
#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::nurbs {

/// Options of closest_point.
struct ClosestPointOptions {
  /// Resolutions: eps1 = resolution_for_size(tolerance, model size) is the
  /// Newton step test of eq. 6.5 (the point after the last step is kept, so
  /// its error is O(eps1²)); tolerance.angular is the zero-cosine test
  /// (eq. 6.4, second line). Points on the curve are recognised at rounding
  /// level (kRelativeResolution × model size). Defaults from Tolerance.
  Tolerance tolerance{};
  /// Sample intervals per knot span; 0 (default) chooses 4 (p + 1). Raise it
  /// only for curves with wiggles finer than their spans. Valid: 0 or ≥ 2.
  int samples_per_span = 0;
  /// Newton iterations per start (bisection steps included). Default 50; valid [1, 1000].
  int max_iterations = 50;
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// Result of closest_point.
struct ClosestPointResult {
  double t = 0.0;         ///< parameter of the closest point, in the domain
  Vec3 point{};           ///< C(t)
  double distance = 0.0;  ///< |C(t) - P| in model units (overflow-safe)
};

/// The point of the curve nearest to `point` (global over the domain).
/// @param point any finite point, at any distance from the curve
/// @returns the nearest point found; it is never farther than any sample
///   the search evaluates (both domain ends included) by more than rounding
///   noise (16 ε × the larger of |point| and the curve's extent). Among
///   candidates whose distances tie within that noise, a converged Newton
///   foot is preferred, because near a minimum the distance is flat and only
///   the foot condition C'·(C - P) = 0 locates the point to full precision.
/// @throws hula::Error(Errc::NonFiniteInput) naming point[c] if a coordinate is not finite
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
/// Complexity O(S · samples + starts · iterations) evaluations for S spans.
/// Example: `closest_point(circle, {2, 0, 0}).point` is (R, 0, 0).
[[nodiscard]] ClosestPointResult closest_point(const NurbsCurve& curve, const Vec3& point,
                                               const ClosestPointOptions& options = {});

}  // namespace hula::nurbs
