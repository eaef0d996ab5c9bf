// SPDX-License-Identifier: MIT
// curve::NaturalData resolved by integration: the exact evaluator (frame from
// reconstruct(), κ^(j) and τ^(j) from compiled derivative laws, the derivative
// vectors by the Frenet–Serret recursion of curve::NaturalEvaluator) and the
// verified NURBS fit that stands in for drawing and export.
#include "hula/intrinsic/natural_curve.hpp"

#include <array>
#include <cmath>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/law/convert.hpp"
#include "hula/law/derive.hpp"
#include "hula/law/parser.hpp"
#include "hula/law/tape.hpp"

namespace hula::intrinsic {

namespace {

constexpr int kMaxOrder = curve::NaturalEvaluator::kMaxOrder;

law::Law parse_scalar(const std::string& text, const law::Context& ctx, const std::string& parameter,
                      const char* field) {
  law::ParseOptions options;
  options.parameters = {parameter};
  law::Law l;
  try {
    options.validate();
    l = law::parse(text, ctx, options);
  } catch (const Error& e) {
    ErrorWhere where = e.where();
    where.field = field;
    throw Error(Errc::ParseError, std::string(field) + ": " + e.message(), where);
  }
  if (l.dimension() != 1)
    throw Error(Errc::ParseError,
                std::string(field) + ": must be a scalar law of " + parameter + ", got a " +
                    std::to_string(l.dimension()) + "-vector",
                {.field = field});
  return l;
}

// r, r', …, r^(order) at one point from the frame f and kappa[j] = κ^(j), tau[j] = τ^(j) (j ≤ order − 2):
// r^(k) = a T + b N + c B, the coefficients carried as arrays of their derivatives (the recursion of
// curve::NaturalEvaluator, products by Leibniz' rule).
void frame_derivatives(const FramePoint& f, std::span<const double> kappa, std::span<const double> tau, int order,
                       std::span<Vec3> out) {
  out[0] = f.position;
  if (order == 0) return;
  out[1] = f.tangent;
  std::array<double, kMaxOrder + 1> a{}, b{}, c{}, na{}, nb{}, nc{};
  a[0] = 1.0;  // r' = 1·T; every derivative of the constant 1 is 0
  // binom[j][i] = C(j, i)
  std::array<std::array<double, kMaxOrder + 1>, kMaxOrder + 1> binom{};
  for (int j = 0; j <= order; ++j) {
    binom[j][0] = 1.0;
    for (int i = 1; i <= j; ++i) binom[j][i] = binom[j - 1][i - 1] + (i < j ? binom[j - 1][i] : 0.0);
  }
  // (x·y)^(j) = Σ_i C(j, i) x^(i) y^(j−i)
  auto leibniz = [&](std::span<const double> x, const std::array<double, kMaxOrder + 1>& y, int j) {
    double sum = 0.0;
    for (int i = 0; i <= j; ++i)
      sum += binom[static_cast<std::size_t>(j)][static_cast<std::size_t>(i)] * x[static_cast<std::size_t>(i)] *
             y[static_cast<std::size_t>(j - i)];
    return sum;
  };
  for (int k = 1; k < order; ++k) {
    const int len = order - k;  // derivatives of the coefficients of r^(k+1) still needed: 0 … len − 1
    for (int j = 0; j < len; ++j) {
      const auto u = static_cast<std::size_t>(j);
      na[u] = a[u + 1] - leibniz(kappa, b, j);                       // a' − κ b
      nb[u] = b[u + 1] + leibniz(kappa, a, j) - leibniz(tau, c, j);  // b' + κ a − τ c
      nc[u] = c[u + 1] + leibniz(tau, b, j);                         // c' + τ b
    }
    for (int j = 0; j < len; ++j) {
      const auto u = static_cast<std::size_t>(j);
      a[u] = na[u];
      b[u] = nb[u];
      c[u] = nc[u];
    }
    for (int j = len; j <= order; ++j)
      a[static_cast<std::size_t>(j)] = b[static_cast<std::size_t>(j)] = c[static_cast<std::size_t>(j)] = 0.0;
    out[static_cast<std::size_t>(k + 1)] = a[0] * f.tangent + b[0] * f.normal + c[0] * f.binormal;
  }
}

// The exact evaluator of a natural curve (curve::NaturalEvaluator).
class NaturalCurveEvaluator final : public curve::NaturalEvaluator {
 public:
  NaturalCurveEvaluator(law::Context ctx, law::Law kappa, law::Law tau, std::string parameter, IntrinsicCurve curve)
      : ctx_(std::move(ctx)),
        kappa_(std::move(kappa)),
        tau_(std::move(tau)),
        parameter_(std::move(parameter)),
        curve_(std::move(curve)) {}

  void derivatives(std::span<const double> s, int order, std::span<Vec3> out) const override {
    const auto per = static_cast<std::size_t>(order) + 1;
    if (order < 0 || order > kMaxOrder || out.size() != s.size() * per)
      throw Error(Errc::InvalidArgument, "natural curve derivatives: bad order or output size", {.field = "order"});
    const int m = std::max(order - 1, 0);  // κ^(j), τ^(j) for j ≤ m
    const auto count = static_cast<std::size_t>(m) + 1;
    const law::Tape* tape = order >= 2 ? &laws(m) : nullptr;
    std::array<double, 2 * (kMaxOrder + 1)> values{};
    for (std::size_t i = 0; i < s.size(); ++i) {
      const FramePoint f = curve_.evaluate(s[i]);
      if (tape) {
        const std::span<double> v(values.data(), 2 * count);
        if (!tape->evaluate(std::span<const double>(&s[i], 1), v))
          throw Error(Errc::NumericalFailure,
                      "the curvature or torsion law (or a derivative) is undefined at s = " + format_number(s[i]),
                      {.field = "curvature"});
      }
      frame_derivatives(f, std::span<const double>(values.data(), count),
                        std::span<const double>(values.data() + count, count), order, out.subspan(i * per, per));
    }
  }

  [[nodiscard]] double tolerance() const noexcept override { return curve_.tolerance(); }
  [[nodiscard]] const IntrinsicCurve& curve() const noexcept { return curve_; }

 private:
  // κ, κ', …, κ^(m), τ, …, τ^(m) compiled, made once per m; the lock covers growing the private context.
  const law::Tape& laws(int m) const {
    const std::lock_guard lock(mutex_);
    auto& t = tapes_[static_cast<std::size_t>(m)];
    if (!t) {
      std::vector<law::Law> outs = law::derivatives(kappa_, parameter_, m);
      const std::vector<law::Law> taus = law::derivatives(tau_, parameter_, m);
      outs.insert(outs.end(), taus.begin(), taus.end());
      const std::string in[1] = {parameter_};
      t = std::make_shared<const law::Tape>(law::Tape::compile(outs, in));
    }
    return *t;
  }

  law::Context ctx_;
  law::Law kappa_, tau_;
  std::string parameter_;
  IntrinsicCurve curve_;
  mutable std::mutex mutex_;
  mutable std::array<std::shared_ptr<const law::Tape>, kMaxOrder + 1> tapes_;
};

}  // namespace

curve::Curve natural_curve(const curve::NaturalData& data, double tolerance) {
  if (!(tolerance >= 1e-9 && tolerance <= 0.1))
    throw Error(Errc::InvalidArgument, "tolerance = " + format_number(tolerance) + " is outside [1e-9, 0.1]",
                {.field = "tolerance"});
  if (!(data.tolerance >= 1e-13 && data.tolerance <= 1e-2))
    throw Error(Errc::InvalidArgument,
                "tolerance = " + format_number(data.tolerance) +
                    " (the integration's position tolerance) is outside [1e-13, 0.01]",
                {.field = "tolerance"});
  // The laws live in a context private to this curve (docs/architecture.md).
  const law::Context ctx;
  const law::Law kappa = parse_scalar(data.curvature, ctx, data.parameter, "curvature");
  const law::Law tau = parse_scalar(data.torsion, ctx, data.parameter, "torsion");
  ReconstructionOptions ro;
  ro.tolerance = data.tolerance;
  IntrinsicCurve r = reconstruct(kappa, tau, data.parameter, data.length,
                                 StartFrame{data.start_point, data.start_tangent, data.start_normal}, ro);
  NurbsFitOptions fo;
  fo.tolerance = tolerance;
  NurbsFitResult fit = fit_nurbs(r, fo);
  if (!fit.converged)
    throw Error(Errc::NumericalFailure,
                "tolerance = " + format_number(tolerance) + " not met by the NURBS fit of the natural curve within " +
                    std::to_string(fo.max_segments) + " segments (reached " + format_number(fit.max_deviation) + ")",
                {.field = "tolerance"});
  auto exact = std::make_shared<const NaturalCurveEvaluator>(ctx, kappa, tau, data.parameter, std::move(r));
  return curve::Curve::natural(curve::NaturalKey{}, data, std::move(exact), std::move(fit.curve), fit.max_deviation);
}

const IntrinsicCurve* intrinsic_of(const curve::Curve& curve) noexcept {
  const auto* e = dynamic_cast<const NaturalCurveEvaluator*>(curve.natural_evaluator());
  return e ? &e->curve() : nullptr;
}

CurveToNurbsResult to_nurbs(const curve::Curve& curve, double tolerance) {
  if (!(tolerance > 0.0 && tolerance <= 1.0))
    throw Error(Errc::InvalidArgument, "tolerance = " + format_number(tolerance) + " is outside (0, 1]",
                {.field = "tolerance"});
  if (const IntrinsicCurve* r = intrinsic_of(curve)) {
    if (tolerance < r->tolerance())
      throw Error(Errc::InvalidArgument,
                  "tolerance = " + format_number(tolerance) + " is below the curve's integration tolerance " +
                      format_number(r->tolerance()) + ": the NURBS cannot be closer to the curve than its positions",
                  {.field = "tolerance"});
    NurbsFitOptions fo;
    fo.tolerance = tolerance;
    NurbsFitResult fit = fit_nurbs_converged(*r, fo);
    return {std::move(fit.curve), fit.max_deviation, fit.tolerance};
  }
  if (const law::Law* l = curve.law()) {
    law::ToNurbsOptions o;
    o.tolerance = tolerance;
    law::ToNurbsResult n = law::to_nurbs(*l, curve.law_parameter(), curve.domain().start, curve.domain().end, o);
    return {std::move(n.curve), n.max_deviation, tolerance};
  }
  return {curve.nurbs(), 0.0, tolerance};
}

}  // namespace hula::intrinsic
