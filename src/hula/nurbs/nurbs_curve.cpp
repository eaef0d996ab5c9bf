// SPDX-License-Identifier: MIT
// NurbsCurve validation, the per-span Taylor cache and the evaluators.
//
// Notation (The NURBS Book): p = degree, U = knots, P_i = control points,
// w_i = weights, Pw_i = (w_i P_i, w_i) homogeneous points, A(t) = Σ N_i Pw_i.xyz,
// w(t) = Σ N_i w_i, C = A / w. Rational derivatives by eq. 4.8:
//   C^(k) = (A^(k) - Σ_{i=1..k} binom(k, i) w^(i) C^(k-i)) / w.
#include "hula/nurbs/nurbs_curve.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <utility>

#include "hula/core/error.hpp"
#include "hula/core/huge_pages.hpp"
#include "hula/nurbs/basis.hpp"
#include "hula/nurbs/detail/basis_fixed.hpp"
#include "hula/nurbs/detail/curve_access.hpp"
#include "hula/nurbs/detail/span_simd.hpp"
#include "hula/nurbs/piece_evaluator.hpp"

#define HULA_SPAN_ISA scalar
#include "hula/nurbs/detail/span_eval.hpp"
#undef HULA_SPAN_ISA

namespace hula::nurbs {

namespace {

// The per-span cache of a curve, in one allocation: breakpoints b[0..S]; per span its midpoint, 2 / length
// and the Taylor coefficients of the homogeneous curve at the midpoint (power j, lane x, y, z, w at
// coef[(s * (p + 1) + j) * 4 + lane]); per breakpoint an exact-point record (flag, x, y, z).
struct SpanCache {
  std::size_t spans = 0;            // S
  std::size_t block = 0;            // (p + 1) * 4 coefficients per span; 0 above kCachedDegreeLimit (direct evaluation)
  std::unique_ptr<double[]> store;  // not zero-filled: build_cache writes every element
  const double* breaks = nullptr;
  const double* mid = nullptr;
  const double* inv_half = nullptr;
  const double* coef = nullptr;
  // Exact ends: at a breakpoint of multiplicity ≥ p (the clamped ends, C0 joins) one
  // basis function is 1 and the curve passes through a control point. exact[4 b] = 1 marks breaks[b] as
  // such a point and exact[4 b + 1 … 3] hold that control point, returned as is instead of the rounded
  // sum of the span polynomial.
  const double* exact = nullptr;
  // Derivatives up to this order cannot overflow inside the domain (bounded when the cache is built), so
  // the evaluators skip the finiteness probe for them; positions (order 0) never overflow there.
  int unchecked_order = 0;
  // Span search: the domain is cut into `buckets` equal buckets; J(t) = the bucket of t,
  // computed by bucket_of, is monotone in t, so the span of any t with J(t) = j lies in
  // [first[j], first[j] + count[j]) (see build_buckets), which `steps` branch-free halvings narrow to one
  // span: O(1) for knots of similar lengths, O(log S) at worst, never a data-dependent branch.
  double bucket_origin = 0.0;
  double bucket_scale = 0.0;          // buckets / domain length
  double last_bucket = 0.0;           // buckets − 1
  std::vector<std::uint32_t> bucket;  // first[j], count[j] interleaved
  int steps = 0;

  SpanCache() = default;
  SpanCache(const SpanCache&) = delete;
  SpanCache& operator=(const SpanCache&) = delete;
};

// Replaces a position computed at breakpoint b by its exact control point, when it has one.
inline void snap_exact(const SpanCache& c, std::size_t b, Vec3& position) {
  const double* e = c.exact + 4 * b;
  if (e[0] != 0.0) position = {e[1], e[2], e[3]};
}

std::string where_t(const char* name, double t) { return std::string(name) + " = " + format_number(t); }

// Scratch of the cache builder and the direct (high-degree) evaluator: one per thread, so both are
// allocation-free once warm and safe under concurrent const use (never used by both at once).
BasisWorkspace& thread_workspace() {
  thread_local BasisWorkspace work;
  return work;
}

}  // namespace

struct NurbsCurve::Data {
  KnotVector knots;
  std::vector<Vec3> points;
  std::vector<double> weights;
  int dimension;
  Box3 box;
  // Built on first use and published with one compare-and-swap (no call_once, whose futex
  // wake cost a system call per curve); a thread that loses the race drops its copy.
  mutable std::atomic<const SpanCache*> cache{nullptr};

  Data(KnotVector k, std::vector<Vec3> p, std::vector<double> w, int dim)
      : knots(std::move(k)), points(std::move(p)), weights(std::move(w)), dimension(dim) {}
  Data(const Data&) = delete;
  Data& operator=(const Data&) = delete;
  ~Data() { delete cache.load(std::memory_order_acquire); }

  [[nodiscard]] bool rational() const { return !weights.empty(); }
  [[nodiscard]] int degree() const { return knots.degree(); }
  [[nodiscard]] const SpanCache& span_cache() const {
    const SpanCache* c = cache.load(std::memory_order_acquire);
    return c != nullptr ? *c : publish_cache();
  }
  const SpanCache& publish_cache() const;
  void build_cache(SpanCache& out) const;
  // Span i's (U[i] < U[i + 1], degree ≤ kCachedDegreeLimit) midpoint, 1 / half-length and Taylor coefficients.
  void piece(std::size_t i, double& mid, double& inv_half, double* coef) const;
  // No derivative up to the cache's unchecked order can overflow on span i (bounds below).
  bool piece_bounded(std::size_t i, double inv_half, const double* coef) const;
  void eval_direct(double t, int order, Side side, Vec3* out, BasisWorkspace& work) const;
  // snap_exact for the direct path (binary search over the breakpoints).
  void snap_direct(const SpanCache& c, double u, Vec3& position) const {
    const double* b = c.breaks;
    const double* it = std::lower_bound(b, b + c.spans + 1, u);
    if (it != b + c.spans + 1 && *it == u) snap_exact(c, static_cast<std::size_t>(it - b), position);
  }
};

namespace {

void validate_points(const std::vector<Vec3>& points, const std::vector<double>& weights, int dimension,
                     std::size_t expected) {
  if (dimension != 2 && dimension != 3)
    throw Error(Errc::InvalidArgument, "dimension = " + std::to_string(dimension) + " must be 2 or 3",
                {.field = "dimension"});
  if (points.size() != expected)
    throw Error(Errc::InvalidKnots,
                "knots define " + std::to_string(expected) + " control points but " + std::to_string(points.size()) +
                    " were given (need #knots = #control_points + degree + 1)",
                {.field = "knots"});
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      const double v = points[i][c];
      if (!std::isfinite(v))
        throw Error(Errc::NonFiniteInput,
                    "control_points[" + std::to_string(i) + "][" + std::to_string(c) + "] = " + format_number(v) +
                        " is not finite",
                    {.field = "control_points", .index = i, .component = c});
      if (std::fabs(v) > kMaxCoordinate)
        throw Error(Errc::ScaleOutOfRange,
                    "control_points[" + std::to_string(i) + "][" + std::to_string(c) + "] = " + format_number(v) +
                        " exceeds the largest supported coordinate magnitude 1e300; rescale the model",
                    {.field = "control_points", .index = i, .component = c});
    }
    if (dimension == 2 && points[i].z != 0.0)
      throw Error(Errc::InvalidArgument,
                  "control_points[" + std::to_string(i) + "] has z = " + format_number(points[i].z) +
                      " but the curve is 2-D (z must be 0)",
                  {.field = "control_points", .index = i, .component = 2});
  }
  if (!weights.empty()) {
    if (weights.size() != points.size())
      throw Error(
          Errc::InvalidWeight,
          std::to_string(weights.size()) + " weights given for " + std::to_string(points.size()) + " control points",
          {.field = "weights"});
    for (std::size_t i = 0; i < weights.size(); ++i) {
      if (!std::isfinite(weights[i]))
        throw Error(Errc::NonFiniteInput,
                    "weights[" + std::to_string(i) + "] = " + format_number(weights[i]) + " is not finite",
                    {.field = "weights", .index = i});
      if (!(weights[i] > 0.0))
        throw Error(Errc::InvalidWeight,
                    "weights[" + std::to_string(i) + "] = " + format_number(weights[i]) + " must be > 0",
                    {.field = "weights", .index = i});
    }
  }
}

// Derivatives 0..order at local x of a cached span with compile-time degree P and a run-time order (the
// general path behind the compile-time orders 0…3 of span_eval.hpp; the same operations per order).
template <int P, bool R>
inline void eval_span(const double* a, double x, double scale, int order, Vec3* out) {
  // All four lanes even when not rational: pairs of doubles vectorise, three do not.
  double d[P + 1][4];
  for (int k = 1; k <= P; ++k)
    for (int c = 0; c < 4; ++c) d[k][c] = 0.0;
  for (int c = 0; c < 4; ++c) d[0][c] = a[P * 4 + c];
  for (int j = P - 1; j >= 0; --j) {
    for (int k = P - j; k >= 1; --k)
      for (int c = 0; c < 4; ++c) d[k][c] = d[k][c] * x + d[k - 1][c];
    for (int c = 0; c < 4; ++c) d[0][c] = d[0][c] * x + a[j * 4 + c];
  }
  const int K = order < P ? order : P;
  double f = 1.0;
  for (int k = 1; k <= K; ++k) {
    f *= k * scale;
    for (int c = 0; c < 4; ++c) d[k][c] *= f;
  }
  if constexpr (!R) {
    for (int k = 0; k <= K; ++k) out[k] = {d[k][0], d[k][1], d[k][2]};
    for (int k = K + 1; k <= order; ++k) out[k] = {};
  } else {
    const double inv_w = 1.0 / d[0][3];
    out[0] = Vec3{d[0][0], d[0][1], d[0][2]} * inv_w;
    for (int k = 1; k <= order; ++k) {
      Vec3 v = k <= K ? Vec3{d[k][0], d[k][1], d[k][2]} : Vec3{};
      double binom = 1.0;
      const int imax = k < K ? k : K;
      for (int i = 1; i <= imax; ++i) {
        binom = binom * (k - i + 1) / i;
        v -= (binom * d[i][3]) * out[k - i];
      }
      out[k] = v * inv_w;
    }
  }
}

// The bucket of t: J(t) = ⌊clamp((t − origin) · scale, 0, buckets − 1)⌋, monotone non-decreasing in t
// (each operation is), which is all the span search relies on.
inline std::size_t bucket_of(const SpanCache& c, double t) {
  double f = (t - c.bucket_origin) * c.bucket_scale;
  f = f > 0.0 ? f : 0.0;
  f = f < c.last_bucket ? f : c.last_bucket;
  return static_cast<std::size_t>(f);
}

// Span index s in [0, S) of t among breakpoints b[0..S] (exact comparisons): the largest s with
// b[s] <= t (Right) or b[s] < t (Left), 0 if none, S − 1 at and beyond the end. The bucket of t gives
// the candidate spans; a fixed number of branch-free halvings picks one (std::upper_bound's
// unpredictable branches cost shuffled input ~30 ns a point, a plain branch-free binary search ~20).
inline std::size_t locate(const SpanCache& c, double t, Side side) {
  const std::size_t j = bucket_of(c, t);
  std::size_t base = c.bucket[2 * j];
  std::size_t len = c.bucket[2 * j + 1];
  const double* b = c.breaks;
  if (side == Side::Right) {
    for (int k = 0; k < c.steps; ++k) {
      const std::size_t half = len / 2;
      base = b[base + half] <= t ? base + half : base;
      len -= half;
    }
  } else {
    for (int k = 0; k < c.steps; ++k) {
      const std::size_t half = len / 2;
      base = b[base + half] < t ? base + half : base;
      len -= half;
    }
  }
  return base;
}

// The bucket table of locate. With J(b[s]) the bucket of breakpoint s and s* the span of a t with
// J(t) = j: b[s] <= t implies J(b[s]) <= j, so s* <= hi_j = max{s < S : J(b[s]) <= j}; and J(b[s]) < j
// implies b[s] < t, so s* >= lo_j = max{s : J(b[s]) < j} (0 if none). Both bounds hold for either side.
// Two buckets per span keep count_j at 1 or 2 for knots of similar lengths.
void build_buckets(SpanCache& c) {
  const std::size_t S = c.spans;
  const std::size_t B = 2 * S;
  c.bucket_origin = c.breaks[0];
  c.bucket_scale = static_cast<double>(B) / (c.breaks[S] - c.breaks[0]);
  c.last_bucket = static_cast<double>(B - 1);
  c.bucket.clear();
  resize_advised(c.bucket, 2 * B);
  std::size_t below = 0, upto = 0;  // spans s < S with J(b[s]) < j, <= j
  std::size_t widest = 1;
  for (std::size_t j = 0; j < B; ++j) {
    while (below < S && bucket_of(c, c.breaks[below]) < j) ++below;
    while (upto < S && bucket_of(c, c.breaks[upto]) <= j) ++upto;
    const std::size_t lo = below == 0 ? 0 : below - 1;
    const std::size_t hi = upto - 1;  // b[0] is in bucket 0, so upto >= 1
    c.bucket[2 * j] = static_cast<std::uint32_t>(lo);
    c.bucket[2 * j + 1] = static_cast<std::uint32_t>(hi - lo + 1);
    widest = std::max(widest, hi - lo + 1);
  }
  // Halvings that reduce `widest` candidates to one (len − len / 2 each time).
  c.steps = 0;
  for (std::size_t len = widest; len > 1; len -= len / 2) ++c.steps;
}

// Applies the domain policy; returns the parameter to evaluate at.
inline double resolve_parameter(double t, Interval d, Domain policy, const char* field, std::size_t index, bool batch) {
  if (!std::isfinite(t)) {
    ErrorWhere w{.field = field};
    if (batch) w.index = index;
    throw Error(Errc::NonFiniteInput,
                (batch ? std::string(field) + "[" + std::to_string(index) + "]" : std::string(field)) + " = " +
                    format_number(t) + " is not finite",
                w);
  }
  if (t >= d.start && t <= d.end) return t;
  switch (policy) {
    case Domain::Clamp:
      return t < d.start ? d.start : d.end;
    case Domain::Extrapolate:
      return t;
    case Domain::Strict:
      break;
  }
  ErrorWhere w{.field = field};
  if (batch) w.index = index;
  throw Error(Errc::OutOfDomain,
              (batch ? std::string(field) + "[" + std::to_string(index) + "]" : std::string(field)) + " = " +
                  format_number(t) + " is outside the curve domain [" + format_number(d.start) + ", " +
                  format_number(d.end) + "] (ask for Domain::Extrapolate or Domain::Clamp by name)",
              w);
}

void check_finite_result(const Vec3* out, int order, double t) {
  for (int k = 0; k <= order; ++k)
    if (!is_finite(out[k]))
      throw Error(Errc::NumericalFailure,
                  "derivative of order " + std::to_string(k) + " at " + where_t("t", t) +
                      " overflows double precision (model or knot scale too extreme)",
                  {.field = "t"});
}

// (v - v) is 0 for finite v and NaN otherwise: one cheap probe for a whole batch instead of a branch per
// value; the slow pass names the culprit.
inline double probe_of(const Vec3* o, std::size_t count) {
  double probe = 0.0;
  for (std::size_t k = 0; k < count; ++k) probe += (o[k].x - o[k].x) + (o[k].y - o[k].y) + (o[k].z - o[k].z);
  return probe;
}

// The evaluation loop for one compile-time degree P and order K (K < 0: the order is a run-time value):
// runs of consecutive parameters strictly inside the current span go to the SIMD run kernel (sorted
// input: one kernel call per span), other points one by one with the domain policy, the previous
// point's span or a branch-free binary search, and breakpoint snapping.
template <int P, bool R, int K>
void eval_batch(const SpanCache& c, std::span<const double> ts, int order, Vec3* out, Interval dom,
                const EvalOptions& options, bool batch_names, detail::RunKernel run) {
  const std::size_t stride = K >= 0 ? static_cast<std::size_t>(K) + 1 : static_cast<std::size_t>(order) + 1;
  constexpr std::size_t block = (P + 1) * 4;
  // Locals, not members: the stores to `out` could alias a member and force it to be reloaded per point.
  const double* const breaks = c.breaks;
  const double* const mid = c.mid;
  const double* const inv_half = c.inv_half;
  const double* const coef = c.coef;
  const double* const t = ts.data();
  const Side side = options.side;
  const bool strict = options.domain == Domain::Strict;
  const double lo = dom.start, hi = dom.end;
  const std::size_t n = ts.size();
  std::size_t s = 0;
  double probe = 0.0;
  bool check = order > c.unchecked_order;
  // A run is tried after a point that stayed in its span (sorted input); shuffled input seldom does.
  bool try_run = run != nullptr;
  for (std::size_t i = 0; i < n;) {
    if (try_run) {
      const std::size_t done =
          run(coef + s * block, mid[s], inv_half[s], breaks[s], breaks[s + 1], t + i, n - i, &out[i * stride].x);
      if (check) probe += probe_of(out + i * stride, done * stride);
      i += done;
      try_run = false;
      if (i == n) break;
    }
    double u = t[i];
    if (!(strict && u >= lo && u <= hi)) [[unlikely]] {
      u = resolve_parameter(u, dom, options.domain, "t", i, batch_names);
      check = check || !dom.contains(u);  // extrapolation leaves the bounded region
    }
    // The previous point's span (sorted input), else a branch-free binary search.
    const bool same = side == Side::Right ? breaks[s] <= u && u < breaks[s + 1] : breaks[s] < u && u <= breaks[s + 1];
    if (!same) s = locate(c, u, side);
    try_run = run != nullptr && same;
    const double x = (u - mid[s]) * inv_half[s];
    Vec3* o = out + i * stride;
    if constexpr (K >= 0) {
      double r[K + 1][3];
      detail::scalar::eval_piece<P, R, K>(coef + s * block, x, inv_half[s], r);
      for (int k = 0; k <= K; ++k) o[k] = {r[k][0], r[k][1], r[k][2]};
    } else {
      eval_span<P, R>(coef + s * block, x, inv_half[s], order, o);
    }
    if (u == breaks[s] || u == breaks[s + 1]) [[unlikely]]
      snap_exact(c, u == breaks[s] ? s : s + 1, o[0]);
    if (check) probe += probe_of(o, stride);
    ++i;
  }
  if (probe != 0.0) {
    for (std::size_t i = 0; i < n; ++i) check_finite_result(out + i * stride, order, ts[i]);
  }
}

using BatchKernel = void (*)(const SpanCache&, std::span<const double>, int, Vec3*, Interval, const EvalOptions&, bool,
                             detail::RunKernel);

// Kernels with a run-time order for degrees 1 … kCachedDegreeLimit, and with compile-time orders 0 … 3 for
// degrees 2 … 5 (the common cases: quadratic conics, cubic splines, quintic Hermite curves).
template <bool R, int... Ps>
constexpr std::array<BatchKernel, sizeof...(Ps)> make_kernels(std::integer_sequence<int, Ps...>) {
  return {&eval_batch<Ps + 1, R, -1>...};
}
constexpr auto kKernels = make_kernels<false>(std::make_integer_sequence<int, kCachedDegreeLimit>{});
constexpr auto kRationalKernels = make_kernels<true>(std::make_integer_sequence<int, kCachedDegreeLimit>{});

template <bool R, int P>
constexpr std::array<BatchKernel, 4> ordered_kernels() {
  return {&eval_batch<P, R, 0>, &eval_batch<P, R, 1>, &eval_batch<P, R, 2>, &eval_batch<P, R, 3>};
}
constexpr std::array<std::array<BatchKernel, 4>, 4> kOrdered = {
    ordered_kernels<false, 2>(), ordered_kernels<false, 3>(), ordered_kernels<false, 4>(), ordered_kernels<false, 5>()};
constexpr std::array<std::array<BatchKernel, 4>, 4> kRationalOrdered = {
    ordered_kernels<true, 2>(), ordered_kernels<true, 3>(), ordered_kernels<true, 4>(), ordered_kernels<true, 5>()};

inline BatchKernel kernel_for(int degree, bool rational, int order) {
  if (degree >= 2 && degree <= 5 && order <= 3) {
    const auto d = static_cast<std::size_t>(degree - 2);
    const auto k = static_cast<std::size_t>(order);
    return rational ? kRationalOrdered[d][k] : kOrdered[d][k];
  }
  const auto i = static_cast<std::size_t>(degree - 1);
  return rational ? kRationalKernels[i] : kKernels[i];
}

// The exact-point record of a break whose knot run starts at index `start` with multiplicity `m`: with
// m ≥ p the curve there is the pole before the run (P[0] for a clamped start), recorded as {1, x, y, z};
// otherwise {0, 0, 0, 0}. Written by the span cache and by the one-span piece alike.
void write_exact_record(double* out, std::size_t m, std::size_t p, std::span<const Vec3> points, std::size_t start) {
  if (m >= p) {
    const Vec3& q = points[start == 0 ? 0 : start - 1];
    out[0] = 1.0;
    out[1] = q.x;
    out[2] = q.y;
    out[3] = q.z;
  } else {
    std::fill_n(out, 4, 0.0);
  }
}

}  // namespace

const SpanCache& NurbsCurve::Data::publish_cache() const {
  auto fresh = std::make_unique<SpanCache>();
  build_cache(*fresh);
  const SpanCache* expected = nullptr;
  if (cache.compare_exchange_strong(expected, fresh.get(), std::memory_order_acq_rel, std::memory_order_acquire))
    return *fresh.release();
  return *expected;  // another thread published first
}

namespace {
// The Taylor coefficients of the homogeneous piece on span i (U[i] < U[i + 1]) at its midpoint, for a
// compile-time degree P: coef[j * 4 + lane], lanes x, y, z, w.
template <int P>
void taylor_piece(std::span<const double> U, std::span<const Vec3> points, std::span<const double> weights,
                  std::size_t i, double& mid, double& inv_half, double* coef) {
  const double half = 0.5 * (U[i + 1] - U[i]);
  const double m = U[i] + half;
  mid = m;
  inv_half = 1.0 / half;
  double ders[P + 1][P + 1];
  detail::basis_derivatives_fixed<P>(U.data(), i, m, ders);
  const bool rational = !weights.empty();
  double f = 1.0;  // half^k / k!
  for (std::size_t k = 0; k <= static_cast<std::size_t>(P); ++k) {
    if (k > 0) f *= half / static_cast<double>(k);
    double acc[4] = {0, 0, 0, 0};
    for (std::size_t j = 0; j <= static_cast<std::size_t>(P); ++j) {
      // Scale N^(k) ~ half^-k back to O(1) before touching the points, so
      // tiny spans with huge coordinates cannot overflow in between.
      const double N = ders[k][j] * f;
      const std::size_t idx = i - static_cast<std::size_t>(P) + j;
      const double w = rational ? weights[idx] : 1.0;
      acc[0] += N * w * points[idx].x;
      acc[1] += N * w * points[idx].y;
      acc[2] += N * w * points[idx].z;
      acc[3] += N * w;
    }
    for (std::size_t c = 0; c < 4; ++c) coef[k * 4 + c] = acc[c];
  }
}

using TaylorPiece = void (*)(std::span<const double>, std::span<const Vec3>, std::span<const double>, std::size_t,
                             double&, double&, double*);
template <int... Ps>
constexpr std::array<TaylorPiece, sizeof...(Ps)> make_pieces(std::integer_sequence<int, Ps...>) {
  return {&taylor_piece<Ps + 1>...};
}
constexpr auto kTaylorPieces = make_pieces(std::make_integer_sequence<int, kCachedDegreeLimit>{});
}  // namespace

void NurbsCurve::Data::piece(std::size_t i, double& mid, double& inv_half, double* coef) const {
  kTaylorPieces[static_cast<std::size_t>(degree() - 1)](knots.values(), points, weights, i, mid, inv_half, coef);
}

// Bounds for |x| ≤ 1: |A^(k)| ≤ k! scale^k Σ_{j≥k} binom(j, k) |c_j| (lanes x, y, z) and likewise |w^(k)|
// (lane w). Non-rational: no derivative of any order can overflow when every bound < 1e300 (orders above
// p are zero). Rational: w ≥ w_min > 0 on the span (a convex combination of its p + 1 weights), and the
// quotient rule gives |C^(k)| ≤ B_k = (|A^(k)| + Σ_{i=1..k} binom(k, i) |w^(i)| B_{k−i}) / w_min for
// k ≤ p; every partial sum of the evaluator is bounded by B_k, so B_k < 1e300 (far below the overflow
// threshold 1.8e308, which rounding cannot bridge) rules out an overflow up to order p.
bool NurbsCurve::Data::piece_bounded(std::size_t i, double inv_half, const double* coef) const {
  const auto P = static_cast<std::size_t>(degree());
  std::array<double, kCachedDegreeLimit + 1> abound{}, wbound{}, B{};
  double scale_k = 1.0;
  for (std::size_t k = 0; k <= P; ++k) {
    if (k > 0) scale_k *= static_cast<double>(k) * inv_half;
    double bound = 0.0, wb = 0.0;
    double binom = 1.0;  // binom(j, k) for j = k, k+1, ...
    for (std::size_t j = k; j <= P; ++j) {
      if (j > k) binom = binom * static_cast<double>(j) / static_cast<double>(j - k);
      const double* cj = &coef[j * 4];
      bound += binom * std::fmax(std::fabs(cj[0]), std::fmax(std::fabs(cj[1]), std::fabs(cj[2])));
      wb += binom * std::fabs(cj[3]);
    }
    abound[k] = bound * scale_k;
    wbound[k] = wb * scale_k;
    if (!(abound[k] < 1e300)) return false;
  }
  if (!rational()) return true;
  double w_min = HUGE_VAL;
  for (std::size_t j = 0; j <= P; ++j) w_min = std::fmin(w_min, weights[i - P + j]);
  for (std::size_t k = 0; k <= P; ++k) {
    double sum = abound[k];
    double binom = 1.0;
    for (std::size_t r = 1; r <= k; ++r) {
      binom = binom * static_cast<double>(k - r + 1) / static_cast<double>(r);
      sum += binom * wbound[r] * B[k - r];
    }
    B[k] = sum / w_min;
    if (!(B[k] < 1e300)) return false;
  }
  return true;
}

void NurbsCurve::Data::build_cache(SpanCache& out) const {
  const int p = degree();
  const auto P = static_cast<std::size_t>(p);
  const std::span<const double> U = knots.values();
  const std::size_t n = points.size() - 1;
  const double a = U[P], b = U[n + 1];
  // Breakpoints: runs of equal knots with a value in the domain; multiplicity over the whole vector.
  std::size_t S = 0;
  for (std::size_t i = 0; i < U.size(); ++i)
    if (U[i] >= a && U[i] <= b && (i == 0 || U[i] != U[i - 1])) ++S;
  --S;
  const std::size_t block = p > kCachedDegreeLimit ? 0 : (P + 1) * 4;
  out.spans = S;
  out.block = block;
  // Default-initialised (no zero fill of a million-span cache); every element is written below.
  const std::size_t doubles = (S + 1) + 2 * S + S * block + 4 * (S + 1);
  out.store.reset(new double[doubles]);
  advise_huge_pages(out.store.get(), doubles * sizeof(double));
  double* breaks = out.store.get();
  double* mid = breaks + S + 1;
  double* inv_half = mid + S;
  double* coef = inv_half + S;
  double* exact = coef + S * block;
  out.breaks = breaks;
  out.mid = mid;
  out.inv_half = inv_half;
  out.coef = coef;
  out.exact = exact;
  std::size_t bi = 0;
  for (std::size_t i = 0; i < U.size();) {
    std::size_t j = i;
    while (j + 1 < U.size() && U[j + 1] == U[i]) ++j;
    const double u = U[i];
    if (u >= a && u <= b) {
      breaks[bi] = u;
      // The run U[i] = … = U[j] = u has multiplicity m = j − i + 1; with m ≥ p the curve there is P[i − 1]
      // (P[0] for a clamped start, i = 0 with m = p + 1; P[n] for a clamped end, i = n + 1).
      write_exact_record(exact + 4 * bi, j - i + 1, P, points, i);
      ++bi;
    }
    i = j + 1;
  }
  HULA_ASSERT(bi == S + 1, "breakpoint count mismatch");
  build_buckets(out);
  if (p > kCachedDegreeLimit) {  // direct evaluation only
    std::fill(mid, coef, 0.0);   // midpoints and scales unused
    return;
  }
  std::size_t s = 0;
  for (std::size_t i = P; i <= n; ++i) {
    if (!(U[i] < U[i + 1])) continue;
    piece(i, mid[s], inv_half[s], coef + s * block);
    ++s;
  }
  HULA_ASSERT(s == S, "span count mismatch between knots and breakpoints");
  bool bounded = true;
  for (std::size_t sp = 0; sp < S && bounded; ++sp) {
    // The span's first control point index: the span starting at breakpoint sp ends at knot index i + 1.
    const std::size_t i = static_cast<std::size_t>(std::upper_bound(U.begin(), U.end(), breaks[sp]) - U.begin()) - 1;
    bounded = piece_bounded(i, inv_half[sp], coef + sp * block);
  }
  out.unchecked_order = !bounded ? 0 : (rational() ? p : std::numeric_limits<int>::max());
}
void NurbsCurve::Data::eval_direct(double t, int order, Side side, Vec3* out, BasisWorkspace& work) const {
  const int p = degree();
  const auto P = static_cast<std::size_t>(p);
  const std::size_t i = knots.find_span(t, side);
  const int K = std::min(order, p);
  const std::span<const double> ders = basis_derivatives(knots, i, t, K, work);
  // Homogeneous derivatives A^(k), w^(k).
  std::vector<double>& h = work.extra;
  h.assign(static_cast<std::size_t>(K + 1) * 4, 0.0);
  for (std::size_t k = 0; k <= static_cast<std::size_t>(K); ++k) {
    for (std::size_t j = 0; j <= P; ++j) {
      const double N = ders[k * (P + 1) + j];
      const std::size_t idx = i - P + j;
      const double w = rational() ? weights[idx] : 1.0;
      h[k * 4 + 0] += N * w * points[idx].x;
      h[k * 4 + 1] += N * w * points[idx].y;
      h[k * 4 + 2] += N * w * points[idx].z;
      h[k * 4 + 3] += N * w;
    }
  }
  const double w0 = h[3];
  for (int k = 0; k <= order; ++k) {
    const auto uk = static_cast<std::size_t>(k);
    Vec3 v = k <= K ? Vec3{h[uk * 4], h[uk * 4 + 1], h[uk * 4 + 2]} : Vec3{};
    double binom = 1.0;
    for (int r = 1; r <= std::min(k, K); ++r) {
      binom = binom * (k - r + 1) / r;
      v -= (binom * h[static_cast<std::size_t>(r) * 4 + 3]) * out[k - r];
    }
    out[k] = v / w0;
  }
}

NurbsCurve::NurbsCurve(int degree, std::vector<double> knots, std::vector<Vec3> control_points,
                       std::vector<double> weights, int dimension) {
  if (degree < 1 || degree > kMaxDegree)
    throw Error(Errc::InvalidDegree,
                "degree = " + std::to_string(degree) + " must be in [1, " + std::to_string(kMaxDegree) + "]",
                {.field = "degree"});
  if (control_points.size() <= static_cast<std::size_t>(degree))
    throw Error(Errc::InvalidDegree,
                "degree = " + std::to_string(degree) + " must be less than the number of control points (" +
                    std::to_string(control_points.size()) + ")",
                {.field = "degree"});
  const std::size_t expected = control_points.size() + static_cast<std::size_t>(degree) + 1;
  if (knots.size() != expected)
    throw Error(Errc::InvalidKnots,
                std::to_string(knots.size()) + " knots given; degree " + std::to_string(degree) + " with " +
                    std::to_string(control_points.size()) + " control points needs " + std::to_string(expected) +
                    " (full form; the ACIS form has 2 fewer)",
                {.field = "knots"});
  *this = NurbsCurve(KnotVector(std::move(knots), degree), std::move(control_points), std::move(weights), dimension);
}

NurbsCurve::NurbsCurve(KnotVector knots, std::vector<Vec3> control_points, std::vector<double> weights, int dimension) {
  if (control_points.size() <= static_cast<std::size_t>(knots.degree()))
    throw Error(Errc::InvalidDegree,
                "degree = " + std::to_string(knots.degree()) + " must be less than the number of control points (" +
                    std::to_string(control_points.size()) + ")",
                {.field = "degree"});
  validate_points(control_points, weights, dimension, knots.control_point_count());
  auto data = std::make_shared<Data>(std::move(knots), std::move(control_points), std::move(weights), dimension);
  for (const Vec3& p : data->points) data->box.add(p);
  data_ = std::move(data);
}

KnotVector detail::CurveAccess::knots(std::vector<double> values, int degree) {
#if !defined(NDEBUG) || defined(HULA_ENABLE_ASSERTS)
  return KnotVector(std::move(values), degree);  // builds with asserts validate anyway
#else
  return KnotVector(KnotVector::Unchecked{}, std::move(values), degree);
#endif
}

NurbsCurve detail::CurveAccess::curve(KnotVector knots, std::vector<Vec3> control_points, int dimension,
                                      const Box3& control_box) {
#if !defined(NDEBUG) || defined(HULA_ENABLE_ASSERTS)
  // Builds with asserts validate anyway, and check the box.
  NurbsCurve c(std::move(knots), std::move(control_points), {}, dimension);
  HULA_ASSERT(c.control_box().min == control_box.min && c.control_box().max == control_box.max,
              "the control box given does not match the control points");
  return c;
#else
  auto data =
      std::make_shared<NurbsCurve::Data>(std::move(knots), std::move(control_points), std::vector<double>{}, dimension);
  data->box = control_box;
  return NurbsCurve(std::move(data));
#endif
}

int NurbsCurve::degree() const noexcept { return data_->degree(); }
const KnotVector& NurbsCurve::knots() const noexcept { return data_->knots; }
std::span<const Vec3> NurbsCurve::control_points() const noexcept { return data_->points; }
std::span<const double> NurbsCurve::weights() const noexcept { return data_->weights; }
bool NurbsCurve::is_rational() const noexcept { return data_->rational(); }
int NurbsCurve::dimension() const noexcept { return data_->dimension; }
Interval NurbsCurve::domain() const noexcept { return data_->knots.domain(); }
Box3 NurbsCurve::control_box() const noexcept { return data_->box; }
double NurbsCurve::model_size() const noexcept { return data_->box.diagonal(); }

Vec3 NurbsCurve::evaluate(double t, const EvalOptions& options) const {
  Vec3 out;
  derivatives(t, 0, std::span<Vec3>(&out, 1), options);
  return out;
}

std::vector<Vec3> NurbsCurve::derivatives(double t, int order, const EvalOptions& options) const {
  if (order < 0)
    throw Error(Errc::InvalidArgument, "derivative order = " + std::to_string(order) + " must be >= 0",
                {.field = "order"});
  std::vector<Vec3> out(static_cast<std::size_t>(order) + 1);
  derivatives(t, order, out, options);
  return out;
}

void NurbsCurve::derivatives(double t, int order, std::span<Vec3> out, const EvalOptions& options) const {
  if (order < 0)
    throw Error(Errc::InvalidArgument, "derivative order = " + std::to_string(order) + " must be >= 0",
                {.field = "order"});
  if (out.size() < static_cast<std::size_t>(order) + 1)
    throw Error(Errc::InvalidArgument,
                "output holds " + std::to_string(out.size()) + " vectors but order " + std::to_string(order) +
                    " needs " + std::to_string(order + 1),
                {.field = "out"});
  const Data& d = *data_;
  const int p = d.degree();
  const SpanCache& c = d.span_cache();
  if (p > kCachedDegreeLimit) {
    const double u = resolve_parameter(t, domain(), options.domain, "t", 0, false);
    BasisWorkspace& work = thread_workspace();
    d.eval_direct(u, order, options.side, out.data(), work);
    d.snap_direct(c, u, out[0]);
  } else {
    kernel_for(p, d.rational(), order)(c, std::span<const double>(&t, 1), order, out.data(), domain(), options, false,
                                       nullptr);
    return;
  }
  check_finite_result(out.data(), order, t);
}

void NurbsCurve::evaluate(std::span<const double> ts, std::span<Vec3> out, const EvalOptions& options) const {
  derivatives(ts, 0, out, options);
}

void NurbsCurve::derivatives(std::span<const double> ts, int order, std::span<Vec3> out,
                             const EvalOptions& options) const {
  if (order < 0)
    throw Error(Errc::InvalidArgument, "derivative order = " + std::to_string(order) + " must be >= 0",
                {.field = "order"});
  const auto stride = static_cast<std::size_t>(order) + 1;
  if (out.size() < ts.size() * stride)
    throw Error(Errc::InvalidArgument,
                "output holds " + std::to_string(out.size()) + " vectors but " + std::to_string(ts.size()) +
                    " parameters × " + std::to_string(stride) + " derivatives need " +
                    std::to_string(ts.size() * stride),
                {.field = "out"});
  const Data& d = *data_;
  const Interval dom = domain();
  const int p = d.degree();
  const SpanCache& c = d.span_cache();
  if (p > kCachedDegreeLimit) {
    BasisWorkspace& work = thread_workspace();
    for (std::size_t i = 0; i < ts.size(); ++i) {
      const double u = resolve_parameter(ts[i], dom, options.domain, "t", i, true);
      d.eval_direct(u, order, options.side, out.data() + i * stride, work);
      d.snap_direct(c, u, out[i * stride]);
    }
  } else {
    kernel_for(p, d.rational(), order)(c, ts, order, out.data(), dom, options, true,
                                       detail::run_kernel(p, d.rational(), order));
    return;
  }
  for (std::size_t i = 0; i < ts.size(); ++i) check_finite_result(out.data() + i * stride, order, ts[i]);
}

bool operator==(const NurbsCurve& a, const NurbsCurve& b) {
  if (a.data_ == b.data_) return true;
  return a.data_->knots == b.data_->knots && a.data_->points == b.data_->points &&
         a.data_->weights == b.data_->weights && a.data_->dimension == b.data_->dimension;
}

// One span's cache (S = 1): the same breakpoints, exact points, midpoint, scale and coefficients as the
// curve's cache holds for that span, so the kernels give the same doubles from it.
struct PieceEvaluator::State {
  SpanCache cache;
  std::size_t span = 0;  // knot index i of the piece in `cache`; 0 (never a span: i ≥ p ≥ 1) before the first
  bool pieces = false;   // large enough, and of a cached degree
  bool whole = false;    // the piece's exact points and span search are written too (not only its coefficients)
};

PieceEvaluator::PieceEvaluator(const NurbsCurve& curve) : curve_(curve), state_(std::make_unique<State>()) {
  const NurbsCurve::Data& d = *curve.data_;
  const std::size_t p = static_cast<std::size_t>(d.degree());
  state_->pieces = d.degree() <= kCachedDegreeLimit && d.points.size() - p >= kMinSpans;
  if (state_->pieces) {
    SpanCache& c = state_->cache;
    c.spans = 1;
    c.block = (p + 1) * 4;
    const std::size_t doubles = 2 + 2 + c.block + 8;
    c.store.reset(new double[doubles]);
    double* breaks = c.store.get();
    c.breaks = breaks;
    c.mid = breaks + 2;
    c.inv_half = breaks + 3;
    c.coef = breaks + 4;
    c.exact = breaks + 4 + c.block;
  }
}

PieceEvaluator::~PieceEvaluator() = default;

std::size_t PieceEvaluator::load_span(double t, bool whole) {
  const NurbsCurve::Data& d = *curve_.data_;
  State& st = *state_;
  const std::span<const double> U = d.knots.values();
  // The previous piece's span or the next one first (one pass along the curve asks about each span in turn).
  const std::size_t next = st.span + 1;
  const std::size_t i = st.span != 0 && next + 1 < d.points.size() + 1 && U[next] <= t && t < U[next + 1]
                            ? next
                            : d.knots.find_span(t, st.span, Side::Right);
  SpanCache& c = st.cache;
  double* breaks = c.store.get();
  if (i != st.span) {
    // The breakpoints U[i] < U[i + 1] and the piece.
    breaks[0] = U[i];
    breaks[1] = U[i + 1];
    double* mid = breaks + 2;
    double* inv_half = breaks + 3;
    double* coef = breaks + 4;
    d.piece(i, *mid, *inv_half, coef);
    st.span = i;
    st.whole = false;
  }
  if (whole && !st.whole) {
    // The exact points of the breakpoints (build_cache: a run of m ≥ p equal knots starting at index r
    // passes through point r − 1, or point 0 at r = 0) and the span search (speeds() needs neither).
    const auto P = static_cast<std::size_t>(d.degree());
    double* exact = breaks + 4 + c.block;
    std::size_t r0 = i;
    while (r0 > 0 && U[r0 - 1] == U[i]) --r0;
    std::size_t e1 = i + 1;
    while (e1 + 1 < U.size() && U[e1 + 1] == U[i + 1]) ++e1;
    const std::array<std::pair<std::size_t, std::size_t>, 2> runs{{{r0, i - r0 + 1}, {i + 1, e1 - i}}};
    for (std::size_t b = 0; b < 2; ++b) {
      const auto [start, m] = runs[b];
      write_exact_record(exact + 4 * b, m, P, d.points, start);
    }
    // Every derivative is probed for overflow (a cheap sum) instead of bounding the piece first (positions
    // never overflow inside the domain): where the cache's bound rules an overflow out the probe finds
    // none, so the values and errors are the same.
    c.unchecked_order = 0;
    build_buckets(c);
    st.whole = true;
  }
  return i;
}

void PieceEvaluator::derivatives(std::span<const double> ts, int order, std::span<Vec3> out) {
  const NurbsCurve::Data& d = *curve_.data_;
  State& st = *state_;
  const Interval dom = curve_.domain();
  // Through the curve: small curves, a cache already built, anything the curve reports as an error.
  const bool direct = !st.pieces || d.cache.load(std::memory_order_acquire) != nullptr || ts.empty() || order < 0 ||
                      out.size() < ts.size() * (static_cast<std::size_t>(order) + 1) ||
                      !(ts[0] >= dom.start && ts[0] <= dom.end);
  if (direct) {
    curve_.derivatives(ts, order, out);
    return;
  }
  const std::span<const double> U = d.knots.values();
  const std::size_t i = load_span(ts[0], true);
  // Every parameter where the curve's cache would look it up: in [U[i], U[i + 1]), or at the end of the
  // last span.
  const double b0 = U[i], b1 = U[i + 1];
  const bool last = b1 == dom.end;
  for (const double t : ts)
    if (!(b0 <= t && (t < b1 || (last && t == b1)))) {
      curve_.derivatives(ts, order, out);
      return;
    }
  const int p = d.degree();
  kernel_for(p, d.rational(), order)(st.cache, ts, order, out.data(), dom, EvalOptions{}, true,
                                     detail::run_kernel(p, d.rational(), order));
}

void PieceEvaluator::speeds(std::span<const double> ts, std::span<double> out) {
  constexpr std::size_t kBlock = 16;  // a multiple of every kernel's lane count
  constexpr std::size_t kMaxPoints = 64;
  HULA_ASSERT(ts.size() <= kMaxPoints && out.size() >= ts.size(), "speeds: at most 64 parameters, one output each");
  const NurbsCurve::Data& d = *curve_.data_;
  State& st = *state_;
  const Interval dom = curve_.domain();
  const std::size_t n = ts.size();
  const detail::SpeedKernel kernel = n == 0 ? nullptr : detail::speed_kernel(d.degree(), d.rational());
  if (kernel != nullptr && ts[0] >= dom.start && ts[0] <= dom.end) {
    // The piece the values come from: the curve's cache (built already, or a curve of few spans, which
    // derivatives() would build) or this evaluator's own piece of the span.
    const SpanCache* c = nullptr;
    std::size_t s = 0;
    if (!st.pieces || d.cache.load(std::memory_order_acquire) != nullptr) {
      c = &d.span_cache();
      s = locate(*c, ts[0], Side::Right);
    } else {
      load_span(ts[0], false);
      c = &st.cache;
    }
    const double b0 = c->breaks[s], b1 = c->breaks[s + 1];
    bool inside = true;
    for (const double t : ts) inside = inside && b0 < t && t < b1;
    if (inside) {
      // Padded to whole blocks with the last parameter (its speed is computed again and dropped).
      std::array<double, kMaxPoints> padded, speed;
      const std::size_t m = (n + kBlock - 1) / kBlock * kBlock;
      std::copy(ts.begin(), ts.end(), padded.begin());
      std::fill(padded.begin() + static_cast<std::ptrdiff_t>(n), padded.begin() + static_cast<std::ptrdiff_t>(m),
                ts[n - 1]);
      if (kernel(c->coef + s * c->block, c->mid[s], c->inv_half[s], padded.data(), m, speed.data())) {
        std::copy_n(speed.begin(), n, out.begin());
        return;
      }
    }
  }
  // The general way: derivatives() (its errors included) and norm() here, where no multiply-add is fused.
  std::array<Vec3, 2 * kMaxPoints> der;
  derivatives(ts, 1, std::span<Vec3>(der.data(), 2 * n));
  for (std::size_t i = 0; i < n; ++i) out[i] = norm(der[2 * i + 1]);
}

}  // namespace hula::nurbs
