// SPDX-License-Identifier: MIT
// Tight bounding box: span-wise extrema of each coordinate.
//
// Notation: x(t) one coordinate of C(t); x'(t), x''(t) its derivatives, taken
// from NurbsCurve::derivatives (quotient rule for rational curves, so the
// roots of x' are exactly the critical points of the rational coordinate).
#include "hula/nurbs/bounding_box.hpp"

#include <algorithm>
#include <array>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace hula::nurbs {

namespace {

// Root of x'_c in (lo, hi), where the samples g_lo = x'_c(lo) and g_hi = x'_c(hi) have opposite signs,
// by Boost.Math's TOMS 748 (Alefeld–Potra–Shi): a true bracket, kept by the sign of x' alone, so a
// piece on which x' is not monotone still converges. Stops when the bracket is at rounding of t on the
// bracket's scale (the extremal value's error is then O(x'' δt²), far below model resolution).
double polish_root(const NurbsCurve& curve, std::size_t c, double lo, double hi, double g_lo, double g_hi) {
  const double width = hi - lo;
  std::array<Vec3, 2> d;
  auto slope = [&](double t) {
    curve.derivatives(t, 1, d);
    return d[1][c];
  };
  auto rounding = [width](double a, double b) {
    return b - a <=
           4.0 * std::numeric_limits<double>::epsilon() * std::fmax(std::fmax(std::fabs(a), std::fabs(b)), width);
  };
  std::uintmax_t iterations = 200;
  const auto [a, b] = boost::math::tools::toms748_solve(slope, lo, hi, g_lo, g_hi, rounding, iterations);
  return 0.5 * (a + b);
}

}  // namespace

Box3 bounding_box(const NurbsCurve& curve) {
  const int p = curve.degree();
  const auto N = static_cast<std::size_t>(8 * (p + 1));
  const std::vector<double> breaks = curve.knots().breakpoints();
  std::vector<std::array<Vec3, 2>> samples(N + 1);
  std::vector<double> ts(N + 1);
  Box3 box;
  for (std::size_t s = 0; s + 1 < breaks.size(); ++s) {
    const double x0 = breaks[s];
    const double x1 = breaks[s + 1];
    for (std::size_t j = 0; j <= N; ++j) {
      ts[j] = j == N ? x1 : x0 + (x1 - x0) * static_cast<double>(j) / static_cast<double>(N);
      // One-sided at the span end so that x' is the span's own polynomial piece.
      const EvalOptions side{.side = j == N ? Side::Left : Side::Right};
      curve.derivatives(ts[j], 1, samples[j], side);
      box.add(samples[j][0]);
    }
    for (std::size_t c = 0; c < 3; ++c) {
      for (std::size_t j = 0; j < N; ++j) {
        const double g0 = samples[j][1][c];
        const double g1 = samples[j + 1][1][c];
        if (!((g0 < 0.0 && g1 > 0.0) || (g0 > 0.0 && g1 < 0.0))) continue;
        const double t = polish_root(curve, c, ts[j], ts[j + 1], g0, g1);
        box.add(curve.evaluate(t));
      }
    }
  }
  // The curve lies in the convex hull of its control points: clip rounding excess.
  const Box3 hull = curve.control_box();
  box.min = {std::fmax(box.min.x, hull.min.x), std::fmax(box.min.y, hull.min.y), std::fmax(box.min.z, hull.min.z)};
  box.max = {std::fmin(box.max.x, hull.max.x), std::fmin(box.max.y, hull.max.y), std::fmin(box.max.z, hull.max.z)};
  return box;
}

}  // namespace hula::nurbs
