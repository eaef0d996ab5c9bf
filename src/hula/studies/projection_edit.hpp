// SPDX-License-Identifier: MIT
// Projection editing (thesis 8.1): one projection of a space curve (on the XY,
// YZ or ZX plane) is replaced by an edited planar curve and the 3-D curve is
// rebuilt from the edited curve's two in-plane coordinates and the original's
// unchanged third coordinate.
//
// Parameter matching: the two curves are matched by NORMALISED parameter, i.e.
// the point of the result at u ∈ [0, 1] takes its in-plane coordinates from
// edited(e0 + u (e1 − e0)) and its dropped coordinate from
// original(a + u (b − a)), where [e0, e1] and [a, b] are the two domains. The
// construction is exact (no fitting): both curves are reparameterised to
// [0, 1], raised to a common degree and refined to a common knot vector (knot
// insertion and degree elevation do not change a curve), after which the
// control points combine coordinate by coordinate
// (diffgeom::reconstruct_from_projection). Rational curves are combined exactly
// only when their weights agree after that refinement; otherwise they are refused.
#pragma once
#include "hula/core/tolerance.hpp"
#include "hula/diffgeom/projection.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::studies {

/// Index of the coordinate a plane drops: XY → 2 (z), YZ → 0 (x), ZX → 1 (y).
[[nodiscard]] std::size_t dropped_coordinate(diffgeom::Plane plane) noexcept;

/// The unit normal of a plane, oriented so that the plane's two coordinates in order form a
/// right-handed pair with it: XY → +Z, YZ → +X, ZX → +Y (signed curvature and signed normals of
/// projections are taken about it).
[[nodiscard]] Vec3 plane_normal(diffgeom::Plane plane) noexcept;

/// Parses "xy", "yz" or "zx".
/// @throws hula::Error(Errc::InvalidArgument) naming `field` and the value otherwise
[[nodiscard]] diffgeom::Plane plane_from_name(std::string_view name, std::string_view field = "plane");

/// Checks that a curve lies in a plane parallel to `plane`: every control point's dropped coordinate
/// equals the first's within resolution_for_size(tolerance, model size).
/// @param field the name of the curve in the message ("edited")
/// @throws hula::Error(Errc::InvalidArgument) naming `field`, the control point index and both values
void require_planar(const nurbs::NurbsCurve& curve, diffgeom::Plane plane, std::string_view field,
                    const Tolerance& tolerance = {});

/// Brings two curves to one structure (domain [0, 1], common degree, common knot vector) without
/// changing either curve.
struct CommonStructure {
  nurbs::NurbsCurve first;   ///< the first curve on [0, 1]
  nurbs::NurbsCurve second;  ///< the second curve on [0, 1], same degree and knots as `first`
};

/// Reparameterises both curves to [0, 1] (affinely), elevates the lower degree and inserts into
/// each the knots (with multiplicity) that the other has and it lacks. A knot of the second curve
/// within 1e-12 of one of the first's is taken as that knot (the two affine maps round a shared
/// breakpoint differently; a 1e-17 span would be meaningless), which moves the second curve by
/// O(1e-12 |C'|).
/// @throws hula::Error as nurbs::reparameterise / elevate_degree / refine_knots
[[nodiscard]] CommonStructure common_structure(const nurbs::NurbsCurve& first, const nurbs::NurbsCurve& second);

/// Result of edit_projection().
struct ProjectionEditResult {
  /// The rebuilt 3-D curve on [0, 1] (on the original's domain when the edited curve already shares
  /// the original's degree, knots and weights).
  nurbs::NurbsCurve curve;
  /// max over dense samples of |result(u) − (edited in-plane, original dropped)(u)|: the measured
  /// error of the construction (rounding only).
  double max_deviation = 0.0;
};

/// Replaces the projection of `original` on `plane` by `edited` and rebuilds the 3-D curve.
/// @param original the 3-D curve
/// @param edited the edited projection: a curve in a plane parallel to `plane` (its dropped coordinate
///   constant; the value is ignored); any degree, knots and domain
/// @param plane the projection plane
/// @param tolerance planarity test of require_planar
/// @returns the curve and its measured deviation
/// @throws hula::Error(Errc::InvalidArgument) naming "edited" if it is not planar in `plane`, or
///   "weights" if the curves are rational with weights that cannot be matched exactly
[[nodiscard]] ProjectionEditResult edit_projection(const nurbs::NurbsCurve& original, const nurbs::NurbsCurve& edited,
                                                   diffgeom::Plane plane, const Tolerance& tolerance = {});

}  // namespace hula::studies
