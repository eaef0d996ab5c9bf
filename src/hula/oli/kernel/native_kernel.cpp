// SPDX-License-Identifier: MIT
// The native backend forwards to the nurbs and diffgeom modules; the only
// logic here is the argument checks the interface adds (derivative order ≤ 3,
// times ≥ 1, tangents both or neither), shared with the OCCT backend through
// detail/checks.hpp so both refuse the same inputs with the same codes.
#include "hula/oli/kernel/native_kernel.hpp"

#include <array>

#include "hula/diffgeom/frenet.hpp"
#include "hula/nurbs/arc_length.hpp"
#include "hula/nurbs/elevate.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/nurbs/refine.hpp"
#include "hula/oli/kernel/detail/checks.hpp"

namespace hula::oli {

nurbs::NurbsCurve NativeKernel::construct(int degree, std::vector<double> knots, std::vector<Vec3> control_points,
                                          std::vector<double> weights, int dimension) const {
  return {degree, std::move(knots), std::move(control_points), std::move(weights), dimension};
}

Vec3 NativeKernel::evaluate(const nurbs::NurbsCurve& curve, double t) const { return curve.evaluate(t); }

std::vector<Vec3> NativeKernel::derivatives(const nurbs::NurbsCurve& curve, double t, int order) const {
  detail::check_derivative_order(order);
  return curve.derivatives(t, order);
}

nurbs::NurbsCurve NativeKernel::insert_knot(const nurbs::NurbsCurve& curve, double u, int times) const {
  detail::check_times(times);
  return nurbs::insert_knot(curve, u, times);
}

nurbs::NurbsCurve NativeKernel::elevate_degree(const nurbs::NurbsCurve& curve, int times) const {
  detail::check_times(times);
  return nurbs::elevate_degree(curve, times);
}

nurbs::SplitResult NativeKernel::split(const nurbs::NurbsCurve& curve, double t) const {
  return nurbs::split(curve, t);
}

nurbs::NurbsCurve NativeKernel::reverse(const nurbs::NurbsCurve& curve) const { return nurbs::reverse(curve); }

nurbs::NurbsCurve NativeKernel::interpolate(std::span<const Vec3> points, const KernelInterpolation& options) const {
  detail::check_interpolation(points, options);
  nurbs::InterpolationOptions o;
  o.parameters = options.parameters;
  if (options.start_tangent) {
    o.start = nurbs::EndCondition::clamped(*options.start_tangent);
    o.end = nurbs::EndCondition::clamped(*options.end_tangent);
  } else {
    o.start = o.end = nurbs::EndCondition::occt();
  }
  return nurbs::interpolate_cubic(points, o);
}

double NativeKernel::curvature(const nurbs::NurbsCurve& curve, double t) const {
  return diffgeom::frenet(curve, t).curvature;
}

double NativeKernel::torsion(const nurbs::NurbsCurve& curve, double t) const {
  return diffgeom::frenet(curve, t).torsion;
}

double NativeKernel::arc_length(const nurbs::NurbsCurve& curve, double a, double b) const {
  return nurbs::arc_length(curve, a, b, {.tolerance = 1e-13});
}

}  // namespace hula::oli
