// SPDX-License-Identifier: MIT
// Random curve generator and dense-sample deviation for property tests.
#include "hula/testing/curve_generators.hpp"

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace hula::testing {

nurbs::NurbsCurve random_curve(Rng& rng, const RandomCurveSpec& spec) {
  const int p = spec.degree;
  const auto n_points = static_cast<std::size_t>(p + 1 + std::max(0, spec.extra_points));
  const auto P = static_cast<std::size_t>(p);
  const double start = rng.uniform(-5.0, 5.0);
  const double length = rng.uniform(0.1, 10.0);
  std::vector<double> U;
  U.reserve(n_points + P + 1);
  if (spec.clamped) {
    // Interior knots: n_points - p - 1 values, in runs of random multiplicity ≤ p.
    const std::size_t interior = n_points - P - 1;
    std::vector<double> inner;
    while (inner.size() < interior) {
      const double u = start + length * rng.uniform(0.02, 0.98);
      const std::size_t mult = std::min<std::size_t>(interior - inner.size(), 1 + rng.below(P));
      for (std::size_t k = 0; k < mult; ++k) inner.push_back(u);
    }
    std::sort(inner.begin(), inner.end());
    U.assign(P + 1, start);
    U.insert(U.end(), inner.begin(), inner.end());
    U.insert(U.end(), P + 1, start + length);
  } else {
    // Strictly increasing random knots, mapped so that the domain
    // [U[p], U[n+1]] is [start, start + length].
    const std::size_t m = n_points + P + 1;
    std::vector<double> V(m);
    V[0] = 0.0;
    for (std::size_t i = 1; i < m; ++i) V[i] = V[i - 1] + rng.uniform(0.2, 1.0);
    const double a = V[P];
    const double scale = length / (V[n_points] - a);
    U.resize(m);
    for (std::size_t i = 0; i < m; ++i) U[i] = start + (V[i] - a) * scale;
    U[P] = start;
    U[n_points] = start + length;
    for (std::size_t i = 1; i < m; ++i) U[i] = std::max(U[i], U[i - 1]);
  }
  std::vector<Vec3> points(n_points);
  for (Vec3& q : points) q = {rng.uniform(-10.0, 10.0), rng.uniform(-10.0, 10.0), rng.uniform(-10.0, 10.0)};
  std::vector<double> weights;
  if (spec.rational) {
    weights.resize(n_points);
    for (double& w : weights) w = rng.uniform(0.2, 5.0);
  }
  return nurbs::NurbsCurve(p, std::move(U), std::move(points), std::move(weights), 3);
}

double max_deviation(const nurbs::NurbsCurve& a, const nurbs::NurbsCurve& b, int samples) {
  const nurbs::Interval d = a.domain();
  double worst = 0.0;
  for (int i = 0; i <= samples; ++i) {
    const double t = i == samples ? d.end : d.start + d.length() * i / samples;
    worst = std::max(worst, distance(a.evaluate(t), b.evaluate(t)));
  }
  return worst;
}

nurbs::NurbsCurve rational_circle(double R, double angle) {
  const double w = std::sqrt(0.5);
  std::vector<Vec3> P = {{R, 0, 0},   {R, R, 0},  {0, R, 0},  {-R, R, 0}, {-R, 0, 0},
                         {-R, -R, 0}, {0, -R, 0}, {R, -R, 0}, {R, 0, 0}};
  if (angle != 0.0)
    for (Vec3& q : P)
      q = {std::cos(angle) * q.x - std::sin(angle) * q.y, std::sin(angle) * q.x + std::cos(angle) * q.y, 0};
  return nurbs::NurbsCurve(2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}, std::move(P),
                           {1, w, 1, w, 1, w, 1, w, 1}, 2);
}

nurbs::NurbsCurve arbitrary_curve(int max_degree) {
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  const int degree = *rc::gen::inRange(1, max_degree + 1);
  const bool rational = *rc::gen::arbitrary<bool>();
  const bool clamped = *rc::gen::weightedElement<bool>({{3, true}, {1, false}});
  const int extra = *rc::gen::inRange(0, 7);
  Rng rng(seed);
  return random_curve(rng, {.degree = degree, .rational = rational, .clamped = clamped, .extra_points = extra});
}

}  // namespace hula::testing
