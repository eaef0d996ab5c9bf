// SPDX-License-Identifier: MIT
// The curve value type (curve.hpp): factories that validate and resolve each
// kind of construction data, and evaluation that prefers the exact law.
#include "hula/curve/curve.hpp"

#include <algorithm>
#include <array>
#include <bit>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <optional>
#include <utility>

#include "hula/core/error.hpp"
#include "hula/law/convert.hpp"
#include "hula/law/derive.hpp"
#include "hula/law/integrate.hpp"
#include "hula/law/parser.hpp"
#include "hula/law/tape.hpp"
#include "hula/nurbs/arc_length.hpp"
#include "hula/nurbs/bezier.hpp"

namespace hula::curve {

namespace {
// Highest derivative order of a compiled law evaluator (law::CurveEvaluator's limit).
constexpr int kMaxLawOrder = 16;
}  // namespace

struct Curve::State {
  Data data;
  nurbs::NurbsCurve curve;
  double deviation = 0.0;
  // The exact evaluation of a natural curve.
  std::shared_ptr<const NaturalEvaluator> natural;
  // Compiled evaluators of the exact law, one per derivative order, made on first use. The mutex
  // serialises their compilation, which grows the law's (private) context.
  mutable std::mutex mutex;
  mutable std::array<std::shared_ptr<const law::CurveEvaluator>, kMaxLawOrder + 1> evaluators;
  // |C'(t)| as a law, made on first use of the arc length.
  mutable law::Law speed;

  State(Data d, nurbs::NurbsCurve c, double dev) : data(std::move(d)), curve(std::move(c)), deviation(dev) {}

  [[nodiscard]] std::shared_ptr<const law::CurveEvaluator> evaluator(int order) const {
    const auto& l = std::get<LawData>(data);
    const std::lock_guard lock(mutex);
    auto& e = evaluators[static_cast<std::size_t>(order)];
    if (!e) e = std::make_shared<const law::CurveEvaluator>(l.law, l.parameter, order);
    return e;
  }

  // ∫_a^b |C'| of the law; the lock covers building the speed law and compiling its integrand.
  [[nodiscard]] double law_length(double a, double b) const {
    const auto& l = std::get<LawData>(data);
    const std::lock_guard lock(mutex);
    if (!speed.valid()) speed = law::norm(law::derivative(l.law, l.parameter));
    return law::integrate(speed, l.parameter, a, b).value;
  }
};

std::string_view kind_name(Kind kind) noexcept {
  switch (kind) {
    case Kind::Nurbs:
      return "nurbs";
    case Kind::Bezier:
      return "bezier";
    case Kind::Interpolated:
      return "interpolated";
    case Kind::Hermite:
      return "hermite";
    case Kind::Law:
      return "law";
    case Kind::Natural:
      return "natural";
  }
  return "nurbs";
}

nurbs::InterpolationOptions InterpolatedData::options() const {
  nurbs::InterpolationOptions o;
  o.parameterisation = parameterisation;
  o.parameters = parameters;
  o.start = start;
  o.end = end;
  o.dimension = dimension;
  return o;
}

Curve::Curve(std::shared_ptr<const State> state) : state_(std::move(state)) {}

Curve::Curve(nurbs::NurbsCurve curve) {
  nurbs::NurbsCurve copy = curve;
  state_ = std::make_shared<const State>(NurbsData{std::move(copy)}, std::move(curve), 0.0);
}

Curve Curve::bezier(BezierData data) {
  const std::size_t n = data.control_points.size();
  if (n < 2)
    throw Error(Errc::TooFewPoints,
                "control_points has " + std::to_string(n) + " point(s); a Bézier curve needs at least 2",
                {.field = "control_points"});
  if (n - 1 > static_cast<std::size_t>(nurbs::kMaxDegree))
    throw Error(Errc::InvalidDegree,
                "control_points has " + std::to_string(n) + " points: degree " + std::to_string(n - 1) +
                    " exceeds the largest supported degree " + std::to_string(nurbs::kMaxDegree),
                {.field = "control_points"});
  nurbs::NurbsCurve c = nurbs::make_bezier(data.control_points, data.weights, data.dimension);
  return Curve(std::make_shared<const State>(std::move(data), std::move(c), 0.0));
}

Curve Curve::interpolated(InterpolatedData data) {
  nurbs::NurbsCurve c = nurbs::interpolate_cubic(data.points, data.options());
  return Curve(std::make_shared<const State>(std::move(data), std::move(c), 0.0));
}

Curve Curve::hermite(HermiteData data) {
  auto rename = [](const Error& e) {
    // The kernel calls the first derivatives "derivatives"; the data call them "tangents".
    if (e.where().field != "derivatives") throw;
    std::string message = e.message();
    for (std::size_t at = message.find("derivatives"); at != std::string::npos;
         at = message.find("derivatives", at + 8)) {
      if (at >= 7 && message.compare(at - 7, 7, "second_") == 0) continue;
      message.replace(at, 11, "tangents");
    }
    ErrorWhere where = e.where();
    where.field = "tangents";
    throw Error(e.code(), message, where);
  };
  try {
    nurbs::NurbsCurve c = data.second_derivatives.empty()
                              ? nurbs::hermite_cubic(data.points, data.tangents, data.parameters, data.dimension)
                              : nurbs::hermite_quintic(data.points, data.tangents, data.second_derivatives,
                                                       data.parameters, data.dimension);
    return Curve(std::make_shared<const State>(std::move(data), std::move(c), 0.0));
  } catch (const Error& e) {
    rename(e);
    throw;
  }
}

Curve Curve::from_law(std::string expression, std::string parameter, Interval domain, double tolerance) {
  if (!(std::isfinite(domain.start) && std::isfinite(domain.end) && domain.start < domain.end))
    throw Error(Errc::InvalidArgument,
                "domain must be [start, end] with finite start < end, got [" + format_number(domain.start) + ", " +
                    format_number(domain.end) + "]",
                {.field = "domain"});
  if (!(tolerance > 0.0 && std::isfinite(tolerance)))
    throw Error(Errc::InvalidArgument, "tolerance = " + format_number(tolerance) + " must be positive and finite",
                {.field = "tolerance"});
  LawData data{std::move(expression), std::move(parameter), domain, {}};
  law::ParseOptions options;
  options.parameters = {data.parameter};
  // One private context per law curve (docs/architecture.md): nothing else grows it.
  const law::Context ctx;
  try {
    options.validate();
    data.law = law::parse(data.expression, ctx, options);
  } catch (const Error& e) {
    ErrorWhere where = e.where();
    where.field = "expression";
    throw Error(Errc::ParseError, "expression: " + e.message(), where);
  }
  if (data.law.dimension() == 1)
    throw Error(Errc::ParseError, "expression: a law curve must be a 2- or 3-vector (vec(x, y[, z])), got a scalar",
                {.field = "expression"});
  law::ToNurbsOptions to;
  to.tolerance = tolerance;
  law::ToNurbsResult approx = [&] {
    try {
      return law::to_nurbs(data.law, data.parameter, domain.start, domain.end, to);
    } catch (const Error& e) {
      // A law undefined inside its own domain is bad input, not a numerical failure.
      if (e.code() != Errc::NumericalFailure || e.message().find("undefined") == std::string::npos) throw;
      throw Error(Errc::InvalidArgument,
                  "domain: " + e.message() + " (inside the domain [" + format_number(domain.start) + ", " +
                      format_number(domain.end) + "])",
                  {.field = "domain"});
    }
  }();
  return Curve(std::make_shared<const State>(std::move(data), std::move(approx.curve), approx.max_deviation));
}

Curve Curve::natural(NaturalKey /*key*/, NaturalData data, std::shared_ptr<const NaturalEvaluator> exact,
                     nurbs::NurbsCurve fit, double deviation) {
  auto state = std::make_shared<State>(std::move(data), std::move(fit), deviation);
  state->natural = std::move(exact);
  return Curve(std::move(state));
}

Kind Curve::kind() const noexcept { return static_cast<Kind>(state_->data.index()); }
std::string_view Curve::kind_name() const noexcept { return curve::kind_name(kind()); }
const Data& Curve::data() const noexcept { return state_->data; }
const nurbs::NurbsCurve& Curve::nurbs() const noexcept { return state_->curve; }
double Curve::approximation_deviation() const noexcept { return state_->deviation; }

const law::Law* Curve::law() const noexcept {
  const auto* l = std::get_if<LawData>(&state_->data);
  return l ? &l->law : nullptr;
}

const std::string& Curve::law_parameter() const noexcept {
  static const std::string kNone;
  const auto* l = std::get_if<LawData>(&state_->data);
  return l ? l->parameter : kNone;
}

const NaturalEvaluator* Curve::natural_evaluator() const noexcept { return state_->natural.get(); }

bool Curve::has_exact_evaluation() const noexcept { return law() != nullptr || state_->natural != nullptr; }

Interval Curve::domain() const noexcept {
  if (const auto* l = std::get_if<LawData>(&state_->data)) return l->domain;
  if (const auto* n = std::get_if<NaturalData>(&state_->data)) return {0.0, n->length};
  return state_->curve.domain();
}

int Curve::dimension() const noexcept { return state_->curve.dimension(); }

Vec3 Curve::point(double t, const nurbs::EvalOptions& options) const { return derivatives(t, 0, options)[0]; }

std::vector<Vec3> Curve::derivatives(double t, int order, const nurbs::EvalOptions& options) const {
  if (!has_exact_evaluation()) return state_->curve.derivatives(t, order, options);
  std::vector<Vec3> out(static_cast<std::size_t>(order < 0 ? 0 : order) + 1);
  const std::array<double, 1> ts{t};
  try {
    derivatives(ts, order, out, options);
  } catch (const Error& e) {
    // Single-parameter form: name "t", not "t[0]".
    if (e.code() != Errc::OutOfDomain) throw;
    const Interval d = domain();
    throw Error(Errc::OutOfDomain,
                "t = " + format_number(t) + " is outside the curve domain [" + format_number(d.start) + ", " +
                    format_number(d.end) + "]" +
                    (state_->natural && options.domain == nurbs::Domain::Extrapolate
                         ? " (a natural curve is integrated on its domain only and is not extrapolated)"
                         : ""),
                {.field = "t"});
  }
  return out;
}

void Curve::derivatives(std::span<const double> ts, int order, std::span<Vec3> out,
                        const nurbs::EvalOptions& options) const {
  if (!has_exact_evaluation()) {
    state_->curve.derivatives(ts, order, out, options);
    return;
  }
  const bool natural = state_->natural != nullptr;
  if (order < 0 || order > kMaxLawOrder)
    throw Error(Errc::InvalidArgument,
                "order = " + std::to_string(order) + " is outside [0, " + std::to_string(kMaxLawOrder) + "] for a " +
                    (natural ? "natural" : "law") + " curve",
                {.field = "order"});
  const auto per_t = static_cast<std::size_t>(order) + 1;
  if (out.size() != ts.size() * per_t)
    throw Error(Errc::InvalidArgument,
                "out has " + std::to_string(out.size()) + " vectors, expected " + std::to_string(ts.size() * per_t),
                {.field = "out"});
  const Interval d = domain();
  std::vector<double> us(ts.begin(), ts.end());
  for (std::size_t i = 0; i < us.size(); ++i) {
    // A natural curve is integrated on [0, L] only: it cannot be extrapolated.
    if (d.contains(us[i]) || (options.domain == nurbs::Domain::Extrapolate && !natural)) continue;
    if (options.domain == nurbs::Domain::Clamp && !std::isnan(us[i])) {
      us[i] = std::clamp(us[i], d.start, d.end);
      continue;
    }
    throw Error(Errc::OutOfDomain,
                "t[" + std::to_string(i) + "] = " + format_number(us[i]) + " is outside the curve domain [" +
                    format_number(d.start) + ", " + format_number(d.end) + "]" +
                    (natural && options.domain == nurbs::Domain::Extrapolate
                         ? " (a natural curve is integrated on its domain only and is not extrapolated)"
                         : ""),
                {.field = "t", .index = i});
  }
  if (natural)
    state_->natural->derivatives(us, order, out);
  else
    state_->evaluator(order)->derivatives(us, out);
}

std::shared_ptr<const law::CurveEvaluator> Curve::law_evaluator(int order) const {
  if (order < 0 || order > kMaxLawOrder)
    throw Error(
        Errc::InvalidArgument,
        "order = " + std::to_string(order) + " is outside [0, " + std::to_string(kMaxLawOrder) + "] for a law curve",
        {.field = "order"});
  return law() ? state_->evaluator(order) : nullptr;
}

double Curve::length_to(double t) const {
  const Interval d = domain();
  if (!d.contains(t))
    throw Error(Errc::OutOfDomain,
                "t = " + format_number(t) + " is outside the curve domain [" + format_number(d.start) + ", " +
                    format_number(d.end) + "]",
                {.field = "t"});
  if (t == d.start) return 0.0;
  if (state_->natural) return t - d.start;  // parameterised by arc length
  if (!law()) return nurbs::arc_length(state_->curve, d.start, t);
  return state_->law_length(d.start, t);
}

double Curve::length() const { return length_to(domain().end); }

double Curve::parameter_at_length(double s) const {
  if (state_->natural) {
    const Interval d = domain();
    if (!(s >= 0.0 && s <= d.length()))
      throw Error(Errc::OutOfDomain, "s = " + format_number(s) + " is outside [0, " + format_number(d.length()) + "]",
                  {.field = "s"});
    return d.start + s;
  }
  if (!law()) return nurbs::parameter_at_length(state_->curve, s);
  const Interval d = domain();
  const double total = length();
  if (!(s >= 0.0 && s <= total))
    throw Error(Errc::OutOfDomain, "s = " + format_number(s) + " is outside [0, " + format_number(total) + "]",
                {.field = "s"});
  // Newton on L(t) − s with |C'(t)| as the derivative, kept inside the bracket [lo, hi] by Boost.Math's
  // newton_raphson_iterate (bisection when a step leaves it); the stand-in NURBS, parameterised like the
  // law, gives the start where s is also a parameter value of it. Converged when the Newton step is at
  // most 1e-15 (1 + |t|), reported to Boost as a zero residual (its own test, relative to |t|, never
  // passes at t = 0).
  const double guess = state_->curve.domain().contains(s) ? nurbs::parameter_at_length(state_->curve, s) : d.start;
  const auto speed_of = law_evaluator(1);
  std::array<Vec3, 2> der;
  auto residual = [&](double t) {
    const double f = length_to(t) - s;
    speed_of->derivatives(t, der);
    const double v = norm(der[1]);
    return std::pair{v > 0 && std::fabs(f) <= 1e-15 * (1.0 + std::fabs(t)) * v ? 0.0 : f, v};
  };
  std::uintmax_t iterations = 60;
  try {
    return boost::math::tools::newton_raphson_iterate(residual, guess, d.start, d.end,
                                                      std::numeric_limits<double>::digits, iterations);
  } catch (const boost::math::evaluation_error&) {
    throw Error(Errc::NumericalFailure, "parameter_at_length: no convergence for s = " + format_number(s),
                {.field = "s"});
  }
}

namespace {
bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }
bool same_bits(const Vec3& a, const Vec3& b) {
  return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z);
}
template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!same_bits(a[i], b[i])) return false;
  return true;
}
bool same_bits(const nurbs::EndCondition& a, const nurbs::EndCondition& b) {
  return a.kind == b.kind && same_bits(a.derivative, b.derivative);
}

bool same_data(const NurbsData& a, const NurbsData& b) { return a.curve == b.curve; }
bool same_data(const BezierData& a, const BezierData& b) {
  return a.dimension == b.dimension && same_bits(a.control_points, b.control_points) && same_bits(a.weights, b.weights);
}
bool same_data(const InterpolatedData& a, const InterpolatedData& b) {
  return a.dimension == b.dimension && a.parameterisation == b.parameterisation && same_bits(a.points, b.points) &&
         same_bits(a.parameters, b.parameters) && same_bits(a.start, b.start) && same_bits(a.end, b.end);
}
bool same_data(const HermiteData& a, const HermiteData& b) {
  return a.dimension == b.dimension && same_bits(a.points, b.points) && same_bits(a.tangents, b.tangents) &&
         same_bits(a.second_derivatives, b.second_derivatives) && same_bits(a.parameters, b.parameters);
}
bool same_data(const LawData& a, const LawData& b) {
  return a.expression == b.expression && a.parameter == b.parameter && same_bits(a.domain.start, b.domain.start) &&
         same_bits(a.domain.end, b.domain.end);
}
bool same_data(const NaturalData& a, const NaturalData& b) {
  return a.curvature == b.curvature && a.torsion == b.torsion && a.parameter == b.parameter &&
         same_bits(a.length, b.length) && same_bits(a.start_point, b.start_point) &&
         same_bits(a.start_tangent, b.start_tangent) && same_bits(a.start_normal, b.start_normal) &&
         same_bits(a.tolerance, b.tolerance);
}
}  // namespace

bool operator==(const Curve& a, const Curve& b) {
  if (a.state_ == b.state_) return true;
  if (a.kind() != b.kind() || !(a.nurbs() == b.nurbs())) return false;
  return std::visit(
      [&](const auto& x) {
        using T = std::decay_t<decltype(x)>;
        return same_data(x, std::get<T>(b.data()));
      },
      a.data());
}

}  // namespace hula::curve
