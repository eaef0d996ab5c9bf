// SPDX-License-Identifier: MIT
// Header-only test and benchmark support (direct-reconstruction tests and
// bench): the curvature
// profile of a known planar NURBS curve tabulated against u = s / L (κ from the
// curve's derivatives, s by nurbs::arc_length), made a natural cubic spline
// B-spline profile, with the curve's own start frame and end; and the distance
// between a reconstruction and the curve at equal arc length.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "hula/intrinsic/natural_equations.hpp"
#include "hula/nurbs/arc_length.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/studies/profile.hpp"

namespace hula::testing {

using studies::Profile;

/// A target profile taken from a known planar curve, with the curve's start frame and end.
struct CurvatureTarget {
  Profile profile;
  double length = 0.0;
  intrinsic::StartFrame start{};
  Vec3 end_point{};
  Vec3 end_tangent{};
};

/// Signed curvature of a planar (z = 0) curve at t: (C' × C'')_z / |C'|³, positive counter-clockwise.
inline double signed_curvature(const nurbs::NurbsCurve& c, double t) {
  const std::vector<Vec3> d = c.derivatives(t, 2);
  return cross(d[1], d[2]).z / std::pow(norm(d[1]), 3);
}

/// κ(u L) at `samples` uniform u, interpolated by a natural cubic spline in u (a smooth profile:
/// a piecewise-linear one has kinks the RKF78 step control does not see, see the docs).
inline CurvatureTarget planar_curvature_target(const nurbs::NurbsCurve& curve, std::size_t samples) {
  const double length = nurbs::arc_length(curve);
  std::vector<double> u(samples);
  std::vector<Vec3> points(samples);
  for (std::size_t i = 0; i < samples; ++i) {
    u[i] = static_cast<double>(i) / static_cast<double>(samples - 1);
    points[i] = {u[i], signed_curvature(curve, nurbs::parameter_at_length(curve, u[i] * length)), 0.0};
  }
  nurbs::InterpolationOptions io;
  io.parameters = u;  // x(t) = t exactly (a natural spline reproduces linear data)
  const nurbs::NurbsCurve spline = nurbs::interpolate_cubic(points, io);
  std::vector<double> coefficients;
  for (const Vec3& p : spline.control_points()) coefficients.push_back(p.y);
  const std::span<const double> knots = spline.knots().values();
  const double t0 = curve.knots().values().front(), t1 = curve.knots().values().back();
  const Vec3 tangent = normalized(curve.derivatives(t0, 1)[1]);
  return {Profile::from_bspline(3, std::vector<double>(knots.begin(), knots.end()), coefficients), length,
          intrinsic::StartFrame{curve.evaluate(t0), tangent, Vec3{-tangent.y, tangent.x, 0.0}}, curve.evaluate(t1),
          normalized(curve.derivatives(t1, 1)[1])};
}

/// max_i |r(s_i) − C(t(s_i))| over samples + 1 uniform arc lengths.
inline double max_distance_at_equal_length(const intrinsic::IntrinsicCurve& r, const nurbs::NurbsCurve& c,
                                           int samples) {
  double worst = 0.0;
  const double length = r.length();
  for (int i = 0; i <= samples; ++i) {
    const double s = length * static_cast<double>(i) / samples;
    worst = std::max(worst, distance(r.evaluate(s).position, c.evaluate(nurbs::parameter_at_length(c, s))));
  }
  return worst;
}

}  // namespace hula::testing
