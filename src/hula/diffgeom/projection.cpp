// SPDX-License-Identifier: MIT
// Bounding-box projections and reconstruction (thesis 8.1); see projection.hpp.
#include "hula/diffgeom/projection.hpp"

#include <algorithm>
#include <vector>

#include "hula/core/error.hpp"

namespace hula::diffgeom {

namespace {
// Index of the dropped coordinate.
std::size_t dropped(Plane plane) { return plane == Plane::XY ? 2 : (plane == Plane::YZ ? 0 : 1); }
}  // namespace

std::string_view plane_name(Plane plane) noexcept {
  switch (plane) {
    case Plane::XY:
      return "xy";
    case Plane::YZ:
      return "yz";
    case Plane::ZX:
      return "zx";
  }
  return "unknown";
}

nurbs::NurbsCurve project(const nurbs::NurbsCurve& curve, Plane plane) {
  const std::size_t k = dropped(plane);
  const double face = curve.control_box().min[k];
  std::vector<Vec3> P(curve.control_points().begin(), curve.control_points().end());
  for (Vec3& p : P) p[k] = face;
  return nurbs::NurbsCurve(curve.knots(), std::move(P),
                           std::vector<double>(curve.weights().begin(), curve.weights().end()), 3);
}

nurbs::NurbsCurve reconstruct_from_projection(const nurbs::NurbsCurve& original,
                                              const nurbs::NurbsCurve& edited_projection, Plane plane) {
  auto mismatch = [](const char* what) {
    throw Error(Errc::InvalidArgument,
                std::string("the edited projection must keep the original's ") + what +
                    " (only control point coordinates in the plane may change)",
                {.field = what});
  };
  if (edited_projection.degree() != original.degree()) mismatch("degree");
  if (!(edited_projection.knots() == original.knots())) mismatch("knots");
  const auto w0 = original.weights(), w1 = edited_projection.weights();
  if (!std::equal(w0.begin(), w0.end(), w1.begin(), w1.end())) mismatch("weights");
  if (edited_projection.control_points().size() != original.control_points().size()) mismatch("control_points");
  const std::size_t k = dropped(plane);
  std::vector<Vec3> P(edited_projection.control_points().begin(), edited_projection.control_points().end());
  for (std::size_t i = 0; i < P.size(); ++i) P[i][k] = original.control_points()[i][k];
  return nurbs::NurbsCurve(original.knots(), std::move(P), std::vector<double>(w0.begin(), w0.end()), 3);
}

}  // namespace hula::diffgeom
