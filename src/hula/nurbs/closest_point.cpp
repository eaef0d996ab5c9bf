// SPDX-License-Identifier: MIT
// Global point projection: span sampling, then Newton (The NURBS Book 6.1).
//
// Notation: P = query point, C(t) the curve, D = C - P.
// Newton on f(t) = C'·D (eq. 6.3): t_{i+1} = t_i - f / f',
// f' = C''·D + |C'|². Convergence (eqs. 6.4–6.5): |D| ≤ eps0 (P on the
// curve; eps0 = kRelativeResolution × model size, rounding level, so points on
// the curve are found to full precision rather than to resabs), or
// |C'·D| / (|C'| |D|) ≤ eps2 (zero cosine), or the step moves the point by
// |(t_{i+1} - t_i) C'| ≤ eps1 (the point after that step is kept, its error
// being O(step²)). f and f' are both divided by
// s = max_abs(D) before use, which leaves the Newton step unchanged and keeps
// far points (|D| up to 1e308) free of overflow.
#include "hula/nurbs/closest_point.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

#include "hula/core/error.hpp"

namespace hula::nurbs {

namespace {

struct Search {
  const NurbsCurve& curve;
  const Vec3& target;
  Interval domain;
  double eps0;
  double eps1;
  double eps2;
  int max_iterations;
  ClosestPointResult best;

  void consider(double t, const Vec3& c, double dist) {
    if (dist < best.distance) best = {t, c, dist};
  }

  // Newton from t0; allocation-free.
  void newton(double t0) {
    double t = t0;
    std::array<Vec3, 3> d;
    for (int it = 0; it < max_iterations; ++it) {
      curve.derivatives(t, 2, d);
      const Vec3 D = d[0] - target;
      const double dist = norm(D);
      consider(t, d[0], dist);
      if (dist <= eps0) return;  // eq. 6.4, first test
      const double speed = norm(d[1]);
      if (!(speed > 0.0)) return;  // C' = 0: stationary parameter, no Newton direction
      const double scale = max_abs(D);
      const Vec3 Ds = D / scale;
      const double f = dot(d[1], Ds);
      if (std::fabs(f) <= eps2 * speed * norm(Ds)) return;  // eq. 6.4, zero cosine
      const double df = dot(d[2], Ds) + speed * (speed / scale);
      if (!(df > 0.0) || !std::isfinite(df)) return;  // not moving towards a minimum
      const double next = std::clamp(t - f / df, domain.start, domain.end);
      if (std::fabs(next - t) * speed <= eps1) {  // eq. 6.5
        if (next != t) consider(next, curve.evaluate(next), distance(curve.evaluate(next), target));
        return;
      }
      t = next;
    }
  }
};

}  // namespace

void ClosestPointOptions::validate() const {
  tolerance.validate();
  if (samples_per_span != 0 && samples_per_span < 2)
    throw Error(Errc::InvalidOption,
                "options.samples_per_span = " + std::to_string(samples_per_span) + " must be 0 (automatic) or >= 2",
                {.field = "samples_per_span"});
  if (max_iterations < 1 || max_iterations > 1000)
    throw Error(Errc::InvalidOption,
                "options.max_iterations = " + std::to_string(max_iterations) + " must be in [1, 1000]",
                {.field = "max_iterations"});
}

ClosestPointResult closest_point(const NurbsCurve& curve, const Vec3& point, const ClosestPointOptions& options) {
  options.validate();
  for (std::size_t c = 0; c < 3; ++c)
    if (!std::isfinite(point[c]))
      throw Error(Errc::NonFiniteInput,
                  "point[" + std::to_string(c) + "] = " + format_number(point[c]) + " is not finite",
                  {.field = "point", .component = c});
  const Interval dom = curve.domain();
  const int p = curve.degree();
  const auto per_span = static_cast<std::size_t>(options.samples_per_span > 0 ? options.samples_per_span : 4 * (p + 1));
  const std::vector<double> breaks = curve.knots().breakpoints();

  // Samples: per_span intervals on every span, plus the domain end.
  std::vector<double> ts;
  ts.reserve((breaks.size() - 1) * per_span + 1);
  for (std::size_t s = 0; s + 1 < breaks.size(); ++s)
    for (std::size_t j = 0; j < per_span; ++j)
      ts.push_back(breaks[s] + (breaks[s + 1] - breaks[s]) * static_cast<double>(j) / static_cast<double>(per_span));
  ts.push_back(dom.end);
  std::vector<Vec3> pts(ts.size());
  curve.evaluate(ts, pts);
  std::vector<double> dist(ts.size());
  for (std::size_t i = 0; i < ts.size(); ++i) dist[i] = distance(pts[i], point);

  Search search{curve,
                point,
                dom,
                kRelativeResolution * curve.model_size(),
                resolution_for_size(options.tolerance, curve.model_size()),
                options.tolerance.angular,
                options.max_iterations,
                {dom.start, pts.front(), dist.front()}};
  for (std::size_t i = 0; i < ts.size(); ++i) search.consider(ts[i], pts[i], dist[i]);
  // Newton from every sampled local minimum of the distance.
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const bool left_ok = i == 0 || dist[i] <= dist[i - 1];
    const bool right_ok = i + 1 == ts.size() || dist[i] <= dist[i + 1];
    if (left_ok && right_ok) search.newton(ts[i]);
  }
  return search.best;
}

}  // namespace hula::nurbs
