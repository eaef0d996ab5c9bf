// SPDX-License-Identifier: MIT
// Homogeneous control points Pw_i = (w_i P_i, w_i) (The NURBS Book eq. 4.2),
// the working form of every knot and degree operation: they are linear in Pw,
// so rational curves are transformed exactly like non-rational ones in 4-D.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::nurbs::detail {

/// One homogeneous point (x w, y w, z w, w).
using Hpoint = std::array<double, 4>;

/// Pw of a curve; w = 1 for non-rational curves.
[[nodiscard]] std::vector<Hpoint> to_homogeneous(const NurbsCurve& curve);

/// The curve with knots U and homogeneous points Pw; weights are kept only
/// when `rational`. Throws hula::Error(Errc::NumericalFailure) if a weight came
/// out ≤ 0 or non-finite (a computation broke down), naming `operation`.
[[nodiscard]] NurbsCurve from_homogeneous(KnotVector knots, const std::vector<Hpoint>& Pw, bool rational, int dimension,
                                          const char* operation);

/// a * x + b * y, component-wise.
[[nodiscard]] inline Hpoint combine(double a, const Hpoint& x, double b, const Hpoint& y) {
  return {a * x[0] + b * y[0], a * x[1] + b * y[1], a * x[2] + b * y[2], a * x[3] + b * y[3]};
}

/// "name = value" for error messages.
[[nodiscard]] std::string named(const char* name, double value);

}  // namespace hula::nurbs::detail
