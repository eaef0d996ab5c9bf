// SPDX-License-Identifier: MIT
// Natural equations (thesis 8.2.2, eq. 34): integration of the planar
// turning-angle equations and of the Frenet–Serret system with Boost.Odeint's
// Runge–Kutta–Fehlberg 7(8) pair, dense output by re-stepping from stored
// nodes, and the quintic Hermite NURBS fit. Notation as in the header.
#include "hula/intrinsic/natural_equations.hpp"

#include <algorithm>
#include <array>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/numeric/odeint/stepper/controlled_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/generation.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>
#include <cmath>
#include <complex>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "hula/core/error.hpp"
#include "hula/law/antiderivative.hpp"
#include "hula/law/singularities.hpp"
#include "hula/law/tape.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/nurbs/knot_removal.hpp"

namespace hula::intrinsic {

namespace odeint = boost::numeric::odeint;

namespace {

// State of the ODE. Frenet–Serret: r (0–2), T (3–5), N (6–8), B (9–11).
// Planar with the exact angle: x, y in 0–1 (plane coordinates along T(0), N(0)), the rest 0.
using State = std::array<double, 12>;
using Stepper = odeint::runge_kutta_fehlberg78<State>;

void require(bool ok, Errc code, const std::string& message, const std::string& field) {
  if (!ok) throw Error(code, message, ErrorWhere{.field = field});
}

void check_range(double value, double lo, double hi, const char* field) {
  if (!(value >= lo && value <= hi))
    throw Error(Errc::InvalidOption,
                std::string(field) + " = " + format_number(value) + " is outside [" + format_number(lo) + ", " +
                    format_number(hi) + "]",
                ErrorWhere{.field = field});
}

void check_law(const law::Law& l, const char* field) {
  require(l.valid(), Errc::InvalidArgument, std::string(field) + " is an empty law", field);
  require(l.dimension() == 1, Errc::InvalidArgument,
          std::string(field) + " must be a scalar law, got a " + std::to_string(l.dimension()) + "-vector", field);
}

Vec3 unit(const Vec3& v) { return v / norm(v); }

}  // namespace

void ReconstructionOptions::validate() const {
  check_range(tolerance, 1e-13, 1e-2, "tolerance");
  if (method != ReconstructionMethod::Auto && method != ReconstructionMethod::FrenetSerret)
    throw Error(Errc::InvalidOption, "method has an unknown value", ErrorWhere{.field = "method"});
  if (max_steps < 1 || max_steps > 100'000'000)
    throw Error(Errc::InvalidOption, "max_steps = " + std::to_string(max_steps) + " is outside [1, 100000000]",
                ErrorWhere{.field = "max_steps"});
  if (breaks)
    for (const double b : *breaks)
      if (!std::isfinite(b))
        throw Error(Errc::InvalidOption, "breaks holds a non-finite value", ErrorWhere{.field = "breaks"});
}

void NurbsFitOptions::validate() const {
  check_range(tolerance, 1e-13, 1.0, "tolerance");
  if (max_segments < 1 || max_segments > 10'000'000)
    throw Error(Errc::InvalidOption, "max_segments = " + std::to_string(max_segments) + " is outside [1, 10000000]",
                ErrorWhere{.field = "max_segments"});
  if (check_samples < 1 || check_samples > 1000)
    throw Error(Errc::InvalidOption, "check_samples = " + std::to_string(check_samples) + " is outside [1, 1000]",
                ErrorWhere{.field = "check_samples"});
}

struct IntrinsicCurve::Impl {
  IntegrationKind kind = IntegrationKind::FrenetSerret;
  double length = 0.0;
  double tolerance = 0.0;
  // Outputs: κ, τ (Frenet–Serret) or κ, θ (planar exact) or κ (planar numeric).
  law::Tape laws;
  Vec3 p0, t0, n0, b0;
  std::vector<double> s;
  std::vector<State> x;
  std::size_t rejected = 0;
  // Interior arc lengths where κ or τ is not smooth (law::singularities), increasing: every step
  // ends on them, so each step integrates a smooth piece (and they are nodes of the dense output).
  std::vector<double> breaks;
  // The laws named in errors of the integration as a whole ("kappa" or "kappa and tau").
  const char* laws_name = "kappa";

  // Values of the compiled laws at s (κ first), with the law named when undefined.
  std::array<double, 2> eval_laws(double at) const {
    std::array<double, 2> out{0.0, 0.0};
    const double in[1] = {at};
    const std::span<double> o(out.data(), laws.output_count());
    if (!laws.evaluate(in, o) || !std::isfinite(out[0]) || !std::isfinite(out[1])) {
      const char* which = !std::isfinite(out[0]) ? "kappa" : (kind == IntegrationKind::FrenetSerret ? "tau" : "kappa");
      throw Error(Errc::NumericalFailure,
                  std::string(which) + " is undefined or infinite at s = " + format_number(at) +
                      (kind == IntegrationKind::PlanarExactAngle && std::isfinite(out[0])
                           ? " (its antiderivative is undefined there)"
                           : ""),
                  ErrorWhere{.field = which});
    }
    return out;
  }

  // The right-hand side dx/ds.
  void rhs(const State& y, State& dy, double at) const {
    const std::array<double, 2> v = eval_laws(at);
    dy.fill(0.0);
    switch (kind) {
      case IntegrationKind::FrenetSerret:
      case IntegrationKind::PlanarNumericAngle: {
        const double k = v[0], t = v[1];
        for (std::size_t c = 0; c < 3; ++c) {
          dy[c] = y[3 + c];                          // r' = T
          dy[3 + c] = k * y[6 + c];                  // T' = κN
          dy[6 + c] = -k * y[3 + c] + t * y[9 + c];  // N' = −κT + τB
          dy[9 + c] = -t * y[6 + c];                 // B' = −τN
        }
        break;
      }
      case IntegrationKind::PlanarExactAngle:
        break;  // integrated by integrate_planar(), not as an ODE
    }
  }

  // Projects the frame back onto SO(3): T normalised, N Gram–Schmidt against T, B = T × N.
  static void orthonormalise(State& y) {
    Vec3 t{y[3], y[4], y[5]}, n{y[6], y[7], y[8]};
    t = unit(t);
    n = unit(n - dot(n, t) * t);
    // A second pass removes the rounding left by the first (frames to ~1e-16).
    n = unit(n - dot(n, t) * t);
    const Vec3 b = cross(t, n);
    for (std::size_t c = 0; c < 3; ++c) {
      y[3 + c] = t[c];
      y[6 + c] = n[c];
      y[9 + c] = b[c];
    }
  }

  FramePoint point(double at, const State& y) const {
    FramePoint p;
    p.s = at;
    const std::array<double, 2> v = eval_laws(at);
    p.curvature = v[0];
    if (kind != IntegrationKind::PlanarExactAngle) {
      p.torsion = v[1];
      p.position = {y[0], y[1], y[2]};
      p.tangent = {y[3], y[4], y[5]};
      p.normal = {y[6], y[7], y[8]};
      p.binormal = {y[9], y[10], y[11]};
      return p;
    }
    // Planar, exact angle: x along T(0), y along N(0); the frame rotates by θ in that plane.
    const double theta = v[1];
    const double c = std::cos(theta), sn = std::sin(theta);
    p.position = p0 + y[0] * t0 + y[1] * n0;
    p.tangent = c * t0 + sn * n0;
    p.normal = -sn * t0 + c * n0;
    p.binormal = b0;
    return p;
  }

  void integrate(std::size_t max_steps) {
    State y{};
    if (kind != IntegrationKind::PlanarExactAngle)
      for (std::size_t c = 0; c < 3; ++c) {
        y[c] = p0[c];
        y[3 + c] = t0[c];
        y[6 + c] = n0[c];
        y[9 + c] = b0[c];
      }
    // Frame errors δ become position errors δ·(remaining length): local error per step below
    // tolerance / max(1, L) / 20 keeps the global error under the tolerance in practice
    // (checked against closed forms in tests/intrinsic).
    const double eps = tolerance / std::max(1.0, length) / 20.0;
    // GCC 12 flags the copy of the stepper's scratch arrays (uninitialised by design, written
    // before they are read) in make_controlled; a false positive inside Boost.Odeint.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
    auto stepper = odeint::make_controlled(eps, 0.0, Stepper());
#pragma GCC diagnostic pop
    auto system = [this](const State& a, State& da, double at) { rhs(a, da, at); };
    s.push_back(0.0);
    x.push_back(y);
    double at = 0.0;
    double h = std::min(length, 0.25);
    std::size_t attempts = 0;
    std::size_t next_break = 0;  // index into breaks of the next step end to hit exactly
    while (at < length) {
      if (++attempts > max_steps)
        throw Error(Errc::NumericalFailure,
                    std::string(laws_name) +
                        ": the integration needed more than max_steps = " + std::to_string(max_steps) +
                        " steps (reached s = " + format_number(at) + " of " + format_number(length) + ")",
                    ErrorWhere{.field = "kappa"});
      const double stop = next_break < breaks.size() ? breaks[next_break] : length;
      // A step never crosses a kink of κ or τ: the RKF78 error estimate assumes a smooth right-hand
      // side, and across a kink it shrinks the step to rounding size.
      const bool last = at + h >= stop;
      const double h_free = h;
      if (last) h = stop - at;
      State trial = y;
      double t_try = at, h_try = h;
      if (stepper.try_step(system, trial, t_try, h_try) == odeint::success) {
        if (kind != IntegrationKind::PlanarExactAngle) orthonormalise(trial);
        y = trial;
        at = last ? stop : t_try;
        s.push_back(at);
        x.push_back(y);
        // A step cut short to land on a kink says nothing about the next smooth piece.
        if (last) h_try = std::max(h_try, h_free);
      } else {
        ++rejected;
      }
      h = h_try;
      // A tiny remainder would be a wasted step of rounding size: absorb it into this one.
      if (stop - at < 1e-12 * length && at < stop) {
        s.back() = stop;
        at = stop;
      }
      if (at == stop && stop < length) ++next_break;
      if (!(h > 0.0) || !std::isfinite(h))
        throw Error(Errc::NumericalFailure, "the step size collapsed at s = " + format_number(at),
                    ErrorWhere{.field = "kappa"});
    }
    if (s.back() != length) s.back() = length;
  }

  // ∫_a^b e^{iθ(σ)} dσ by 10-point Gauss–Legendre (exact for degree 19): x + iy of eq. 34.
  std::complex<double> chord(double a, double b) const {
    const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
    const auto f = [&](double u) { return std::polar(1.0, eval_laws(mid + half * u)[1]); };
    return half * boost::math::quadrature::gauss<double, 10>::integrate(f);
  }

  // Eq. 34 with the exact angle: adaptive Gauss–Legendre, bisecting [a, b] until the rule on
  // the whole and on the halves agree to tolerance × (b − a) / max(1, L) / 20. Why not the
  // RKF78 ODE here: its error estimate (41/840)(k1 + k11 − k12 − k13) h vanishes identically
  // for a right-hand side independent of the state (a pure quadrature), so the step control
  // would accept any step.
  void integrate_planar(std::size_t max_steps) {
    const double eps = tolerance / std::max(1.0, length) / 20.0;
    State y{};
    s.push_back(0.0);
    x.push_back(y);
    std::complex<double> z{0.0, 0.0};
    // Intervals [a, b] to do, last = leftmost; at first the smooth pieces between the kinks.
    std::vector<std::pair<double, double>> todo;
    for (std::size_t i = breaks.size() + 1; i-- > 0;)
      todo.emplace_back(i == 0 ? 0.0 : breaks[i - 1], i == breaks.size() ? length : breaks[i]);
    std::size_t attempts = 0;
    while (!todo.empty()) {
      const auto [a, b] = todo.back();
      todo.pop_back();
      if (++attempts > max_steps)
        throw Error(Errc::NumericalFailure,
                    "kappa: the quadrature needed more than max_steps = " + std::to_string(max_steps) +
                        " intervals (reached s = " + format_number(a) + " of " + format_number(length) + ")",
                    ErrorWhere{.field = "kappa"});
      const double m = 0.5 * (a + b);
      const std::complex<double> whole = chord(a, b), left = chord(a, m), halves = left + chord(m, b);
      if (std::abs(whole - halves) <= eps * (b - a) || !(m > a && m < b)) {
        // Store the halves (the more accurate value) and keep the node list sorted.
        for (const auto& [at, v] : {std::pair{m, z + left}, std::pair{b, z + halves}}) {
          y[0] = v.real();
          y[1] = v.imag();
          s.push_back(at);
          x.push_back(y);
        }
        z += halves;
      } else {
        ++rejected;
        todo.emplace_back(m, b);
        todo.emplace_back(a, m);
      }
    }
    s.back() = length;
  }

  FramePoint evaluate(double at) const {
    const auto it = std::upper_bound(s.begin(), s.end(), at);
    const auto k = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, (it - s.begin()) - 1));
    if (at == s[k]) return point(at, x[k]);
    State y = x[k];
    if (kind == IntegrationKind::PlanarExactAngle) {
      const std::complex<double> z = std::complex<double>(y[0], y[1]) + chord(s[k], at);
      y[0] = z.real();
      y[1] = z.imag();
      return point(at, y);
    }
    Stepper stepper;
    auto system = [this](const State& a, State& da, double t) { rhs(a, da, t); };
    stepper.do_step(system, y, s[k], at - s[k]);
    if (kind != IntegrationKind::PlanarExactAngle) orthonormalise(y);
    return point(at, y);
  }
};

IntrinsicCurve::IntrinsicCurve(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}
double IntrinsicCurve::length() const noexcept { return impl_->length; }
IntegrationKind IntrinsicCurve::method() const noexcept { return impl_->kind; }
double IntrinsicCurve::tolerance() const noexcept { return impl_->tolerance; }
std::span<const double> IntrinsicCurve::nodes() const noexcept { return impl_->s; }
std::size_t IntrinsicCurve::rejected_steps() const noexcept { return impl_->rejected; }
std::span<const double> IntrinsicCurve::breakpoints() const noexcept { return impl_->breaks; }

FramePoint IntrinsicCurve::evaluate(double s) const {
  const double L = impl_->length;
  const double slack = 1e-12 * L;
  if (!(s >= -slack && s <= L + slack))
    throw Error(Errc::OutOfDomain, "s = " + format_number(s) + " is outside [0, " + format_number(L) + "]",
                ErrorWhere{.field = "s"});
  return impl_->evaluate(std::clamp(s, 0.0, L));
}

std::vector<FramePoint> IntrinsicCurve::evaluate(std::span<const double> s) const {
  std::vector<FramePoint> out;
  out.reserve(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) {
    try {
      out.push_back(evaluate(s[i]));
    } catch (const Error& e) {
      if (e.code() != Errc::OutOfDomain) throw;
      throw Error(Errc::OutOfDomain, "s[" + std::to_string(i) + "]: " + e.message(),
                  ErrorWhere{.field = "s", .index = i});
    }
  }
  return out;
}

namespace {

struct Frame {
  Vec3 p, t, n, b;
};

Frame check_start(const StartFrame& start) {
  for (std::size_t c = 0; c < 3; ++c) {
    const std::pair<const Vec3*, const char*> fields[3] = {{&start.point, "start_frame.point"},
                                                           {&start.tangent, "start_frame.tangent"},
                                                           {&start.normal, "start_frame.normal"}};
    for (const auto& [v, name] : fields)
      if (!std::isfinite((*v)[c]))
        throw Error(Errc::NonFiniteInput,
                    std::string(name) + "[" + std::to_string(c) + "] = " + format_number((*v)[c]) + " is not finite",
                    ErrorWhere{.field = name, .component = c});
  }
  const double tn = norm(start.tangent);
  require(tn > 0.0 && std::isfinite(tn), Errc::InvalidArgument, "start_frame.tangent must be a non-zero vector",
          "start_frame.tangent");
  const Vec3 t = start.tangent / tn;
  const double nn = norm(start.normal);
  const Vec3 n_perp = start.normal - dot(start.normal, t) * t;
  const double pn = norm(n_perp);
  require(nn > 0.0 && pn > 1e-10 * nn, Errc::InvalidArgument,
          nn > 0.0 ? "start_frame.normal is parallel to start_frame.tangent"
                   : "start_frame.normal must be a non-zero vector",
          "start_frame.normal");
  Vec3 n = n_perp / pn;
  n = unit(n - dot(n, t) * t);
  return {start.point, t, n, cross(t, n)};
}

std::shared_ptr<IntrinsicCurve::Impl> prepare(const law::Law& kappa, std::string_view parameter, double length,
                                              const StartFrame& start, const ReconstructionOptions& options) {
  options.validate();
  check_law(kappa, "kappa");
  if (!std::isfinite(length))
    throw Error(Errc::NonFiniteInput, "length = " + format_number(length) + " is not finite",
                ErrorWhere{.field = "length"});
  require(length > 0.0, Errc::InvalidArgument, "length = " + format_number(length) + " must be > 0", "length");
  const Frame f = check_start(start);
  auto impl = std::make_shared<IntrinsicCurve::Impl>();
  impl->length = length;
  impl->tolerance = options.tolerance;
  impl->p0 = f.p;
  impl->t0 = f.t;
  impl->n0 = f.n;
  impl->b0 = f.b;
  (void)parameter;
  return impl;
}

// The law's singularity analysis before integrating (law::singularities: roots of each node's
// condition law, no sampling of the law itself).
// - Rejects a pole of κ or τ on [0, L]: an integrator approaching 1/(s − 1) would shrink its
//   steps until the budget runs out. A candidate point (division by zero, log or tan pole, power
//   base at 0) is a pole when |f| at δ = 1e-7 max(1, L) on either side exceeds 1 / (1000 δ), the
//   size of a simple pole; removable points such as sin(s − 1)/(s − 1) pass.
// - Appends to `breaks` every other reported point inside (0, L) where f is finite: kinks and
//   jumps (abs, min/max, sign, piecewise, comparisons, NURBS knots), sqrt or asin boundaries. The
//   integration ends steps there and the NURBS fit puts knots there, so that both work on smooth
//   pieces (64 kinks cost 64 steps, not a step control shrinking to rounding size at each).
//   Points where f is undefined (a removable 0/0) are left out: a node there could not be evaluated.
void analyse_singularities(const law::Law& f, std::string_view parameter, double length, const char* field,
                           std::vector<double>& breaks) {
  if (f.is_constant()) return;
  law::SingularityOptions so;
  so.samples = 2;  // undefined regions are found by the integration itself, with their s
  const law::SingularityReport report = law::singularities(f, parameter, 0.0, length, so);
  const std::string in_name[1] = {std::string(parameter)};
  const law::Law one[1] = {f};
  const law::Tape tape = law::Tape::compile(one, in_name);
  const double delta = 1e-7 * std::max(1.0, length);
  for (const law::Singularity& p : report.points) {
    if (p.kind != law::SingularityKind::DivisionByZero && p.kind != law::SingularityKind::LogBoundary &&
        p.kind != law::SingularityKind::TanPole && p.kind != law::SingularityKind::PowerBase) {
      double v = 0.0;
      const double in[1] = {p.t};
      if (p.t > 0.0 && p.t < length && tape.evaluate(in, std::span<double>(&v, 1)) && std::isfinite(v))
        breaks.push_back(p.t);
      continue;
    }
    double worst = 0.0;
    for (const double at : {p.t - delta, p.t + delta}) {
      if (at < 0.0 || at > length) continue;
      double v = 0.0;
      const double in[1] = {at};
      (void)tape.evaluate(in, std::span<double>(&v, 1));
      worst = std::max(worst, std::isfinite(v) ? std::abs(v) : std::numeric_limits<double>::infinity());
    }
    if (worst > 1.0 / (1000.0 * delta))
      throw Error(Errc::NumericalFailure,
                  std::string(field) + " has a pole at s = " + format_number(p.t) + " (" + p.expression +
                      "): the curve is not defined on [0, " + format_number(length) + "]",
                  ErrorWhere{.field = field});
  }
}

// Sorts the kinks of κ and τ into impl->breaks, merging points closer than 1e-12 L and dropping
// those as close to the ends (a step of rounding size would be wasted there).
void set_breaks(IntrinsicCurve::Impl& impl, std::vector<double> breaks) {
  std::sort(breaks.begin(), breaks.end());
  const double merge = 1e-12 * impl.length;
  double last = 0.0;
  for (const double b : breaks)
    if (b - last > merge && impl.length - b > merge) {
      impl.breaks.push_back(b);
      last = b;
    }
}

law::Tape compile(std::span<const law::Law> laws, std::string_view parameter, const char* field) {
  const std::string in[1] = {std::string(parameter)};
  try {
    return law::Tape::compile(laws, in);
  } catch (const Error& e) {
    throw Error(Errc::InvalidArgument, std::string(field) + ": " + e.message(), ErrorWhere{.field = field});
  }
}

}  // namespace

std::vector<double> reconstruction_breaks(const law::Law& kappa, const law::Law& tau, std::string_view parameter,
                                          double length) {
  check_law(kappa, "kappa");
  check_law(tau, "tau");
  require(std::isfinite(length) && length > 0.0, Errc::InvalidArgument,
          "length = " + format_number(length) + " must be > 0 and finite", "length");
  std::vector<double> breaks;
  analyse_singularities(kappa, parameter, length, "kappa", breaks);
  analyse_singularities(tau, parameter, length, "tau", breaks);
  return breaks;
}

IntrinsicCurve reconstruct_planar(const law::Law& kappa, std::string_view parameter, double length,
                                  const StartFrame& start, const ReconstructionOptions& options) {
  auto impl = prepare(kappa, parameter, length, start, options);
  {
    const law::Law one[1] = {kappa};
    (void)compile(one, parameter, "kappa");  // names "kappa" for a foreign parameter
  }
  std::vector<double> breaks;
  if (options.breaks)
    breaks = *options.breaks;
  else
    analyse_singularities(kappa, parameter, length, "kappa", breaks);
  set_breaks(*impl, std::move(breaks));
  // θ(s) = F(s) − F(0) when the antiderivative exists and κ has no pole or undefined region on
  // [0, L]. Only the closed form decides: no quadrature here (adaptive quadrature of a kinked κ,
  // e.g. a sum of hat functions, took minutes just to pick the method); the ODE reports an
  // undefined κ itself.
  const std::optional<law::DefiniteIntegralResult> total =
      law::symbolic_definite_integral(kappa, parameter, 0.0, length);
  if (total) {
    const law::Context ctx = kappa.context();
    const law::Law& F = total->antiderivative;
    // Shift by F(0) so that θ(0) = 0.
    const law::Law only_f[1] = {F};
    const law::Tape f_tape = compile(only_f, parameter, "kappa");
    double f0 = 0.0;
    const double in[1] = {0.0};
    if (!f_tape.evaluate(in, std::span<double>(&f0, 1)) || !std::isfinite(f0))
      throw Error(Errc::NumericalFailure, "the antiderivative of kappa is undefined at s = 0",
                  ErrorWhere{.field = "kappa"});
    const law::Law shifted[2] = {kappa, F - ctx.constant(f0)};
    impl->laws = compile(shifted, parameter, "kappa");
    impl->kind = IntegrationKind::PlanarExactAngle;
  } else {
    // No closed-form angle: the Frenet–Serret system with τ = 0 (its frame ODE keeps the
    // error estimate of RKF78 meaningful, unlike θ' = κ alone; see integrate_planar()).
    const law::Law outs[2] = {kappa, kappa.context().constant(0.0)};
    impl->laws = compile(outs, parameter, "kappa");
    impl->kind = IntegrationKind::PlanarNumericAngle;
  }
  if (impl->kind == IntegrationKind::PlanarExactAngle)
    impl->integrate_planar(options.max_steps);
  else
    impl->integrate(options.max_steps);
  return IntrinsicCurve(std::move(impl));
}

IntrinsicCurve reconstruct(const law::Law& kappa, const law::Law& tau, std::string_view parameter, double length,
                           const StartFrame& start, const ReconstructionOptions& options) {
  check_law(kappa, "kappa");
  check_law(tau, "tau");
  require(kappa.context() == tau.context(), Errc::InvalidArgument, "kappa and tau must belong to one law context",
          "tau");
  if (options.method == ReconstructionMethod::Auto && tau.is_constant() && tau.node().value == 0.0)
    return reconstruct_planar(kappa, parameter, length, start, options);
  auto impl = prepare(kappa, parameter, length, start, options);
  {
    const law::Law one[1] = {kappa};
    (void)compile(one, parameter, "kappa");
    const law::Law other[1] = {tau};
    (void)compile(other, parameter, "tau");
  }
  std::vector<double> breaks;
  if (options.breaks) {
    breaks = *options.breaks;
  } else {
    analyse_singularities(kappa, parameter, length, "kappa", breaks);
    analyse_singularities(tau, parameter, length, "tau", breaks);
  }
  set_breaks(*impl, std::move(breaks));
  impl->laws_name = "kappa and tau";
  const law::Law outs[2] = {kappa, tau};
  impl->laws = compile(outs, parameter, "kappa");
  impl->kind = IntegrationKind::FrenetSerret;
  impl->integrate(options.max_steps);
  return IntrinsicCurve(std::move(impl));
}

namespace {

// Quintic Hermite on u ∈ [0, 1] with end values p, first derivatives h·d and second h²·a.
Vec3 hermite(const FramePoint& a, const FramePoint& b, double h, double u) {
  const double u2 = u * u, u3 = u2 * u, u4 = u3 * u, u5 = u4 * u;
  const double h0 = 1 - 10 * u3 + 15 * u4 - 6 * u5;
  const double h1 = u - 6 * u3 + 8 * u4 - 3 * u5;
  const double h2 = 0.5 * u2 - 1.5 * u3 + 1.5 * u4 - 0.5 * u5;
  const double h3 = 0.5 * u3 - u4 + 0.5 * u5;
  const double h4 = -4 * u3 + 7 * u4 - 3 * u5;
  const double h5 = 10 * u3 - 15 * u4 + 6 * u5;
  return h0 * a.position + (h1 * h) * a.tangent + (h2 * h * h * a.curvature) * a.normal +
         (h3 * h * h * b.curvature) * b.normal + (h4 * h) * b.tangent + h5 * b.position;
}

// Largest deviation of the Hermite segment [a, b] from the curve at m interior samples.
double segment_deviation(const IntrinsicCurve& curve, const FramePoint& a, const FramePoint& b, int m) {
  const double h = b.s - a.s;
  double worst = 0.0;
  for (int j = 1; j <= m; ++j) {
    const double u = static_cast<double>(j) / (m + 1);
    const FramePoint r = curve.evaluate(a.s + u * h);
    worst = std::max(worst, distance(hermite(a, b, h, u), r.position));
  }
  return worst;
}

}  // namespace

NurbsFitResult fit_nurbs(const IntrinsicCurve& curve, const NurbsFitOptions& options) {
  options.validate();
  const double L = curve.length();
  double tolerance = options.tolerance;
  if (options.relative) {
    const std::vector<FramePoint> nodes = curve.evaluate(curve.nodes());
    Vec3 lo = nodes.front().position, hi = lo;
    for (const FramePoint& q : nodes)
      for (std::size_t k = 0; k < 3; ++k) {
        lo[k] = std::min(lo[k], q.position[k]);
        hi[k] = std::max(hi[k], q.position[k]);
      }
    const double size = distance(lo, hi);
    tolerance *= size > 0.0 ? size : L;
  }
  // Greedy longest segments within each smooth piece (header). Half the tolerance as the target
  // leaves room for the final, independent measurement on the NURBS itself.
  const double target = 0.5 * tolerance;
  const int m = options.check_samples;
  // Below this length a segment is accepted even if it misses the target (the tolerance is then
  // below what the integration resolves): converged = false.
  const double min_length = 1e-9 * L;
  std::vector<double> edges{0.0};
  edges.insert(edges.end(), curve.breakpoints().begin(), curve.breakpoints().end());
  edges.push_back(L);
  // The curve at a piece's end with κ from inside the piece (its one-sided limit, equal to κ there
  // unless κ jumps): κ at δ inside, δ far below any length the fit resolves.
  const auto piece_end = [&](double at, double inside) {
    FramePoint q = curve.evaluate(at);
    const double delta = std::min(1e-11 * std::max(1.0, L), 0.25 * std::abs(inside - at));
    q.curvature = curve.evaluate(at + std::copysign(delta, inside - at)).curvature;
    return q;
  };
  // Runs of breakpoints with C2 joins; a new run starts where κ jumps.
  std::vector<std::vector<FramePoint>> runs{{piece_end(0.0, edges[1])}};
  std::size_t segments = 0;
  bool converged = true;
  for (std::size_t e = 0; e + 1 < edges.size(); ++e) {
    const double end = edges[e + 1];
    const FramePoint last = piece_end(end, edges[e]);
    std::vector<FramePoint>& pts = runs.back();
    while (pts.back().s < end) {
      const FramePoint a = pts.back();
      ++segments;
      if (segments > options.max_segments) {
        // Out of budget: one segment to the end of the piece.
        pts.push_back(last);
        converged = false;
        break;
      }
      const auto fits = [&](const FramePoint& b) { return segment_deviation(curve, a, b, m) <= target; };
      FramePoint good = last;
      if (!fits(good)) {
        // Halve the remaining length until a segment fits, then bisect between fitting and failing ends.
        double fail = end, ok = a.s + 0.5 * (end - a.s);
        bool too_short = false;
        for (;;) {
          good = curve.evaluate(ok);
          if (fits(good)) break;
          fail = ok;
          if (ok - a.s <= min_length) {
            too_short = true;
            converged = false;
            break;
          }
          ok = a.s + 0.5 * (ok - a.s);
        }
        for (int step = 0; step < 8 && !too_short; ++step) {
          const double mid = 0.5 * (good.s + fail);
          const FramePoint trial = curve.evaluate(mid);
          if (fits(trial))
            good = trial;
          else
            fail = mid;
        }
      }
      pts.push_back(good);
    }
    if (e + 2 < edges.size()) {
      const FramePoint next = piece_end(end, edges[e + 2]);
      // κ jumps: r'' = κN jumps, so the join can only be C1 (a new run, knot multiplicity 5).
      if (std::abs(next.curvature - last.curvature) >
          1e-9 * std::max({1.0, std::abs(next.curvature), std::abs(last.curvature)}))
        runs.push_back({next});
    }
  }
  // Each run as a quintic Hermite (C2, triple knots) on its arc-length interval, then the runs
  // joined end to start with a knot of multiplicity 5 (the shared end point kept once).
  std::vector<double> knots;
  std::vector<Vec3> cps;
  for (const std::vector<FramePoint>& run : runs) {
    const double s0 = run.front().s, s1 = run.back().s, span = s1 - s0;
    std::vector<Vec3> p, d, a;
    std::vector<double> params;
    p.reserve(run.size());
    d.reserve(run.size());
    a.reserve(run.size());
    params.reserve(run.size());
    // hermite_quintic maps the parameters to [0, 1]: derivatives are given in that parameter
    // (d/dt = span d/ds), then the knots are mapped back to arc length.
    for (const FramePoint& q : run) {
      p.push_back(q.position);
      d.push_back(span * q.tangent);
      a.push_back((span * span * q.curvature) * q.normal);
      params.push_back(q.s);
    }
    const nurbs::NurbsCurve piece = nurbs::hermite_quintic(p, d, a, params, 3);
    const std::span<const double> u = piece.knots().values();
    const std::span<const Vec3> c = piece.control_points();
    // The unit knots end exactly at 0 and 1: the ends map exactly to s0 and s1.
    const auto to_s = [&](double k) { return k == 1.0 ? s1 : s0 + k * span; };
    if (knots.empty()) {
      for (std::size_t i = 0; i + 6 < u.size(); ++i) knots.push_back(to_s(u[i]));
      cps.assign(c.begin(), c.end());
    } else {
      for (std::size_t i = 6; i + 6 < u.size(); ++i) knots.push_back(to_s(u[i]));
      cps.insert(cps.end(), c.begin() + 1, c.end());
    }
    // The run's end: multiplicity 6 at L, 5 at a join (the next run's interior knots follow).
    knots.insert(knots.end(), &run == &runs.back() ? 6 : 5, s1);
  }
  nurbs::NurbsCurve fitted(5, std::move(knots), std::move(cps));
  // The deviation re-measured on the NURBS, segment by segment (consecutive points of each run).
  double worst = 0.0;
  for (const std::vector<FramePoint>& run : runs) {
    for (std::size_t i = 0; i + 1 < run.size(); ++i) {
      const double h = run[i + 1].s - run[i].s;
      for (int j = 1; j <= m; ++j) {
        const double at = run[i].s + h * static_cast<double>(j) / (m + 1);
        worst = std::max(worst, distance(fitted.derivatives(at, 0)[0], curve.evaluate(at).position));
      }
      worst = std::max(worst, distance(fitted.derivatives(run[i].s, 0)[0], run[i].position));
    }
    worst = std::max(worst, distance(fitted.derivatives(run.back().s, 0)[0], run.back().position));
  }
  if (!converged || worst > tolerance) return NurbsFitResult{std::move(fitted), worst, segments, tolerance, false};
  // Knot removal within what the fit left of the tolerance (The NURBS Book A5.8): the Hermite form
  // spends 3 control points per segment and keeps κ continuous only as C2; most of its knots come
  // out, and the removal's bound (rigorous against the fitted NURBS) keeps the result within the
  // tolerance. Measured again at the same samples.
  const nurbs::KnotRemovalResult reduced = nurbs::remove_knots(fitted, tolerance - worst);
  double reduced_worst = 0.0;
  for (const std::vector<FramePoint>& run : runs)
    for (std::size_t i = 0; i + 1 < run.size(); ++i) {
      const double h = run[i + 1].s - run[i].s;
      for (int j = 0; j <= m + 1; ++j) {
        const double at = j == m + 1 ? run[i + 1].s : run[i].s + h * static_cast<double>(j) / (m + 1);
        const Vec3 r = j == 0 ? run[i].position : j == m + 1 ? run[i + 1].position : curve.evaluate(at).position;
        reduced_worst = std::max(reduced_worst, distance(reduced.curve.derivatives(at, 0)[0], r));
      }
    }
  if (reduced_worst > tolerance) return NurbsFitResult{std::move(fitted), worst, segments, tolerance, true};
  return NurbsFitResult{reduced.curve, reduced_worst, segments, tolerance, true};
}

NurbsFitResult fit_nurbs_converged(const IntrinsicCurve& curve, const NurbsFitOptions& options) {
  NurbsFitResult fit = fit_nurbs(curve, options);
  if (!fit.converged)
    throw Error(Errc::NumericalFailure,
                "kappa: the NURBS fit does not hold the tolerance " + format_number(fit.tolerance) +
                    " within max_segments = " + std::to_string(options.max_segments) +
                    " segments (reached a deviation of " + format_number(fit.max_deviation) + ")",
                ErrorWhere{.field = "kappa"});
  return fit;
}

}  // namespace hula::intrinsic
