// SPDX-License-Identifier: MIT
// Curve–curve intersection, self-intersection and the distance between two
// NURBS curves (planar or spatial, rational or not), by subdivision with
// proofs of exclusion and uniqueness, then Newton refinement on the curves
// themselves (Sederberg & Nishita, "Curve intersection using Bézier
// clipping", CAD 22(9), 1990, for the hull tests; Sederberg & Meyers' tangent
// cones, "Loop detection in surface patch intersections", CAGD 5, 1988, for
// uniqueness; The NURBS Book A5.6 for the Bézier decomposition).
//
// Both curves are cut into their Bézier pieces (decompose_to_bezier), and
// pairs of pieces are examined recursively, halving a piece with de
// Casteljau's algorithm (de_casteljau) when the pair is not decided:
//   - excluded when a lower bound on the distance between the pieces (their
//     control boxes, and their chords thickened by the control polygons'
//     distance from them) exceeds the tolerance (convex hull property; for
//     rational pieces with positive weights too);
//   - at most one common point when the pieces' tangent cones cannot hold
//     parallel directions (every tangent of a rational Bézier piece lies in
//     the cone of the differences P_j − P_i, j > i, of its control points):
//     Gauss–Newton on A(s) − B(t) = 0 from the chords' closest points decides it;
//   - coincident within the tolerance (samples of each piece lie within tol of
//     the other): a contact zone. Zones are merged and reported as a tangent
//     point when the curves separate from a single tangential contact inside
//     the zone (located by Newton on the tangency system D·A' = 0,
//     A' × B' = 0, which is regular where the relative curvature is not zero),
//     and otherwise as an overlap.
// A self-intersection search runs the same machinery on a curve against
// itself, skipping pieces whose control polygon is monotone along a direction
// (they cannot meet themselves) and neighbours that are monotone together.
#pragma once

#include <vector>

#include "hula/core/tolerance.hpp"
#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::nurbs {

/// Options of intersect(), self_intersect() and curve_distance().
struct IntersectOptions {
  /// Resolution: the curves meet where they come closer than
  /// tol = resolution_for_size(tolerance, model size) (model size: the larger of
  /// the two curves' control-box diagonals). Points closer than tol along both
  /// curves are one point. Default resabs 1e-6. `angular` is not used.
  Tolerance tolerance{};
  /// Newton iterations per start. Default 50; valid [1, 1000].
  int max_iterations = 50;
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// How two curves meet at a point.
enum class IntersectionKind {
  Crossing,  ///< transversal: the tangents differ; the point is exact to rounding / sin(angle)
  Tangent,   ///< the tangents are parallel (a touch, a tangential crossing) or a curve is singular there
};

/// "crossing" or "tangent".
[[nodiscard]] const char* intersection_kind_name(IntersectionKind kind) noexcept;

/// One point where two curves (or two parts of one curve) meet.
struct CurveIntersection {
  double s = 0.0;         ///< parameter on the first curve (self: the smaller parameter)
  double t = 0.0;         ///< parameter on the second curve (self: the larger parameter)
  Vec3 point{};           ///< (A(s) + B(t)) / 2
  double distance = 0.0;  ///< |A(s) − B(t)| ≤ tol, model units
  /// Angle between the tangent lines in [0, π/2] radians (0 at a tangent point).
  double angle = 0.0;
  IntersectionKind kind = IntersectionKind::Crossing;
};

/// A stretch where the curves coincide within the tolerance.
struct CurveOverlap {
  double s0 = 0.0;  ///< start on the first curve (s0 < s1)
  double s1 = 0.0;  ///< end on the first curve
  double t0 = 0.0;  ///< parameter on the second curve matching s0 (self: t0 > s1)
  double t1 = 0.0;  ///< parameter matching s1; t1 < t0 when the curves run in opposite directions
  Vec3 start{};     ///< A(s0)
  Vec3 end{};       ///< A(s1)
};

/// Result of intersect() and self_intersect().
struct IntersectionResult {
  std::vector<CurveIntersection> points;  ///< isolated meeting points, in increasing s
  std::vector<CurveOverlap> overlaps;     ///< coincident stretches, in increasing s0
  double tolerance = 0.0;                 ///< the tol used, model units
};

/// Every point where curves a and b meet, and every stretch where they coincide.
/// @param a, b any valid curves (2-D curves lie in z = 0; a 2-D and a 3-D curve may be mixed)
/// @returns the points sorted by s; a closed curve's closure is not reported by self_intersect
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
/// @throws hula::Error(Errc::NumericalFailure) naming "tolerance" when the curves stay within a few
///   tolerances of each other (but not within one) over a stretch too long to resolve: more than 10⁶
///   piece pairs (concentric arcs 2 tol apart at a tolerance of 1e-14 of their size)
/// Complexity: O(S_a · S_b) piece pairs for S spans, plus O(log(size / tol)) levels of subdivision
///   around each meeting point and O(length / tol-resolution) pieces along an overlap.
/// Example: a circle of radius 1 and the line y = 0.5 across it meet at two crossings, angle π/3.
[[nodiscard]] IntersectionResult intersect(const NurbsCurve& a, const NurbsCurve& b,
                                           const IntersectOptions& options = {});

/// Every point where a curve meets itself (s < t), and every stretch it runs over twice.
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
/// @throws hula::Error(Errc::NumericalFailure) naming "tolerance" as intersect()
/// @note a closed curve (C(start) = C(end) within tol) is not reported as meeting itself at its
///   ends, nor is a knot where the curve merely continues, nor the tip of a spike (a corner or cusp
///   where the curve turns back by nearly π, whose two sides stay within tol near the tip), nor a
///   loop whose arc stays within 8 tol of its start (below the resolution). A curve that runs back
///   over itself exactly overlaps itself up to the fold.
[[nodiscard]] IntersectionResult self_intersect(const NurbsCurve& curve, const IntersectOptions& options = {});

/// Result of curve_distance().
struct CurveDistanceResult {
  double distance = 0.0;  ///< min |A(s) − B(t)|, model units (0 to rounding where the curves meet)
  double s = 0.0;         ///< parameter on a of the nearest pair
  double t = 0.0;         ///< parameter on b
  Vec3 point_a{};         ///< A(s)
  Vec3 point_b{};         ///< B(t)
  /// No pair of points of the curves is closer than this (model units): at least distance − tol, unless the
  /// curves run within a few tolerances of each other over a long stretch (concentric arcs at a tolerance of
  /// 1e-14 of their size), where the search stops after 300,000 piece pairs with the bound it proved.
  double lower_bound = 0.0;
};

/// The smallest distance between two curves, and where it is reached.
/// @returns a local minimum of |A(s) − B(t)| (or a domain-end foot) refined by Newton, so the distance
///   is exact to rounding at the pair reported; no pair of points of the curves is closer than
///   lower_bound ≥ distance − tol (best-first branch and bound over piece pairs with the bounds of
///   intersect())
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
[[nodiscard]] CurveDistanceResult curve_distance(const NurbsCurve& a, const NurbsCurve& b,
                                                 const IntersectOptions& options = {});

}  // namespace hula::nurbs
