// SPDX-License-Identifier: MIT
#include "hula/studies/match_study.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <utility>

#include "hula/core/error.hpp"
#include "hula/intrinsic/clothoid.hpp"
#include "hula/nurbs/arc_length.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/optim/sweep.hpp"

namespace hula::studies {

std::string_view match_method_name(MatchMethod m) noexcept {
  switch (m) {
    case MatchMethod::Ga:
      return "ga";
    case MatchMethod::Hybrid:
      return "hybrid";
    case MatchMethod::Direct:
      return "direct";
  }
  return "?";
}

MatchMethod match_method_from_name(std::string_view name, std::string_view field) {
  if (name == "ga") return MatchMethod::Ga;
  if (name == "hybrid") return MatchMethod::Hybrid;
  if (name == "direct") return MatchMethod::Direct;
  throw Error(Errc::ParseError,
              std::string(field) + " = \"" + std::string(name) + "\" must be \"ga\", \"hybrid\" or \"direct\"",
              {.field = std::string(field)});
}

namespace {

double mean_of(const std::vector<double>& x, const CurvatureMatch& match) { return match.distances(x).mean; }

optim::GaResult run_ga(const CurvatureMatch& match, const MatchStudy& study, MatchResult& result, bool keep_log) {
  const MatchGaSettings& g = study.ga;
  optim::RunSettings run;
  run.seed = study.header.seed;
  run.threads = study.header.threads;
  run.stop.generations = g.generations;
  run.stop.deadline = study.header.deadline;
  run.stop.cancel = study.header.cancel;
  if (g.seed_start) run.initial = {match.start_variables()};
  match.setup().validity.apply(run);
  double best = std::numeric_limits<double>::infinity();
  run.on_generation = [&](const optim::GenerationLog& log) {
    for (std::size_t i = 0; i < log.size(); ++i) {
      const double e = log.objective_values[i * log.objectives];
      if (!log.failed[i] && std::isfinite(e)) best = std::min(best, e);
    }
    result.convergence.push_back(best);
    if (keep_log || g.distinct > 0) result.log.append(log);
    if (study.header.on_generation) study.header.on_generation(log);
  };
  if (g.algorithm == MatchGaSettings::Algorithm::Binary) {
    optim::BinaryGaOptions o;
    o.population = g.population;
    o.selection = g.selection;
    o.crossover_probability = g.crossover_probability;
    o.mutation_probability = g.mutation_probability.value_or(0.01);
    o.boost_start = g.boost_start;
    o.boost_end = g.boost_end;
    o.run = run;
    return optim::solve_binary_ga(match.problem(g.precision), o);
  }
  optim::RealGaOptions o;
  o.population = g.population;
  o.crossover_probability = g.crossover_probability;
  o.mutation_probability = g.mutation_probability;
  o.run = run;
  return optim::solve_real_ga(match.problem(), o);
}

// Arc-length fractions v(t) of the start spline at parameters t of its domain.
double length_fraction(const nurbs::NurbsCurve& curve, double t, double length) {
  return std::clamp(nurbs::arc_length(curve, curve.domain().start, t) / length, 0.0, 1.0);
}

// A target given over the spline parameter (abscissa "parameter": κ* at t = u) as a profile of normalised arc
// length, through the start spline's own map: κ_arc(v) = κ*(u(v)), u(v) the normalised parameter where the
// start spline has covered the fraction v of its length. Sampled at kConversionSamples + 1 arc-length
// fractions and joined by a C2 cubic spline (a piecewise-linear profile would put kinks in the integrand).
Profile arclength_target(const Profile& target, const nurbs::NurbsCurve& start_curve, double length) {
  constexpr int kConversionSamples = 256;
  const auto dom = start_curve.domain();
  std::vector<Vec3> values;
  std::vector<double> v;
  for (int j = 0; j <= kConversionSamples; ++j) {
    const double f = static_cast<double>(j) / kConversionSamples;
    const double t = j == kConversionSamples ? dom.end : nurbs::parameter_at_length(start_curve, f * length);
    const double u = std::clamp((t - dom.start) / dom.length(), 0.0, 1.0);
    v.push_back(f);
    values.push_back({target(u), 0.0, 0.0});
  }
  nurbs::InterpolationOptions o;
  o.parameters = v;
  o.start = nurbs::EndCondition::not_a_knot();
  o.end = nurbs::EndCondition::not_a_knot();
  const nurbs::NurbsCurve spline = nurbs::interpolate_cubic(values, o);
  std::vector<double> coefficients;
  for (const Vec3& c : spline.control_points()) coefficients.push_back(c.x);
  const std::span<const double> knots = spline.knots().values();
  return Profile::from_bspline(3, knots, coefficients);
}

// The direct route's problem: the target as an arc-length profile (a parameter-abscissa target converted through the
// start spline) integrated from the start point and frame of the spline through the start points (its turning side for
// planar curves), held to the last data point and the end tangent when asked.
DirectReconstructionProblem direct_problem(const CurvatureMatch& match, const MatchStudy& study) {
  const CurvatureMatchSetup& s = match.setup();
  const MatchDirectSettings& d = study.direct;
  const nurbs::NurbsCurve start_curve = match.sampler().curve(s.points);
  const std::vector<Vec3> d0 = start_curve.derivatives(start_curve.domain().start, 2);
  const double start_length = nurbs::arc_length(start_curve);
  DirectReconstructionProblem p{.curvature = s.abscissa == ProfileAbscissa::ArcLength
                                                 ? *s.target
                                                 : arclength_target(*s.target, start_curve, start_length)};
  p.length = d.length ? *d.length : start_length;
  p.start.point = s.points.front();
  p.start.tangent = s.start_tangent ? *s.start_tangent : d0[1];
  const Vec3 t = normalized(p.start.tangent);
  if (s.dimension == 2) {
    // The thesis's profiles are unsigned: turn towards the side of the last data point (the turning side
    // of a curve without inflection).
    const double turn = cross(t, s.points.back() - s.points.front()).z;
    p.start.normal = (turn < 0.0 ? -1.0 : 1.0) * Vec3{-t.y, t.x, 0.0};
  } else {
    Vec3 n = d0[2] - dot(d0[2], t) * t;
    if (!(norm(n) > 1e-12 * norm(d0[2]) && norm(n) > 0.0))
      n = std::abs(t.z) < 0.9 ? cross(t, Vec3{0, 0, 1}) : cross(t, Vec3{1, 0, 0});
    p.start.normal = n;
  }
  return p;
}

DirectReconstructionResult run_direct(const CurvatureMatch& match, const MatchStudy& study) {
  const CurvatureMatchSetup& s = match.setup();
  const MatchDirectSettings& d = study.direct;
  if (d.end_tangent && !s.end_tangent)
    throw Error(Errc::InvalidOption, "direct.end_tangent = true needs the study's \"end_tangent\"",
                {.field = "direct.end_tangent"});
  DirectReconstructionProblem p = direct_problem(match, study);
  if (d.end_point) p.end_point = s.points.back();
  if (d.end_tangent) p.end_tangent = *s.end_tangent;
  DirectReconstructionOptions o;
  o.correction_degree = d.correction_degree;
  o.vary_length = d.vary_length;
  o.length_weight = d.length_weight;
  o.end_tolerance = d.end_tolerance;
  o.deviation_samples = s.samples;
  return reconstruct_direct(p, o);
}

// The hybrid's second start: the planar curve integrated from the target profile (read as a
// function of the normalised arc length, which the chord-length parameter approximates), its points taken at
// the start design's chord-length parameters and clamped into the bounds. Unset for space studies (no torsion
// to integrate) or where the integration fails.
std::optional<std::vector<double>> direct_start(const CurvatureMatch& match, const MatchStudy& study) {
  const CurvatureMatchSetup& s = match.setup();
  if (s.dimension != 2) return std::nullopt;
  try {
    DirectReconstructionOptions o;
    o.fit = false;
    o.integration_tolerance = 1e-9;
    o.deviation_samples = 2;
    const DirectReconstructionResult d = reconstruct_direct(direct_problem(match, study), o);
    const std::size_t n = s.points.size();
    double total = 0.0;
    std::vector<double> chord(n, 0.0);
    for (std::size_t k = 1; k < n; ++k) chord[k] = total += distance(s.points[k - 1], s.points[k]);
    const std::vector<optim::Variable> vars = match.variables();
    std::vector<Vec3> pts(n);
    // The curve's points at fractions f_k of its length, clamped into the bounds.
    auto candidate = [&](auto&& fraction) {
      for (std::size_t k = 0; k < n; ++k) pts[k] = d.curve.evaluate(d.length * fraction(k)).position;
      std::vector<double> x = match.variables_from(pts);
      for (std::size_t j = 0; j < x.size(); ++j) x[j] = std::clamp(x[j], vars[j].lower, vars[j].upper);
      return x;
    };
    // Two spacings: the start design's chord fractions, and equal spacing (a noisy start's chords are uneven,
    // and the solver moves points along the curve only slowly: that direction barely changes κ(u)).
    std::vector<double> by_chord = candidate([&](std::size_t k) { return chord[k] / total; });
    std::vector<double> equal =
        candidate([&](std::size_t k) { return static_cast<double>(k) / static_cast<double>(n - 1); });
    return mean_of(equal, match) < mean_of(by_chord, match) ? equal : by_chord;
  } catch (const Error&) {
    return std::nullopt;
  }
}

// The hybrid's start through the target's own data parameters. A target that is the curvature
// profile of a spline through the data points tells where they sit: its slope jumps at their parameters t_k, and
// its zero crossings give the sign of κ (spline_profile_breaks). The signed samples, read as a profile of the
// normalised arc length (a chord-length parameter differs from it by O(h² κ²) within a span) and joined linearly,
// are a chain of clothoids: integrated exactly from the start point and tangent with length L, the data points are
// put at L t_k along it. L is left free by the profile up to the spline's interpolation ripples: it is chosen by a
// scan over ±20 % of the start spline's length and a golden-section search on the mean curvature distance, then
// refined (LM). Where that does not reach the target (the end may slide: the scan is flat over a range of lengths),
// a golden-section search over that range on the distance after a 20-step refinement from each length, and LM from
// the best. Returns the refinement (its iterations and evaluations summed); unset where the breaks cannot be told
// (a smooth law profile, too few samples per span), for space studies, or where the start is degenerate.
std::optional<LmResult> knot_refine(const CurvatureMatch& match, const LmOptions& lm) try {
  const CurvatureMatchSetup& s = match.setup();
  if (s.dimension != 2) return std::nullopt;
  const std::size_t n = s.points.size();
  const std::optional<SplineProfileBreaks> breaks = spline_profile_breaks(match.target_samples(), n - 2);
  if (!breaks) return std::nullopt;
  const nurbs::NurbsCurve start_curve = match.sampler().curve(s.points);
  const Vec3 tangent =
      normalized(s.start_tangent ? *s.start_tangent : start_curve.derivatives(start_curve.domain().start, 1)[1]);
  // Unsigned profiles turn towards the last data point where they turn most (as direct_problem).
  const double side = cross(tangent, s.points.back() - s.points.front()).z < 0.0 ? -1.0 : 1.0;
  const std::vector<double>& u = match.sampler().abscissae();
  const std::vector<double>& kappa = breaks->signed_samples;
  const std::vector<double>& t = breaks->parameters;
  const std::vector<optim::Variable> vars = match.variables();
  std::vector<Vec3> pts(n);
  // The chain for length L; the data points at s_k = L t_k for an arc-length target, else where their chord-length
  // fractions are t_k (three corrections: a chord is shorter than its arc by O(h³ κ²), which shifts the fractions as
  // much as L does).
  const int corrections = s.abscissa == ProfileAbscissa::ArcLength ? 0 : 3;
  std::vector<intrinsic::ClothoidSegment> chain(u.size() - 1);
  std::vector<double> at(n);
  auto point_at = [&](double arc, double length) {
    const double f = std::clamp(arc / length, 0.0, 1.0);
    const auto i = static_cast<std::size_t>(std::upper_bound(u.begin(), u.end(), f) - u.begin());
    const std::size_t seg = std::min(i == 0 ? 0 : i - 1, chain.size() - 1);
    return chain[seg].point(arc - length * u[seg]);
  };
  auto design = [&](double length) {
    intrinsic::ClothoidSegment c{.start = s.points.front(), .theta0 = std::atan2(tangent.y, tangent.x)};
    for (std::size_t i = 0; i + 1 < u.size(); ++i) {
      c.length = length * (u[i + 1] - u[i]);
      c.kappa0 = side * kappa[i];
      c.dkappa = side * (kappa[i + 1] - kappa[i]) / c.length;
      chain[i] = c;
      const double theta = c.angle(c.length);
      c.start = c.point(c.length);
      c.theta0 = theta;
    }
    for (std::size_t k = 0; k < n; ++k) at[k] = length * t[k];
    for (int pass = 0;; ++pass) {
      double total = 0.0;
      for (std::size_t k = 0; k < n; ++k) {
        pts[k] = point_at(at[k], length);
        if (k > 0) total += distance(pts[k - 1], pts[k]);
      }
      if (pass == corrections || !(total > 0.0)) break;
      double chord = 0.0;
      for (std::size_t k = 1; k + 1 < n; ++k) {
        chord += distance(pts[k - 1], pts[k]);
        at[k] += total * (t[k] - chord / total);
      }
    }
    std::vector<double> x = match.variables_from(pts);
    for (std::size_t j = 0; j < x.size(); ++j) x[j] = std::clamp(x[j], vars[j].lower, vars[j].upper);
    return x;
  };
  auto cost = [&](double length) {
    const double m = mean_of(design(length), match);
    return std::isfinite(m) ? m : std::numeric_limits<double>::infinity();
  };
  const double l0 = nurbs::arc_length(start_curve);
  constexpr int kScan = 80;
  constexpr double kRange = 0.2;  // lengths l0 exp(±0.2)
  std::vector<double> lengths, costs;
  for (int i = 0; i <= kScan; ++i) {
    lengths.push_back(l0 * std::exp(kRange * (2.0 * i / kScan - 1.0)));
    costs.push_back(cost(lengths.back()));
  }
  const auto best = static_cast<std::size_t>(std::min_element(costs.begin(), costs.end()) - costs.begin());
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  // Golden-section search for the least f on [a, b] (f evaluated at most 2 + steps times, until done()); returns the
  // better abscissa.
  auto golden = [g](double a, double b, int steps, auto&& f, auto&& done) {
    double c = b - g * (b - a), e = a + g * (b - a), fc = f(c), fe = done() ? fc : f(e);
    for (int it = 0; it < steps && !done(); ++it) {
      if (fc < fe) {
        b = e, e = c, fe = fc, c = b - g * (b - a), fc = f(c);
      } else {
        a = c, c = e, fc = fe, e = a + g * (b - a), fe = f(e);
      }
    }
    return fc < fe ? c : e;
  };
  const double l1 = golden(lengths[best > 0 ? best - 1 : 0], lengths[std::min<std::size_t>(best + 1, kScan)], 30, cost,
                           [] { return false; });
  const std::vector<double> x1 = design(l1);
  LmResult result = refine_levenberg_marquardt(match, x1, lm);
  result.mean_before = mean_of(x1, match);
  if (result.mean_after <= lm.target_mean) return result;
  // Where the free end lets L slide (a plateau of the scan), the lengths differ only by the interpolation ripples,
  // below what reading the profile as one of arc length costs; a short refinement from each length removes that
  // cost, and a golden-section search over the plateau on the refined distance finds L.
  constexpr std::size_t kPolishIterations = 20;
  constexpr int kPolishSteps = 12;
  std::size_t lo = best, hi = best;
  while (lo > 0 && costs[lo - 1] <= 10.0 * costs[best]) --lo;
  while (hi < kScan && costs[hi + 1] <= 10.0 * costs[best]) ++hi;
  LmOptions polish = lm;
  polish.max_iterations = kPolishIterations;
  auto accumulate = [&](LmResult r) {
    r.iterations += result.iterations;
    r.evaluations += result.evaluations;
    r.seconds += result.seconds;
    r.mean_before = result.mean_before;
    if (r.mean_after < result.mean_after) {
      result = std::move(r);
    } else {
      result.iterations = r.iterations, result.evaluations = r.evaluations, result.seconds = r.seconds;
    }
  };
  auto reached = [&] { return result.mean_after <= lm.target_mean; };
  golden(
      lengths[lo], lengths[hi], kPolishSteps,
      [&](double length) {
        LmResult r = refine_levenberg_marquardt(match, design(length), polish);
        const double m = r.mean_after;
        accumulate(std::move(r));
        return m;
      },
      reached);
  if (!reached()) accumulate(refine_levenberg_marquardt(match, result.variables, lm));
  return result;
} catch (const Error&) {
  return std::nullopt;
}

// One run of the study's method on one problem (one round of run_recentred).
MatchResult run_once(const CurvatureMatch& match, const MatchStudy& study, bool keep_log) {
  const auto t0 = std::chrono::steady_clock::now();
  MatchResult result;
  result.start = match.start_variables();
  result.before = match.distances(result.start);
  if (study.method == MatchMethod::Direct) {
    result.direct = run_direct(match, study);
    // The reconstructed curve at the data points' abscissae: the arc-length fraction of each start point on
    // the start spline (chord-length parameters, as the sampler builds it), scaled to the curve's length.
    const CurvatureMatchSetup& s = match.setup();
    const nurbs::NurbsCurve start_curve = match.sampler().curve(s.points);
    const double start_length = nurbs::arc_length(start_curve);
    const std::vector<double> t = nurbs::parameterise(s.points, nurbs::Parameterisation::ChordLength);
    const double length = result.direct->curve.length();
    for (std::size_t i = 0; i < t.size(); ++i) {
      const double dom_t = start_curve.domain().start + t[i] * start_curve.domain().length();
      const double v = i + 1 == t.size() ? 1.0 : length_fraction(start_curve, dom_t, start_length);
      result.direct_points.push_back(result.direct->curve.evaluate(v * length).position);
    }
    result.ga_best = result.best = result.start;
    result.after_ga = result.after = result.before;
    if (s.validity.any() && result.direct->nurbs)
      result.validity = check_validity(result.direct->nurbs->curve, s.validity);
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return result;
  }
  const optim::GaResult ga = run_ga(match, study, result, keep_log);
  result.ga_report = ga.report;
  result.ga_best = ga.best.variables;
  if (study.ga.distinct > 0) {
    result.distinct = optim::distinct_best(result.log, match.variables(), study.ga.distinct, study.ga.distinct_radius);
    if (!keep_log) result.log = {};
  }
  // The GA keeps the best it saw; the start itself is a candidate the designer already has. With validity
  // requirements a valid candidate beats an invalid one whatever their distances.
  const bool checked = match.setup().validity.any();
  const auto valid = [&](const std::vector<double>& x) { return !checked || match.validity(x).valid(); };
  const bool ga_valid = valid(result.ga_best);
  if (ga_valid == valid(result.start) ? !(mean_of(result.ga_best, match) <= result.before.mean) : !ga_valid)
    result.ga_best = result.start;
  result.after_ga = match.distances(result.ga_best);
  result.best = result.ga_best;
  switch (study.method) {
    case MatchMethod::Ga:
      break;
    case MatchMethod::Direct:
      break;
    case MatchMethod::Hybrid: {
      // Multi-start: where the target shows its data parameters, first the refinement from the direct start through
      // them (knot_refine); otherwise LM from the closer of the GA's best and the direct start. If that does not
      // reach the target, also from the other, keeping the better (a close start can lie in a worse basin).
      std::vector<std::pair<std::string, std::vector<double>>> starts{{"ga", result.ga_best}};
      auto keep = [&](const std::string& name, LmResult lm) {
        const bool better = !result.lm || lm.mean_after < result.lm->mean_after;
        if (result.lm) {
          lm.iterations += result.lm->iterations;
          lm.evaluations += result.lm->evaluations;
          lm.seconds += result.lm->seconds;
        }
        if (better) {
          if (result.lm) lm.mean_before = result.lm->mean_before;
          result.lm = std::move(lm);
          result.lm_start = name;
        } else {
          result.lm->iterations = lm.iterations;
          result.lm->evaluations = lm.evaluations;
          result.lm->seconds = lm.seconds;
        }
      };
      if (study.lm.direct_start) {
        if (std::optional<LmResult> k = knot_refine(match, study.lm)) {
          keep("direct", std::move(*k));
        } else if (auto d = direct_start(match, study)) {
          if (mean_of(*d, match) < result.after_ga.mean)
            starts.insert(starts.begin(), {"direct", std::move(*d)});
          else
            starts.emplace_back("direct", std::move(*d));
        }
      }
      for (const auto& [name, from] : starts) {
        if (result.lm && result.lm->mean_after <= study.lm.target_mean) break;
        keep(name, refine_levenberg_marquardt(match, from, study.lm));
      }
    }
      // LM minimises the sum of squares; where no exact solution exists that can raise the mean |r| of eq. 31
      // slightly, and the study reports the better of the two by eq. 31.
      if (mean_of(result.lm->variables, match) <= result.after_ga.mean &&
          (valid(result.lm->variables) || !valid(result.ga_best)))
        result.best = result.lm->variables;
      break;
  }
  result.after = match.distances(result.best);
  if (checked) result.validity = match.validity(result.best);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace

std::vector<optim::BoundHit> match_bound_hits(std::span<const optim::Variable> variables, std::span<const double> x) {
  return optim::bound_hits(variables, x, kOnBoundFraction);
}

CurvatureMatchSetup recentred_setup(const CurvatureMatch& match, std::span<const double> x) {
  CurvatureMatchSetup s = match.setup();  // its proximity_centre is filled in (the start, unless given)
  match.points_from(x, s.points);
  return s;
}

std::vector<RecentreRound> run_recentred(
    const CurvatureMatch& match, std::size_t max_recentres,
    const std::function<RoundOutcome(const CurvatureMatch&, std::size_t round)>& run) {
  std::vector<RecentreRound> rounds;
  std::optional<CurvatureMatch> recentred;
  for (std::size_t round = 0;; ++round) {
    const CurvatureMatch& m = recentred ? *recentred : match;
    RoundOutcome outcome = run(m, round);
    RecentreRound r;
    r.variables = m.variables();
    r.on_bound = match_bound_hits(r.variables, outcome.best);
    r.after = m.distances(outcome.best);
    r.best = std::move(outcome.best);
    r.evaluations = outcome.evaluations;
    const bool again = !r.on_bound.empty() && round < max_recentres && !outcome.stopped;
    rounds.push_back(std::move(r));
    if (!again) break;
    recentred.emplace(recentred_setup(m, rounds.back().best));
  }
  return rounds;
}

std::array<std::size_t, 2> MatchMapSettings::axes(std::span<const optim::Variable> candidates) const {
  std::array<std::size_t, 2> index{};
  for (std::size_t k = 0; k < 2; ++k) {
    const std::string field = "map.variables[" + std::to_string(k) + "]";
    const auto it = std::find_if(candidates.begin(), candidates.end(),
                                 [&](const optim::Variable& v) { return v.name == variables[k]; });
    if (it == candidates.end()) {
      std::string names;
      for (const optim::Variable& v : candidates) names += (names.empty() ? "" : ", ") + v.name;
      throw Error(Errc::InvalidOption,
                  field + " = \"" + variables[k] + "\" is not a free design variable (" + names + ")",
                  {.field = "map.variables", .index = k});
    }
    index[k] = static_cast<std::size_t>(it - candidates.begin());
  }
  if (index[0] == index[1])
    throw Error(Errc::InvalidOption, "map.variables names \"" + variables[0] + "\" twice",
                {.field = "map.variables", .index = 1});
  if (grid < 2 || grid > 500)
    throw Error(Errc::InvalidOption, "map.grid = " + std::to_string(grid) + " must be in 2 … 500",
                {.field = "map.grid"});
  for (const auto& [name, range] : {std::pair{"map.from", &from}, std::pair{"map.to", &to}})
    if (*range)
      for (std::size_t k = 0; k < 2; ++k)
        if (!std::isfinite((**range)[k]))
          throw Error(
              Errc::InvalidOption,
              std::string(name) + "[" + std::to_string(k) + "] = " + format_number((**range)[k]) + " must be finite",
              {.field = name, .index = k});
  return index;
}

optim::SweepResult match_fitness_map(const optim::Problem& problem, std::span<const double> at,
                                     const MatchMapSettings& settings, std::size_t threads) {
  const std::array<std::size_t, 2> axes = settings.axes(problem.variables);
  optim::SweepOptions o;
  o.nominal.assign(at.begin(), at.end());
  o.threads = threads;
  optim::SweepAxis x{.variable = axes[0], .steps = settings.grid};
  optim::SweepAxis y{.variable = axes[1], .steps = settings.grid};
  if (settings.from) {
    x.from = (*settings.from)[0];
    y.from = (*settings.from)[1];
  }
  if (settings.to) {
    x.to = (*settings.to)[0];
    y.to = (*settings.to)[1];
  }
  o.x = x;
  o.y = y;
  return optim::sweep(problem, o);
}

MatchResult run_curvature_match(const CurvatureMatch& match, const MatchStudy& study, bool keep_log) {
  study.lm.validate();
  if (!(study.ga.precision > 0.0) || !std::isfinite(study.ga.precision))
    throw Error(Errc::InvalidOption, "ga.precision = " + format_number(study.ga.precision) + " must be > 0",
                {.field = "ga.precision"});
  if (study.map) (void)study.map->axes(match.variables());
  const auto t0 = std::chrono::steady_clock::now();
  MatchResult result;
  if (study.method == MatchMethod::Direct) {
    result = run_once(match, study, keep_log);
  } else {
    // Each round's result replaces `result` (keeping the designer's start); the rounds are set after the last.
    std::vector<RecentreRound> rounds =
        run_recentred(match, study.max_recentres, [&](const CurvatureMatch& m, std::size_t round) {
          MatchStudy s = study;
          if (round > 0) {
            // "Each new GA run takes the best results of the previous run as initial variable values" (8.2.1).
            s.header.seed = study.header.seed + round;
            s.ga.seed_start = true;
          }
          MatchResult r = run_once(m, s, keep_log);
          const optim::Termination t = r.ga_report.termination;
          RoundOutcome outcome{r.best, r.ga_report.evaluations + (r.lm ? r.lm->evaluations : 0),
                               optim::stopped_early(t)};
          if (round > 0) {
            // The study's start stays the designer's; the convergence record and the log go on over the rounds.
            r.start = std::move(result.start);
            r.before = result.before;
            r.convergence.insert(r.convergence.begin(), result.convergence.begin(), result.convergence.end());
            for (const optim::GenerationLog& g : r.log.generations()) result.log.append(g);
            r.log = std::move(result.log);
          }
          result = std::move(r);
          return outcome;
        });
    result.rounds = std::move(rounds);
  }
  result.variables = result.rounds.empty() ? match.variables() : result.rounds.back().variables;
  if (study.map) {
    // The GA's objective (mean distance + proximity penalty towards the designer's start in every round).
    optim::Problem problem = match.problem();
    problem.variables = result.variables;
    result.map = match_fitness_map(problem, result.best, *study.map, study.header.threads);
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

std::optional<nurbs::NurbsCurve> match_result_curve(const CurvatureMatch& match, const MatchResult& result) {
  if (result.validity && !result.validity->valid()) return std::nullopt;
  if (result.direct) {
    if (!result.direct->nurbs) return std::nullopt;
    return result.direct->nurbs->curve;
  }
  std::vector<Vec3> pts(match.setup().points.size());
  match.points_from(result.best, pts);
  return match.sampler().curve(pts);
}

}  // namespace hula::studies
