// SPDX-License-Identifier: MIT
// Root isolation by derivative splitting and TOMS 748 (see roots.hpp).
#include "hula/law/roots.hpp"

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <cmath>
#include <cstdint>
#include <string>

#include "hula/core/error.hpp"
#include "hula/law/derive.hpp"
#include "hula/law/tape.hpp"

namespace hula::law {

void RootOptions::validate() const {
  auto bad = [](const char* field, const std::string& why) {
    throw Error(Errc::InvalidOption, std::string("RootOptions::") + field + " " + why, ErrorWhere{.field = field});
  };
  if (samples < 2) bad("samples", "must be >= 2, got " + std::to_string(samples));
  if (derivative_levels < 0 || derivative_levels > 6)
    bad("derivative_levels", "must be in [0, 6], got " + std::to_string(derivative_levels));
  if (!(tolerance > 0 && tolerance <= 1e-3)) bad("tolerance", "must be in (0, 1e-3], got " + format_number(tolerance));
  if (!(value_tolerance >= 0 && value_tolerance <= 1e-3))
    bad("value_tolerance", "must be in [0, 1e-3], got " + format_number(value_tolerance));
}

namespace {

/// Evaluations of f^(k) per sign change: TOMS 748 needs a few tens; 200 bound a bisection to the tolerance.
constexpr std::uintmax_t kMaxEvaluations = 200;

/// f and its derivatives compiled once; value(k, t) = f^(k)(t) (NaN where undefined).
class Derivs {
 public:
  Derivs(const Law& f, std::string_view parameter, int levels) {
    const std::string p(parameter);
    std::vector<Law> laws = derivatives(f, p, levels + 1);
    const std::string in[1] = {p};
    tape_ = Tape::compile(laws, in);
    work_ = tape_.make_workspace();
    out_.resize(tape_.output_count());
  }
  double value(int k, double t) {
    if (t != last_t_) {
      (void)tape_.evaluate(std::span<const double>(&t, 1), out_, work_);
      last_t_ = t;
    }
    return out_[static_cast<std::size_t>(k)];
  }

 private:
  Tape tape_;
  Workspace work_;
  std::vector<double> out_;
  double last_t_ = std::numeric_limits<double>::quiet_NaN();
};

/// The sign change of f^(k) on [lo, hi] (f(lo), f(hi) of opposite signs) by Boost.Math's TOMS 748
/// (Alefeld–Potra–Shi): a true bracket kept by sign alone, so a pole or a jump is closed in on like a
/// root and find() tells them apart by |f| afterwards. A point where f^(k) is undefined is reported
/// to the solver as a zero, which stops it there (find() then sees NaN and keeps no root).
double refine(Derivs& d, int k, double lo, double hi, double flo, double fhi, double tol) {
  auto f = [&](double x) {
    const double v = d.value(k, x);
    return std::isnan(v) ? 0.0 : v;
  };
  auto narrow = [tol](double a, double b) { return b - a <= tol * std::max({1.0, std::fabs(a), std::fabs(b)}); };
  std::uintmax_t evaluations = kMaxEvaluations;
  const auto [a, b] = boost::math::tools::toms748_solve(f, lo, hi, flo, fhi, narrow, evaluations);
  return 0.5 * (a + b);
}

void add_root(std::vector<double>& out, double t) { out.push_back(t); }

/// Roots of f^(k) on [a, b] (see roots.hpp); sign changes that are not roots go to `unresolved`
/// when it is given (only for the top level: a pole of a derivative is no business of f's roots).
std::vector<double> find(Derivs& d, int k, int levels, double a, double b, const RootOptions& o, double scale,
                         std::vector<double>* unresolved = nullptr) {
  // Cuts: a uniform grid (which also isolates undefined regions) refined by the roots of the next
  // derivative, so f^(k) is monotone between consecutive cuts whenever k < levels.
  std::vector<double> cuts{a};
  for (std::size_t i = 1; i < o.samples; ++i)
    cuts.push_back(a + (b - a) * static_cast<double>(i) / static_cast<double>(o.samples));
  if (k < levels) {
    for (double c : find(d, k + 1, levels, a, b, o, scale))
      if (c > a && c < b) cuts.push_back(c);
    std::sort(cuts.begin(), cuts.end());
  }
  cuts.push_back(b);
  // value scale of f^(k) for the even-multiplicity test
  double fmax = 0.0;
  for (double c : cuts) {
    const double v = d.value(k, c);
    if (std::isfinite(v)) fmax = std::max(fmax, std::fabs(v));
  }
  (void)scale;
  double dmax = 0.0;
  for (double c : cuts) {
    const double v = d.value(k + 1, c);
    if (std::isfinite(v)) dmax = std::max(dmax, std::fabs(v));
  }
  std::vector<double> out;
  const double vt = o.value_tolerance * fmax;
  const double vt_d = 1e-6 * dmax;
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    const double c = cuts[i];
    const double fc = d.value(k, c);
    const bool interior_cut = i > 0 && i + 1 < cuts.size();
    // even-multiplicity roots sit at critical points (|f| tiny where f' = 0)
    const bool critical = interior_cut && k < levels && std::fabs(d.value(k + 1, c)) <= vt_d;
    if (fc == 0.0 || (critical && std::fabs(fc) <= vt)) add_root(out, c);
    if (i + 1 == cuts.size()) break;
    const double n = cuts[i + 1];
    const double fn = d.value(k, n);
    // An isolated undefined cut between values of opposite signs (a cut landing exactly on the
    // pole of 1/(t − 1)) is a sign change without a root.
    if (unresolved != nullptr && std::isnan(fc) && interior_cut && !std::isnan(fn) && fn != 0.0) {
      const double fp = d.value(k, cuts[i - 1]);
      if (!std::isnan(fp) && fp != 0.0 && (fp < 0) != (fn < 0)) unresolved->push_back(c);
    }
    if (std::isnan(fc) || std::isnan(fn) || fc == 0.0 || fn == 0.0) continue;
    if ((fc < 0) != (fn < 0)) {
      const double x = refine(d, k, c, n, fc, fn, o.tolerance);
      const double fx = std::fabs(d.value(k, x));
      // A root makes |f| fall: to the value tolerance, or well below both bracket ends. A pole
      // (|f| grows) or a jump (|f| stays) keeps a sign change without a root. Inner levels keep
      // every sign change: a jump of f^(k+1) is still a cut that makes f^(k) monotone between cuts.
      if (unresolved == nullptr || fx <= vt || fx <= 1e-3 * std::min(std::fabs(fc), std::fabs(fn)))
        add_root(out, x);
      else
        unresolved->push_back(x);
    }
  }
  std::sort(out.begin(), out.end());
  std::vector<double> merged;
  for (double r : out)
    if (merged.empty() || r - merged.back() > 4 * o.tolerance * std::max(1.0, std::fabs(r))) merged.push_back(r);
  // ends: a root exactly at an end is reported once (the end itself)
  return merged;
}

void check_args(const Law& f, double a, double b, const char* what) {
  if (!f.valid() || f.dimension() != 1)
    throw Error(Errc::InvalidArgument, std::string(what) + ": expects a scalar law");
  if (!(std::isfinite(a) && std::isfinite(b) && a < b))
    throw Error(Errc::InvalidArgument, std::string(what) + ": needs a finite interval a < b, got [" + format_number(a) +
                                           ", " + format_number(b) + "]");
}

}  // namespace

RootReport find_roots(const Law& f, std::string_view parameter, double a, double b, const RootOptions& options) {
  options.validate();
  check_args(f, a, b, "roots");
  Derivs d(f, parameter, options.derivative_levels);
  RootReport r;
  r.roots = find(d, 0, options.derivative_levels, a, b, options, 1.0, &r.unresolved);
  std::sort(r.unresolved.begin(), r.unresolved.end());
  return r;
}

std::vector<double> roots(const Law& f, std::string_view parameter, double a, double b, const RootOptions& options) {
  return find_roots(f, parameter, a, b, options).roots;
}

ExtremaResult extrema(const Law& f, std::string_view parameter, double a, double b, const RootOptions& options) {
  options.validate();
  check_args(f, a, b, "extrema");
  Derivs d(f, parameter, options.derivative_levels + 1);
  std::vector<double> crit = find(d, 1, options.derivative_levels + 1, a, b, options, 1.0);
  ExtremaResult r;
  std::vector<double> ts{a};
  for (double c : crit)
    if (c > a && c < b) ts.push_back(c);
  ts.push_back(b);
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const double t = ts[i];
    const double v = d.value(0, t);
    if (std::isnan(v)) continue;
    // compare with the values a little inside the neighbouring pieces
    const double h = 1e-6 * (b - a);
    const double left = i > 0 ? d.value(0, std::max(a, t - std::min(h, 0.5 * (t - ts[i - 1])))) : std::nan("");
    const double right =
        i + 1 < ts.size() ? d.value(0, std::min(b, t + std::min(h, 0.5 * (ts[i + 1] - t)))) : std::nan("");
    ExtremumKind kind;
    const bool above_l = std::isnan(left) || left >= v;
    const bool above_r = std::isnan(right) || right >= v;
    const bool below_l = std::isnan(left) || left <= v;
    const bool below_r = std::isnan(right) || right <= v;
    if (above_l && above_r)
      kind = ExtremumKind::Minimum;
    else if (below_l && below_r)
      kind = ExtremumKind::Maximum;
    else
      kind = ExtremumKind::Stationary;
    r.points.push_back({t, v, kind});
  }
  if (r.points.empty())
    throw Error(Errc::NumericalFailure, "extrema: the law is undefined at both ends and every critical point");
  r.minimum = *std::min_element(r.points.begin(), r.points.end(),
                                [](const Extremum& x, const Extremum& y) { return x.value < y.value; });
  r.maximum = *std::max_element(r.points.begin(), r.points.end(),
                                [](const Extremum& x, const Extremum& y) { return x.value < y.value; });
  return r;
}

}  // namespace hula::law
