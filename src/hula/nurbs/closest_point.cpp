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
#include <limits>
#include <string>
#include <vector>

#include "hula/core/error.hpp"

namespace hula::nurbs {

namespace {

struct Candidate {
  ClosestPointResult result;
  bool converged = false;  // met a Newton convergence test (eqs. 6.4–6.5)
};

struct Search {
  const NurbsCurve& curve;
  const Vec3& target;
  Interval domain;
  double eps0;
  double eps1;
  double eps2;
  double noise;  // rounding level of a computed distance
  int max_iterations;
  Candidate best;

  // Near a minimum the distance is flat (it changes by O(δ²) for a foot moved
  // by δ), so distances within rounding noise cannot rank candidates; a
  // converged Newton foot then wins over a sample or an unconverged iterate.
  void consider(const Candidate& c) {
    const double d = c.result.distance;
    const double b = best.result.distance;
    if (d < b - noise || (d <= b + noise && c.converged && !best.converged)) best = c;
  }

  // Safeguarded Newton from t0 inside the bracket [lo, hi] (a sample
  // interval where f changes sign); allocation-free. f = C'·D is < 0 where the distance falls and
  // > 0 where it rises, so its sign shrinks the bracket; a Newton step that
  // leaves the bracket or has f' ≤ 0 (C''·D can dominate |C'|² on strongly
  // rational pieces) is replaced by bisection. Offers its final iterate
  // (converged) or, after max_iterations, its best iterate (not converged). Not Boost.Math's
  // newton_raphson_iterate: it keeps its bracket by the sign of f / f', which f' ≤ 0 breaks, and stops on
  // the step relative to t, where The NURBS Book's tests are on the distance vector (eqs. 6.4–6.5).
  void newton(double t0, double lo, double hi) {
    double t = t0;
    std::array<Vec3, 3> d;
    Candidate local{{t0, curve.evaluate(t0), HUGE_VAL}, false};
    bool newton_step = false;
    for (int it = 0; it < max_iterations; ++it) {
      // The bracket lies in one span: at its upper end take that span's (left) derivative.
      curve.derivatives(t, 2, d, {.side = t >= hi ? Side::Left : Side::Right});
      const Vec3 D = d[0] - target;
      const double dist = norm(D);
      if (dist < local.result.distance) local.result = {t, d[0], dist};
      if (dist <= eps0) return consider({{t, d[0], dist}, true});  // eq. 6.4, first test
      const double speed = norm(d[1]);
      const double scale = max_abs(D);
      const Vec3 Ds = D / scale;
      const double f = dot(d[1], Ds);
      if (speed > 0.0 && std::fabs(f) <= eps2 * speed * norm(Ds))
        return consider({{t, d[0], dist}, true});  // eq. 6.4, zero cosine
      if (f > 0.0)
        hi = t;
      else if (f < 0.0)
        lo = t;
      const double df = dot(d[2], Ds) + speed * (speed / scale);
      double next = df > 0.0 && std::isfinite(df) ? t - f / df : std::numeric_limits<double>::quiet_NaN();
      const bool inside = next >= lo && next <= hi;
      if (!inside) next = f > 0.0 ? 0.5 * (lo + t) : 0.5 * (t + hi);
      // eq. 6.5 after a Newton step (the new point's error is O(step²)); a
      // collapsed bracket ends bisection.
      if ((inside && newton_step && std::fabs(next - t) * speed <= eps1) || !(hi > lo) || next == t) {
        const Vec3 c = curve.evaluate(next);
        return consider({{next, c, distance(c, target)}, true});
      }
      newton_step = inside;
      t = next;
    }
    consider(local);
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

  // Samples: per_span + 1 on every span, both ends included, with the
  // derivative of that span (Side::Left at its end): at a C0 knot the sign of f
  // must be read on each side separately. Breakpoints thus appear twice.
  const std::size_t spans = breaks.size() - 1;
  const std::size_t stride = per_span + 1;
  std::vector<double> ts(spans * stride);
  std::vector<Vec3> ders(2 * ts.size());
  for (std::size_t s = 0; s < spans; ++s) {
    double* t = ts.data() + s * stride;
    for (std::size_t j = 0; j < per_span; ++j)
      t[j] = breaks[s] + (breaks[s + 1] - breaks[s]) * static_cast<double>(j) / static_cast<double>(per_span);
    t[per_span] = breaks[s + 1];
    curve.derivatives(std::span<const double>(t, per_span), 1,
                      std::span<Vec3>(ders.data() + 2 * s * stride, 2 * per_span));
    curve.derivatives(t[per_span], 1, std::span<Vec3>(ders.data() + 2 * (s * stride + per_span), 2),
                      {.side = Side::Left});
  }
  // Distance and the sign of f = C'·(C - P), which goes from - to + across
  // every local minimum of the distance.
  std::vector<Vec3> pts(ts.size());
  std::vector<double> dist(ts.size()), fs(ts.size());
  for (std::size_t i = 0; i < ts.size(); ++i) {
    pts[i] = ders[2 * i];
    const Vec3 D = pts[i] - point;
    dist[i] = norm(D);
    const double scale = max_abs(D);
    fs[i] = scale > 0.0 ? dot(ders[2 * i + 1], D / scale) : 0.0;
  }

  const double size = curve.model_size();
  const double magnitude = std::fmax(max_abs(point), curve.control_box().extent());
  Search search{curve,
                point,
                dom,
                kRelativeResolution * size,
                resolution_for_size(options.tolerance, size),
                options.tolerance.angular,
                16.0 * std::numeric_limits<double>::epsilon() * magnitude,
                options.max_iterations,
                {{dom.start, pts.front(), dist.front()}, false}};
  for (std::size_t i = 0; i < ts.size(); ++i) search.consider({{ts[i], pts[i], dist[i]}, false});
  // Newton in every sample interval where f changes sign from - to + (a
  // local minimum of the distance inside it), from the nearer end; and from
  // every sample that is a local minimum of the distance, between its
  // neighbours (this catches a minimum and a maximum inside one interval,
  // where f has the same sign at both ends).
  for (std::size_t i = 0; i + 1 < ts.size(); ++i)
    if (ts[i] < ts[i + 1] && fs[i] < 0.0 && fs[i + 1] > 0.0)
      search.newton(dist[i] <= dist[i + 1] ? ts[i] : ts[i + 1], ts[i], ts[i + 1]);
  for (std::size_t i = 1; i + 1 < ts.size(); ++i)
    if (dist[i] <= dist[i - 1] && dist[i] <= dist[i + 1] && ts[i - 1] < ts[i + 1])
      search.newton(ts[i], ts[i - 1], ts[i + 1]);
  // Narrow features (a hairpin passing near P between two samples) can hide
  // a minimum from both tests above. On a sample interval of width h inside
  // span s the distance is at least (d_i + d_{i+1} - M_s h) / 2, where M_s
  // bounds the speed |C'| on the span (twice the largest sampled speed); every
  // interval whose bound is below the best distance so far gets a Newton
  // start from its left end.
  for (std::size_t s = 0; s < spans; ++s) {
    double max_speed = 0.0;
    for (std::size_t j = 0; j <= per_span; ++j) max_speed = std::fmax(max_speed, norm(ders[2 * (s * stride + j) + 1]));
    const double M = 2.0 * max_speed;
    for (std::size_t j = 0; j < per_span; ++j) {
      const std::size_t i = s * stride + j;
      const double bound = 0.5 * (dist[i] + dist[i + 1] - M * (ts[i + 1] - ts[i]));
      if (bound < search.best.result.distance) search.newton(ts[i], ts[i], ts[i + 1]);
    }
  }
  return search.best.result;
}

}  // namespace hula::nurbs
