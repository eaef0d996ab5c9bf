// SPDX-License-Identifier: MIT
// Projections of a space curve on the faces of its bounding box (thesis 8.1)
// and the reconstruction of the 3-D curve from one edited projection plus the
// unchanged third coordinate. A NURBS curve projects exactly by projecting its
// control points (affine invariance), so both operations are exact on the
// control net.
#pragma once
#include <string_view>

#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::diffgeom {

/// A coordinate plane.
enum class Plane {
  XY,  ///< drops z (z set to the bounding box's minimum z)
  YZ,  ///< drops x (x set to the minimum x)
  ZX,  ///< drops y (y set to the minimum y)
};

/// "xy", "yz" or "zx".
[[nodiscard]] std::string_view plane_name(Plane plane) noexcept;

/// The projection of the curve on the face of its control box normal to the dropped axis: the same
/// degree, knots and weights, each control point with the dropped coordinate set to the box minimum.
/// The result is a 3-D curve (on the face z = min z for XY, which is 0 only if the box touches it).
[[nodiscard]] nurbs::NurbsCurve project(const nurbs::NurbsCurve& curve, Plane plane);

/// Rebuilds a 3-D curve from an edited projection and the original: the two in-plane coordinates
/// of each control point come from `edited_projection`, the dropped coordinate from `original`.
/// @param original the unedited 3-D curve
/// @param edited_projection a curve with the same degree, knots, weights and number of control points
///   (only its in-plane coordinates are used)
/// @param plane the plane of the projection
/// @throws hula::Error(Errc::InvalidArgument) naming the property (degree, knots, weights,
///   control_points) in which the two curves differ
[[nodiscard]] nurbs::NurbsCurve reconstruct_from_projection(const nurbs::NurbsCurve& original,
                                                            const nurbs::NurbsCurve& edited_projection, Plane plane);

}  // namespace hula::diffgeom
