// SPDX-License-Identifier: MIT
// Knot and join continuity from one-sided derivatives (thesis 7.1.2, Table 3);
// the tests are stated in continuity.hpp.
#include "hula/diffgeom/continuity.hpp"

#include <algorithm>
#include <cmath>

#include "hula/core/error.hpp"

namespace hula::diffgeom {

void ContinuityOptions::validate() const {
  tolerance.validate();
  if (!(relative_tolerance > 0.0 && relative_tolerance < 1.0))
    throw Error(Errc::InvalidOption, "relative_tolerance = " + format_number(relative_tolerance) + " must be in (0, 1)",
                {.field = "relative_tolerance"});
}

Continuity compare_sides(double t, const std::array<Vec3, 4>& left, const std::array<Vec3, 4>& right, double size,
                         double step, const ContinuityOptions& options) {
  Continuity c;
  c.t = t;
  c.left = left;
  c.right = right;
  const double eps = options.relative_tolerance;
  const double model = size > 0.0 ? size : 1.0;
  // Parametric: every derivative up to k agrees relative to its own magnitude or the model's.
  for (int k = 0; k <= 3; ++k) {
    const auto uk = static_cast<std::size_t>(k);
    const double scale = std::max({norm(left[uk]), norm(right[uk]), model / std::pow(step, k)});
    if (!(distance(left[uk], right[uk]) <= eps * scale)) break;
    c.parametric = k;
  }
  // Geometric: the Frenet quantities from each side.
  const FrenetScale fs = frenet_scale(model, step, options.tolerance);
  FrenetOptions fo;
  fo.tolerance = options.tolerance;
  const FrenetPoint l = frenet_from_derivatives(t, left, fs, fo);
  const FrenetPoint r = frenet_from_derivatives(t, right, fs, fo);
  c.curvature_left = l.curvature;
  c.curvature_right = r.curvature;
  c.tangent_angle = l.tangent_defined && r.tangent_defined
                        ? std::atan2(norm(cross(l.tangent, r.tangent)), dot(l.tangent, r.tangent))
                        : std::nan("");
  if (c.parametric < 0) return c;
  c.geometric = 0;
  if (!(l.tangent_defined && r.tangent_defined && distance(l.tangent, r.tangent) <= eps)) return c;
  c.geometric = 1;
  const Vec3 kl = l.frame_defined ? l.normal * l.curvature : Vec3{};
  const Vec3 kr = r.frame_defined ? r.normal * r.curvature : Vec3{};
  if (distance(kl, kr) <= eps * std::max({l.curvature, r.curvature, 1.0 / model})) {
    c.geometric = 2;
    // G3: torsion and dκ/ds agree (both undefined counts as agreeing: a straight or planar join).
    auto same = [&](double a, double b, double unit) {
      if (std::isnan(a) || std::isnan(b)) return std::isnan(a) == std::isnan(b);
      return std::fabs(a - b) <= eps * std::max({std::fabs(a), std::fabs(b), unit});
    };
    if (same(l.torsion, r.torsion, 1.0 / model) &&
        same(l.curvature_derivative, r.curvature_derivative, 1.0 / (model * model)))
      c.geometric = 3;
  }
  // Parametric continuity with non-zero speed (checked above) implies the same geometric order.
  c.geometric = std::max(c.geometric, std::min(c.parametric, 3));
  return c;
}

std::vector<Continuity> knot_continuity(const nurbs::NurbsCurve& curve, const ContinuityOptions& options) {
  options.validate();
  const std::vector<double> bp = curve.knots().breakpoints();
  std::vector<Continuity> out;
  nurbs::EvalOptions lo, ro;
  lo.side = nurbs::Side::Left;
  ro.side = nurbs::Side::Right;
  for (std::size_t i = 1; i + 1 < bp.size(); ++i) {
    std::array<Vec3, 4> l, r;
    curve.derivatives(bp[i], 3, l, lo);
    curve.derivatives(bp[i], 3, r, ro);
    Continuity c = compare_sides(bp[i], l, r, curve.model_size(), curve.domain().length(), options);
    c.multiplicity = curve.knots().multiplicity(bp[i]);
    out.push_back(c);
  }
  return out;
}

Continuity join_continuity(const nurbs::NurbsCurve& first, const nurbs::NurbsCurve& second,
                           const ContinuityOptions& options) {
  options.validate();
  std::array<Vec3, 4> l, r;
  nurbs::EvalOptions lo;
  lo.side = nurbs::Side::Left;
  first.derivatives(first.domain().end, 3, l, lo);
  second.derivatives(second.domain().start, 3, r);
  const double size = std::max(first.model_size(), second.model_size());
  const double step = std::max(first.domain().length(), second.domain().length());
  Continuity c = compare_sides(first.domain().end, l, r, size, step, options);
  c.multiplicity = 0;
  return c;
}

}  // namespace hula::diffgeom
