// SPDX-License-Identifier: MIT
// Bézier curves (thesis 5.4): construction as a NurbsCurve on [0, 1], the de
// Casteljau algorithm with subdivision (The NURBS Book A1.5; thesis 5.4.4),
// and evaluation in Bernstein form (thesis 5.4.3, A1.4 with A1.3's
// all-Bernstein recursion). Rational Bézier curves work on homogeneous points
// (w P, w) (The NURBS Book 4.2).
#pragma once

#include <span>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::nurbs {

/// The Bézier curve of degree n - 1 with the given n control points, as a
/// NurbsCurve with knots {0^n, 1^n} (domain [0, 1]).
/// @param control_points n ≥ 2 points in model units (n ≤ kMaxDegree + 1)
/// @param weights empty (non-rational) or n positive weights
/// @param dimension 2 (all z = 0) or 3
/// @throws hula::Error(Errc::TooFewPoints) if fewer than 2 points (names the count)
/// @throws hula::Error(Errc::InvalidDegree) if more than kMaxDegree + 1 points
/// @throws as the NurbsCurve constructor for non-finite points and bad weights
[[nodiscard]] NurbsCurve make_bezier(std::span<const Vec3> control_points, std::span<const double> weights = {},
                                     int dimension = 3);

/// Result of de_casteljau.
struct DeCasteljauResult {
  Vec3 point{};  ///< C(t)
  /// Control polygon of C on [0, t] (reparameterised to [0, 1]); left.front() is P_0, left.back() is C(t).
  std::vector<Vec3> left;
  /// Control polygon of C on [t, 1] (reparameterised to [0, 1]); right.front() is C(t), right.back() is P_n.
  std::vector<Vec3> right;
  /// Weights of the two halves; empty for a non-rational curve.
  std::vector<double> left_weights, right_weights;
};

/// de Casteljau's algorithm (A1.5, thesis eq. 5.4.4): the point at t and the
/// two subdivision polygons (with weights for rational curves).
/// @param control_points n ≥ 2 points; @param weights empty or n positive weights
/// @param t parameter in [0, 1]
/// @throws hula::Error(Errc::TooFewPoints) if fewer than 2 points
/// @throws hula::Error(Errc::InvalidWeight) if the weight count differs (names both counts) or a weight ≤ 0 (names it)
/// @throws hula::Error(Errc::NonFiniteInput) if t is not finite (names t)
/// @throws hula::Error(Errc::OutOfDomain) if t is outside [0, 1] (names t)
/// Complexity O(n²).
[[nodiscard]] DeCasteljauResult de_casteljau(std::span<const Vec3> control_points, std::span<const double> weights,
                                             double t);

/// C(t) = Σ B_{i,n}(t) w_i P_i / Σ B_{i,n}(t) w_i in Bernstein form (bernstein_all). No allocation.
/// @throws as de_casteljau, and hula::Error(Errc::InvalidDegree) above kMaxDegree + 1 points
[[nodiscard]] Vec3 evaluate_bernstein(std::span<const Vec3> control_points, std::span<const double> weights, double t);

}  // namespace hula::nurbs
