// SPDX-License-Identifier: MIT
// Hermite editing (thesis 7.5.2); see hermite_edit.hpp.
#include "hula/studies/hermite_edit.hpp"

#include <cmath>
#include <string>

#include "hula/core/error.hpp"
#include "hula/diffgeom/frenet.hpp"

namespace hula::studies {

namespace {

std::string edit_field(std::size_t i, const char* member) { return "edits[" + std::to_string(i) + "]." + member; }

[[noreturn]] void bad_edit(std::size_t i, const char* member, const std::string& what) {
  throw Error(Errc::InvalidArgument, edit_field(i, member) + " " + what, {.field = edit_field(i, member), .index = i});
}

}  // namespace

void HermiteEditOptions::validate() const {
  interpolation.validate();
  if (rebuild != HermiteRebuild::Quintic && rebuild != HermiteRebuild::Cubic)
    throw Error(Errc::InvalidOption, "rebuild is not quintic or cubic", {.field = "rebuild"});
}

Vec3 rotate_about(const Vec3& v, const Vec3& axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return c * v + s * cross(axis, v) + (1.0 - c) * dot(axis, v) * axis;
}

HermiteHandles hermite_handles(const nurbs::NurbsCurve& curve, std::span<const double> parameters) {
  HermiteHandles h;
  h.parameters.assign(parameters.begin(), parameters.end());
  diffgeom::FrenetOptions fo;
  for (const double t : parameters) {
    const std::vector<Vec3> d = curve.derivatives(t, 2);
    h.points.push_back(d[0]);
    h.first.push_back(d[1]);
    h.second.push_back(d[2]);
    const diffgeom::FrenetPoint f = diffgeom::frenet(curve, t, fo);
    h.normal_handle.push_back(f.frame_defined ? norm(d[2]) * f.normal : Vec3{});
  }
  return h;
}

HermiteEditResult hermite_edit(std::span<const Vec3> points, std::span<const HandleEdit> edits,
                               const HermiteEditOptions& options) {
  options.validate();
  // The parameters are fixed once and shared by the spline and the rebuild.
  std::vector<double> ts =
      options.interpolation.parameters.empty()
          ? nurbs::parameterise(points, options.interpolation.parameterisation, options.interpolation.tolerance)
          : options.interpolation.parameters;
  nurbs::InterpolationOptions io = options.interpolation;
  io.parameters = ts;
  nurbs::NurbsCurve spline = nurbs::interpolate_cubic(points, io);
  // interpolate_cubic maps given parameters affinely to [0, 1]; use the mapped values.
  const double t0 = ts.front(), t1 = ts.back();
  for (double& t : ts) t = (t - t0) / (t1 - t0);
  ts.front() = 0.0;
  ts.back() = 1.0;
  HermiteHandles before = hermite_handles(spline, ts);
  std::vector<Vec3> d1 = before.first, d2 = before.second;
  const bool planar = options.interpolation.dimension == 2;
  std::vector<bool> seen(points.size(), false);
  for (std::size_t i = 0; i < edits.size(); ++i) {
    const HandleEdit& e = edits[i];
    if (e.knot >= points.size())
      bad_edit(
          i, "knot",
          "= " + std::to_string(e.knot) + " is not a data point index (0 … " + std::to_string(points.size() - 1) + ")");
    if (seen[e.knot]) bad_edit(i, "knot", "= " + std::to_string(e.knot) + " is edited twice");
    seen[e.knot] = true;
    if (!std::isfinite(e.tangent_angle)) bad_edit(i, "tangent_angle", "must be finite");
    if (!std::isfinite(e.normal_angle)) bad_edit(i, "normal_angle", "must be finite");
    if (!(e.tangent_scale > 0.0 && std::isfinite(e.tangent_scale)))
      bad_edit(i, "tangent_scale", "= " + format_number(e.tangent_scale) + " must be finite and > 0");
    if (!(e.normal_scale > 0.0 && std::isfinite(e.normal_scale)))
      bad_edit(i, "normal_scale", "= " + format_number(e.normal_scale) + " must be finite and > 0");
    if (options.rebuild == HermiteRebuild::Cubic && (e.normal_angle != 0.0 || e.normal_scale != 1.0))
      bad_edit(i, "normal_angle",
               "edits the normal handle, which the cubic rebuild cannot honour (use \"rebuild\": \"quintic\")");
    Vec3 axis{0.0, 0.0, 1.0};
    if (e.axis) {
      const double n = norm(*e.axis);
      if (!(n > 0.0 && std::isfinite(n))) bad_edit(i, "axis", "must be finite and non-zero");
      axis = *e.axis / n;
      if (planar && (std::abs(axis.x) > 0.0 || std::abs(axis.y) > 0.0) &&
          (e.tangent_angle != 0.0 || e.normal_angle != 0.0))
        bad_edit(i, "axis", "must be +-Z for a planar curve (a rotation about another axis leaves the plane)");
    } else if (!planar && (e.tangent_angle != 0.0 || e.normal_angle != 0.0)) {
      const diffgeom::FrenetPoint f = diffgeom::frenet(spline, ts[e.knot]);
      if (!f.frame_defined)
        bad_edit(i, "axis",
                 "is needed: the binormal at knot " + std::to_string(e.knot) + " is undefined (" +
                     std::string(diffgeom::undefined_name(f.reason)) + ")");
      axis = f.binormal;
    }
    d1[e.knot] = e.tangent_scale * rotate_about(d1[e.knot], axis, e.tangent_angle);
    d2[e.knot] = e.normal_scale * rotate_about(d2[e.knot], axis, e.normal_angle);
  }
  const int dim = options.interpolation.dimension;
  nurbs::NurbsCurve curve = options.rebuild == HermiteRebuild::Quintic ? nurbs::hermite_quintic(points, d1, d2, ts, dim)
                                                                       : nurbs::hermite_cubic(points, d1, ts, dim);
  HermiteHandles after = hermite_handles(curve, ts);
  return {std::move(spline), std::move(before), std::move(after), std::move(curve)};
}

}  // namespace hula::studies
