// SPDX-License-Identifier: MIT
// Planarity of a curve, judged on its control points: a NURBS curve with
// positive weights lies in a plane exactly when its control points do (convex
// hull property, Piegl & Tiller 4.2). The plane is found once per curve and is
// the plane about which the signed curvature and the inflections of a planar
// curve are measured (analysis.hpp).
#pragma once

#include <optional>

#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::diffgeom {

/// Result of planarity().
struct Planarity {
  /// True when every control point lies within `tolerance` of one plane (also for collinear or
  /// coincident control points, which every plane through them contains).
  bool planar = false;
  /// Unit normal of the plane, its largest-magnitude component positive (the XY plane gives +Z; a 2-D
  /// curve +Z); absent when the curve is not planar or its control points are collinear or coincide
  /// (no unique plane).
  std::optional<Vec3> normal{};
  /// Largest distance of a control point from the plane, model units (0 without a unique plane).
  double max_deviation = 0.0;
  /// The tolerance used: resolution_for_size(Tolerance{}, model size), model units.
  double tolerance = 0.0;
};

/// The plane of a curve: through P0, the control point farthest from it, and the control point
/// farthest from that line (robust for any point order, exact for collinear sets).
/// @returns see Planarity; never throws for a valid curve
[[nodiscard]] Planarity planarity(const nurbs::NurbsCurve& curve);

}  // namespace hula::diffgeom
