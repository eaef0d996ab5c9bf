// SPDX-License-Identifier: MIT
// The fairing assistant; see fairing_assistant.hpp.
//
// Notation: q_k the data points (q0_k the input's), x the vector of their free
// moves along move_axes() (in the plane of a planar curve), r(x) the residuals
// sqrt(w_q (h/2) |C'(t_q)|) κ'(t_q) at the 5 Gauss–Legendre nodes of every
// knot span (h the span width); Ceres minimises ‖r(x)‖² with J = ∂r/∂x by
// forward differences (refine_levenberg_marquardt).
#include "hula/studies/fairing_assistant.hpp"

#include <algorithm>
#include <array>
#include <boost/math/quadrature/gauss.hpp>
#include <chrono>
#include <cmath>
#include <numeric>
#include <span>
#include <string>

#include "hula/core/error.hpp"
#include "hula/diffgeom/energy.hpp"
#include "hula/diffgeom/frenet.hpp"
#include "hula/diffgeom/planarity.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/studies/hybrid_refine.hpp"
#include "hula/studies/knot_fairing.hpp"

namespace hula::studies {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// The 5-point Gauss–Legendre rule on [-1, 1]: Boost.Math's nodes (it keeps the non-negative half of the
// symmetric rule) and their mirror images.
struct GaussRule {
  std::vector<double> nodes, weights;
};

const GaussRule& gauss5() {
  static const GaussRule rule = [] {
    using Gauss = boost::math::quadrature::gauss<double, 5>;
    GaussRule r;
    for (std::size_t i = 0; i < Gauss::abscissa().size(); ++i) {
      const double x = Gauss::abscissa()[i], w = Gauss::weights()[i];
      r.nodes.push_back(x);
      r.weights.push_back(w);
      if (x != 0.0) {
        r.nodes.push_back(-x);
        r.weights.push_back(w);
      }
    }
    return r;
  }();
  return rule;
}

// A tolerance ball is shrunk by this relative amount, so that the rounding of q0 + d never puts a
// point outside the user's tolerance.
constexpr double kBallMargin = 1e-9;

// The energy options of the reported energies: 1e-8 relative is far below any difference the user
// can see and several times cheaper than the 1e-10 default on 100-span curves.
diffgeom::EnergyOptions reported_energy_options() {
  diffgeom::EnergyOptions o;
  o.relative_tolerance = 1e-8;
  return o;
}

double variation(const nurbs::NurbsCurve& c) {
  return diffgeom::curvature_variation_energy(c, reported_energy_options()).value;
}

// The data points of a curve (see the header) and a rebuild of the curve from moved ones.
std::vector<Vec3> data_points_of(const curve::Curve& c) {
  switch (c.kind()) {
    case curve::Kind::Interpolated:
      return std::get<curve::InterpolatedData>(c.data()).points;
    case curve::Kind::Hermite:
      return std::get<curve::HermiteData>(c.data()).points;
    case curve::Kind::Bezier:
      return std::get<curve::BezierData>(c.data()).control_points;
    case curve::Kind::Nurbs: {
      const auto cps = c.nurbs().control_points();
      return {cps.begin(), cps.end()};
    }
    case curve::Kind::Law:
    case curve::Kind::Natural:
      break;
  }
  throw Error(Errc::InvalidArgument,
              "a " + std::string(c.kind_name()) +
                  " curve has no data points to hold within a tolerance: fair an interpolated, Hermite, NURBS or "
                  "Bézier curve",
              ErrorWhere{.field = "curve"});
}

curve::Curve rebuild(const curve::Curve& c, std::vector<Vec3> points) {
  switch (c.kind()) {
    case curve::Kind::Interpolated: {
      curve::InterpolatedData d = std::get<curve::InterpolatedData>(c.data());
      d.points = std::move(points);
      return curve::Curve::interpolated(std::move(d));
    }
    case curve::Kind::Hermite: {
      curve::HermiteData d = std::get<curve::HermiteData>(c.data());
      d.points = std::move(points);
      return curve::Curve::hermite(std::move(d));
    }
    case curve::Kind::Bezier: {
      curve::BezierData d = std::get<curve::BezierData>(c.data());
      d.control_points = std::move(points);
      return curve::Curve::bezier(std::move(d));
    }
    default: {
      const nurbs::NurbsCurve& n = c.nurbs();
      const auto w = n.weights();
      return curve::Curve(nurbs::NurbsCurve(n.knots(), std::move(points), {w.begin(), w.end()}, n.dimension()));
    }
  }
}

// The curve the search rebuilds from moved data points. With held tangents an interpolated curve's
// end conditions that follow the points (natural, Bessel, not-a-knot, OCCT) become clamped ones with
// the curve's own end derivatives dC/dt (t on [0, 1]): the same curve at the input's points, whose end
// tangents no longer move with them. Clamped and direction ends already hold their tangents.
curve::Curve prepared(const curve::Curve& c, AssistantHold hold) {
  if (hold != AssistantHold::Tangents || c.kind() != curve::Kind::Interpolated) return c;
  curve::InterpolatedData d = std::get<curve::InterpolatedData>(c.data());
  const nurbs::NurbsCurve& n = c.nurbs();
  const Interval dom = n.domain();
  const auto fixed = [](const nurbs::EndCondition& e) {
    return e.kind == nurbs::EndCondition::Kind::Clamped || e.kind == nurbs::EndCondition::Kind::Direction;
  };
  if (!fixed(d.start)) d.start = nurbs::EndCondition::clamped(n.derivatives(dom.start, 1)[1] * dom.length());
  if (!fixed(d.end)) d.end = nurbs::EndCondition::clamped(n.derivatives(dom.end, 1)[1] * dom.length());
  return curve::Curve::interpolated(std::move(d));
}

// The data points that do not move (see AssistantOptions::hold).
std::vector<bool> held_points(const curve::Curve& c, AssistantHold hold, std::size_t n) {
  std::vector<bool> held(n, false);
  if (hold == AssistantHold::Free || n == 0) return held;
  if (c.kind() == curve::Kind::Nurbs && !c.nurbs().knots().is_clamped())
    throw Error(Errc::InvalidArgument,
                "hold = " + std::string(assistant_hold_name(hold)) +
                    ": the NURBS curve is not clamped, so its ends are not control points that can be held",
                ErrorWhere{.field = "hold"});
  held.front() = held.back() = true;
  const bool control = c.kind() == curve::Kind::Nurbs || c.kind() == curve::Kind::Bezier;
  if (hold == AssistantHold::Tangents && control && n >= 2) held[1] = held[n - 2] = true;
  return held;
}

// The residuals of a curve (Σ r_q² approximates ∫κ'² ds): sqrt(w_q (h/2) |C'(t_q)|) κ'(t_q) at the
// Gauss–Legendre nodes of every knot span.
class Residuals {
 public:
  explicit Residuals(const nurbs::NurbsCurve& reference)
      : scale_(diffgeom::frenet_scale(reference, options_.tolerance)) {}

  /// The number of residuals of a curve with the knot spans of `c`.
  [[nodiscard]] static std::size_t count(const nurbs::NurbsCurve& c) {
    return (c.knots().breakpoints().size() - 1) * gauss5().nodes.size();
  }

  /// Writes the residuals of c into out; false when c has another number of spans than out has room for.
  bool operator()(const nurbs::NurbsCurve& c, std::span<double> out) const {
    const std::vector<double> bp = c.knots().breakpoints();
    const GaussRule& rule = gauss5();
    if ((bp.size() - 1) * rule.nodes.size() != out.size()) return false;
    std::size_t row = 0;
    std::array<Vec3, 4> d;
    for (std::size_t i = 0; i + 1 < bp.size(); ++i) {
      const double half = 0.5 * (bp[i + 1] - bp[i]), mid = 0.5 * (bp[i + 1] + bp[i]);
      for (std::size_t q = 0; q < rule.nodes.size(); ++q) {
        const double t = mid + half * rule.nodes[q];
        c.derivatives(t, 3, d, {});
        const diffgeom::FrenetPoint p = diffgeom::frenet_from_derivatives(t, d, scale_, options_);
        // Where the frame is undefined the energy code counts 0 (diffgeom/energy.hpp); so does the proxy.
        const double k1 = p.frame_defined && std::isfinite(p.curvature_derivative) ? p.curvature_derivative : 0.0;
        out[row++] = std::sqrt(rule.weights[q] * half * p.speed) * k1;
      }
    }
    return true;
  }

 private:
  diffgeom::FrenetOptions options_{};
  diffgeom::FrenetScale scale_;
};

// The directions a data point may move in: the two axes of its plane for a planar curve (a
// planar curve stays planar: off the plane κ′ changes only to second order, so its finite
// differences are noise, and a step along them would bend the curve out of its plane by up to
// the tolerance), the coordinate axes otherwise.
std::vector<Vec3> move_axes(const curve::Curve& c) {
  if (c.dimension() == 2) return {Vec3{1, 0, 0}, Vec3{0, 1, 0}};
  const diffgeom::Planarity plane = diffgeom::planarity(c.nurbs());
  if (!plane.planar || !plane.normal) return {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
  const Vec3 n = *plane.normal;
  // The coordinate axis least aligned with n, made orthogonal to it.
  const Vec3 pick = std::abs(n.x) <= std::abs(n.y) && std::abs(n.x) <= std::abs(n.z) ? Vec3{1, 0, 0}
                    : std::abs(n.y) <= std::abs(n.z)                                 ? Vec3{0, 1, 0}
                                                                                     : Vec3{0, 0, 1};
  const Vec3 u = normalized(pick - n * dot(pick, n));
  return {u, cross(n, u)};
}

// Min-variation: the moved points' residuals as a least-squares problem solved by Ceres's
// Levenberg–Marquardt (refine_levenberg_marquardt, the hybrid's solver). The variables are, for every
// data point that is not held, u in the cube [-1, 1]^d (d = 2 or 3 move axes: Ceres's box bounds), and the
// point moves by R s(u) along the axes (R = the tolerance shrunk by kBallMargin), where s maps the cube onto
// the unit ball (Nowell's cube-to-sphere map, in 2-D the elliptical grid map):
//   s_i(u) = u_i sqrt(1 − Σ_{j≠i} u_j²/2 + Π_{j≠i} u_j²/3)   (3-D; 2-D: u_i sqrt(1 − u_j²/2)),
// with |s(u)|² = 1 − Π_j (1 − u_j²) ≤ 1, s(u) = u to first order at 0, and the box's faces on the sphere. So
// no point Ceres tries leaves its tolerance (no projection step), and where the optimum sits on the
// tolerance (as it does, docs/studies.md) the variable sits on a bound with the move still differentiable,
// which a smooth map of all of R^d into the ball would not allow.
struct MinVariation {
  curve::Curve input;  // the curve rebuilt from moved points (prepared for the held ends)
  const AssistantOptions& options;
  std::vector<Vec3> q0;
  std::vector<std::size_t> free;  // the data points that move (the held ones stay exactly at q0)
  std::vector<Vec3> axes;         // orthonormal move directions, the same for every point
  std::size_t dim;                // axes.size()
  double radius;                  // R
  Residuals residuals;
  Clock::time_point t0;

  MinVariation(const curve::Curve& c, const AssistantOptions& o, Clock::time_point start)
      : input(prepared(c, o.hold)),
        options(o),
        q0(data_points_of(c)),
        axes(move_axes(c)),
        dim(axes.size()),
        radius(o.tolerance * (1.0 - kBallMargin)),
        residuals(c.nurbs()),
        t0(start) {
    const std::vector<bool> held = held_points(c, o.hold, q0.size());
    for (std::size_t k = 0; k < q0.size(); ++k)
      if (!held[k]) free.push_back(k);
  }

  [[nodiscard]] std::vector<Vec3> points_of(std::span<const double> x) const {
    std::vector<Vec3> q = q0;
    for (std::size_t f = 0; f < free.size(); ++f) {
      const std::span<const double> u = x.subspan(f * dim, dim);
      for (std::size_t i = 0; i < dim; ++i) {
        double sum = 0.0, product = 1.0;
        for (std::size_t j = 0; j < dim; ++j) {
          if (j == i) continue;
          sum += 0.5 * u[j] * u[j];
          product *= u[j] * u[j];
        }
        const double inside = dim == 3 ? 1.0 - sum + product / 3.0 : 1.0 - sum;
        q[free[f]] = q[free[f]] + axes[i] * (radius * u[i] * std::sqrt(std::max(inside, 0.0)));
      }
    }
    return q;
  }

  // r(x); false when the moved points do not make a curve (e.g. two coincide).
  bool evaluate(std::span<const double> x, std::span<double> r) const {
    try {
      if (!residuals(rebuild(input, points_of(x)).nurbs(), r)) return false;
    } catch (const Error&) {
      return false;
    }
    return std::all_of(r.begin(), r.end(), [](double v) { return std::isfinite(v); });
  }

  AssistantResult run() {
    LeastSquaresProblem problem;
    for (std::size_t f = 0; f < free.size(); ++f)
      for (std::size_t j = 0; j < dim; ++j)
        problem.variables.push_back(
            {.name = "point " + std::to_string(free[f]) + " move " + std::to_string(j), .lower = -1.0, .upper = 1.0});
    problem.residual_count = Residuals::count(input.nurbs());
    problem.residuals = [this](std::span<const double> x, std::span<double> r) { return evaluate(x, r); };
    const std::vector<double> start(problem.variables.size(), 0.0);
    std::vector<double> r0(problem.residual_count);
    if (!evaluate(start, r0))
      throw Error(Errc::NumericalFailure, "the curve's curvature variation is not finite at its own data points",
                  ErrorWhere{.field = "curve"});
    AssistantResult out{.curve = input};
    out.data_points = q0;
    out.faired_points = q0;
    if (free.empty()) return out;
    LmOptions lm;
    // As many accepted steps as options.max_iterations, each after at most 12 tries of the damping.
    lm.max_accepted_steps = options.max_iterations;
    lm.max_iterations = 12 * options.max_iterations;
    lm.target_mean = 0.0;
    lm.relative_tolerance = 1e-9;
    // The budget is the call's: what is left of it (the first accepted step always runs).
    lm.time_budget_seconds = std::max(options.time_budget_seconds - seconds_since(t0), 1e-9);
    // One-sided differences (n evaluations per Jacobian, not 2n: the ghost has a deadline) with a move of
    // 1e-7 of the model's size, as far as the steps allow.
    lm.forward_differences = true;
    lm.difference_step = std::min(1e-2, 1e-7 * std::max(1.0, input.nurbs().model_size()) / radius);
    const LmResult fit = refine_levenberg_marquardt(problem, start, lm);
    out.iterations = fit.iterations;
    out.stopped = fit.termination == optim::Termination::WallTime;
    // Kept only when the quadrature proxy of the energy, Σ r², is lower than at the start.
    std::vector<double> r1(problem.residual_count);
    const auto squares = [](const std::vector<double>& r) {
      return std::accumulate(r.begin(), r.end(), 0.0, [](double a, double v) { return a + v * v; });
    };
    if (evaluate(fit.variables, r1) && squares(r1) < squares(r0)) {
      out.faired_points = points_of(fit.variables);
      out.curve = rebuild(input, out.faired_points);
    }
    return out;
  }
};

AssistantResult fair_knots_within(const curve::Curve& c, const AssistantOptions& options) {
  if (c.kind() != curve::Kind::Interpolated || std::get<curve::InterpolatedData>(c.data()).points.size() < 3)
    throw Error(Errc::InvalidArgument,
                "knot fairing moves the parameters of an interpolated spline's data points: it needs an interpolated "
                "curve through at least 3 points, not a " +
                    std::string(c.kind_name()) + " curve",
                ErrorWhere{.field = "curve"});
  // Points are kept by the method itself; held tangents become the ends' own derivatives.
  const curve::Curve base = prepared(c, options.hold);
  const auto& data = std::get<curve::InterpolatedData>(base.data());
  KnotFairingSetup setup;
  setup.points = data.points;
  setup.dimension = data.dimension;
  setup.start = data.start;
  setup.end = data.end;
  setup.energy = FairingEnergy::Variation;
  setup.energy_options.relative_tolerance = 1e-6;  // the search's objective; the result is re-measured at 1e-8
  std::vector<double> start =
      data.parameters.empty() ? nurbs::parameterise(data.points, data.parameterisation) : data.parameters;
  const double a = start.front(), b = start.back();
  for (double& p : start) p = (p - a) / (b - a);
  start.front() = 0.0;
  start.back() = 1.0;
  optim::NelderMeadOptions nm;
  nm.wall_time_seconds = options.time_budget_seconds;
  nm.initial_step = 0.2;
  nm.x_tolerance = 1e-6;
  nm.f_tolerance = 1e-9;
  nm.restarts = 1;
  const FairingResult f = fair_knots_deterministic(setup, start, nm);
  AssistantResult out{.curve = c};
  out.iterations = f.evaluations;
  out.stopped = f.stopped();
  out.data_points = data.points;
  out.faired_points = data.points;
  curve::InterpolatedData faired = data;
  faired.parameters = f.best.parameters;
  out.curve = curve::Curve::interpolated(std::move(faired));
  return out;
}

}  // namespace

std::string_view assistant_method_name(AssistantMethod method) noexcept {
  return method == AssistantMethod::Knots ? "knots" : "min-variation";
}

AssistantMethod assistant_method_from_name(std::string_view name) {
  if (name == "knots") return AssistantMethod::Knots;
  if (name == "min-variation") return AssistantMethod::MinimalVariation;
  throw Error(Errc::InvalidOption, "method '" + std::string(name) + "' is not \"knots\" or \"min-variation\"",
              ErrorWhere{.field = "method"});
}

std::string_view assistant_hold_name(AssistantHold hold) noexcept {
  switch (hold) {
    case AssistantHold::Points:
      return "points";
    case AssistantHold::Tangents:
      return "tangents";
    case AssistantHold::Free:
      break;
  }
  return "free";
}

AssistantHold assistant_hold_from_name(std::string_view name) {
  if (name == "free") return AssistantHold::Free;
  if (name == "points") return AssistantHold::Points;
  if (name == "tangents") return AssistantHold::Tangents;
  throw Error(Errc::InvalidOption, "hold '" + std::string(name) + "' is not \"free\", \"points\" or \"tangents\"",
              ErrorWhere{.field = "hold"});
}

void AssistantOptions::validate() const {
  if (!(std::isfinite(tolerance) && tolerance > 0.0))
    throw Error(Errc::InvalidOption, "tolerance = " + format_number(tolerance) + " must be finite and > 0",
                ErrorWhere{.field = "tolerance"});
  if (!(time_budget_seconds > 0.0 && time_budget_seconds <= 60.0))
    throw Error(Errc::InvalidOption,
                "time_budget_seconds = " + format_number(time_budget_seconds) + " must be in (0, 60]",
                ErrorWhere{.field = "time_budget_seconds"});
  if (max_iterations < 1 || max_iterations > 1000)
    throw Error(Errc::InvalidOption, "max_iterations = " + std::to_string(max_iterations) + " must be in [1, 1000]",
                ErrorWhere{.field = "max_iterations"});
}

AssistantResult fair_within_tolerance(const curve::Curve& curve, const AssistantOptions& options) {
  const auto t0 = Clock::now();
  options.validate();
  AssistantResult out = options.method == AssistantMethod::Knots ? fair_knots_within(curve, options)
                                                                 : MinVariation(curve, options, t0).run();
  out.energy_before = variation(curve.nurbs());
  out.energy_after = variation(out.curve.nurbs());
  if (!(out.energy_after < out.energy_before)) {
    // The search's quadrature proxy and the adaptive energy disagree on a step too small to matter:
    // the input stays the ghost, so the assistant never proposes a worse curve.
    out.curve = curve;
    out.energy_after = out.energy_before;
    out.faired_points = out.data_points;
  }
  out.max_deviation = 0.0;
  for (std::size_t k = 0; k < out.data_points.size(); ++k)
    out.max_deviation = std::max(out.max_deviation, distance(out.faired_points[k], out.data_points[k]));
  out.seconds = seconds_since(t0);
  return out;
}

}  // namespace hula::studies
