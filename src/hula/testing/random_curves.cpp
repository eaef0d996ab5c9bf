// SPDX-License-Identifier: MIT
#include "hula/testing/random_curves.hpp"

#include <algorithm>
#include <vector>

namespace hula::testing {

nurbs::NurbsCurve random_curve(Rng& rng, const RandomCurveOptions& o) {
  const int p = o.min_degree + static_cast<int>(rng.below(static_cast<std::uint64_t>(o.max_degree - o.min_degree + 1)));
  const auto P = static_cast<std::size_t>(p);
  const std::size_t lo = std::max(o.min_points, P + 1);
  const std::size_t hi = std::max(lo, o.max_points);
  const std::size_t n1 = lo + rng.below(hi - lo + 1);  // number of control points
  const double a = rng.uniform(-2.0, 2.0);
  const double b = a + rng.uniform(0.5, 3.0);
  // Interior knots: n1 - p - 1 values, sorted, some repeated (≤ p times).
  std::vector<double> inner;
  const std::size_t count = n1 - P - 1;
  while (inner.size() < count) {
    const double u = a + (b - a) * (0.02 + 0.96 * rng.uniform());
    std::size_t times = 1;
    if (o.repeated_knots && rng.below(4) == 0) times = 1 + rng.below(P);
    for (std::size_t k = 0; k < times && inner.size() < count; ++k) inner.push_back(u);
  }
  std::sort(inner.begin(), inner.end());
  std::vector<double> U(P + 1, a);
  U.insert(U.end(), inner.begin(), inner.end());
  U.insert(U.end(), P + 1, b);
  std::vector<Vec3> pts(n1);
  for (auto& q : pts)
    q = {rng.uniform(-o.scale, o.scale), rng.uniform(-o.scale, o.scale),
         o.planar ? 0.0 : rng.uniform(-o.scale, o.scale)};
  std::vector<double> w;
  if (o.rational) {
    w.resize(n1);
    for (auto& x : w) x = rng.uniform(0.3, 3.0);
  }
  return nurbs::NurbsCurve(p, std::move(U), std::move(pts), std::move(w), o.planar ? 2 : 3);
}

}  // namespace hula::testing
