// SPDX-License-Identifier: MIT
// The fairing assistant; see fairing_assistant.hpp.
//
// Notation: q_k the data points (q0_k the input's), x the vector of their free
// moves along move_axes() (in the plane of a planar curve), r(x) the residuals
// sqrt(w_q (h/2) |C'(t_q)|) κ'(t_q) at the 5 Gauss–Legendre nodes of every
// knot span (h the span width), J = ∂r/∂x by forward differences.
#include "hula/studies/fairing_assistant.hpp"

#include <Eigen/Dense>
#include <array>
#include <boost/math/quadrature/gauss.hpp>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>

#include "hula/core/error.hpp"
#include "hula/diffgeom/energy.hpp"
#include "hula/diffgeom/frenet.hpp"
#include "hula/diffgeom/planarity.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/studies/knot_fairing.hpp"

namespace hula::studies {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// 5-point Gauss–Legendre rule on [-1, 1]: Boost.Math's non-negative nodes (0 first, used ±) and their weights.
constexpr int kGaussPoints = 5;
using Gauss = boost::math::quadrature::gauss<double, kGaussPoints>;

// A tolerance ball is shrunk by this relative amount before projecting into it, so that the
// rounding of q0 + d never puts a point outside the user's tolerance.
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

// The residual vector r of a curve (its squared norm approximates ∫κ'² ds).
class Residuals {
 public:
  explicit Residuals(const nurbs::NurbsCurve& reference)
      : scale_(diffgeom::frenet_scale(reference, options_.tolerance)) {}

  void operator()(const nurbs::NurbsCurve& c, Eigen::VectorXd& out) const {
    const std::vector<double> bp = c.knots().breakpoints();
    const auto& nodes = Gauss::abscissa();
    const auto& weights = Gauss::weights();
    out.resize(static_cast<Eigen::Index>((bp.size() - 1) * static_cast<std::size_t>(kGaussPoints)));
    Eigen::Index row = 0;
    std::array<Vec3, 4> d;
    for (std::size_t i = 0; i + 1 < bp.size(); ++i) {
      const double half = 0.5 * (bp[i + 1] - bp[i]), mid = 0.5 * (bp[i + 1] + bp[i]);
      // Nodes from −1 to 1: index |q| of the tables, signed.
      for (int q = -kGaussPoints / 2; q <= kGaussPoints / 2; ++q) {
        const auto k = static_cast<std::size_t>(std::abs(q));
        const double t = mid + (q < 0 ? -half : half) * nodes[k];
        c.derivatives(t, 3, d, {});
        const diffgeom::FrenetPoint p = diffgeom::frenet_from_derivatives(t, d, scale_, options_);
        // Where the frame is undefined the energy code counts 0 (diffgeom/energy.hpp); so does the proxy.
        const double k1 = p.frame_defined && std::isfinite(p.curvature_derivative) ? p.curvature_derivative : 0.0;
        out[row++] = std::sqrt(weights[k] * half * p.speed) * k1;
      }
    }
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

// Min-variation: Levenberg–Marquardt on x (the points' moves along their axes) with every
// point projected into its tolerance ball.
struct MinVariation {
  curve::Curve input;  // the curve rebuilt from moved points (prepared for the held ends)
  const AssistantOptions& options;
  std::vector<Vec3> q0;
  std::vector<bool> held;  // data points that stay exactly at q0
  std::vector<Vec3> axes;  // orthonormal move directions, the same for every point
  int dim;                 // axes.size()
  Residuals residuals;
  Clock::time_point t0;

  MinVariation(const curve::Curve& c, const AssistantOptions& o, Clock::time_point start)
      : input(prepared(c, o.hold)),
        options(o),
        q0(data_points_of(c)),
        held(held_points(c, o.hold, q0.size())),
        axes(move_axes(c)),
        dim(static_cast<int>(axes.size())),
        residuals(c.nurbs()),
        t0(start) {}

  [[nodiscard]] std::vector<Vec3> points_of(const Eigen::VectorXd& x) const {
    std::vector<Vec3> q = q0;
    for (std::size_t k = 0; k < q.size(); ++k) {
      if (held[k]) continue;  // exactly q0, not q0 + 0 · axes
      for (int j = 0; j < dim; ++j)
        q[k] = q[k] + axes[static_cast<std::size_t>(j)] * x[static_cast<Eigen::Index>(k) * dim + j];
    }
    return q;
  }

  // Moves every point of x back into its ball of radius tolerance (1 − kBallMargin) about q0
  // (the axes are orthonormal: the move's length is the norm of its coefficients).
  void project(Eigen::VectorXd& x) const {
    const double radius = options.tolerance * (1.0 - kBallMargin);
    for (std::size_t k = 0; k < q0.size(); ++k) {
      auto move = x.segment(static_cast<Eigen::Index>(k) * dim, dim);
      if (held[k]) {
        move.setZero();
        continue;
      }
      const double n = move.norm();
      if (n > radius) move *= radius / n;
    }
  }

  // r(x); false when the moved points do not make a curve (e.g. two coincide).
  bool evaluate(const Eigen::VectorXd& x, Eigen::VectorXd& r) const {
    try {
      residuals(rebuild(input, points_of(x)).nurbs(), r);
    } catch (const Error&) {
      return false;
    }
    return r.allFinite();
  }

  [[nodiscard]] bool out_of_time() const { return seconds_since(t0) >= options.time_budget_seconds; }

  AssistantResult run() {
    const auto n = static_cast<Eigen::Index>(q0.size()) * dim;
    Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
    Eigen::VectorXd r, r_try, r_h;
    if (!evaluate(x, r))
      throw Error(Errc::NumericalFailure, "the curve's curvature variation is not finite at its own data points",
                  ErrorWhere{.field = "curve"});
    double energy = r.squaredNorm();
    const double h = 1e-7 * std::max(1.0, input.nurbs().model_size());
    Eigen::MatrixXd J(r.size(), n);
    double mu = 1e-3;
    AssistantResult out{.curve = input};
    for (std::size_t it = 0; it < options.max_iterations; ++it) {
      if (it > 0 && out_of_time()) {  // the first step always runs: a ghost that is not fairer is no ghost
        out.stopped = true;
        break;
      }
      for (Eigen::Index c = 0; c < n; ++c) {
        if (held[static_cast<std::size_t>(c / dim)]) {  // no step: A(c, c) = g(c) = 0
          J.col(c).setZero();
          continue;
        }
        Eigen::VectorXd xh = x;
        xh[c] += h;
        if (!evaluate(xh, r_h)) r_h = r;  // a column that cannot move is left out of the step
        J.col(c) = (r_h - r) / h;
      }
      const Eigen::MatrixXd A = J.transpose() * J;
      const Eigen::VectorXd g = J.transpose() * r;
      const double floor = 1e-12 * std::max(A.diagonal().maxCoeff(), 1e-300);
      bool accepted = false;
      for (int attempt = 0; attempt < 12 && !accepted; ++attempt) {
        Eigen::MatrixXd M = A;
        for (Eigen::Index c = 0; c < n; ++c) M(c, c) += mu * A(c, c) + floor;
        Eigen::VectorXd x_try = x - M.ldlt().solve(g);
        project(x_try);
        if (x_try.allFinite() && evaluate(x_try, r_try) && r_try.squaredNorm() < energy) {
          const double previous = energy;
          x = x_try;
          r = r_try;
          energy = r.squaredNorm();
          mu = std::max(mu / 3.0, 1e-9);
          accepted = true;
          out.iterations = it + 1;
          if (previous - energy <= 1e-9 * previous) it = options.max_iterations;  // converged
        } else {
          mu *= 10.0;
        }
      }
      if (!accepted) break;
    }
    out.data_points = q0;
    out.faired_points = out.iterations > 0 ? points_of(x) : q0;
    if (out.iterations > 0) out.curve = rebuild(input, out.faired_points);
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
