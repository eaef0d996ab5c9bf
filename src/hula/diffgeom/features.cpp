// SPDX-License-Identifier: MIT
// Sign-change search with bisection for inflections and curvature extrema;
// see features.hpp.
#include "hula/diffgeom/features.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/diffgeom/frenet_law.hpp"
#include "hula/law/derive.hpp"
#include "hula/law/parser.hpp"
#include "hula/law/tape.hpp"

namespace hula::diffgeom {

namespace {
using Eval = std::function<FrenetPoint(double)>;
using Quantity = double (*)(const FrenetPoint&);

double signed_kappa(const FrenetPoint& p) { return p.tangent_defined ? p.signed_curvature : std::nan(""); }
double kappa_prime(const FrenetPoint& p) { return p.frame_defined ? p.curvature_derivative : std::nan(""); }

int sign(double x) { return x > 0.0 ? 1 : (x < 0.0 ? -1 : 0); }

// Values of the searched quantity at many parameters (out[i] at ts[i]), evaluated as a batch.
using Sample = std::function<void(std::span<const double>, std::span<double>)>;

// Roots with a strict sign change of q over the pieces [cuts[i], cuts[i+1]], each sampled at n points.
// A zero sample (or run of zero samples) between samples of opposite signs is itself the root (exact
// inflections, also at knots).
// `sample` gives the searched quantity on the n samples of a piece at once, `value` at one parameter (the
// bisection); a root where it falls from + to − is `falling`, else `rising`.
void search(const Eval& eval, const Sample& sample, const std::function<double(double)>& value,
            const std::vector<double>& cuts, int n, FeatureKind falling, FeatureKind rising,
            std::vector<Feature>& out) {
  std::vector<double> ts(static_cast<std::size_t>(n)), vs(static_cast<std::size_t>(n));
  // One pass over all spans, so a zero sample at a knot is judged by the signs on both sides.
  double t_prev = cuts.front();
  double q_prev = value(t_prev);
  double t_zero = std::nan("");  // a zero sample waiting for the next sign
  int s_before = sign(q_prev);
  for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
    const double a = cuts[c], b = cuts[c + 1];
    for (int i = 1; i <= n; ++i) ts[static_cast<std::size_t>(i - 1)] = i == n ? b : a + (b - a) * i / n;
    sample(ts, vs);
    for (int i = 1; i <= n; ++i) {
      const double t = ts[static_cast<std::size_t>(i - 1)];
      const double v = vs[static_cast<std::size_t>(i - 1)];
      const int s = sign(v);
      if (std::isnan(v) || std::isnan(q_prev)) {
        t_prev = t;
        q_prev = v;
        s_before = sign(v);
        t_zero = std::nan("");
        continue;
      }
      double root = std::nan("");
      int from = 0;
      if (s == 0 && sign(q_prev) != 0) {
        t_zero = t;  // decide when the sign after it is known
      } else if (s != 0 && sign(q_prev) == 0 && !std::isnan(t_zero)) {
        if (s_before != 0 && s != s_before) {
          root = t_zero;
          from = s_before;
        }
        t_zero = std::nan("");
      } else if (s != 0 && sign(q_prev) != 0 && s != sign(q_prev)) {
        // Bisection on [t_prev, t]: halves the bracket until it stops shrinking (~1 ulp).
        double lo = t_prev, hi = t;
        const int s_lo = sign(q_prev);
        for (int it = 0; it < 200; ++it) {
          const double mid = 0.5 * (lo + hi);
          if (mid <= lo || mid >= hi) break;
          const double vm = value(mid);
          if (std::isnan(vm)) break;
          if (sign(vm) == 0) {
            lo = hi = mid;
            break;
          }
          (sign(vm) == s_lo ? lo : hi) = mid;
        }
        root = 0.5 * (lo + hi);
        from = s_lo;
      }
      if (!std::isnan(root)) {
        const FrenetPoint p = eval(root);
        Feature f;
        f.kind = from > 0 ? falling : rising;
        f.t = root;
        f.position = p.position;
        f.curvature = f.kind == FeatureKind::Inflection ? 0.0 : p.curvature;
        f.torsion = p.torsion;
        if (out.empty() || out.back().t != root || out.back().kind != f.kind) out.push_back(f);
      }
      if (s != 0) s_before = s;
      t_prev = t;
      q_prev = v;
    }
  }
}

std::vector<double> nurbs_cuts(const nurbs::NurbsCurve& curve) { return curve.knots().breakpoints(); }
std::vector<double> law_cuts(nurbs::Interval d) {
  std::vector<double> c;
  for (int i = 0; i <= 64; ++i) c.push_back(d.start + d.length() * i / 64.0);
  c.back() = d.end;
  return c;
}
// Sign changes that happen across an interior knot (a jump of κ_s or dκ/ds between one-sided limits),
// which the per-span sampling cannot see; the results stay sorted by t.
void knot_jumps(const nurbs::NurbsCurve& curve, const FrenetOptions& o, Quantity q, bool extrema,
                std::vector<Feature>& out) {
  const std::vector<double> bp = curve.knots().breakpoints();
  FrenetOptions left = o, right = o;
  left.eval.side = nurbs::Side::Left;
  right.eval.side = nurbs::Side::Right;
  for (std::size_t i = 1; i + 1 < bp.size(); ++i) {
    const FrenetPoint l = frenet(curve, bp[i], left), r = frenet(curve, bp[i], right);
    const int sl = sign(q(l)), sr = sign(q(r));
    if (sl == 0 || sr == 0 || sl == sr) continue;
    Feature f;
    f.kind =
        !extrema ? FeatureKind::Inflection : (sl > 0 ? FeatureKind::CurvatureMaximum : FeatureKind::CurvatureMinimum);
    f.t = bp[i];
    f.position = r.position;
    f.curvature = extrema ? std::max(l.curvature, r.curvature) : 0.0;
    const auto at = std::lower_bound(out.begin(), out.end(), f.t, [](const Feature& a, double t) { return a.t < t; });
    if (at == out.end() || at->t != f.t) out.insert(at, f);
  }
}

Eval nurbs_eval(const nurbs::NurbsCurve& curve, const FrenetOptions& o) {
  return [&curve, o](double t) { return frenet(curve, t, o); };
}

// q of the Frenet points at ts, from a batch Frenet evaluator; `points` is the reused scratch buffer.
template <class Frenet>
Sample frenet_sample(Frenet batch, Quantity q, std::vector<FrenetPoint>& points) {
  return [batch, q, &points](std::span<const double> ts, std::span<double> out) {
    points.resize(ts.size());
    batch(ts, std::span<FrenetPoint>(points.data(), ts.size()));
    for (std::size_t i = 0; i < ts.size(); ++i) out[i] = q(points[i]);
  };
}
Sample nurbs_sample(const nurbs::NurbsCurve& curve, const FrenetOptions& o, Quantity q,
                    std::vector<FrenetPoint>& points) {
  return frenet_sample([&curve, o](std::span<const double> ts, std::span<FrenetPoint> p) { frenet(curve, ts, p, o); },
                       q, points);
}
// q sampled through an exact Frenet evaluator (LawFrenet or CurveFrenet).
template <class Exact>
Sample law_sample(const Exact& curve, Quantity q, std::vector<FrenetPoint>& points) {
  return frenet_sample([&curve](std::span<const double> ts, std::span<FrenetPoint> p) { curve.at(ts, p); }, q, points);
}

// The one significance rule of every extremum search (features.hpp): persistence simplification of the
// sequence start, extrema..., end on `value` (κ or τ of each feature). While the closest neighbouring
// pair differs by at most the floor, it goes: a maximum and a minimum side by side cancel, an extremum
// next to an end goes alone. Undefined values never cancel.
void keep_significant(std::vector<Feature>& extrema, double start_value, double end_value, bool curvature,
                      double significance) {
  const auto value = [curvature](const Feature& f) { return curvature ? f.curvature : f.torsion; };
  // An extremum of a quantity that is undefined there (τ where the frame is, at a knot where it jumps) is none.
  std::erase_if(extrema, [&](const Feature& f) { return !std::isfinite(value(f)); });
  if (extrema.empty()) return;
  const auto is_max = [](const Feature& f) {
    return f.kind == FeatureKind::CurvatureMaximum || f.kind == FeatureKind::TorsionMaximum;
  };
  double largest = 0.0;
  for (const double v : {start_value, end_value})
    if (std::isfinite(v)) largest = std::max(largest, std::fabs(v));
  for (const Feature& f : extrema)
    if (std::isfinite(value(f))) largest = std::max(largest, std::fabs(value(f)));
  const double limit = significance * largest;
  // Node i: the start (i = 0), extrema[i - 1], the end (i = n + 1); `alive` marks the ones kept.
  const std::size_t n = extrema.size();
  std::vector<char> alive(n + 2, 1);
  const auto at = [&](std::size_t i) { return i == 0 ? start_value : i == n + 1 ? end_value : value(extrema[i - 1]); };
  for (;;) {
    double best = HUGE_VAL;
    std::size_t a_best = 0, b_best = 0;
    std::size_t a = 0;
    for (std::size_t b = 1; b < n + 2; ++b) {
      if (!alive[b]) continue;
      // Two extrema of one kind side by side have an unreported turn between them (the zero of |κ| at an
      // inflection): equal or not, both stand.
      const bool candidate = a == 0 ? b != n + 1 : b == n + 1 || is_max(extrema[a - 1]) != is_max(extrema[b - 1]);
      const double d = std::fabs(at(a) - at(b));
      if (candidate && std::isfinite(d) && d < best) {
        best = d;
        a_best = a;
        b_best = b;
      }
      a = b;
    }
    if (!(best <= limit)) break;
    if (a_best == 0) {
      alive[b_best] = 0;
    } else if (b_best == n + 1) {
      alive[a_best] = 0;
    } else {
      alive[a_best] = alive[b_best] = 0;  // a maximum and a minimum that cancel
    }
  }
  std::vector<Feature> kept;
  for (std::size_t i = 0; i < n; ++i)
    if (alive[i + 1]) kept.push_back(extrema[i]);
  extrema = std::move(kept);
}

// κ (curvature) or τ at the domain ends, for keep_significant.
std::pair<double, double> end_values(const Eval& eval, nurbs::Interval d, bool curvature) {
  const FrenetPoint a = eval(d.start), b = eval(d.end);
  const auto v = [curvature](const FrenetPoint& p) {
    return curvature ? (p.tangent_defined ? p.curvature : std::nan(""))
                     : (p.torsion_defined ? p.torsion : std::nan(""));
  };
  return {v(a), v(b)};
}
}  // namespace

void FeatureOptions::validate() const {
  frenet.validate();
  if (samples_per_span < 2 || samples_per_span > 100000)
    throw Error(Errc::InvalidOption,
                "samples_per_span = " + std::to_string(samples_per_span) + " must be in [2, 100000]",
                {.field = "samples_per_span"});
  if (!(significance >= 0.0 && significance <= 1e-3))
    throw Error(Errc::InvalidOption, "significance = " + format_number(significance) + " must be in [0, 1e-3]",
                {.field = "significance"});
}

std::string_view feature_kind_name(FeatureKind kind) noexcept {
  switch (kind) {
    case FeatureKind::Inflection:
      return "inflection";
    case FeatureKind::CurvatureMaximum:
      return "curvature-maximum";
    case FeatureKind::CurvatureMinimum:
      return "curvature-minimum";
    case FeatureKind::TorsionMaximum:
      return "torsion-maximum";
    case FeatureKind::TorsionMinimum:
      return "torsion-minimum";
  }
  return "unknown";
}

std::vector<Feature> inflections(const nurbs::NurbsCurve& curve, const FeatureOptions& options) {
  options.validate();
  std::vector<Feature> out;
  const Eval eval = nurbs_eval(curve, options.frenet);
  std::vector<FrenetPoint> points;
  search(
      eval, nurbs_sample(curve, options.frenet, signed_kappa, points), [&](double t) { return signed_kappa(eval(t)); },
      nurbs_cuts(curve), options.samples_per_span, FeatureKind::Inflection, FeatureKind::Inflection, out);
  knot_jumps(curve, options.frenet, signed_kappa, false, out);
  return out;
}

std::vector<Feature> curvature_extrema(const nurbs::NurbsCurve& curve, const FeatureOptions& options) {
  options.validate();
  std::vector<Feature> out;
  const Eval eval = nurbs_eval(curve, options.frenet);
  std::vector<FrenetPoint> points;
  search(
      eval, nurbs_sample(curve, options.frenet, kappa_prime, points), [&](double t) { return kappa_prime(eval(t)); },
      nurbs_cuts(curve), options.samples_per_span, FeatureKind::CurvatureMaximum, FeatureKind::CurvatureMinimum, out);
  knot_jumps(curve, options.frenet, kappa_prime, true, out);
  const auto [a, b] = end_values(eval, curve.domain(), true);
  keep_significant(out, a, b, true, options.significance);
  return out;
}

namespace {
template <class Exact>
std::vector<Feature> law_inflections(const Exact& curve, Interval domain, const FeatureOptions& options) {
  std::vector<Feature> out;
  const Eval eval = [&curve](double t) { return curve.at(t); };
  std::vector<FrenetPoint> points;
  search(
      eval, law_sample(curve, signed_kappa, points), [&](double t) { return signed_kappa(eval(t)); }, law_cuts(domain),
      options.samples_per_span, FeatureKind::Inflection, FeatureKind::Inflection, out);
  return out;
}

template <class Exact>
std::vector<Feature> law_curvature_extrema(const Exact& curve, Interval domain, const FeatureOptions& options) {
  std::vector<Feature> out;
  const Eval eval = [&curve](double t) { return curve.at(t); };
  std::vector<FrenetPoint> points;
  search(
      eval, law_sample(curve, kappa_prime, points), [&](double t) { return kappa_prime(eval(t)); }, law_cuts(domain),
      options.samples_per_span, FeatureKind::CurvatureMaximum, FeatureKind::CurvatureMinimum, out);
  const auto [a, b] = end_values(eval, domain, true);
  keep_significant(out, a, b, true, options.significance);
  return out;
}
}  // namespace

namespace {
// Defined below with the law searches: a natural curve's features from its own laws κ(s), τ(s).
std::vector<Feature> natural_inflections(const curve::Curve& c, const curve::NaturalData& d);
std::vector<Feature> natural_extrema(const curve::Curve& c, const curve::NaturalData& d, bool curvature,
                                     double significance);
}  // namespace

std::vector<Feature> inflections(const curve::Curve& curve, const FeatureOptions& options) {
  options.validate();
  if (const auto* n = std::get_if<curve::NaturalData>(&curve.data())) return natural_inflections(curve, *n);
  if (!curve.law()) return inflections(curve.nurbs(), options);
  return law_inflections(LawFrenet(*curve.law_evaluator(3), curve.domain(), options.frenet), curve.domain(), options);
}

std::vector<Feature> curvature_extrema(const curve::Curve& curve, const FeatureOptions& options) {
  options.validate();
  if (const auto* n = std::get_if<curve::NaturalData>(&curve.data()))
    return natural_extrema(curve, *n, true, options.significance);
  if (!curve.law()) return curvature_extrema(curve.nurbs(), options);
  return law_curvature_extrema(LawFrenet(*curve.law_evaluator(3), curve.domain(), options.frenet), curve.domain(),
                               options);
}

namespace {
// Sign changes of dτ/dt from the derivatives r … r'''' of a NURBS or of a curve value (natural curves:
// exact κ, τ and their derivatives), sampled over `cuts`.
template <class C>
std::vector<Feature> derivative_torsion_extrema(const C& curve, const FrenetScale& scale, const Eval& eval,
                                                const std::vector<double>& cuts, const FeatureOptions& options) {
  const FrenetOptions fo = options.frenet;
  // The sign of dτ/dt (= sign of dτ/ds): with a = r' × r'', a' = r' × r''',
  // dτ/dt = [(a' · r''' + a · r'''') |a|² − 2 (a · r''') (a · a')] / |a|⁴; only the numerator is needed.
  auto dtau_of = [&scale, fo](double t, std::span<const Vec3> d) {
    const FrenetPoint p = frenet_from_derivatives(t, std::span<const Vec3, 4>(d.data(), 4), scale, fo);
    if (!p.frame_defined) return std::nan("");
    const Vec3 a = cross(d[1], d[2]), a1 = cross(d[1], d[3]);
    return (dot(a1, d[3]) + dot(a, d[4])) * dot(a, a) - 2.0 * dot(a, d[3]) * dot(a, a1);
  };
  auto dtau = [&curve, fo, &dtau_of](double t) {
    std::array<Vec3, 5> d;
    const std::array<double, 1> ts{t};
    curve.derivatives(ts, 4, d, fo.eval);
    return dtau_of(t, d);
  };
  std::vector<Vec3> derivs;
  auto sample = [&curve, fo, &dtau_of, &derivs](std::span<const double> ts, std::span<double> vs) {
    derivs.resize(5 * ts.size());
    curve.derivatives(ts, 4, derivs, fo.eval);
    for (std::size_t i = 0; i < ts.size(); ++i) vs[i] = dtau_of(ts[i], std::span<const Vec3>(derivs.data() + 5 * i, 5));
  };
  std::vector<Feature> out;
  search(eval, sample, dtau, cuts, options.samples_per_span, FeatureKind::TorsionMaximum, FeatureKind::TorsionMinimum,
         out);
  const auto [a, b] = end_values(eval, curve.domain(), false);
  keep_significant(out, a, b, false, options.significance);
  return out;
}
}  // namespace

std::vector<Feature> torsion_extrema(const nurbs::NurbsCurve& curve, const FeatureOptions& options) {
  options.validate();
  return derivative_torsion_extrema(curve, frenet_scale(curve, options.frenet.tolerance),
                                    nurbs_eval(curve, options.frenet), nurbs_cuts(curve), options);
}

namespace {
// The curve as a 3-vector law (2-vector laws embedded in z = 0), after checking the inputs.
law::Law law_curve3(const law::Law& curve, nurbs::Interval domain) {
  if (!curve.valid() || (curve.dimension() != 2 && curve.dimension() != 3))
    throw Error(Errc::InvalidArgument, "the curve law must be a 2- or 3-vector", {.field = "law"});
  if (!std::isfinite(domain.start) || !std::isfinite(domain.end) || !(domain.start < domain.end))
    throw Error(Errc::InvalidArgument,
                "domain [" + format_number(domain.start) + ", " + format_number(domain.end) +
                    "] must be finite with start < end",
                {.field = "domain"});
  if (curve.dimension() == 3) return curve;
  return law::vec(law::term(curve, 1), law::term(curve, 2), curve.context().constant(0.0));
}

// The interior parameters where the scalar law g changes sign: its roots and, since a curvature that
// changes sign through a jump (a join of two arcs turning opposite ways) is an inflection too, the sign
// changes without a root; a root is kept when g has opposite signs half-way to its neighbouring roots
// (or the ends).
std::vector<double> sign_changes(const law::Law& g, std::string_view parameter, nurbs::Interval domain,
                                 const law::RootOptions& roots) {
  const law::RootReport found = law::find_roots(g, parameter, domain.start, domain.end, roots);
  std::vector<double> zeros = found.roots;
  zeros.insert(zeros.end(), found.unresolved.begin(), found.unresolved.end());
  std::sort(zeros.begin(), zeros.end());
  const std::string name(parameter);
  const law::Tape tape = law::Tape::compile(std::span<const law::Law>(&g, 1), std::span<const std::string>(&name, 1));
  auto g_at = [&tape](double t) {
    double v = 0.0;
    tape.evaluate(std::span<const double>(&t, 1), std::span<double>(&v, 1));
    return v;
  };
  std::vector<double> out;
  for (std::size_t i = 0; i < zeros.size(); ++i) {
    const double t = zeros[i];
    if (!(t > domain.start && t < domain.end)) continue;
    const double left = 0.5 * (t + (i > 0 ? zeros[i - 1] : domain.start));
    const double right = 0.5 * (t + (i + 1 < zeros.size() ? zeros[i + 1] : domain.end));
    const double gl = g_at(left), gr = g_at(right);
    if ((gl < 0.0 && gr > 0.0) || (gl > 0.0 && gr < 0.0)) out.push_back(t);
  }
  return out;
}

// A natural curve's own laws: the signed curvature κ(s) and the torsion τ(s) of its natural equations,
// compiled together; its parameter is the arc length s on [0, L] (curve::NaturalData).
class NaturalLaws {
 public:
  explicit NaturalLaws(const curve::NaturalData& d) : parameter_(d.parameter), domain_{0.0, d.length} {
    law::ParseOptions o;
    o.parameters = {d.parameter};
    kappa_ = law::parse(d.curvature, context_, o);
    tau_ = law::parse(d.torsion, context_, o);
    const std::array<law::Law, 2> both{kappa_, tau_};
    tape_ = std::make_unique<law::Tape>(law::Tape::compile(both, std::span<const std::string>(&parameter_, 1)));
  }
  [[nodiscard]] const law::Law& kappa() const { return kappa_; }
  [[nodiscard]] const law::Law& tau() const { return tau_; }
  [[nodiscard]] const std::string& parameter() const { return parameter_; }
  [[nodiscard]] nurbs::Interval domain() const { return domain_; }
  // {κ_s(s), τ(s)}.
  [[nodiscard]] std::array<double, 2> at(double s) const {
    std::array<double, 2> v{};
    tape_->evaluate(std::span<const double>(&s, 1), v);
    return v;
  }
  [[nodiscard]] Feature feature(const curve::Curve& c, double s, FeatureKind kind) const {
    const auto [k, t] = at(s);
    return {.kind = kind, .t = s, .position = c.point(s), .curvature = std::fabs(k), .torsion = t};
  }

 private:
  law::Context context_;
  std::string parameter_;
  nurbs::Interval domain_;
  law::Law kappa_, tau_;
  std::unique_ptr<law::Tape> tape_;
};

std::vector<Feature> natural_inflections(const curve::Curve& c, const curve::NaturalData& d) {
  const NaturalLaws n(d);
  std::vector<Feature> out;
  for (const double s : sign_changes(n.kappa(), n.parameter(), n.domain(), {}))
    out.push_back(n.feature(c, s, FeatureKind::Inflection));
  for (Feature& f : out) f.curvature = 0.0;
  return out;
}

// Extrema of κ = |κ_s| (curvature) or of τ from the exact laws, by the one significance rule. An extremum
// of κ_s where κ_s < 0 is the opposite extremum of |κ_s|; where κ_s = 0 it is an inflection, not an
// extremum of κ (as the sampled searches, where dκ/ds is undefined at κ = 0).
std::vector<Feature> natural_extrema(const curve::Curve& c, const curve::NaturalData& d, bool curvature,
                                     double significance) {
  const NaturalLaws n(d);
  const nurbs::Interval dom = n.domain();
  const law::ExtremaResult r =
      law::extrema(curvature ? n.kappa() : n.tau(), n.parameter(), dom.start, dom.end, law::RootOptions{});
  std::vector<Feature> out;
  for (const law::Extremum& e : r.points) {
    if (!(e.t > dom.start && e.t < dom.end) || e.kind == law::ExtremumKind::Stationary) continue;
    bool maximum = e.kind == law::ExtremumKind::Maximum;
    if (curvature) {
      if (e.value == 0.0) continue;
      if (e.value < 0.0) maximum = !maximum;
      out.push_back(n.feature(c, e.t, maximum ? FeatureKind::CurvatureMaximum : FeatureKind::CurvatureMinimum));
    } else {
      out.push_back(n.feature(c, e.t, maximum ? FeatureKind::TorsionMaximum : FeatureKind::TorsionMinimum));
    }
  }
  const auto a = n.at(dom.start), b = n.at(dom.end);
  keep_significant(out, curvature ? std::fabs(a[0]) : a[1], curvature ? std::fabs(b[0]) : b[1], curvature,
                   significance);
  return out;
}

Feature law_feature(const LawFrenet& frenet, double t, FeatureKind kind) {
  const FrenetPoint p = frenet.at(t);
  return Feature{.kind = kind,
                 .t = t,
                 .position = p.position,
                 .curvature = kind == FeatureKind::Inflection ? 0.0 : p.curvature,
                 .torsion = p.torsion};
}

// Interior minima and maxima of f (law::extrema) as features, kept by the significance rule on κ
// (curvature = true) or τ.
std::vector<Feature> law_extrema(const law::Law& f, const LawFrenet& frenet, std::string_view parameter,
                                 nurbs::Interval domain, const law::RootOptions& roots, FeatureKind maximum,
                                 FeatureKind minimum, bool curvature, double significance) {
  const law::ExtremaResult r = law::extrema(f, parameter, domain.start, domain.end, roots);
  std::vector<Feature> out;
  for (const law::Extremum& e : r.points) {
    if (!(e.t > domain.start && e.t < domain.end) || e.kind == law::ExtremumKind::Stationary) continue;
    out.push_back(law_feature(frenet, e.t, e.kind == law::ExtremumKind::Maximum ? maximum : minimum));
  }
  const auto [a, b] = end_values([&frenet](double t) { return frenet.at(t); }, domain, curvature);
  keep_significant(out, a, b, curvature, significance);
  return out;
}
}  // namespace

std::vector<Feature> inflections(const law::Law& curve, std::string_view parameter, nurbs::Interval domain,
                                 const FeatureOptions& options, const law::RootOptions& roots) {
  options.validate();
  roots.validate();
  const law::Law r = law_curve3(curve, domain);
  const Vec3 n = options.frenet.plane_normal / norm(options.frenet.plane_normal);
  const law::Law r1 = law::derivative(r, parameter, 1);
  const law::Law g = law::dot(law::cross(r1, law::derivative(r, parameter, 2)), r.context().constant(n));
  const LawFrenet frenet(r, std::string(parameter), domain, options.frenet);
  std::vector<Feature> out;
  for (const double t : sign_changes(g, parameter, domain, roots))
    out.push_back(law_feature(frenet, t, FeatureKind::Inflection));
  return out;
}

std::vector<Feature> curvature_extrema(const law::Law& curve, std::string_view parameter, nurbs::Interval domain,
                                       const FeatureOptions& options, const law::RootOptions& roots) {
  options.validate();
  roots.validate();
  const law::Law r = law_curve3(curve, domain);
  const law::Law r1 = law::derivative(r, parameter, 1);
  const law::Law a = law::cross(r1, law::derivative(r, parameter, 2));
  const law::Law v2 = law::dot(r1, r1);
  const law::Law kappa2 = law::dot(a, a) / (v2 * v2 * v2);
  const LawFrenet frenet(r, std::string(parameter), domain, options.frenet);
  return law_extrema(kappa2, frenet, parameter, domain, roots, FeatureKind::CurvatureMaximum,
                     FeatureKind::CurvatureMinimum, true, options.significance);
}

std::vector<Feature> torsion_extrema(const law::Law& curve, std::string_view parameter, nurbs::Interval domain,
                                     const FeatureOptions& options, const law::RootOptions& roots) {
  options.validate();
  roots.validate();
  const law::Law r = law_curve3(curve, domain);
  const FrenetLaws laws = frenet_laws(r, parameter);
  const LawFrenet frenet(r, std::string(parameter), domain, options.frenet);
  return law_extrema(laws.torsion, frenet, parameter, domain, roots, FeatureKind::TorsionMaximum,
                     FeatureKind::TorsionMinimum, false, options.significance);
}

std::vector<Feature> torsion_extrema(const curve::Curve& curve, const FeatureOptions& options) {
  options.validate();
  if (const auto* n = std::get_if<curve::NaturalData>(&curve.data()))
    return natural_extrema(curve, *n, false, options.significance);
  if (!curve.law()) return torsion_extrema(curve.nurbs(), options);
  return torsion_extrema(*curve.law(), curve.law_parameter(), curve.domain(), options);
}

}  // namespace hula::diffgeom
