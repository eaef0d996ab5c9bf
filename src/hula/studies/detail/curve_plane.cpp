// SPDX-License-Identifier: MIT
// Plane of a planar curve: the least-variance direction of its control points
// (the smallest eigenvector of their covariance), accepted when every control
// point lies within kPlanarity × model size of the plane (a curve lies in the
// convex hull of its control points, so then the whole curve does).
#include "hula/studies/detail/curve_plane.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace hula::studies::detail {
namespace {

// Planar: every control point within this fraction of the model size from the plane.
constexpr double kPlanarity = 1e-9;

}  // namespace

std::optional<Vec3> plane_normal(const nurbs::NurbsCurve& curve) {
  if (curve.dimension() == 2) return Vec3{0.0, 0.0, 1.0};
  const std::span<const Vec3> p = curve.control_points();
  Vec3 centre{};
  for (const Vec3& q : p) centre += q;
  centre = centre / static_cast<double>(p.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const Vec3& q : p) {
    const Eigen::Vector3d d(q.x - centre.x, q.y - centre.y, q.z - centre.z);
    cov += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);
  const Eigen::Vector3d e = eig.eigenvectors().col(0);  // the smallest eigenvalue comes first
  Vec3 n = normalized(Vec3{e(0), e(1), e(2)});
  const double size = std::max(curve.model_size(), 1e-300);
  for (const Vec3& q : p)
    if (std::abs(dot(q - centre, n)) > kPlanarity * size) return std::nullopt;
  const double ax = std::abs(n.x), ay = std::abs(n.y), az = std::abs(n.z);
  const double largest = (ax >= ay && ax >= az) ? n.x : (ay >= az ? n.y : n.z);
  if (largest < 0.0) n = n * -1.0;
  return n;
}

}  // namespace hula::studies::detail
