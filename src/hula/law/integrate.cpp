// SPDX-License-Identifier: MIT
// Adaptive Gauss–Kronrod, tanh-sinh, exp-sinh and sinh-sinh integration of
// compiled laws, with the growth analysis of singular ends (see integrate.hpp).
#include "hula/law/integrate.hpp"

#include <algorithm>
#include <boost/math/quadrature/exp_sinh.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/quadrature/sinh_sinh.hpp>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/core/nan.hpp"
#include "hula/law/detail/improper.hpp"
#include "hula/law/detail/short_print.hpp"
#include "hula/law/parser.hpp"
#include "hula/law/simplify.hpp"
#include "hula/law/singularities.hpp"
#include "hula/law/tape.hpp"

namespace hula::law {

using detail::short_print;

bool detail::is_improper_kind(SingularityKind k) noexcept {
  switch (k) {
    case SingularityKind::DivisionByZero:
    case SingularityKind::SqrtBoundary:
    case SingularityKind::LogBoundary:
    case SingularityKind::PowerBase:
    case SingularityKind::InverseTrigBound:
    case SingularityKind::TanPole:
    case SingularityKind::Atan2Origin:
    case SingularityKind::NormalizeZero:
      return true;
    default:
      return false;
  }
}

Law detail::shifted_law(const Law& f, std::string_view parameter, double t0, double dir) {
  if (t0 == 0.0 && dir > 0.0) return f;
  const Context ctx = f.context();
  const Law p = ctx.parameter(parameter);
  const Law moved = substitute(f, parameter, dir > 0.0 ? ctx.constant(t0) + p : ctx.constant(t0) - p);
  return simplify(moved);
}

double detail::growth_exponent(const Law& g, std::string_view parameter, double w) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  const std::string in[1] = {std::string(parameter)};
  const Law outs[1] = {g};
  const Tape tape = Tape::compile(outs, in);
  auto at = [&](double u) {
    double v = 0.0;
    return tape.evaluate(std::span<const double>(&u, 1), std::span<double>(&v, 1)) ? v : kNaN;
  };
  const double u2 = w * 1e-8, u3 = w * 1e-12;
  const double f2 = std::fabs(at(u2)), f3 = std::fabs(at(u3));
  if (std::isnan(f2) || std::isnan(f3)) return kNaN;
  if (std::isinf(f3)) return -kInf;
  if (f3 == 0.0) return kInf;
  if (f2 == 0.0) return 0.0;
  return std::log(f3 / f2) / std::log(u3 / u2);
}

void IntegrationOptions::validate() const {
  if (!(relative_tolerance >= 1e-15 && relative_tolerance <= 0.1))
    throw Error(
        Errc::InvalidOption,
        "IntegrationOptions::relative_tolerance must be in [1e-15, 0.1], got " + format_number(relative_tolerance),
        ErrorWhere{.field = "relative_tolerance"});
  if (max_depth < 1 || max_depth > 40)
    throw Error(Errc::InvalidOption,
                "IntegrationOptions::max_depth must be in [1, 40], got " + std::to_string(max_depth),
                ErrorWhere{.field = "max_depth"});
}

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
using detail::kGrowthSlack;
// Refinement levels of the double-exponential rules (each doubles the nodes; Boost's default is 15
// for tanh-sinh): options.max_depth, capped here.
constexpr int kMaxDoubleExponentialLevels = 15;

// A compiled scalar law of the parameter; NaN where undefined.
class Scalar {
 public:
  Scalar(const Law& f, std::string_view parameter) : tape_(compile(f, parameter)), work_(tape_.make_workspace()) {}
  double operator()(double t) const {
    double v = 0.0;
    if (!tape_.evaluate(std::span<const double>(&t, 1), std::span<double>(&v, 1), work_)) return kNaN;
    return v;
  }

 private:
  static Tape compile(const Law& f, std::string_view parameter) {
    const std::string in[1] = {std::string(parameter)};
    const Law outs[1] = {f};
    return Tape::compile(outs, in);
  }
  Tape tape_;
  mutable Workspace work_;
};

// p of |g(u)| ≈ C u^p as u → +infinity, from u = s·1e4 and s·1e8 (−infinity when g vanishes there
// faster than any power, +infinity when it overflows).
double growth_at_infinity(const Scalar& g, double s) {
  const double u2 = s * 1e4, u3 = s * 1e8;
  const double f2 = std::fabs(g(u2)), f3 = std::fabs(g(u3));
  if (std::isnan(f2) || std::isnan(f3)) return kNaN;
  if (f3 == 0.0) return -kInf;
  if (std::isinf(f3)) return kInf;
  if (f2 == 0.0) return 0.0;
  return std::log(f3 / f2) / std::log(u3 / u2);
}

struct Piece {
  double value = 0.0;
  double error = 0.0;
  double l1 = 0.0;
};

[[noreturn]] void undefined_at(std::string_view parameter, double t) {
  throw Error(Errc::NumericalFailure,
              "integrate: the integrand is undefined at " + std::string(parameter) + " = " + format_number(t));
}

class Integration {
 public:
  Integration(const Law& f, std::string_view parameter, const IntegrationOptions& options)
      : f_(f), name_(parameter), options_(options), direct_(f, parameter) {}

  IntegrationResult run(double lo, double hi) {
    if (!std::isfinite(lo) || !std::isfinite(hi)) {
      infinite(lo, hi);
    } else {
      finite(lo, hi);
    }
    std::sort(result_.singular_points.begin(), result_.singular_points.end(),
              [](const SingularPoint& x, const SingularPoint& y) { return x.t < y.t; });
    // An interior point was classified from each side: one entry with the faster growth.
    std::vector<SingularPoint> merged;
    for (SingularPoint& s : result_.singular_points) {
      if (!merged.empty() && merged.back().t == s.t) {
        merged.back().exponent = std::min(merged.back().exponent, s.exponent);
        merged.back().integrable = merged.back().integrable && s.integrable;
      } else {
        merged.push_back(std::move(s));
      }
    }
    result_.singular_points = std::move(merged);
    return std::move(result_);
  }

 private:
  int levels() const { return std::min(options_.max_depth, kMaxDoubleExponentialLevels); }

  void add(const Piece& p) {
    result_.value += p.value;
    result_.error_estimate += p.error;
    result_.l1_norm += p.l1;
    ++result_.pieces;
  }

  void diverge() {
    result_.divergent = true;
    result_.value = kNaN;
    result_.error_estimate = kInf;
  }

  // Records the behaviour of f at the end t0 of [t0, t0 + dir·w] (dir = ±1) and returns the law of u.
  // nullopt when the end is not integrable.
  std::optional<Law> classify_end(double t0, double dir, double w, const std::string& expression) {
    const Law g = detail::shifted_law(f_, name_, t0, dir);
    const double p = detail::growth_exponent(g, name_, w);
    if (std::isnan(p)) undefined_at(name_, t0 + dir * w * 1e-12);
    const bool integrable = detail::integrable_growth(p);
    result_.singular_points.push_back({t0, expression, p, integrable});
    result_.improper = true;
    if (!integrable) return std::nullopt;
    return g;
  }

  Piece gauss_kronrod(double a, double b) {
    auto g = [&](double t) {
      const double v = direct_(t);
      if (std::isnan(v)) undefined_at(name_, t);
      return v;
    };
    using Rule = boost::math::quadrature::gauss_kronrod<double, 61>;
    Piece p;
    p.value = Rule::integrate(g, a, b, static_cast<unsigned>(options_.max_depth), options_.relative_tolerance, &p.error,
                              &p.l1);
    return p;
  }

  // ∫_0^w g(u) du by tanh-sinh, g = f(t0 + dir·u) (the integral over the original piece is that times 1:
  // dt = dir du and the bounds swap with dir).
  Piece tanh_sinh(const Law& g, double t0, double dir, double w) {
    const Scalar gs(g, name_);
    auto fn = [&](double u) {
      const double v = gs(u);
      if (std::isnan(v)) undefined_at(name_, t0 + dir * u);
      return v;
    };
    boost::math::quadrature::tanh_sinh<double> rule(static_cast<std::size_t>(levels()));
    Piece p;
    try {
      p.value = rule.integrate(fn, 0.0, w, options_.relative_tolerance, &p.error, &p.l1);
    } catch (const std::domain_error&) {
      p = {kNaN, kInf, kInf};
    } catch (const std::overflow_error&) {
      p = {kNaN, kInf, kInf};
    }
    return p;
  }

  void finite(double lo, double hi) {
    // Cuts at every kink, switch and pole; the hazardous ones (poles, boundaries) keyed by position.
    std::vector<double> cuts{lo};
    std::vector<std::pair<double, std::string>> hazards;
    if (options_.split_at_singularities) {
      const SingularityReport rep = singularities(f_, name_, lo, hi);  // points increasing in t
      for (const Singularity& s : rep.points) {
        if (s.t > cuts.back() && s.t < hi) cuts.push_back(s.t);
        if (detail::is_improper_kind(s.kind)) hazards.emplace_back(s.t, s.expression);
      }
      // An undefined region of positive length is an error; one that shrinks onto a point (1/0 sampled
      // exactly at a pole) is that point.
      const double close = 1e-9 * (hi - lo);
      for (const UndefinedInterval& u : rep.undefined) {
        double mid = std::clamp(0.5 * (u.start + u.end), lo, hi);
        if (u.end - u.start > close) undefined_at(name_, mid);
        // The point is the root already found there (or an end), not the middle of the bisected bracket.
        for (const double x : {lo, hi})
          if (std::fabs(x - mid) <= close) mid = x;
        for (const double x : cuts)
          if (std::fabs(x - mid) <= close) mid = x;
        if (mid > lo && mid < hi) cuts.push_back(mid);
        hazards.emplace_back(mid, short_print(f_));
      }
      std::sort(cuts.begin(), cuts.end());
      cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    }
    // An end where f itself is not finite is hazardous too (log t at 0).
    for (const double end : {lo, hi})
      if (!std::isfinite(direct_(end))) hazards.emplace_back(end, short_print(f_));
    auto hazard_at = [&](double t) -> const std::string* {
      for (const auto& [x, e] : hazards)
        if (x == t) return &e;
      return nullptr;
    };
    // Classify every hazardous end of every piece first: a divergent piece makes the whole integral
    // divergent, whatever the others give.
    struct Plan {
      double a, b;
      std::optional<Law> left, right;  // shifted laws for the double-exponential rule
    };
    std::vector<Plan> plans;
    cuts.push_back(hi);
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
      Plan plan{cuts[i], cuts[i + 1], std::nullopt, std::nullopt};
      const double w = plan.b - plan.a;
      const std::string* left = hazard_at(plan.a);
      const std::string* right = hazard_at(plan.b);
      // With both ends singular each half takes one (a double-exponential rule from 0 per end).
      const double half = left && right ? 0.5 * w : w;
      if (left) {
        plan.left = classify_end(plan.a, 1.0, half, *left);
        if (!plan.left) diverge();
      }
      if (right) {
        plan.right = classify_end(plan.b, -1.0, half, *right);
        if (!plan.right) diverge();
      }
      plans.push_back(std::move(plan));
    }
    if (result_.divergent) return;
    for (const Plan& plan : plans) {
      const double w = plan.b - plan.a;
      if (plan.left && plan.right) {
        add(tanh_sinh(*plan.left, plan.a, 1.0, 0.5 * w));
        add(tanh_sinh(*plan.right, plan.b, -1.0, 0.5 * w));
      } else if (plan.left) {
        add(tanh_sinh(*plan.left, plan.a, 1.0, w));
      } else if (plan.right) {
        add(tanh_sinh(*plan.right, plan.b, -1.0, w));
      } else {
        add(gauss_kronrod(plan.a, plan.b));
      }
    }
  }

  // One piece reaching ±infinity: exp-sinh from the finite end (moved to 0), sinh-sinh for the whole line.
  void infinite(double lo, double hi) {
    result_.improper = true;
    const std::string expr = short_print(f_);
    Piece p;
    try {
      if (std::isinf(lo) && std::isinf(hi)) {
        for (const double dir : {-1.0, 1.0}) {
          const double q = growth_at_infinity(Scalar(detail::shifted_law(f_, name_, 0.0, dir), name_), 1.0);
          const bool ok = q < -1.0 - kGrowthSlack;
          result_.singular_points.push_back({dir * kInf, expr, q, ok});
          if (!ok) diverge();
        }
        if (result_.divergent) return;
        auto fn = [&](double t) {
          const double v = direct_(t);
          if (std::isnan(v)) undefined_at(name_, t);
          return v;
        };
        boost::math::quadrature::sinh_sinh<double> rule(static_cast<std::size_t>(levels()));
        p.value = rule.integrate(fn, options_.relative_tolerance, &p.error, &p.l1);
      } else {
        const double end = std::isinf(lo) ? hi : lo;
        const double dir = std::isinf(lo) ? -1.0 : 1.0;
        const Law g = detail::shifted_law(f_, name_, end, dir);
        const Scalar gs(g, name_);
        const double q = growth_at_infinity(gs, std::max(1.0, std::fabs(end)));
        const bool ok = q < -1.0 - kGrowthSlack;
        result_.singular_points.push_back({dir * kInf, expr, q, ok});
        if (!ok) {
          diverge();
          return;
        }
        auto fn = [&](double u) {
          const double v = gs(u);
          if (std::isnan(v)) undefined_at(name_, end + dir * u);
          return v;
        };
        boost::math::quadrature::exp_sinh<double> rule(static_cast<std::size_t>(levels()));
        p.value = rule.integrate(fn, 0.0, kInf, options_.relative_tolerance, &p.error, &p.l1);
      }
    } catch (const std::domain_error&) {
      p = {kNaN, kInf, kInf};
    } catch (const std::overflow_error&) {
      p = {kNaN, kInf, kInf};
    }
    add(p);
  }

  Law f_;
  std::string name_;
  IntegrationOptions options_;
  Scalar direct_;
  IntegrationResult result_;
};

}  // namespace

IntegrationResult integrate(const Law& f, std::string_view parameter, double a, double b,
                            const IntegrationOptions& options) {
  options.validate();
  if (!f.valid() || f.dimension() != 1) throw Error(Errc::InvalidArgument, "integrate: expects a scalar law");
  if (std::isnan(a) || std::isnan(b))
    throw Error(Errc::InvalidArgument,
                "integrate: bounds must be numbers, got [" + format_number(a) + ", " + format_number(b) + "]");
  IntegrationResult r;
  if (a == b) {
    r.converged = true;
    return r;
  }
  const double sign = a < b ? 1.0 : -1.0;
  r = Integration(f, parameter, options).run(std::min(a, b), std::max(a, b));
  if (r.divergent) return r;
  r.value *= sign;
  r.converged =
      std::isfinite(r.value) && (r.error_estimate <= options.relative_tolerance * r.l1_norm || r.l1_norm == 0.0);
  return r;
}

}  // namespace hula::law
