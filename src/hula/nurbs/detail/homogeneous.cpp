// SPDX-License-Identifier: MIT
// Conversions between NurbsCurve and homogeneous control points.
#include "hula/nurbs/detail/homogeneous.hpp"

#include <cmath>

#include "hula/core/error.hpp"

namespace hula::nurbs::detail {

std::vector<Hpoint> to_homogeneous(const NurbsCurve& curve) {
  const std::span<const Vec3> P = curve.control_points();
  const std::span<const double> W = curve.weights();
  std::vector<Hpoint> Pw(P.size());
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double w = W.empty() ? 1.0 : W[i];
    Pw[i] = {w * P[i].x, w * P[i].y, w * P[i].z, w};
  }
  return Pw;
}

NurbsCurve from_homogeneous(KnotVector knots, const std::vector<Hpoint>& Pw, bool rational, int dimension,
                            const char* operation) {
  std::vector<Vec3> P(Pw.size());
  std::vector<double> W;
  if (rational) W.resize(Pw.size());
  for (std::size_t i = 0; i < Pw.size(); ++i) {
    const double w = Pw[i][3];
    if (!(std::isfinite(w) && w > 0.0))
      throw Error(Errc::NumericalFailure,
                  std::string(operation) + " produced weight[" + std::to_string(i) + "] = " + format_number(w) +
                      " (numerical breakdown)",
                  {.field = "weights", .index = i});
    // Non-rational curves keep w = 1 exactly, so no division is needed.
    P[i] = rational ? Vec3{Pw[i][0] / w, Pw[i][1] / w, Pw[i][2] / w} : Vec3{Pw[i][0], Pw[i][1], Pw[i][2]};
    if (dimension == 2) P[i].z = 0.0;
    if (rational) W[i] = w;
  }
  return NurbsCurve(std::move(knots), std::move(P), std::move(W), dimension);
}

std::string named(const char* name, double value) { return std::string(name) + " = " + format_number(value); }

}  // namespace hula::nurbs::detail
