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
};

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

// All derivatives d[k] = f^(k)(x) / k!, k = 0..K, of f(x) = Σ_j a_j x^j (j = 0..p),
// for C components of stride 4: repeated synthetic division (Horner).
template <int C>
inline void taylor_at(const double* a, int p, double x, int K, double* d) {
  for (int k = 0; k <= K; ++k)
    for (int c = 0; c < C; ++c) d[k * 4 + c] = 0.0;
  for (int c = 0; c < C; ++c) d[c] = a[p * 4 + c];
  for (int j = p - 1; j >= 0; --j) {
    const int kmax = std::min(K, p - j);
    for (int k = kmax; k >= 1; --k)
      for (int c = 0; c < C; ++c) d[k * 4 + c] = d[k * 4 + c] * x + d[(k - 1) * 4 + c];
    for (int c = 0; c < C; ++c) d[c] = d[c] * x + a[j * 4 + c];
  }
}

// Evaluates order 0..order of a cached span at local x; scale = inv_half.
inline void eval_span(const double* a, int p, bool rational, double x, double scale, int order, Vec3* out) {
  const int K = std::min(order, p);
  std::array<double, (kCachedDegreeLimit + 1) * 4> d;
  if (!rational) {
    if (K == 0) {
      // Position only: plain Horner.
      double X = a[p * 4], Y = a[p * 4 + 1], Z = a[p * 4 + 2];
      for (int j = p - 1; j >= 0; --j) {
        X = X * x + a[j * 4];
        Y = Y * x + a[j * 4 + 1];
        Z = Z * x + a[j * 4 + 2];
      }
      out[0] = {X, Y, Z};
    } else {
      taylor_at<3>(a, p, x, K, d.data());
      double f = 1.0;  // k! * scale^k
      for (int k = 0; k <= K; ++k) {
        if (k > 0) f *= k * scale;
        out[k] = {d[k * 4] * f, d[k * 4 + 1] * f, d[k * 4 + 2] * f};
      }
    }
    for (int k = K + 1; k <= order; ++k) out[k] = {};
    return;
  }
  taylor_at<4>(a, p, x, K, d.data());
  // Scale to derivatives in t: A^(k) = k! scale^k d_k.
  double f = 1.0;
  for (int k = 0; k <= K; ++k) {
    if (k > 0) f *= k * scale;
    for (int c = 0; c < 4; ++c) d[k * 4 + c] *= f;
  }
  const double w = d[3];
  out[0] = Vec3{d[0], d[1], d[2]} / w;
  for (int k = 1; k <= order; ++k) {
    Vec3 v = k <= K ? Vec3{d[k * 4], d[k * 4 + 1], d[k * 4 + 2]} : Vec3{};
    double binom = 1.0;
    for (int i = 1; i <= std::min(k, K); ++i) {
      binom = binom * (k - i + 1) / i;
      v -= (binom * d[i * 4 + 3]) * out[k - i];
    }
    out[k] = v / w;
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
        const double N = ders[k * (P + 1) + j];
        const std::size_t idx = i - P + j;
        const double w = rational() ? weights[idx] : 1.0;
        acc[0] += N * w * points[idx].x;
        acc[1] += N * w * points[idx].y;
        acc[2] += N * w * points[idx].z;
        acc[3] += N * w;
      }
      for (std::size_t c = 0; c < 4; ++c) cache.coef[(s * (P + 1) + k) * 4 + c] = acc[c] * f;
    }
    ++s;
  }
  HULA_ASSERT(s == S, "span count mismatch between knots and breakpoints");
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
  HULA_ASSERT(out.size() >= static_cast<std::size_t>(order) + 1, "derivative output too small");
  const Data& d = *data_;
  const double u = resolve_parameter(t, domain(), options.domain, "t", 0, false);
  const int p = d.degree();
  const SpanCache& c = d.span_cache();
  if (p > kCachedDegreeLimit) {
    BasisWorkspace work;
    d.eval_direct(u, order, options.side, out.data(), work);
  } else {
    const std::size_t s = locate(c.breaks, u, options.side);
    const double x = (u - c.mid[s]) * c.inv_half[s];
    eval_span(c.coef.data() + s * static_cast<std::size_t>(p + 1) * 4, p, d.rational(), x, c.inv_half[s], order,
              out.data());
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
    BasisWorkspace work;
    for (std::size_t i = 0; i < ts.size(); ++i) {
      const double u = resolve_parameter(ts[i], dom, options.domain, "t", i, true);
      d.eval_direct(u, order, options.side, out.data() + i * stride, work);
    }
  } else {
    const bool rational = d.rational();
    const auto block = static_cast<std::size_t>(p + 1) * 4;
    std::size_t s = 0;
    const bool strict_inside = options.domain == Domain::Strict;
    for (std::size_t i = 0; i < ts.size(); ++i) {
      double u = ts[i];
      if (!(strict_inside && u >= dom.start && u <= dom.end))
        u = resolve_parameter(u, dom, options.domain, "t", i, true);
      s = locate_hinted(c.breaks, u, options.side, s);
      const double x = (u - c.mid[s]) * c.inv_half[s];
      eval_span(c.coef.data() + s * block, p, rational, x, c.inv_half[s], order, out.data() + i * stride);
    }
  }
  if (order > 0) {
    for (std::size_t i = 0; i < ts.size(); ++i) check_finite_result(out.data() + i * stride, order, ts[i]);
  }
}

bool operator==(const NurbsCurve& a, const NurbsCurve& b) {
  if (a.data_ == b.data_) return true;
  return a.data_->knots == b.data_->knots && a.data_->points == b.data_->points &&
         a.data_->weights == b.data_->weights && a.data_->dimension == b.data_->dimension;
}

}  // namespace hula::nurbs
