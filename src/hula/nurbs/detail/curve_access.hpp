// SPDX-License-Identifier: MIT
// Construction of knot vectors and curves from data that is valid by construction
// (validation once): interpolate_cubic checks its points once and builds strictly increasing
// parameters and finite control points below kMaxCoordinate itself, so the validating constructors'
// second and third passes over the same numbers are skipped. In builds with asserts
// (HULA_ENABLE_ASSERTS, the ci preset) the full validation still runs and a violation is an
// InternalError: a bug here, never bad input.
#pragma once

#include <vector>

#include "hula/core/vec.hpp"
#include "hula/nurbs/knot_vector.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::nurbs::detail {

struct CurveAccess {
  /// A knot vector the caller guarantees valid (KnotVector's invariants).
  [[nodiscard]] static KnotVector knots(std::vector<double> values, int degree);
  /// A non-rational curve the caller guarantees valid (NurbsCurve's invariants, z = 0 when dimension = 2),
  /// with the box of its control points.
  [[nodiscard]] static NurbsCurve curve(KnotVector knots, std::vector<Vec3> control_points, int dimension,
                                        const Box3& control_box);
};

}  // namespace hula::nurbs::detail
