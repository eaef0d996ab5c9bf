// SPDX-License-Identifier: MIT
#include "hula/studies/match_study.hpp"

#include <chrono>
#include <cmath>
#include <limits>

#include "hula/core/error.hpp"
#include "hula/io/json_read.hpp"
#include "hula/nurbs/arc_length.hpp"

namespace hula::studies {

namespace jr = io::json;

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
  throw Error(
      Errc::ParseError,
      std::string(field) + " = " + io::json::quote(std::string(name)) + " must be \"ga\", \"hybrid\" or \"direct\"",
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
  run.stop.wall_time_seconds = study.header.wall_time_seconds;
  run.stop.cancel = study.header.cancel;
  double best = std::numeric_limits<double>::infinity();
  run.on_generation = [&](const optim::GenerationLog& log) {
    for (std::size_t i = 0; i < log.size(); ++i) {
      const double e = log.objective_values[i * log.objectives];
      if (!log.failed[i] && std::isfinite(e)) best = std::min(best, e);
    }
    result.convergence.push_back(best);
    if (keep_log) result.log.append(log);
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

// The direct route: the target as an arc-length profile integrated from the start point and frame of the
// spline through the start points (its turning side for planar curves), held to the last data point and the
// end tangent when asked.
DirectReconstructionResult run_direct(const CurvatureMatch& match, const MatchStudy& study) {
  const CurvatureMatchSetup& s = match.setup();
  if (s.abscissa != ProfileAbscissa::ArcLength)
    throw Error(Errc::InvalidOption,
                "method = \"direct\" integrates the natural equations in arc length: set \"abscissa\": \"arclength\"",
                {.field = "abscissa"});
  const MatchDirectSettings& d = study.direct;
  if (d.end_tangent && !s.end_tangent)
    throw Error(Errc::InvalidOption, "direct.end_tangent = true needs the study's \"end_tangent\"",
                {.field = "direct.end_tangent"});
  const nurbs::NurbsCurve start_curve = match.sampler().curve(s.points);
  const std::vector<Vec3> d0 = start_curve.derivatives(start_curve.domain().start, 2);
  DirectReconstructionProblem p{.curvature = *s.target};
  p.length = d.length ? *d.length : nurbs::arc_length(start_curve);
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

}  // namespace

MatchResult run_curvature_match(const CurvatureMatch& match, const MatchStudy& study, bool keep_log) {
  study.lm.validate();
  if (!(study.ga.precision > 0.0) || !std::isfinite(study.ga.precision))
    throw Error(Errc::InvalidOption, "ga.precision = " + format_number(study.ga.precision) + " must be > 0",
                {.field = "ga.precision"});
  const auto t0 = std::chrono::steady_clock::now();
  MatchResult result;
  result.start = match.start_variables();
  result.before = match.distances(result.start);
  if (study.method == MatchMethod::Direct) {
    result.direct = run_direct(match, study);
    result.ga_best = result.best = result.start;
    result.after_ga = result.after = result.before;
    result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return result;
  }
  const optim::GaResult ga = run_ga(match, study, result, keep_log);
  result.ga_report = ga.report;
  result.ga_best = ga.best.variables;
  // The GA keeps the best it saw; the start itself is a candidate the designer already has.
  if (!(mean_of(result.ga_best, match) <= result.before.mean)) result.ga_best = result.start;
  result.after_ga = match.distances(result.ga_best);
  result.best = result.ga_best;
  switch (study.method) {
    case MatchMethod::Ga:
      break;
    case MatchMethod::Direct:
      break;
    case MatchMethod::Hybrid:
      result.lm = refine_levenberg_marquardt(match, result.ga_best, study.lm);
      // LM minimises the sum of squares; where no exact solution exists that can raise the mean |r| of eq. 31
      // slightly, and the study reports the better of the two by eq. 31.
      if (mean_of(result.lm->variables, match) <= result.after_ga.mean) result.best = result.lm->variables;
      break;
  }
  result.after = match.distances(result.best);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

namespace {

Vec3 read_vector(const Json& v, const jr::JsonPath& path, int dimension) {
  const auto [p, count] = jr::get_point(v, path);
  if (count != dimension)
    throw Error(
        Errc::ParseError,
        path.text + " has " + std::to_string(count) + " components but the points have " + std::to_string(dimension),
        path.where);
  return p;
}

std::vector<Vec3> read_offsets(const Json& body, std::string_view name, std::size_t count, int dimension) {
  const jr::JsonPath path = jr::root_path(name);
  const Json& arr = jr::require_member(body, jr::root_path(""), name);
  const jr::PointArray pa = jr::get_points(arr, path);
  if (pa.points.size() != count)
    throw Error(Errc::ParseError,
                std::string(name) + " has " + std::to_string(pa.points.size()) + " entries but there are " +
                    std::to_string(count) + " points",
                {.field = std::string(name)});
  if (!pa.points.empty() && pa.dimension != dimension)
    throw Error(Errc::ParseError,
                std::string(name) + " entries have " + std::to_string(pa.dimension) +
                    " components but the points have " + std::to_string(dimension),
                {.field = std::string(name)});
  return pa.points;
}

// The "known curve" target form: the curvature profile of the spline through `of_points`, optionally mirrored
// (κ(1 − u)), symmetrised ((κ(u) + κ(1 − u)) / 2) and multiplied by a factor profile.
Profile known_curve_target(const Json& t, const jr::JsonPath& path, const CurvatureMatchSetup& setup,
                           const std::filesystem::path& base, const law::Context& context, bool torsion) {
  jr::reject_unknown_members(t, path, {"of_points", "mirror", "symmetrise", "factor"});
  const jr::PointArray pa = jr::get_points(jr::require_member(t, path, "of_points"), path.member("of_points"));
  if (pa.dimension != setup.dimension)
    throw Error(Errc::ParseError, path.text + ".of_points must have as many components as the points", path.where);
  std::vector<double> kappa;
  try {
    kappa = torsion
                ? torsion_profile_of(pa.points, setup.samples, setup.start_tangent, setup.end_tangent, setup.abscissa)
                : curvature_profile_of(pa.points, setup.dimension, setup.samples, setup.start_tangent,
                                       setup.end_tangent, setup.abscissa);
  } catch (const Error& e) {
    throw Error(e.code(), path.text + ".of_points: " + e.message(), path.where);
  }
  const std::size_t N = kappa.size();
  auto flag = [&](std::string_view name) {
    const Json* v = jr::optional_member(t, name);
    if (v == nullptr) return false;
    if (!v->is_boolean()) jr::type_error(*v, path.member(name), "true or false");
    return v->get<bool>();
  };
  std::vector<double> v = kappa;
  if (flag("mirror"))
    for (std::size_t i = 0; i < N; ++i) v[i] = kappa[N - 1 - i];
  if (flag("symmetrise")) {
    const std::vector<double> w = v;
    for (std::size_t i = 0; i < N; ++i) v[i] = 0.5 * (w[i] + w[N - 1 - i]);
  }
  const std::vector<double> u = uniform_abscissae(N);
  if (const Json* f = jr::optional_member(t, "factor")) {
    const Profile factor = profile_from_json(*f, path.member("factor"), base, context);
    std::vector<double> fv(N);
    factor.sample(u, fv);
    for (std::size_t i = 0; i < N; ++i) v[i] *= fv[i];
  }
  return Profile::from_samples(u, v, context);
}

double read_positive(const Json& obj, const jr::JsonPath& path, std::string_view name, double current) {
  const Json* v = jr::optional_member(obj, name);
  if (v == nullptr) return current;
  const double x = jr::get_number(*v, path.member(name));
  if (!(x > 0.0))
    throw Error(Errc::InvalidOption, path.member(name).text + " = " + format_number(x) + " must be > 0",
                path.member(name).where);
  return x;
}

double read_probability(const Json& obj, const jr::JsonPath& path, std::string_view name, double current) {
  const Json* v = jr::optional_member(obj, name);
  if (v == nullptr) return current;
  const double x = jr::get_number(*v, path.member(name));
  if (!(x >= 0.0 && x <= 1.0))
    throw Error(Errc::InvalidOption, path.member(name).text + " = " + format_number(x) + " must be in [0, 1]",
                path.member(name).where);
  return x;
}

MatchGaSettings read_ga(const Json& g, const jr::JsonPath& path) {
  jr::reject_unknown_members(g, path,
                             {"algorithm", "population", "generations", "boost_start", "boost_end",
                              "crossover_probability", "mutation_probability", "precision", "selection"});
  MatchGaSettings s;
  if (const Json* a = jr::optional_member(g, "algorithm")) {
    const std::string name = jr::get_string(*a, path.member("algorithm"));
    if (name == "binary")
      s.algorithm = MatchGaSettings::Algorithm::Binary;
    else if (name == "real")
      s.algorithm = MatchGaSettings::Algorithm::Real;
    else
      throw Error(Errc::ParseError, "ga.algorithm = " + io::json::quote(name) + " must be \"binary\" or \"real\"",
                  {.field = "ga.algorithm"});
  }
  if (const Json* a = jr::optional_member(g, "selection")) {
    const std::string name = jr::get_string(*a, path.member("selection"));
    if (name == "roulette")
      s.selection = optim::Selection::Roulette;
    else if (name == "tournament")
      s.selection = optim::Selection::Tournament;
    else
      throw Error(Errc::ParseError,
                  "ga.selection = " + io::json::quote(name) + " must be \"roulette\" or \"tournament\"",
                  {.field = "ga.selection"});
  }
  if (const Json* v = jr::optional_member(g, "population")) {
    s.population = static_cast<std::size_t>(jr::get_integer(*v, path.member("population"), 2, 100000));
    if (s.population % 2 != 0)
      throw Error(Errc::InvalidOption, "ga.population = " + std::to_string(s.population) + " must be even",
                  {.field = "ga.population"});
  }
  if (const Json* v = jr::optional_member(g, "generations"))
    s.generations = static_cast<std::size_t>(jr::get_integer(*v, path.member("generations"), 0, 1000000));
  s.boost_start = read_positive(g, path, "boost_start", s.boost_start);
  s.boost_end = read_positive(g, path, "boost_end", s.boost_end);
  s.precision = read_positive(g, path, "precision", s.precision);
  s.crossover_probability = read_probability(g, path, "crossover_probability", s.crossover_probability);
  if (jr::optional_member(g, "mutation_probability") != nullptr)
    s.mutation_probability = read_probability(g, path, "mutation_probability", 0.0);
  return s;
}

}  // namespace

LmOptions lm_options_from_json(const Json& g, const io::json::JsonPath& path) {
  jr::reject_unknown_members(
      g, path, {"max_iterations", "target_mean", "relative_tolerance", "initial_lambda", "difference_step"});
  LmOptions o;
  if (const Json* v = jr::optional_member(g, "max_iterations"))
    o.max_iterations = static_cast<std::size_t>(jr::get_integer(*v, path.member("max_iterations"), 1, 1000000));
  if (const Json* v = jr::optional_member(g, "target_mean"))
    o.target_mean = jr::get_number(*v, path.member("target_mean"));
  if (const Json* v = jr::optional_member(g, "relative_tolerance"))
    o.relative_tolerance = jr::get_number(*v, path.member("relative_tolerance"));
  if (const Json* v = jr::optional_member(g, "initial_lambda"))
    o.initial_lambda = jr::get_number(*v, path.member("initial_lambda"));
  if (const Json* v = jr::optional_member(g, "difference_step"))
    o.difference_step = jr::get_number(*v, path.member("difference_step"));
  o.validate();
  return o;
}

Json lm_options_to_json(const LmOptions& o) {
  Json lm = Json::object();
  lm["max_iterations"] = o.max_iterations;
  lm["target_mean"] = o.target_mean;
  lm["relative_tolerance"] = o.relative_tolerance;
  lm["initial_lambda"] = o.initial_lambda;
  lm["difference_step"] = o.difference_step;
  return lm;
}

namespace {

Json point_json(const Vec3& p, int dimension) {
  Json a = Json::array({p.x, p.y});
  if (dimension == 3) a.push_back(p.z);
  return a;
}

Json points_json(std::span<const Vec3> pts, int dimension) {
  Json a = Json::array();
  for (const Vec3& p : pts) a.push_back(point_json(p, dimension));
  return a;
}

Json distances_json(const MatchDistances& d) {
  Json o = Json::object();
  auto num = [](double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); };
  o["mean"] = num(d.mean);
  o["max"] = num(d.max);
  if (std::isfinite(d.torsion_mean)) o["torsion_mean"] = d.torsion_mean;
  return o;
}

}  // namespace

MatchSetupJson match_setup_from_json(const Json& body, const std::filesystem::path& base, bool with_torsion) {
  const jr::JsonPath root = jr::root_path("");
  MatchSetupJson out;
  CurvatureMatchSetup& s = out.setup;
  const jr::PointArray pa = jr::get_points(jr::require_member(body, root, "points"), jr::root_path("points"));
  s.points = pa.points;
  s.dimension = pa.dimension;
  if (s.points.size() < 2)
    throw Error(Errc::TooFewPoints, "points: at least 2 data points are needed, got " + std::to_string(s.points.size()),
                {.field = "points"});
  if (with_torsion && s.dimension != 3)
    throw Error(Errc::InvalidArgument, "points: matching torsion needs 3-D points ([x, y, z]); planar curves have none",
                {.field = "points"});
  s.lower = read_offsets(body, "lower", s.points.size(), s.dimension);
  s.upper = read_offsets(body, "upper", s.points.size(), s.dimension);
  if (const Json* v = jr::optional_member(body, "start_tangent"))
    s.start_tangent = read_vector(*v, jr::root_path("start_tangent"), s.dimension);
  if (const Json* v = jr::optional_member(body, "end_tangent"))
    s.end_tangent = read_vector(*v, jr::root_path("end_tangent"), s.dimension);
  if (const Json* v = jr::optional_member(body, "samples"))
    s.samples = static_cast<std::size_t>(jr::get_integer(*v, jr::root_path("samples"), 0, 1000000));
  if (s.samples < 2)
    throw Error(Errc::InvalidArgument, "samples = " + std::to_string(s.samples) + " must be at least 2",
                {.field = "samples"});
  if (const Json* v = jr::optional_member(body, "abscissa"))
    s.abscissa = profile_abscissa_from_name(jr::get_string(*v, jr::root_path("abscissa")), "abscissa");
  // Bounds before the targets: a bad bound is reported without evaluating anything.
  s.target = Profile::from_samples(std::vector<double>{0.0, 1.0}, std::vector<double>{0.0, 0.0});
  s.validate();
  const law::Context context{};
  const auto read_target = [&](std::string_view name, bool torsion, Json& echo) {
    const Json& t = jr::require_member(body, root, name);
    echo = t;
    const jr::JsonPath tpath = jr::root_path(name);
    if (t.is_object() && t.contains("of_points")) return known_curve_target(t, tpath, s, base, context, torsion);
    return profile_from_json(t, tpath, base, context);
  };
  s.target = read_target("target", false, out.target);
  if (with_torsion) s.torsion_target = read_target("torsion_target", true, out.torsion_target);
  return out;
}

void match_setup_to_json(const MatchSetupJson& setup, Json& out) {
  const CurvatureMatchSetup& s = setup.setup;
  out["points"] = points_json(s.points, s.dimension);
  out["lower"] = points_json(s.lower, s.dimension);
  out["upper"] = points_json(s.upper, s.dimension);
  if (s.start_tangent) out["start_tangent"] = point_json(*s.start_tangent, s.dimension);
  if (s.end_tangent) out["end_tangent"] = point_json(*s.end_tangent, s.dimension);
  out["target"] = setup.target;
  if (s.torsion_target) out["torsion_target"] = setup.torsion_target;
  out["abscissa"] = std::string(profile_abscissa_name(s.abscissa));
  out["samples"] = s.samples;
}

MatchStudy match_study_from_json(const StudyDocument& document, const std::filesystem::path& base) {
  const Json& body = document.body;
  check_members(body, {"points", "lower", "upper", "start_tangent", "end_tangent", "target", "abscissa", "samples",
                       "method", "ga", "lm", "direct"});
  MatchStudy study;
  study.header = document.header;
  if (const Json* v = jr::optional_member(body, "method"))
    study.method = match_method_from_name(jr::get_string(*v, jr::root_path("method")), "method");
  if (const Json* v = jr::optional_member(body, "ga")) study.ga = read_ga(*v, jr::root_path("ga"));
  if (const Json* v = jr::optional_member(body, "lm")) study.lm = lm_options_from_json(*v, jr::root_path("lm"));
  if (const Json* v = jr::optional_member(body, "direct")) {
    const jr::JsonPath path = jr::root_path("direct");
    jr::reject_unknown_members(
        *v, path,
        {"length", "end_point", "end_tangent", "correction_degree", "vary_length", "length_weight", "end_tolerance"});
    MatchDirectSettings& d = study.direct;
    if (const Json* l = jr::optional_member(*v, "length")) {
      d.length = jr::get_number(*l, path.member("length"));
      if (!(*d.length > 0.0))
        throw Error(Errc::InvalidOption, "direct.length = " + format_number(*d.length) + " must be > 0",
                    path.member("length").where);
    }
    for (auto [flag, target] : {std::pair{"end_point", &d.end_point}, std::pair{"end_tangent", &d.end_tangent},
                                std::pair{"vary_length", &d.vary_length}})
      if (const Json* b = jr::optional_member(*v, flag)) {
        if (!b->is_boolean()) jr::type_error(*b, path.member(flag), "true or false");
        *target = b->get<bool>();
      }
    if (const Json* e = jr::optional_member(*v, "end_tolerance"))
      d.end_tolerance = jr::get_number(*e, path.member("end_tolerance"));
    if (const Json* w = jr::optional_member(*v, "length_weight")) {
      d.length_weight = jr::get_number(*w, path.member("length_weight"));
      if (!(d.length_weight > 0.0))
        throw Error(Errc::InvalidOption, "direct.length_weight = " + format_number(d.length_weight) + " must be > 0",
                    path.member("length_weight").where);
    }
    if (const Json* c = jr::optional_member(*v, "correction_degree"))
      d.correction_degree = static_cast<int>(jr::get_integer(*c, path.member("correction_degree"), 1, 20));
  }
  MatchSetupJson setup = match_setup_from_json(body, base, false);
  study.setup = std::move(setup.setup);
  study.target_json = std::move(setup.target);
  return study;
}

Json match_study_to_json(const MatchStudy& study) {
  Json out = header_to_json(study.header);
  match_setup_to_json({study.setup, study.target_json, {}}, out);
  out["method"] = std::string(match_method_name(study.method));
  Json ga = Json::object();
  ga["algorithm"] = study.ga.algorithm == MatchGaSettings::Algorithm::Binary ? "binary" : "real";
  ga["selection"] = study.ga.selection == optim::Selection::Roulette ? "roulette" : "tournament";
  ga["population"] = study.ga.population;
  ga["generations"] = study.ga.generations;
  ga["boost_start"] = study.ga.boost_start;
  ga["boost_end"] = study.ga.boost_end;
  ga["crossover_probability"] = study.ga.crossover_probability;
  if (study.ga.mutation_probability) ga["mutation_probability"] = *study.ga.mutation_probability;
  ga["precision"] = study.ga.precision;
  out["ga"] = ga;
  out["lm"] = lm_options_to_json(study.lm);
  Json direct = Json::object();
  if (study.direct.length) direct["length"] = *study.direct.length;
  direct["end_point"] = study.direct.end_point;
  direct["end_tangent"] = study.direct.end_tangent;
  direct["correction_degree"] = study.direct.correction_degree;
  direct["vary_length"] = study.direct.vary_length;
  direct["length_weight"] = study.direct.length_weight;
  direct["end_tolerance"] = study.direct.end_tolerance;
  out["direct"] = direct;
  return out;
}

Json match_result_to_json(const CurvatureMatch& match, const MatchStudy& study, const MatchResult& result) {
  const int dim = study.setup.dimension;
  std::vector<Vec3> pts(study.setup.points.size());
  Json out = Json::object();
  out["method"] = std::string(match_method_name(study.method));
  out["variables"] = Json::array();
  for (const auto& v : match.variables()) out["variables"].push_back(v.name);
  match.points_from(result.start, pts);
  out["start_points"] = points_json(pts, dim);
  match.points_from(result.best, pts);
  out["best_points"] = points_json(pts, dim);
  out["before"] = distances_json(result.before);
  out["after_ga"] = distances_json(result.after_ga);
  if (result.lm) {
    out["after_lm"] = distances_json(result.after);
    Json lm = Json::object();
    lm["iterations"] = result.lm->iterations;
    lm["evaluations"] = result.lm->evaluations;
    lm["termination"] = result.lm->termination;
    lm["seconds"] = result.lm->seconds;
    out["lm"] = lm;
  }
  out["after"] = distances_json(result.after);
  if (result.direct) {
    // The direct curve matches the profile by construction (up to the correction that holds its end); its
    // distance from the target and where its end lands are what to compare with the GA routes.
    const DirectReconstructionResult& d = *result.direct;
    out["after"] = {{"mean", d.mean_curvature_deviation}, {"max", d.max_curvature_deviation}};
    out["direct"] = direct_reconstruction_summary(d);
    if (d.nurbs) {
      const nurbs::NurbsCurve& c = d.nurbs->curve;
      out["direct"]["end_miss"] = norm(c.evaluate(c.domain().end) - study.setup.points.back());
      out["curve"] = io::curve_to_json(c);
    }
    out["seconds"] = result.seconds;
    out["study"] = match_study_to_json(study);
    return out;
  }
  Json ga = Json::object();
  ga["generations"] = result.ga_report.generations;
  ga["evaluations"] = result.ga_report.evaluations;
  ga["failed_evaluations"] = result.ga_report.failed_evaluations;
  ga["termination"] = std::string(optim::termination_name(result.ga_report.termination));
  ga["seconds"] = result.ga_report.seconds;
  out["ga"] = ga;
  out["evaluations"] = result.ga_report.evaluations + (result.lm ? result.lm->evaluations : 0);
  out["seconds"] = result.seconds;
  out["curve"] = io::curve_to_json(match.sampler().curve(pts));
  out["study"] = match_study_to_json(study);
  return out;
}

}  // namespace hula::studies
