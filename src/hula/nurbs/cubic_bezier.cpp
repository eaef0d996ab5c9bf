// SPDX-License-Identifier: MIT
#include "hula/nurbs/cubic_bezier.hpp"

#include <cmath>
#include <string>

#include "hula/core/error.hpp"
#include "hula/nurbs/refine.hpp"

namespace hula::nurbs {
namespace {

// Degree elevation of one Bézier segment to 3 (The NURBS Book eq. 5.36): exact up to rounding.
std::array<Vec3, 4> as_cubic(std::span<const Vec3> p) {
  switch (p.size()) {
    case 2:
      return {p[0], p[0] + (p[1] - p[0]) / 3.0, p[1] + (p[0] - p[1]) / 3.0, p[1]};
    case 3:
      return {p[0], p[0] + (p[1] - p[0]) * (2.0 / 3.0), p[2] + (p[1] - p[2]) * (2.0 / 3.0), p[2]};
    default:
      return {p[0], p[1], p[2], p[3]};
  }
}

Vec3 bezier_point(const std::array<Vec3, 4>& p, double x) {
  const double y = 1.0 - x;
  return p[0] * (y * y * y) + p[1] * (3.0 * y * y * x) + p[2] * (3.0 * y * x * x) + p[3] * (x * x * x);
}

// Halves [a, b] of one Bézier segment until the cubic Hermite piece on it is within the tolerance.
void approximate(const NurbsCurve& segment, double a, double b, double tolerance, int depth, CubicPath& path) {
  const EvalOptions right{.side = Side::Right}, left{.side = Side::Left};
  const auto start = segment.derivatives(a, 1, right);
  const auto end = segment.derivatives(b, 1, left);
  const double h = b - a;
  const std::array<Vec3, 4> piece{start[0], start[0] + start[1] * (h / 3.0), end[0] - end[1] * (h / 3.0), end[0]};
  double deviation = 0.0;
  for (int i = 1; i <= kCubicSamples; ++i) {
    const double x = static_cast<double>(i) / (kCubicSamples + 1);
    deviation = std::max(deviation, distance(bezier_point(piece, x), segment.evaluate(a + x * h)));
  }
  if (deviation <= tolerance) {
    path.pieces.push_back({piece, a, b});
    path.max_deviation = std::max(path.max_deviation, deviation);
    return;
  }
  if (depth == 30)
    throw Error(Errc::NumericalFailure,
                "cannot approximate the curve on [" + format_number(a) + ", " + format_number(b) +
                    "] by cubic pieces within tolerance = " + format_number(tolerance) + " (deviation " +
                    format_number(deviation) + " after 30 halvings)",
                {.field = "tolerance"});
  const double mid = a + 0.5 * h;
  approximate(segment, a, mid, tolerance, depth + 1, path);
  approximate(segment, mid, b, tolerance, depth + 1, path);
}

}  // namespace

CubicPath cubic_beziers(const NurbsCurve& curve, double tolerance) {
  if (!std::isfinite(tolerance) || !(tolerance > 0.0))
    throw Error(Errc::InvalidArgument, "tolerance = " + format_number(tolerance) + " must be finite and > 0",
                {.field = "tolerance"});
  CubicPath path;
  path.exact = !curve.is_rational() && curve.degree() <= 3;
  for (const NurbsCurve& segment : decompose_to_bezier(curve)) {
    const Interval d = segment.domain();
    if (path.exact)
      path.pieces.push_back({as_cubic(segment.control_points()), d.start, d.end});
    else
      approximate(segment, d.start, d.end, tolerance, 0, path);
  }
  return path;
}

}  // namespace hula::nurbs
