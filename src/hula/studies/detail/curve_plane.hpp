// SPDX-License-Identifier: MIT
// The plane of a planar curve, for the studies that sign curvature about it
// (design by curvature, setups seeded from a curve).
#pragma once

#include <optional>

#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::studies::detail {

/// The unit normal of the plane holding every control point of `curve` (within 1e-9 of its model size), or
/// nothing for a space curve. 2-D curves and curves in a plane parallel to X-Y give +Z; otherwise the normal's
/// largest component is positive. Signed curvature about it is positive counter-clockwise seen from it.
[[nodiscard]] std::optional<Vec3> plane_normal(const nurbs::NurbsCurve& curve);

}  // namespace hula::studies::detail
