// SPDX-License-Identifier: MIT
// Law ↔ NURBS conversion (see convert.hpp). Quintic Hermite basis on a
// segment of length h in the local variable s ∈ [0, 1]:
//   p(s) = H0 P0 + H1 h V0 + H2 h² A0 + H3 h² A1 + H4 h V1 + H5 P1,
//   H0 = 1 − 10s³ + 15s⁴ − 6s⁵, H1 = s − 6s³ + 8s⁴ − 3s⁵, H2 = (s² − 3s³ + 3s⁴ − s⁵)/2,
//   H3 = (s³ − 2s⁴ + s⁵)/2,     H4 = −4s³ + 7s⁴ − 3s⁵,   H5 = 10s³ − 15s⁴ + 6s⁵.
#include "hula/law/convert.hpp"

#include <array>
#include <cmath>
#include <span>
#include <string>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/law/tape.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/nurbs/refine.hpp"

namespace hula::law {

Law from_nurbs(const nurbs::NurbsCurve& curve, const Context& context, std::string_view parameter,
               std::string_view name) {
  return context.curve(curve, context.parameter(parameter), name);
}

void ToNurbsOptions::validate() const {
  auto bad = [](const char* field, const std::string& why) {
    throw Error(Errc::InvalidOption, std::string("ToNurbsOptions::") + field + " " + why, ErrorWhere{.field = field});
  };
  if (!(tolerance > 0 && std::isfinite(tolerance)))
    bad("tolerance", "must be > 0 and finite, got " + format_number(tolerance));
  if (max_segments < 1) bad("max_segments", "must be >= 1");
  if (initial_segments < 1 || initial_segments > max_segments)
    bad("initial_segments", "must be in [1, max_segments], got " + std::to_string(initial_segments));
  if (check_samples < 2) bad("check_samples", "must be >= 2, got " + std::to_string(check_samples));
  if (verify_samples < 2) bad("verify_samples", "must be >= 2, got " + std::to_string(verify_samples));
}

namespace {

struct Sample {
  Vec3 p, d1, d2;
};

class Sampler {
 public:
  Sampler(const Law& law, std::string_view parameter) : ev_(law, std::string(parameter), 2), name_(parameter) {}
  Sample at(double t) const {
    std::array<Vec3, 3> out;
    if (!ev_.derivatives(t, out))
      throw Error(Errc::NumericalFailure, "to_nurbs: the law or its first two derivatives are undefined at " + name_ +
                                              " = " + format_number(t));
    return {out[0], out[1], out[2]};
  }
  Vec3 position(double t) const {
    std::array<Vec3, 3> out;
    (void)ev_.derivatives(t, out);
    return out[0];
  }

 private:
  CurveEvaluator ev_;
  std::string name_;
};

Vec3 hermite(const Sample& a, const Sample& b, double h, double s) {
  const double s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s;
  const double H0 = 1 - 10 * s3 + 15 * s4 - 6 * s5;
  const double H1 = s - 6 * s3 + 8 * s4 - 3 * s5;
  const double H2 = 0.5 * (s2 - 3 * s3 + 3 * s4 - s5);
  const double H3 = 0.5 * (s3 - 2 * s4 + s5);
  const double H4 = -4 * s3 + 7 * s4 - 3 * s5;
  const double H5 = 10 * s3 - 15 * s4 + 6 * s5;
  return H0 * a.p + (H1 * h) * a.d1 + (H2 * h * h) * a.d2 + (H3 * h * h) * b.d2 + (H4 * h) * b.d1 + H5 * b.p;
}

}  // namespace

ToNurbsResult to_nurbs(const Law& law, std::string_view parameter, double a, double b, const ToNurbsOptions& options) {
  options.validate();
  if (!law.valid() || law.dimension() == 1)
    throw Error(Errc::InvalidArgument, "to_nurbs: expects a 2- or 3-vector law, got a scalar");
  if (!(std::isfinite(a) && std::isfinite(b) && a < b))
    throw Error(Errc::InvalidArgument,
                "to_nurbs: needs a finite interval a < b, got [" + format_number(a) + ", " + format_number(b) + "]");
  const Sampler f(law, parameter);
  // Breakpoints with their samples; refine by bisection until every segment passes its check.
  std::vector<double> ts;
  std::vector<Sample> ss;
  for (std::size_t i = 0; i <= options.initial_segments; ++i) {
    const double t = i == options.initial_segments
                         ? b
                         : a + (b - a) * static_cast<double>(i) / static_cast<double>(options.initial_segments);
    ts.push_back(t);
    ss.push_back(f.at(t));
  }
  // The end sample takes its derivatives from inside the interval: at a knot of a NURBS leaf the evaluator
  // gives the right-hand derivatives, and where they jump (an interval ending at a break of the law's
  // smoothness) the last Hermite segment would follow the next span and never converge.
  {
    const Sample inside = f.at(std::nextafter(b, a));
    ss.back().d1 = inside.d1;
    ss.back().d2 = inside.d2;
  }
  const double check_tol = 0.5 * options.tolerance;
  for (int round = 0;; ++round) {
    std::vector<double> nts{ts[0]};
    std::vector<Sample> nss{ss[0]};
    bool refined = false;
    for (std::size_t i = 0; i + 1 < ts.size(); ++i) {
      const double h = ts[i + 1] - ts[i];
      double err = 0.0;
      for (std::size_t k = 1; k < options.check_samples; ++k) {
        // offset samples so they do not coincide with the midpoint a bisection would test again
        const double s = (static_cast<double>(k) - 0.37) / static_cast<double>(options.check_samples - 1);
        err = std::max(err, distance(f.position(ts[i] + s * h), hermite(ss[i], ss[i + 1], h, s)));
      }
      if (err > check_tol && !(h > 1e-12 * std::max(1.0, std::fabs(ts[i]))))
        // Bisected down to rounding and still off by more than the tolerance: the law jumps here (a
        // comparison, a step), and no C2 curve follows it within the tolerance.
        throw Error(Errc::NumericalFailure, "to_nurbs: the law is not continuous near " + std::string(parameter) +
                                                " = " + format_number(ts[i]) + " (still " + format_number(err) +
                                                " off at the finest step; tolerance " +
                                                format_number(options.tolerance) + ")");
      if (err > check_tol) {
        const double m = 0.5 * (ts[i] + ts[i + 1]);
        nts.push_back(m);
        nss.push_back(f.at(m));
        refined = true;
      }
      nts.push_back(ts[i + 1]);
      nss.push_back(ss[i + 1]);
    }
    ts = std::move(nts);
    ss = std::move(nss);
    if (ts.size() - 1 > options.max_segments)
      throw Error(Errc::NumericalFailure, "to_nurbs: tolerance " + format_number(options.tolerance) +
                                              " not reached within " + std::to_string(options.max_segments) +
                                              " segments (ToNurbsOptions::max_segments)");
    if (!refined) break;
  }
  // Build the NURBS on [0, 1] (hermite_quintic's convention: derivatives w.r.t. the mapped
  // parameter u = (t − a)/(b − a), so scaled by (b − a) and (b − a)²), then map the knots back.
  const double L = b - a;
  std::vector<Vec3> pts, d1, d2;
  std::vector<double> us;
  for (std::size_t i = 0; i < ts.size(); ++i) {
    pts.push_back(ss[i].p);
    d1.push_back(ss[i].d1 * L);
    d2.push_back(ss[i].d2 * (L * L));
    us.push_back(i + 1 == ts.size() ? 1.0 : (ts[i] - a) / L);
  }
  const int dim = law.dimension() == 2 ? 2 : 3;
  const nurbs::NurbsCurve unit = nurbs::hermite_quintic(pts, d1, d2, us, dim);
  ToNurbsResult r{
      nurbs::NurbsCurve(unit.knots().reparameterised({a, b}),
                        std::vector<Vec3>(unit.control_points().begin(), unit.control_points().end()), {}, dim),
      0.0, 0, ts.size() - 1};
  r.control_points = r.curve.control_points().size();
  // Independent verification: dense samples of the finished NURBS against the law.
  for (std::size_t i = 0; i + 1 < ts.size(); ++i)
    for (std::size_t k = 0; k <= options.verify_samples; ++k) {
      const double t =
          ts[i] + (ts[i + 1] - ts[i]) * static_cast<double>(k) / static_cast<double>(options.verify_samples);
      r.max_deviation = std::max(r.max_deviation, distance(f.position(t), r.curve.evaluate(std::min(t, b))));
    }
  if (r.max_deviation > options.tolerance && options.check_samples < 1024) {
    // The refinement checks missed a bump between their samples: refine again with 4× the checks.
    ToNurbsOptions denser = options;
    denser.check_samples = options.check_samples * 4;
    return to_nurbs(law, parameter, a, b, denser);
  }
  return r;
}

namespace {

// Power-basis coefficients a_j of the Bernstein coefficients b_k of degree p: a_j = C(p, j) Σ_k (−1)^(j−k) C(j, k) b_k.
std::vector<double> power_basis(const std::vector<double>& b) {
  const std::size_t p = b.size() - 1;
  auto binomial = [](std::size_t n, std::size_t k) {
    double r = 1.0;
    for (std::size_t i = 1; i <= k; ++i) r = r * static_cast<double>(n - k + i) / static_cast<double>(i);
    return r;
  };
  std::vector<double> a(p + 1, 0.0);
  for (std::size_t j = 0; j <= p; ++j) {
    double sum = 0.0;
    for (std::size_t k = 0; k <= j; ++k) sum += ((j - k) % 2 == 0 ? 1.0 : -1.0) * binomial(j, k) * b[k];
    a[j] = binomial(p, j) * sum;
  }
  return a;
}

Law horner(const std::vector<double>& a, const Law& s, const Context& context) {
  Law acc = context.constant(a.back());
  for (std::size_t j = a.size() - 1; j-- > 0;) acc = acc * s + a[j];
  return acc;
}

Law balanced(const std::vector<Law>& spans, const std::vector<double>& starts, const Law& t, const Context& context,
             std::size_t lo, std::size_t hi) {
  if (lo == hi) return spans[lo];
  const std::size_t mid = (lo + hi + 1) / 2;
  return piecewise(less(t, context.constant(starts[mid])), balanced(spans, starts, t, context, lo, mid - 1),
                   balanced(spans, starts, t, context, mid, hi));
}

}  // namespace

Law explicit_from_nurbs(const nurbs::NurbsCurve& curve, const Context& context, std::string_view parameter) {
  const Law t = context.parameter(parameter);
  const bool rational = curve.is_rational();
  const int dim = curve.dimension() == 2 ? 2 : 3;
  std::vector<Law> spans;
  std::vector<double> starts;
  for (const nurbs::NurbsCurve& piece : nurbs::decompose_to_bezier(curve)) {
    const Interval d = piece.domain();
    const Law s = (t - d.start) / (d.end - d.start);
    const std::span<const Vec3> P = piece.control_points();
    const std::span<const double> W = piece.weights();
    std::array<std::vector<double>, 3> xyz;
    std::vector<double> w;
    for (std::size_t k = 0; k < P.size(); ++k) {
      const double wk = rational && !W.empty() ? W[k] : 1.0;
      // Rational: the homogeneous coordinates w P; the weights their own polynomial.
      const double m = rational ? wk : 1.0;
      xyz[0].push_back(m * P[k].x);
      xyz[1].push_back(m * P[k].y);
      xyz[2].push_back(m * P[k].z);
      w.push_back(wk);
    }
    std::array<Law, 3> c{horner(power_basis(xyz[0]), s, context), horner(power_basis(xyz[1]), s, context),
                         horner(power_basis(xyz[2]), s, context)};
    if (rational) {
      const Law den = horner(power_basis(w), s, context);
      for (Law& ci : c) ci = ci / den;
    }
    spans.push_back(dim == 2 ? vec(c[0], c[1]) : vec(c[0], c[1], c[2]));
    starts.push_back(d.start);
  }
  return balanced(spans, starts, t, context, 0, spans.size() - 1);
}

}  // namespace hula::law
