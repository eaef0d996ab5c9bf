// SPDX-License-Identifier: MIT
// Knot removal (The NURBS Book A5.8) on homogeneous control points, one removal
// at a time. Notation as in refine.cpp: p = degree, U = knots, Pw = homogeneous
// points, u = the knot, r = index of its last occurrence in U, s = its
// multiplicity; the removal solves for the p − s points Pw[first .. last] of
// the curve without one copy of u from both ends inwards (eqs. 5.28–5.29) and
// measures where the two sweeps meet (the removal bound, eqs. 5.30–5.31).
#include "hula/nurbs/knot_removal.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/nurbs/detail/homogeneous.hpp"

namespace hula::nurbs {

using detail::Hpoint;

namespace {

double distance4(const Hpoint& a, const Hpoint& b) {
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]) +
                   (a[3] - b[3]) * (a[3] - b[3]));
}

// The working curve: knots and homogeneous points, changed in place by apply().
struct Working {
  std::vector<double> U;
  std::vector<Hpoint> Pw;
  std::ptrdiff_t p = 0;
};

// One trial removal of the knot whose last occurrence is U[r] (multiplicity s).
struct Trial {
  double bound = 0.0;  // homogeneous distance where the two sweeps meet
  std::ptrdiff_t r = 0, s = 0, first = 0, last = 0;
  std::vector<Hpoint> temp;  // temp[k] is the new point first − 1 + k
};

Trial trial(const Working& w, std::ptrdiff_t r, std::ptrdiff_t s) {
  const std::vector<double>& U = w.U;
  const std::vector<Hpoint>& Pw = w.Pw;
  const std::ptrdiff_t p = w.p;
  const double u = U[static_cast<std::size_t>(r)];
  Trial t{.r = r, .s = s, .first = r - p, .last = r - s, .temp = {}};
  const std::ptrdiff_t off = t.first - 1;
  t.temp.resize(static_cast<std::size_t>(t.last + 2 - off));
  auto T = [&](std::ptrdiff_t k) -> Hpoint& { return t.temp[static_cast<std::size_t>(k)]; };
  auto P = [&](std::ptrdiff_t k) -> const Hpoint& { return Pw[static_cast<std::size_t>(k)]; };
  auto K = [&](std::ptrdiff_t k) { return U[static_cast<std::size_t>(k)]; };
  T(0) = P(off);
  T(t.last + 1 - off) = P(t.last + 1);
  std::ptrdiff_t i = t.first, j = t.last, ii = 1, jj = t.last - off;
  while (j - i > 0) {
    // u lies strictly inside both knot intervals (U[i] < u < U[i+p+1]), so 0 < alpha < 1.
    const double ai = (u - K(i)) / (K(i + p + 1) - K(i));
    const double aj = (u - K(j)) / (K(j + p + 1) - K(j));
    T(ii) = detail::combine(1.0 / ai, P(i), -(1.0 - ai) / ai, T(ii - 1));
    T(jj) = detail::combine(1.0 / (1.0 - aj), P(j), -aj / (1.0 - aj), T(jj + 1));
    ++i, ++ii, --j, --jj;
  }
  if (j - i < 0) {
    t.bound = distance4(T(ii - 1), T(jj + 1));
  } else {
    const double ai = (u - K(i)) / (K(i + p + 1) - K(i));
    t.bound = distance4(P(i), detail::combine(ai, T(ii + 1), 1.0 - ai, T(ii - 1)));
  }
  // A removal of a rational curve's knot that would give a point a weight ≤ 0 is no removal of this curve:
  // it is never within any tolerance (its bound is infinite).
  // (The points apply() writes: temp[i − off] and temp[j − off] for i = first…, j = last… while j > i.)
  for (std::ptrdiff_t a = t.first, b = t.last; b - a > 0; ++a, --b)
    if (!(T(a - off)[3] > 0.0) || !(T(b - off)[3] > 0.0)) t.bound = std::numeric_limits<double>::infinity();
  return t;
}

void apply(Working& w, const Trial& t) {
  const std::ptrdiff_t off = t.first - 1;
  for (std::ptrdiff_t i = t.first, j = t.last; j - i > 0; ++i, --j) {
    w.Pw[static_cast<std::size_t>(i)] = t.temp[static_cast<std::size_t>(i - off)];
    w.Pw[static_cast<std::size_t>(j)] = t.temp[static_cast<std::size_t>(j - off)];
  }
  w.U.erase(w.U.begin() + t.r);
  w.Pw.erase(w.Pw.begin() + (2 * t.r - t.s - w.p) / 2);
}

// Multiplier from the homogeneous bound to model units: 1 for a polynomial curve; (1 + max |P|) / min w for a
// rational one (The NURBS Book eq. 5.36).
double bound_scale(const NurbsCurve& curve) {
  if (!curve.is_rational()) return 1.0;
  double size = 0.0;
  for (const Vec3& q : curve.control_points()) size = std::max(size, norm(q));
  const auto w = curve.weights();
  return (1.0 + size) / *std::min_element(w.begin(), w.end());
}

double checked_tolerance(const NurbsCurve& curve, double tolerance) {
  if (!std::isfinite(tolerance))
    throw Error(Errc::NonFiniteInput, detail::named("tolerance", tolerance) + " is not finite", {.field = "tolerance"});
  if (tolerance < 0.0)
    throw Error(Errc::InvalidArgument, detail::named("tolerance", tolerance) + " must be >= 0", {.field = "tolerance"});
  // Removing an inserted knot reproduces the points only to rounding.
  return std::max(tolerance, 1e-12 * curve.model_size());
}

Working working(const NurbsCurve& curve) {
  const std::span<const double> U = curve.knots().values();
  return {.U = {U.begin(), U.end()}, .Pw = detail::to_homogeneous(curve), .p = curve.degree()};
}

NurbsCurve finish(const NurbsCurve& curve, Working& w) {
  return detail::from_homogeneous(KnotVector(std::move(w.U), curve.degree()), w.Pw, curve.is_rational(),
                                  curve.dimension(), "remove_knot");
}

}  // namespace

KnotRemovalResult remove_knot(const NurbsCurve& curve, double u, int times, double tolerance) {
  if (!std::isfinite(u)) throw Error(Errc::NonFiniteInput, detail::named("u", u) + " is not finite", {.field = "u"});
  const Interval d = curve.domain();
  const int multiplicity = curve.knots().multiplicity(u);
  if (!(u > d.start && u < d.end) || multiplicity == 0)
    throw Error(Errc::InvalidArgument,
                detail::named("u", u) + " is not an interior knot of the curve (domain [" + format_number(d.start) +
                    ", " + format_number(d.end) + "])",
                {.field = "u"});
  if (times < 1)
    throw Error(Errc::InvalidArgument, "times = " + std::to_string(times) + " must be >= 1", {.field = "times"});
  const double tol = checked_tolerance(curve, tolerance);
  const double scale = bound_scale(curve);
  Working w = working(curve);
  KnotRemovalResult result{.curve = curve};
  for (int k = 0; k < std::min(times, multiplicity); ++k) {
    const auto r = static_cast<std::ptrdiff_t>(std::upper_bound(w.U.begin(), w.U.end(), u) - w.U.begin()) - 1;
    const Trial t = trial(w, r, multiplicity - k);
    if (result.error_bound + t.bound * scale > tol) break;
    apply(w, t);
    result.error_bound += t.bound * scale;
    ++result.removed;
  }
  if (result.removed > 0) result.curve = finish(curve, w);
  return result;
}

KnotRemovalResult remove_knots(const NurbsCurve& curve, double tolerance) {
  const double tol = checked_tolerance(curve, tolerance);
  const double scale = bound_scale(curve);
  // Accumulated bound per span of the input's breakpoints: the curves differ only where a removal's changed
  // points have support, so |C_k(t) − C(t)| ≤ the sum of the bounds of the removals whose support holds t.
  const std::vector<double> breaks = curve.knots().breakpoints();
  std::vector<double> span_error(breaks.size() - 1, 0.0);
  // The spans of the input's breakpoints that meet [a, b] (a and b may lie outside the domain of an unclamped curve).
  auto spans_of = [&](double a, double b) {
    const auto lo = static_cast<std::size_t>(
        std::max(std::upper_bound(breaks.begin(), breaks.end(), a) - breaks.begin() - 1, std::ptrdiff_t{0}));
    const auto hi = static_cast<std::size_t>(std::lower_bound(breaks.begin(), breaks.end(), b) - breaks.begin());
    return std::pair{lo, std::min(hi, span_error.size())};
  };
  Working w = working(curve);
  const Interval d = curve.domain();
  constexpr double kNever = std::numeric_limits<double>::infinity();
  // Multiplicity of the knot whose last occurrence is U[r], or 0 when U[r] is not that (not interior, or not last).
  auto last_multiplicity = [&](std::ptrdiff_t r) -> std::ptrdiff_t {
    if (r < w.p + 1 || r + 1 >= static_cast<std::ptrdiff_t>(w.U.size())) return 0;
    const double u = w.U[static_cast<std::size_t>(r)];
    if (!(u > d.start && u < d.end) || w.U[static_cast<std::size_t>(r + 1)] == u) return 0;
    std::ptrdiff_t s = 1;
    while (w.U[static_cast<std::size_t>(r - s)] == u) ++s;
    return s;
  };
  auto cost_of = [&](std::ptrdiff_t r) {
    const std::ptrdiff_t s = last_multiplicity(r);
    return s == 0 ? kNever : trial(w, r, s).bound * scale;
  };
  // The removal cost of each knot, kept up to date: a removal at r changes only the points and knots
  // within p + 1 of r, so only the costs within 2p + 3 of it are computed again (O(p) trials per
  // removal instead of one per knot).
  std::vector<double> cost(w.U.size());
  for (std::size_t r = 0; r < cost.size(); ++r) cost[r] = cost_of(static_cast<std::ptrdiff_t>(r));
  KnotRemovalResult result{.curve = curve};
  for (;;) {
    std::ptrdiff_t best = -1;
    double best_cost = kNever;
    for (std::size_t r = 0; r < cost.size(); ++r) {
      if (!(cost[r] < best_cost) || cost[r] > tol) continue;
      const auto R = static_cast<std::ptrdiff_t>(r);
      const std::ptrdiff_t s = last_multiplicity(R);
      const auto [lo, hi] =
          spans_of(w.U[r - static_cast<std::size_t>(w.p)], w.U[static_cast<std::size_t>(R - s + w.p + 1)]);
      const double used = *std::max_element(span_error.begin() + static_cast<std::ptrdiff_t>(lo),
                                            span_error.begin() + static_cast<std::ptrdiff_t>(hi));
      if (cost[r] > tol - used) continue;
      best = R;
      best_cost = cost[r];
    }
    if (best < 0) break;
    const Trial t = trial(w, best, last_multiplicity(best));
    const auto [lo, hi] =
        spans_of(w.U[static_cast<std::size_t>(t.first)], w.U[static_cast<std::size_t>(t.last + w.p + 1)]);
    for (std::size_t k = lo; k < hi; ++k) span_error[k] += best_cost;
    apply(w, t);
    cost.erase(cost.begin() + best);
    const std::ptrdiff_t reach = 2 * w.p + 3;
    for (std::ptrdiff_t r = std::max<std::ptrdiff_t>(0, best - reach);
         r < std::min<std::ptrdiff_t>(static_cast<std::ptrdiff_t>(cost.size()), best + reach); ++r)
      cost[static_cast<std::size_t>(r)] = cost_of(r);
    ++result.removed;
  }
  if (result.removed > 0) {
    result.curve = finish(curve, w);
    result.error_bound = *std::max_element(span_error.begin(), span_error.end());
  }
  return result;
}

}  // namespace hula::nurbs
