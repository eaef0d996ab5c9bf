// SPDX-License-Identifier: MIT
// The plane of a curve's control points (planarity.hpp).
#include "hula/diffgeom/planarity.hpp"

#include <cmath>
#include <span>

#include "hula/core/tolerance.hpp"

namespace hula::diffgeom {

Planarity planarity(const nurbs::NurbsCurve& curve) {
  const std::span<const Vec3> P = curve.control_points();
  Planarity out;
  out.tolerance = resolution_for_size(Tolerance{}, curve.model_size());
  if (curve.dimension() == 2) {
    out.planar = true;
    out.normal = Vec3{0, 0, 1};
    return out;
  }
  const Vec3 p0 = P[0];
  std::size_t i1 = 0;
  for (std::size_t i = 1; i < P.size(); ++i)
    if (distance(P[i], p0) > distance(P[i1], p0)) i1 = i;
  const Vec3 axis = P[i1] - p0;
  const double axis_length = norm(axis);
  if (!(axis_length > out.tolerance)) {
    out.planar = true;  // all control points coincide: no unique plane
    return out;
  }
  std::size_t i2 = 0;
  double best = -1.0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const double d = norm(cross(axis, P[i] - p0)) / axis_length;  // distance from the line
    if (d > best) {
      best = d;
      i2 = i;
    }
  }
  if (!(best > out.tolerance)) {
    out.planar = true;  // collinear: every plane through the line contains the curve
    out.max_deviation = best;
    return out;
  }
  Vec3 n = normalized(cross(axis, P[i2] - p0));
  double deviation = 0.0;
  for (const Vec3& p : P) deviation = std::fmax(deviation, std::fabs(dot(n, p - p0)));
  // Sign convention: the largest-magnitude component is positive, so the XY plane gives +Z.
  std::size_t k = 0;
  for (std::size_t c = 1; c < 3; ++c)
    if (std::fabs(n[c]) > std::fabs(n[k])) k = c;
  if (n[k] < 0) n = -n;
  n += Vec3{0.0, 0.0, 0.0};  // turns -0.0 components into +0.0 for clean output
  out.max_deviation = deviation;
  out.planar = deviation <= out.tolerance;
  if (out.planar) out.normal = n;
  return out;
}

}  // namespace hula::diffgeom
