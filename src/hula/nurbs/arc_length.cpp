// SPDX-License-Identifier: MIT
// Arc length by adaptive Gauss–Kronrod quadrature (the 7/15-point pair of
// QUADPACK's qk15; Piessens et al. 1983) on every non-empty knot span, where
// the speed |C'(t)| is smooth (analytic except where C' vanishes), and its
// inverse by Newton's method on s(t) - s, bracketed and safeguarded by
// bisection (Boost.Math's newton_raphson_iterate).
//
// Error control: on [x0, x1] of width h the estimate |K15 - G7| must be at
// most tolerance × L0 × h / (b - a), L0 being a first estimate of the length
// on the requested interval, so the accepted pieces add up to at most
// tolerance × L0. An estimate within 50 ulps of the piece's magnitude is
// accepted as rounding noise. Bisection stops at kMaxDepth levels or after
// kMaxEvaluations + kEvaluationsPerSpan × (number of spans) speed evaluations
// with Errc::NumericalFailure: the budget scales with the curve, so a valid
// 300,000-span cubic is integrated, and a pathological span still ends.
#include "hula/nurbs/arc_length.hpp"

#include <algorithm>
#include <array>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/core/huge_pages.hpp"
#include "hula/core/parallel.hpp"
#include "hula/nurbs/piece_evaluator.hpp"

namespace hula::nurbs {

namespace {

// QUADPACK's qk15 pair from Boost.Math's tables: the non-negative Kronrod nodes of [-1, 1], increasing
// from 0, the even indices being the Gauss 7-point nodes (gauss<double, 7> holds their weights at
// index / 2). Both are references to static arrays, so a rule costs no allocation.
using Kronrod15 = boost::math::quadrature::gauss_kronrod<double, 15>;
using Gauss7 = boost::math::quadrature::gauss<double, 7>;

constexpr int kMaxDepth = 48;
// Newton iterations of parameter_at_length (bisections included): 100 halvings exhaust any bracket.
constexpr std::uintmax_t kMaxNewtonIterations = 100;
constexpr long kMaxEvaluations = 2'000'000;
// 32 GK15 rules per span: a smooth span needs one to a few.
constexpr long kEvaluationsPerSpan = 32 * 15;
constexpr long kRuleEvaluations = 15;
// Pieces from which a length is computed on several threads, and pieces per task.
constexpr std::size_t kParallelPieces = 16384;
constexpr std::size_t kPiecesPerTask = 4096;

struct GkResult {
  double kronrod;
  double error;  // |K15 - G7|
};

// One thread's span pieces and its count of speed evaluations.
struct Worker {
  explicit Worker(const NurbsCurve& curve) : pieces(curve) {}
  PieceEvaluator pieces;
  long evaluations = 0;
};

// Integrates |C'| with adaptive bisection; allocation-free (recursion on the stack).
//
// On a curve of many spans both passes run on several threads, and the result is that of one thread
// bit for bit: every piece's estimate and adaptive integral is computed by the same operations wherever
// it runs, and the sums are taken in span order afterwards. The evaluation budget is global (the count
// of every piece before it): a thread counts each piece's evaluations from zero and stops a piece only
// where the run on one thread would certainly have stopped too; the sum in span order then adds the
// counts, and from the first piece whose count could have crossed the budget (or that stopped) the rest
// is integrated again on one thread, which gives the one-thread run's result or error exactly.
class SpeedIntegrator {
 public:
  SpeedIntegrator(const NurbsCurve& curve, double tolerance, std::size_t threads)
      : curve_(curve),
        main_(curve),
        tolerance_(tolerance),
        threads_(threads),
        breaks_(curve.knots().breakpoints()),
        budget_(kMaxEvaluations + kEvaluationsPerSpan * static_cast<long>(breaks_.size())) {}

  double speed(double t) {
    ++main_.evaluations;
    double v = 0.0;
    main_.pieces.speeds(std::span<const double>(&t, 1), std::span<double>(&v, 1));
    return v;
  }

  // The 15 nodes of a rule at once, in increasing order (one span located once, their speeds computed
  // together by the SIMD speed kernel: the same values as one call per node). A long curve is evaluated
  // one span's piece at a time (PieceEvaluator: the same values without building the curve's cache).
  static GkResult gk15(Worker& w, double x0, double x1) {
    const auto& x = Kronrod15::abscissa();
    const auto& wk = Kronrod15::weights();
    const auto& wg = Gauss7::weights();
    constexpr std::size_t m = 7;  // nodes on each side of the centre
    static_assert(std::tuple_size_v<std::remove_cvref_t<decltype(x)>> == m + 1);
    static_assert(2 * m + 1 == kRuleEvaluations);
    const double c = 0.5 * (x0 + x1);
    const double h = 0.5 * (x1 - x0);
    std::array<double, 2 * m + 1> ts;
    ts[m] = c;
    for (std::size_t j = 1; j <= m; ++j) {
      const double dx = h * x[j];
      ts[m - j] = c - dx;
      ts[m + j] = c + dx;
    }
    std::array<double, 2 * m + 1> speed;
    w.pieces.speeds(ts, speed);
    w.evaluations += kRuleEvaluations;
    const double fc = speed[m];
    double k = fc * wk[0];
    double g = fc * wg[0];
    for (std::size_t j = 1; j <= m; ++j) {
      const double f = speed[m - j] + speed[m + j];
      k += wk[j] * f;
      if (j % 2 == 0) g += wg[j / 2] * f;
    }
    return {k * h, std::fabs((k - g) * h)};
  }

  // Adaptive integral over [x0, x1] with per-unit-width error budget `density`; fails once w's count
  // exceeds `cap`.
  double adapt(Worker& w, double x0, double x1, const GkResult& est, double density, int depth, long cap) const {
    const double width = x1 - x0;
    const double noise = 50.0 * std::numeric_limits<double>::epsilon() * std::fabs(est.kronrod);
    if (est.error <= std::max(density * width, noise)) return est.kronrod;
    const double mid = 0.5 * (x0 + x1);
    if (depth >= kMaxDepth || w.evaluations > cap || !(mid > x0 && mid < x1)) fail(x0, x1, w.evaluations);
    const GkResult left = gk15(w, x0, mid);
    const GkResult right = gk15(w, mid, x1);
    return adapt(w, x0, mid, left, density, depth + 1, cap) + adapt(w, mid, x1, right, density, depth + 1, cap);
  }

  // Length over [a, b] (inside the domain), integrating span by span.
  double integrate(double a, double b) {
    if (!(a < b)) return 0.0;
    // The spans meeting (a, b), lo … hi − 1 (every piece cut to [a, b] is non-empty; the others are).
    const std::size_t spans = breaks_.size() - 1;
    const auto first = breaks_.begin();
    const auto lo = static_cast<std::size_t>(std::upper_bound(first + 1, breaks_.end(), a) - (first + 1));
    const auto hi =
        static_cast<std::size_t>(std::lower_bound(first, first + static_cast<std::ptrdiff_t>(spans), b) - first);
    const std::size_t count = hi - lo;
    // First pass: one GK15 per span piece gives L0 for the error budget.
    // The estimates are kept (16 bytes a span, allocated once at their final size, not zero-filled: a
    // million-span curve grew them by doubling, and the copies and page faults were a tenth of
    // `hula info`); each piece's ends are computed again, the same way, in the second pass.
    if (capacity_ < count) {
      estimates_.reset(new GkResult[count]);
      advise_huge_pages(estimates_.get(), count * sizeof(GkResult));
      capacity_ = count;
    }
    GkResult* const est = estimates_.get();
    const bool parallel = count >= kParallelPieces && threads_ != 1;
    if (parallel) {
      for_tasks(lo, hi, [&](Worker& w, std::size_t s) {
        const auto [x0, x1] = piece(a, b, s);
        est[s - lo] = gk15(w, x0, x1);
      });
      main_.evaluations += kRuleEvaluations * static_cast<long>(count);
    } else {
      for (std::size_t s = lo; s < hi; ++s) {
        const auto [x0, x1] = piece(a, b, s);
        est[s - lo] = gk15(main_, x0, x1);
      }
    }
    double l0 = 0.0;
    for (std::size_t e = 0; e < count; ++e) l0 += est[e].kronrod;
    const double density = tolerance_ * l0 / (b - a);
    double total = 0.0;
    std::size_t next = lo;  // the first piece not yet added
    if (parallel) {
      // Second pass on the threads: each piece's integral and its own evaluation count replace its estimate
      // (NaN: stopped, for the budget as counted from the lowest possible start or for any other error).
      const long start = main_.evaluations;
      for_tasks(lo, hi, [&](Worker& w, std::size_t s) {
        const auto [x0, x1] = piece(a, b, s);
        w.evaluations = 0;
        GkResult& r = est[s - lo];
        try {
          r = {adapt(w, x0, x1, r, density, 0, budget_ - start), static_cast<double>(w.evaluations)};
        } catch (const Error&) {
          r = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()};
        }
      });
      for (; next < hi; ++next) {
        const GkResult& r = est[next - lo];
        if (std::isnan(r.error) || main_.evaluations + static_cast<long>(r.error) > budget_) break;
        total += r.kronrod;
        main_.evaluations += static_cast<long>(r.error);
      }
    }
    // One thread: from the start, or where the threads' result could differ from its own (the estimate is
    // computed again, uncounted: the first pass counted it).
    for (std::size_t s = next; s < hi; ++s) {
      const auto [x0, x1] = piece(a, b, s);
      GkResult e = est[s - lo];
      if (parallel) {
        e = gk15(main_, x0, x1);
        main_.evaluations -= kRuleEvaluations;
      }
      total += adapt(main_, x0, x1, e, density, 0, budget_);
    }
    return total;
  }

 private:
  [[noreturn]] void fail(double x0, double x1, long evaluations) const {
    throw Error(Errc::NumericalFailure,
                "arc length: tolerance = " + format_number(tolerance_) + " not met on [" + format_number(x0) + ", " +
                    format_number(x1) + "] within the recursion budget (" + std::to_string(evaluations) +
                    " evaluations)",
                {.field = "tolerance"});
  }

  // body(worker, s) for every span s in [lo, hi), in tasks of kPiecesPerTask consecutive spans, each task
  // with its own worker, on up to threads_ threads; an error is the lowest span's (hula::parallel_for).
  template <class Body>
  void for_tasks(std::size_t lo, std::size_t hi, const Body& body) const {
    const std::size_t tasks = (hi - lo + kPiecesPerTask - 1) / kPiecesPerTask;
    parallel_for(0, tasks,
                 [&](std::size_t task) {
                   Worker w(curve_);
                   const std::size_t s0 = lo + task * kPiecesPerTask;
                   const std::size_t s1 = std::min(hi, s0 + kPiecesPerTask);
                   for (std::size_t s = s0; s < s1; ++s) body(w, s);
                 },
                 {.threads = threads_, .grain = 1});
  }

  // Span s of the curve cut to [a, b] (empty when x0 >= x1).
  [[nodiscard]] std::pair<double, double> piece(double a, double b, std::size_t s) const {
    return {std::max(a, breaks_[s]), std::min(b, breaks_[s + 1])};
  }

  const NurbsCurve& curve_;
  Worker main_;
  double tolerance_;
  std::size_t threads_;
  std::vector<double> breaks_;
  long budget_;
  std::unique_ptr<GkResult[]> estimates_;
  std::size_t capacity_ = 0;
};

void check_parameter(const char* name, double t, const Interval& d) {
  if (!std::isfinite(t))
    throw Error(Errc::NonFiniteInput, std::string(name) + " = " + format_number(t) + " is not finite", {.field = name});
  if (t < d.start || t > d.end)
    throw Error(Errc::OutOfDomain,
                std::string(name) + " = " + format_number(t) + " is outside the curve domain [" +
                    format_number(d.start) + ", " + format_number(d.end) + "]",
                {.field = name});
}

}  // namespace

void ArcLengthOptions::validate() const {
  if (!(tolerance >= 1e-15 && tolerance <= 1e-2))
    throw Error(Errc::InvalidOption, "options.tolerance = " + format_number(tolerance) + " must be in [1e-15, 1e-2]",
                {.field = "tolerance"});
}

double arc_length(const NurbsCurve& curve, double a, double b, const ArcLengthOptions& options) {
  options.validate();
  const Interval d = curve.domain();
  check_parameter("a", a, d);
  check_parameter("b", b, d);
  if (a > b)
    throw Error(Errc::InvalidArgument, "a = " + format_number(a) + " is greater than b = " + format_number(b),
                {.field = "a"});
  SpeedIntegrator integrator(curve, options.tolerance, options.threads);
  return integrator.integrate(a, b);
}

double arc_length(const NurbsCurve& curve, const ArcLengthOptions& options) {
  const Interval d = curve.domain();
  return arc_length(curve, d.start, d.end, options);
}

double parameter_at_length(const NurbsCurve& curve, double s, const ArcLengthOptions& options) {
  options.validate();
  if (!std::isfinite(s))
    throw Error(Errc::NonFiniteInput, "s = " + format_number(s) + " is not finite", {.field = "s"});
  if (s < 0.0)
    throw Error(Errc::OutOfDomain, "s = " + format_number(s) + " is negative; arc length runs from 0", {.field = "s"});
  SpeedIntegrator integrator(curve, options.tolerance, options.threads);
  const Interval d = curve.domain();
  const std::vector<double> breaks = curve.knots().breakpoints();
  // Cumulative length at each breakpoint brackets s in one span.
  std::vector<double> cumulative(breaks.size(), 0.0);
  for (std::size_t i = 1; i < breaks.size(); ++i)
    cumulative[i] = cumulative[i - 1] + integrator.integrate(breaks[i - 1], breaks[i]);
  const double total = cumulative.back();
  if (s > total * (1.0 + options.tolerance))
    throw Error(Errc::OutOfDomain,
                "s = " + format_number(s) + " exceeds the curve length " + format_number(total) + " (tolerance " +
                    format_number(options.tolerance) + ")",
                {.field = "s"});
  if (s >= total) return d.end;
  if (s == 0.0) return d.start;
  const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), s);
  const auto span = static_cast<std::size_t>(std::max<std::ptrdiff_t>(1, it - cumulative.begin())) - 1;
  const double lo = breaks[span];
  const double hi = breaks[std::min(span + 1, breaks.size() - 1)];
  const double base = cumulative[span];
  const double target = s - base;
  const double span_length = cumulative[span + 1] - base;
  if (!(span_length > 0.0)) return lo;
  // Initial guess: linear in the span's length.
  const double guess = lo + (hi - lo) * std::clamp(target / span_length, 0.0, 1.0);
  const double goal = options.tolerance * std::max(total, std::numeric_limits<double>::min());
  // Newton on s(t) − s by Boost.Math's bracketed newton_raphson_iterate (a step leaving the bracket, or
  // two steps that do not halve, become bisections). Convergence is |s(t) − s| ≤ goal, reported to Boost
  // as a zero residual: its own test is on the step relative to t, which never passes at t = 0, and
  // serves only as the rounding-level stop (full double digits).
  bool converged = false;
  auto residual = [&](double t) {
    const double f = integrator.integrate(breaks[span], t) - target;
    converged = std::fabs(f) <= goal;
    return std::pair{converged ? 0.0 : f, integrator.speed(t)};
  };
  std::uintmax_t iterations = kMaxNewtonIterations;
  double t = guess;
  try {
    t = boost::math::tools::newton_raphson_iterate(residual, guess, lo, hi, std::numeric_limits<double>::digits,
                                                   iterations);
  } catch (const boost::math::evaluation_error&) {
    converged = false;  // the bracket lost its sign change (rounding in the integral): reported below
  }
  if (!converged && iterations >= kMaxNewtonIterations)
    throw Error(Errc::NumericalFailure, "parameter_at_length: no convergence for s = " + format_number(s),
                {.field = "s"});
  return t;
}

}  // namespace hula::nurbs
