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
#include <cmath>
#include <mutex>
#include <string>
#include <utility>

#include "hula/core/error.hpp"
#include "hula/nurbs/basis.hpp"

namespace hula::nurbs {

namespace {

// Per-span Taylor coefficients of the homogeneous curve: span s, power j,
// component c (x, y, z, w) at coef[(s * (p + 1) + j) * 4 + c].
struct SpanCache {
  std::vector<double> breaks;    // S + 1 strictly increasing breakpoints
  std::vector<double> mid;       // S span midpoints
  std::vector<double> inv_half;  // S values 2 / (b[s+1] - b[s])
  std::vector<double> coef;
  // True when no derivative of a non-rational curve can overflow inside the
  // domain (bounded at build time), so the evaluators skip the finiteness probe.
  bool derivatives_bounded = false;
  // Exact ends: at a breakpoint of multiplicity ≥ p (the clamped ends, C0
  // joins) one basis function is 1 and the curve passes through a control point. exact[b] = 1
  // marks breaks[b] as such a point and exact_point[b] holds that control point, returned as is
  // instead of the rounded sum of the span polynomial.
  std::vector<std::uint8_t> exact;
  std::vector<Vec3> exact_point;
};

// Replaces a position computed at breakpoint b by its exact control point, when it has one.
inline void snap_exact(const SpanCache& c, std::size_t b, Vec3& position) {
  if (c.exact[b] != 0) position = c.exact_point[b];
}

std::string where_t(const char* name, double t) { return std::string(name) + " = " + format_number(t); }

}  // namespace

struct NurbsCurve::Data {
  KnotVector knots;
  std::vector<Vec3> points;
  std::vector<double> weights;
  int dimension;
  Box3 box;
  mutable std::once_flag once;
  mutable SpanCache cache;

  Data(KnotVector k, std::vector<Vec3> p, std::vector<double> w, int dim)
      : knots(std::move(k)), points(std::move(p)), weights(std::move(w)), dimension(dim) {}

  [[nodiscard]] bool rational() const { return !weights.empty(); }
  [[nodiscard]] int degree() const { return knots.degree(); }
  [[nodiscard]] const SpanCache& span_cache() const {
    std::call_once(once, [this] { build_cache(); });
    return cache;
  }
  void build_cache() const;
  void eval_direct(double t, int order, Side side, Vec3* out, BasisWorkspace& work) const;
  // snap_exact for the direct path (binary search over the breakpoints).
  void snap_direct(double u, Vec3& position) const {
    const auto& b = cache.breaks;
    const auto it = std::lower_bound(b.begin(), b.end(), u);
    if (it != b.end() && *it == u) snap_exact(cache, static_cast<std::size_t>(it - b.begin()), position);
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

// Derivatives 0..order at local x of a cached span with compile-time degree P
// (R: rational). d[k] = f^(k)(x) / k! by repeated synthetic division (Horner),
// then f^(k)(t) = k! scale^k d[k] with scale = 1 / half, then eq. 4.8 for R.
template <int P, bool R>
inline void eval_span(const double* a, double x, double scale, int order, Vec3* out) {
  constexpr int C = R ? 4 : 3;
  if (order == 0) {
    double acc[C];
    for (int c = 0; c < C; ++c) acc[c] = a[P * 4 + c];
    for (int j = P - 1; j >= 0; --j)
      for (int c = 0; c < C; ++c) acc[c] = acc[c] * x + a[j * 4 + c];
    if constexpr (R) {
      const double inv = 1.0 / acc[3];
      out[0] = {acc[0] * inv, acc[1] * inv, acc[2] * inv};
    } else {
      out[0] = {acc[0], acc[1], acc[2]};
    }
    return;
  }
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

// Span index s in [0, S) of t among breakpoints b[0..S] (exact comparisons).
inline std::size_t locate(const std::vector<double>& b, double t, Side side) {
  const std::size_t S = b.size() - 1;
  std::size_t s;
  if (side == Side::Right)
    s = static_cast<std::size_t>(std::upper_bound(b.begin(), b.end(), t) - b.begin());
  else
    s = static_cast<std::size_t>(std::lower_bound(b.begin(), b.end(), t) - b.begin());
  s = s == 0 ? 0 : s - 1;
  return std::min(s, S - 1);
}

inline std::size_t locate_hinted(const std::vector<double>& b, double t, Side side, std::size_t hint) {
  const std::size_t S = b.size() - 1;
  if (side == Side::Right) {
    if (b[hint] <= t && t < b[hint + 1]) return hint;
    if (hint + 1 < S && b[hint + 1] <= t && t < b[hint + 2]) return hint + 1;
  } else {
    if (b[hint] < t && t <= b[hint + 1]) return hint;
    if (hint + 1 < S && b[hint + 1] < t && t <= b[hint + 2]) return hint + 1;
  }
  return locate(b, t, side);
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

// The evaluation loop for one compile-time degree: hinted span search (O(1)
// for sorted parameters), domain policy, one eval_span per parameter.
template <int P, bool R>
void eval_batch(const SpanCache& c, std::span<const double> ts, int order, Vec3* out, Interval dom,
                const EvalOptions& options, bool batch_names) {
  const auto stride = static_cast<std::size_t>(order) + 1;
  constexpr std::size_t block = (P + 1) * 4;
  const bool strict = options.domain == Domain::Strict;
  std::size_t s = 0;
  // (v - v) is 0 for finite v and NaN otherwise: one cheap probe for the
  // whole batch instead of a branch per value; the slow pass names the culprit.
  double probe = 0.0;
  // Positions inside the domain are convex combinations of the control points: never overflow.
  bool check = order > 0 && (R || !c.derivatives_bounded);
  for (std::size_t i = 0; i < ts.size(); ++i) {
    double u = ts[i];
    if (!(strict && u >= dom.start && u <= dom.end)) {
      u = resolve_parameter(u, dom, options.domain, "t", i, batch_names);
      check = check || !dom.contains(u);  // extrapolation leaves the bounded region
    }
    s = locate_hinted(c.breaks, u, options.side, s);
    const double x = (u - c.mid[s]) * c.inv_half[s];
    Vec3* o = out + i * stride;
    eval_span<P, R>(c.coef.data() + s * block, x, c.inv_half[s], order, o);
    if (u == c.breaks[s]) snap_exact(c, s, o[0]);
    if (u == c.breaks[s + 1]) snap_exact(c, s + 1, o[0]);
    if (check)
      for (std::size_t k = 0; k < stride; ++k) probe += (o[k].x - o[k].x) + (o[k].y - o[k].y) + (o[k].z - o[k].z);
  }
  if (probe != 0.0) {
    for (std::size_t i = 0; i < ts.size(); ++i) check_finite_result(out + i * stride, order, ts[i]);
  }
}

using BatchKernel = void (*)(const SpanCache&, std::span<const double>, int, Vec3*, Interval, const EvalOptions&, bool);

template <bool R, int... Ps>
constexpr std::array<BatchKernel, sizeof...(Ps)> make_kernels(std::integer_sequence<int, Ps...>) {
  return {&eval_batch<Ps + 1, R>...};
}
constexpr auto kKernels = make_kernels<false>(std::make_integer_sequence<int, kCachedDegreeLimit>{});
constexpr auto kRationalKernels = make_kernels<true>(std::make_integer_sequence<int, kCachedDegreeLimit>{});

inline BatchKernel kernel_for(int degree, bool rational) {
  const auto i = static_cast<std::size_t>(degree - 1);
  return rational ? kRationalKernels[i] : kKernels[i];
}
}  // namespace

namespace {
// Scratch of the direct (high-degree) evaluator: one per thread, so it is
// allocation-free once warm and safe under concurrent const use.
BasisWorkspace& direct_workspace() {
  thread_local BasisWorkspace work;
  return work;
}
}  // namespace

void NurbsCurve::Data::build_cache() const {
  const int p = degree();
  const auto P = static_cast<std::size_t>(p);
  const std::span<const double> U = knots.values();
  const std::size_t n = points.size() - 1;
  cache.breaks = knots.breakpoints();
  const std::size_t S = cache.breaks.size() - 1;
  cache.mid.resize(S);
  cache.inv_half.resize(S);
  cache.exact.assign(S + 1, 0);
  cache.exact_point.assign(S + 1, Vec3{});
  for (std::size_t b = 0; b <= S; ++b) {
    // The run U[k] = … = U[k+m−1] = breaks[b]; with m ≥ p the curve there is P[k−1] (P[0] for a
    // clamped start, k = 0 with m = p + 1; P[n] for a clamped end, k = n + 1).
    const double u = cache.breaks[b];
    const auto first = std::lower_bound(U.begin(), U.end(), u);
    const auto k = static_cast<std::size_t>(first - U.begin());
    const auto m = static_cast<std::size_t>(std::upper_bound(first, U.end(), u) - first);
    if (m < P) continue;
    cache.exact[b] = 1;
    cache.exact_point[b] = points[k == 0 ? 0 : k - 1];
  }
  if (p > kCachedDegreeLimit) return;  // direct evaluation only
  cache.coef.assign(S * (P + 1) * 4, 0.0);
  BasisWorkspace work;
  std::size_t s = 0;
  for (std::size_t i = P; i <= n; ++i) {
    if (!(U[i] < U[i + 1])) continue;
    const double half = 0.5 * (U[i + 1] - U[i]);
    const double mid = U[i] + half;
    cache.mid[s] = mid;
    cache.inv_half[s] = 1.0 / half;
    const std::span<const double> ders = basis_derivatives(knots, i, mid, p, work);
    double f = 1.0;  // half^k / k!
    for (std::size_t k = 0; k <= P; ++k) {
      if (k > 0) f *= half / static_cast<double>(k);
      double acc[4] = {0, 0, 0, 0};
      for (std::size_t j = 0; j <= P; ++j) {
        // Scale N^(k) ~ half^-k back to O(1) before touching the points, so
        // tiny spans with huge coordinates cannot overflow in between.
        const double N = ders[k * (P + 1) + j] * f;
        const std::size_t idx = i - P + j;
        const double w = rational() ? weights[idx] : 1.0;
        acc[0] += N * w * points[idx].x;
        acc[1] += N * w * points[idx].y;
        acc[2] += N * w * points[idx].z;
        acc[3] += N * w;
      }
      for (std::size_t c = 0; c < 4; ++c) cache.coef[(s * (P + 1) + k) * 4 + c] = acc[c];
    }
    ++s;
  }
  HULA_ASSERT(s == S, "span count mismatch between knots and breakpoints");
  // Bound |C^(k)(t)| ≤ k! scale^k Σ_{j≥k} binom(j, k) |c_j| for |x| ≤ 1 (non-rational only).
  cache.derivatives_bounded = !rational();
  for (std::size_t sp = 0; sp < S && cache.derivatives_bounded; ++sp) {
    double scale_k = 1.0;
    for (std::size_t k = 0; k <= P; ++k) {
      if (k > 0) scale_k *= static_cast<double>(k) * cache.inv_half[sp];
      double bound = 0.0;
      double binom = 1.0;  // binom(j, k) for j = k, k+1, ...
      for (std::size_t j = k; j <= P; ++j) {
        if (j > k) binom = binom * static_cast<double>(j) / static_cast<double>(j - k);
        const double* cj = &cache.coef[(sp * (P + 1) + j) * 4];
        bound += binom * std::fmax(std::fabs(cj[0]), std::fmax(std::fabs(cj[1]), std::fabs(cj[2])));
      }
      if (!(bound * scale_k < 1e300)) cache.derivatives_bounded = false;
    }
  }
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
    BasisWorkspace& work = direct_workspace();
    d.eval_direct(u, order, options.side, out.data(), work);
    d.snap_direct(u, out[0]);
  } else {
    kernel_for(p, d.rational())(c, std::span<const double>(&t, 1), order, out.data(), domain(), options, false);
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
    BasisWorkspace& work = direct_workspace();
    for (std::size_t i = 0; i < ts.size(); ++i) {
      const double u = resolve_parameter(ts[i], dom, options.domain, "t", i, true);
      d.eval_direct(u, order, options.side, out.data() + i * stride, work);
      d.snap_direct(u, out[i * stride]);
    }
  } else {
    kernel_for(p, d.rational())(c, ts, order, out.data(), dom, options, true);
    return;
  }
  for (std::size_t i = 0; i < ts.size(); ++i) check_finite_result(out.data() + i * stride, order, ts[i]);
}

bool operator==(const NurbsCurve& a, const NurbsCurve& b) {
  if (a.data_ == b.data_) return true;
  return a.data_->knots == b.data_->knots && a.data_->points == b.data_->points &&
         a.data_->weights == b.data_->weights && a.data_->dimension == b.data_->dimension;
}

}  // namespace hula::nurbs
