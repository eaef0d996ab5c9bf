// SPDX-License-Identifier: MIT
// The codecs of the curvature-matching study kinds (match_study_file.hpp).
#include "hula/io/match_study_file.hpp"

#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/profile_file.hpp"
#include "hula/io/run_report_json.hpp"
#include "hula/io/validity_json.hpp"

namespace hula::io {

using namespace studies;  // NOLINT(google-build-using-namespace): this file is the studies' codec
namespace jr = json;

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
                           const PathResolver& resolver, const law::Context& context, bool torsion) {
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
    const Profile factor = profile_from_json(*f, path.member("factor"), resolver, context);
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
  jr::reject_unknown_members(
      g, path,
      {"algorithm", "population", "generations", "boost_start", "boost_end", "crossover_probability",
       "mutation_probability", "precision", "selection", "seed_start", "distinct", "distinct_radius"});
  MatchGaSettings s;
  if (const Json* v = jr::optional_member(g, "seed_start")) {
    if (!v->is_boolean()) jr::type_error(*v, path.member("seed_start"), "true or false");
    s.seed_start = v->get<bool>();
  }
  if (const Json* v = jr::optional_member(g, "distinct"))
    s.distinct = static_cast<std::size_t>(jr::get_integer(*v, path.member("distinct"), 0, 1000));
  if (const Json* v = jr::optional_member(g, "distinct_radius")) {
    s.distinct_radius = jr::get_number(*v, path.member("distinct_radius"));
    if (!(s.distinct_radius > 0.0 && s.distinct_radius <= 1.0))
      throw Error(Errc::InvalidOption,
                  "ga.distinct_radius = " + format_number(s.distinct_radius) + " must be in (0, 1]",
                  {.field = "ga.distinct_radius"});
  }
  if (const Json* a = jr::optional_member(g, "algorithm")) {
    const std::string name = jr::get_string(*a, path.member("algorithm"));
    if (name == "binary")
      s.algorithm = MatchGaSettings::Algorithm::Binary;
    else if (name == "real")
      s.algorithm = MatchGaSettings::Algorithm::Real;
    else
      throw Error(Errc::ParseError, "ga.algorithm = " + json::quote(name) + " must be \"binary\" or \"real\"",
                  {.field = "ga.algorithm"});
  }
  if (const Json* a = jr::optional_member(g, "selection")) {
    const std::string name = jr::get_string(*a, path.member("selection"));
    if (name == "roulette")
      s.selection = optim::Selection::Roulette;
    else if (name == "tournament")
      s.selection = optim::Selection::Tournament;
    else
      throw Error(Errc::ParseError, "ga.selection = " + json::quote(name) + " must be \"roulette\" or \"tournament\"",
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
  jr::reject_unknown_members(g, path,
                             {"max_iterations", "target_mean", "relative_tolerance", "initial_lambda",
                              "difference_step", "solver", "direct_start", "exact_jacobian"});
  LmOptions o;
  if (const Json* v = jr::optional_member(g, "solver"))
    o.solver = lsq_solver_from_name(jr::get_string(*v, path.member("solver")), path.member("solver").text);
  if (const Json* v = jr::optional_member(g, "direct_start")) {
    if (!v->is_boolean()) jr::type_error(*v, path.member("direct_start"), "true or false");
    o.direct_start = v->get<bool>();
  }
  if (const Json* v = jr::optional_member(g, "exact_jacobian")) {
    if (!v->is_boolean()) jr::type_error(*v, path.member("exact_jacobian"), "true or false");
    o.exact_jacobian = v->get<bool>();
  }
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
  lm["solver"] = std::string(lsq_solver_name(o.solver));
  lm["direct_start"] = o.direct_start;
  lm["exact_jacobian"] = o.exact_jacobian;
  return lm;
}

namespace {

Json on_bound_json(std::span<const optim::Variable> vars, std::span<const optim::BoundHit> hits) {
  Json a = Json::array();
  for (const optim::BoundHit& h : hits)
    a.push_back({{"variable", vars[h.variable].name}, {"bound", h.upper ? "upper" : "lower"}, {"value", h.value}});
  return a;
}

// "on_bound" (every variable of x on a bound of `vars`, the box of the round that gave x) and "warnings" (one line
// each) of a result.
void bound_report(std::span<const optim::Variable> vars, std::span<const double> x, Json& out) {
  const std::vector<optim::BoundHit> hits = match_bound_hits(vars, x);
  out["on_bound"] = on_bound_json(vars, hits);
  out["warnings"] = optim::bound_warnings(vars, hits);
}

// The "map" settings: {"variables", "grid", "from"?, "to"?}.
MatchMapSettings map_settings_from_json(const Json& m) {
  const jr::JsonPath p = jr::root_path("map");
  jr::reject_unknown_members(m, p, {"variables", "grid", "from", "to"});
  MatchMapSettings o;
  const Json& names = jr::require_member(m, p, "variables");
  const Json& arr = jr::get_array(names, p.member("variables"));
  if (arr.size() != 2) jr::type_error(names, p.member("variables"), "two variable names [\"points[i].x\", ...]");
  for (std::size_t k = 0; k < 2; ++k) o.variables[k] = jr::get_string(arr[k], p.member("variables").element(k));
  if (const Json* v = jr::optional_member(m, "grid"))
    o.grid = static_cast<std::size_t>(jr::get_integer(*v, p.member("grid"), 2, 500));
  for (auto [name, range] : {std::pair{"from", &o.from}, std::pair{"to", &o.to}})
    if (const Json* v = jr::optional_member(m, name)) {
      const std::vector<double> a = jr::get_number_array(*v, p.member(name));
      if (a.size() != 2) jr::type_error(*v, p.member(name), "two numbers (one per mapped variable)");
      *range = std::array<double, 2>{a[0], a[1]};
    }
  return o;
}

Json map_settings_to_json(const MatchMapSettings& o) {
  Json m = {{"variables", Json::array({o.variables[0], o.variables[1]})}, {"grid", o.grid}};
  if (o.from) m["from"] = Json::array({(*o.from)[0], (*o.from)[1]});
  if (o.to) m["to"] = Json::array({(*o.to)[0], (*o.to)[1]});
  return m;
}

// Row-major grid values as rows of a JSON array (null where the evaluation failed).
Json grid_json(std::span<const double> values, std::size_t columns, std::size_t stride, std::size_t offset) {
  Json rows = Json::array();
  const std::size_t count = values.size() / stride;
  for (std::size_t row = 0; row * columns < count; ++row) {
    Json r = Json::array();
    for (std::size_t col = 0; col < columns; ++col) {
      const double v = values[(row * columns + col) * stride + offset];
      r.push_back(std::isfinite(v) ? Json(v) : Json(nullptr));
    }
    rows.push_back(std::move(r));
  }
  return rows;
}

// The "map" result: the axes, one grid per objective name (row j = y_values[j], column i = x_values[i]), the
// result's own values and the grid's smallest first objective.
Json map_json(const MatchMapSettings& settings, const optim::SweepResult& map, std::span<const double> at,
              std::span<const std::string> objectives, const optim::Problem& problem) {
  const std::array<std::size_t, 2> axes = settings.axes(problem.variables);
  const std::size_t nx = map.x_values.size(), k = objectives.size();
  Json out = {{"variables", Json::array({settings.variables[0], settings.variables[1]})},
              {"x", map.x_values},
              {"y", map.y_values},
              {"failed", map.failed}};
  for (std::size_t o = 0; o < k; ++o) out[objectives[o]] = grid_json(map.values, nx, k, o);
  if (k == 1) out["fitness"] = grid_json(map.fitness, nx, 1, 0);
  std::vector<double> values(problem.objectives);
  problem.evaluate(at, values);
  Json result = {{"x", at[axes[0]]}, {"y", at[axes[1]]}};
  for (std::size_t o = 0; o < k; ++o) result[objectives[o]] = values[o];
  out["result"] = std::move(result);
  std::size_t best = map.objective.size();
  for (std::size_t i = 0; i < map.objective.size(); ++i)
    if (std::isfinite(map.objective[i]) && (best == map.objective.size() || map.objective[i] < map.objective[best]))
      best = i;
  if (best < map.objective.size())
    out["min"] = {{"x", map.x_values[best % nx]}, {"y", map.y_values[best / nx]}, {objectives[0], map.objective[best]}};
  return out;
}

Json distances_json(const MatchDistances& d) {
  Json o = Json::object();
  auto num = [](double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); };
  o["mean"] = num(d.mean);
  o["max"] = num(d.max);
  if (std::isfinite(d.torsion_mean)) o["torsion_mean"] = d.torsion_mean;
  return o;
}

// "rounds": one entry per round of the re-centred re-runs (thesis 7.4.1).
Json rounds_json(const CurvatureMatch& match, std::span<const RecentreRound> rounds, int dimension) {
  Json out = Json::array();
  std::vector<Vec3> pts(match.setup().points.size());
  for (std::size_t i = 0; i < rounds.size(); ++i) {
    const RecentreRound& r = rounds[i];
    std::vector<double> lower, upper;
    for (const optim::Variable& v : r.variables) {
      lower.push_back(v.lower);
      upper.push_back(v.upper);
    }
    match.points_from(r.best, pts);
    out.push_back({{"round", i},
                   {"lower", lower},
                   {"upper", upper},
                   {"best_points", points_to_json(pts, dimension)},
                   {"after", distances_json(r.after)},
                   {"on_bound", on_bound_json(r.variables, r.on_bound)},
                   {"evaluations", r.evaluations}});
  }
  return out;
}

// "max_recentres" and "map", checked against the setup's design variables before any run.
void read_recentre_and_map(const Json& body, const CurvatureMatchSetup& setup, std::size_t& max_recentres,
                           std::optional<MatchMapSettings>& map) {
  if (const Json* v = jr::optional_member(body, "max_recentres"))
    max_recentres = static_cast<std::size_t>(jr::get_integer(*v, jr::root_path("max_recentres"), 0, 1000));
  if (const Json* v = jr::optional_member(body, "map")) {
    map = map_settings_from_json(*v);
    (void)map->axes(CurvatureMatch(setup).variables());
  }
}

}  // namespace

MatchSetupJson match_setup_from_json(const Json& body, const PathResolver& resolver, bool with_torsion) {
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
  // "movable": the indices of the data points that may move; the others' offsets are zeroed.
  if (const Json* v = jr::optional_member(body, "movable")) {
    const jr::JsonPath mp = jr::root_path("movable");
    const Json& a = jr::get_array(*v, mp);
    std::vector<bool> keep(s.points.size(), false);
    for (std::size_t k = 0; k < a.size(); ++k)
      keep[static_cast<std::size_t>(
          jr::get_integer(a[k], mp.element(k), 1, static_cast<long long>(s.points.size()) - 1))] = true;
    for (std::size_t i = 0; i < s.points.size(); ++i)
      if (!keep[i]) s.lower[i] = s.upper[i] = Vec3{};
  }
  // "proximity": one weight for every point or one per point.
  if (const Json* v = jr::optional_member(body, "proximity")) {
    const jr::JsonPath pp = jr::root_path("proximity");
    if (v->is_number())
      s.proximity.assign(s.points.size(), jr::get_number(*v, pp));
    else
      s.proximity = jr::get_number_array(*v, pp);
  }
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
  if (const Json* v = jr::optional_member(body, "validity"))
    s.validity = validity_from_json(*v, jr::root_path("validity"));
  // Bounds before the targets: a bad bound is reported without evaluating anything.
  s.target = Profile::from_samples(std::vector<double>{0.0, 1.0}, std::vector<double>{0.0, 0.0});
  s.validate();
  const law::Context context{};
  const auto read_target = [&](std::string_view name, bool torsion, Json& echo) {
    const Json& t = jr::require_member(body, root, name);
    echo = t;
    const jr::JsonPath tpath = jr::root_path(name);
    if (t.is_object() && t.contains("of_points")) return known_curve_target(t, tpath, s, resolver, context, torsion);
    return profile_from_json(t, tpath, resolver, context);
  };
  s.target = read_target("target", false, out.target);
  if (with_torsion) s.torsion_target = read_target("torsion_target", true, out.torsion_target);
  return out;
}

void match_setup_to_json(const MatchSetupJson& setup, Json& out) {
  const CurvatureMatchSetup& s = setup.setup;
  out["points"] = points_to_json(s.points, s.dimension);
  out["lower"] = points_to_json(s.lower, s.dimension);
  out["upper"] = points_to_json(s.upper, s.dimension);
  if (!s.proximity.empty()) out["proximity"] = s.proximity;
  if (s.start_tangent) out["start_tangent"] = point_to_json(*s.start_tangent, s.dimension);
  if (s.end_tangent) out["end_tangent"] = point_to_json(*s.end_tangent, s.dimension);
  out["target"] = setup.target;
  if (s.torsion_target) out["torsion_target"] = setup.torsion_target;
  out["abscissa"] = std::string(profile_abscissa_name(s.abscissa));
  out["samples"] = s.samples;
  if (s.validity.any()) out["validity"] = validity_to_json(s.validity);
}

MatchStudyFile match_study_from_json(const StudyDocument& document, const PathResolver& resolver) {
  const Json& body = document.body;
  check_members(body, {"points", "lower", "upper", "movable", "proximity", "validity", "start_tangent", "end_tangent",
                       "target", "abscissa", "samples", "method", "ga", "lm", "direct", "max_recentres", "map"});
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
  MatchSetupJson setup = match_setup_from_json(body, resolver, false);
  study.setup = std::move(setup.setup);
  read_recentre_and_map(body, study.setup, study.max_recentres, study.map);
  return {std::move(study), std::move(setup.target)};
}

Json match_study_to_json(const MatchStudyFile& file) {
  const MatchStudy& study = file.study;
  Json out = header_to_json(study.header);
  match_setup_to_json({study.setup, file.target, {}}, out);
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
  ga["seed_start"] = study.ga.seed_start;
  ga["distinct"] = study.ga.distinct;
  ga["distinct_radius"] = study.ga.distinct_radius;
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
  out["max_recentres"] = study.max_recentres;
  if (study.map) out["map"] = map_settings_to_json(*study.map);
  return out;
}

namespace {

// "validity" (the check of the result) and, for an invalid result, "refused" with the reasons, one warning each,
// and no "curve": an invalid design is not offered as the study's answer.
void validity_report(const ValidityRequirements& required, const std::optional<ValidityCheck>& check, Json& out) {
  if (!required.any() || !check) return;
  out["validity"] = validity_check_to_json(*check, required);
  if (check->valid()) return;
  out["refused"] = check->reasons;
  out.erase("curve");
  if (!out.contains("warnings")) out["warnings"] = Json::array();
  for (const std::string& r : check->reasons) out["warnings"].push_back("the result is refused as a design: " + r);
}

}  // namespace

Json match_result_to_json(const CurvatureMatch& match, const MatchStudyFile& file, const MatchResult& result) {
  const MatchStudy& study = file.study;
  const int dim = study.setup.dimension;
  std::vector<Vec3> pts(study.setup.points.size());
  Json out = Json::object();
  out["method"] = std::string(match_method_name(study.method));
  out["variables"] = Json::array();
  for (const auto& v : match.variables()) out["variables"].push_back(v.name);
  match.points_from(result.start, pts);
  out["start_points"] = points_to_json(pts, dim);
  match.points_from(result.best, pts);
  // The direct route moves no data point: its best points are the reconstructed curve at the data abscissae.
  out["best_points"] = points_to_json(result.direct ? result.direct_points : pts, dim);
  out["before"] = distances_json(result.before);
  out["after_ga"] = distances_json(result.after_ga);
  if (result.lm) {
    out["after_lm"] = distances_json(result.after);
    Json lm = Json::object();
    lm["iterations"] = result.lm->iterations;
    lm["evaluations"] = result.lm->evaluations;
    lm["termination"] = std::string(optim::termination_name(result.lm->termination));
    lm["message"] = result.lm->message;
    lm["start"] = result.lm_start;
    lm["seconds"] = result.lm->seconds;
    out["lm"] = lm;
  }
  out["after"] = distances_json(result.after);
  if (result.map) {
    optim::Problem problem = match.problem();
    problem.variables = result.variables;
    out["map"] = map_json(*study.map, *result.map, result.best, std::vector<std::string>{"objective"}, problem);
  }
  if (result.direct) {
    // The direct curve matches the profile by construction (up to the correction that holds its end); its
    // distance from the target and where its end lands are what to compare with the GA routes.
    const DirectReconstructionResult& d = *result.direct;
    out["after"] = {{"mean", d.mean_curvature_deviation}, {"max", d.max_curvature_deviation}};
    out["direct"] = direct_reconstruction_summary(d);
    if (d.nurbs) {
      const nurbs::NurbsCurve& c = d.nurbs->curve;
      out["direct"]["end_miss"] = norm(c.evaluate(c.domain().end) - study.setup.points.back());
    }
    if (const std::optional<nurbs::NurbsCurve> c = match_result_curve(match, result)) out["curve"] = curve_to_json(*c);
    validity_report(study.setup.validity, result.validity, out);
    out["seconds"] = result.seconds;
    out["study"] = match_study_to_json(file);
    return out;
  }
  out["ga"] = run_report_to_json(result.ga_report);
  std::size_t evaluations = 0;
  for (const RecentreRound& r : result.rounds) evaluations += r.evaluations;
  out["evaluations"] = evaluations;
  out["seconds"] = result.seconds;
  bound_report(result.variables, result.best, out);
  out["rounds"] = rounds_json(match, result.rounds, dim);
  if (study.ga.distinct > 0) {
    out["distinct"] = Json::array();
    for (const optim::Solution& d : result.distinct) {
      match.points_from(d.variables, pts);
      out["distinct"].push_back({{"objective", d.objectives.at(0)}, {"points", points_to_json(pts, dim)}});
    }
  }
  // The best curve (not the last distinct design's, which `pts` holds after the loop above).
  if (const std::optional<nurbs::NurbsCurve> c = match_result_curve(match, result)) out["curve"] = curve_to_json(*c);
  validity_report(study.setup.validity, result.validity, out);
  out["study"] = match_study_to_json(file);
  return out;
}

namespace {

Json points_of(const CurvatureMatch& match, std::span<const double> x) {
  std::vector<Vec3> pts(match.setup().points.size());
  match.points_from(x, pts);
  Json a = Json::array();
  for (const Vec3& p : pts) a.push_back(Json::array({p.x, p.y, p.z}));
  return a;
}

Json number_or_null(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

}  // namespace

TorsionMatchStudyFile torsion_match_study_from_json(const StudyDocument& document, const PathResolver& resolver) {
  const Json& body = document.body;
  check_members(body, {"points", "lower", "upper", "movable", "proximity", "validity", "start_tangent", "end_tangent",
                       "target", "torsion_target", "abscissa", "samples", "nsga2", "polish", "torsion_weight", "lm",
                       "max_recentres", "map"});
  TorsionMatchStudy study;
  study.header = document.header;
  TorsionMatchSettings& t = study.settings;
  if (const Json* g = jr::optional_member(body, "nsga2")) {
    const jr::JsonPath path = jr::root_path("nsga2");
    jr::reject_unknown_members(*g, path,
                               {"population", "generations", "crossover_probability", "crossover_eta", "mutation_eta",
                                "mutation_probability"});
    if (const Json* v = jr::optional_member(*g, "population"))
      t.population = static_cast<std::size_t>(jr::get_integer(*v, path.member("population"), 0, 100000));
    if (const Json* v = jr::optional_member(*g, "generations"))
      t.generations = static_cast<std::size_t>(jr::get_integer(*v, path.member("generations"), 0, 1000000));
    if (const Json* v = jr::optional_member(*g, "crossover_probability"))
      t.crossover_probability = jr::get_number(*v, path.member("crossover_probability"));
    if (const Json* v = jr::optional_member(*g, "crossover_eta"))
      t.crossover_eta = jr::get_number(*v, path.member("crossover_eta"));
    if (const Json* v = jr::optional_member(*g, "mutation_eta"))
      t.mutation_eta = jr::get_number(*v, path.member("mutation_eta"));
    if (const Json* v = jr::optional_member(*g, "mutation_probability"))
      t.mutation_probability = jr::get_number(*v, path.member("mutation_probability"));
  }
  if (const Json* v = jr::optional_member(body, "polish")) {
    if (!v->is_boolean()) jr::type_error(*v, jr::root_path("polish"), "true or false");
    t.polish = v->get<bool>();
  }
  if (const Json* v = jr::optional_member(body, "torsion_weight"))
    t.torsion_weight = jr::get_number(*v, jr::root_path("torsion_weight"));
  if (const Json* v = jr::optional_member(body, "lm")) t.lm = lm_options_from_json(*v, jr::root_path("lm"));
  t.validate();
  MatchSetupJson setup = match_setup_from_json(body, resolver, true);
  study.setup = std::move(setup.setup);
  read_recentre_and_map(body, study.setup, t.max_recentres, t.map);
  return {std::move(study), std::move(setup.target), std::move(setup.torsion_target)};
}

Json seeded_torsion_study_to_json(const curve::Curve& curve, const TorsionMatchSettings& settings) {
  return seeded_torsion_study_to_json(seed_match_setup(curve), settings);
}

Json seeded_torsion_study_to_json(const MatchSeed& seed, const TorsionMatchSettings& settings) {
  if (seed.setup.dimension != 3 || !seed.setup.torsion_target)
    throw Error(Errc::InvalidArgument,
                "the curve is planar: a curvature + torsion study needs a space curve (use match-curvature)",
                ErrorWhere{.field = "curve"});
  const auto samples = [&](const std::vector<double>& v) {
    Json list = Json::array();
    for (std::size_t i = 0; i < seed.u.size(); ++i) list.push_back(Json::array({seed.u[i], v[i]}));
    Json profile = Json::object();
    profile["samples"] = std::move(list);
    return profile;
  };
  TorsionMatchStudyFile file;
  file.study.header.kind = "match-curvature-torsion";
  file.study.setup = seed.setup;
  file.study.settings = settings;
  file.target = samples(seed.curvature);
  file.torsion_target = samples(seed.torsion);
  return torsion_match_study_to_json(file);
}

Json torsion_match_study_to_json(const TorsionMatchStudyFile& file) {
  const TorsionMatchStudy& study = file.study;
  Json out = header_to_json(study.header);
  match_setup_to_json({study.setup, file.target, file.torsion_target}, out);
  const TorsionMatchSettings& t = study.settings;
  Json g = Json::object();
  g["population"] = t.population;
  g["generations"] = t.generations;
  g["crossover_probability"] = t.crossover_probability;
  g["crossover_eta"] = t.crossover_eta;
  g["mutation_eta"] = t.mutation_eta;
  if (t.mutation_probability) g["mutation_probability"] = *t.mutation_probability;
  out["nsga2"] = g;
  out["polish"] = t.polish;
  out["torsion_weight"] = t.torsion_weight;
  out["lm"] = lm_options_to_json(t.lm);
  out["max_recentres"] = t.max_recentres;
  if (t.map) out["map"] = map_settings_to_json(*t.map);
  return out;
}

Json torsion_match_result_to_json(const CurvatureMatch& match, const TorsionMatchStudyFile& file,
                                  const TorsionMatchResult& result) {
  Json out = Json::object();
  out["variables"] = Json::array();
  for (const auto& v : match.variables()) out["variables"].push_back(v.name);
  out["start"] = {{"curvature", number_or_null(result.start_curvature)},
                  {"torsion", number_or_null(result.start_torsion)},
                  {"points", points_of(match, match.start_variables())}};
  const auto members = [&](const std::vector<TorsionFrontMember>& set) {
    Json front = Json::array();
    std::vector<Vec3> pts(match.setup().points.size());
    for (const TorsionFrontMember& m : set) {
      match.points_from(m.variables, pts);
      // Each member's curve (the spline its errors were measured on), so a client can preview and apply any of them.
      front.push_back({{"curvature", m.curvature},
                       {"torsion", m.torsion},
                       {"polished", m.polished},
                       {"points", points_to_json(pts, 3)},
                       {"curve", curve_to_json(match.sampler().curve(pts))}});
    }
    return front;
  };
  out["front"] = members(result.front);
  out["nsga2_front"] = members(result.nsga2_front);
  if (match.setup().validity.any()) {
    // Refused members carry their reasons and no curve: they are not designs to apply.
    Json refused = Json::array();
    std::vector<Vec3> pts(match.setup().points.size());
    for (const TorsionFrontMember& m : result.refused) {
      match.points_from(m.variables, pts);
      refused.push_back({{"curvature", m.curvature},
                         {"torsion", m.torsion},
                         {"polished", m.polished},
                         {"points", points_to_json(pts, 3)},
                         {"reasons", m.invalid}});
    }
    out["refused_members"] = std::move(refused);
    if (result.front.empty() && !result.refused.empty()) {
      out["refused"] = result.refused.front().invalid;
      out["warnings"] = Json::array();
      for (const std::string& r : result.refused.front().invalid)
        out["warnings"].push_back("no valid design was found; the best compromise is refused: " + r);
    }
  }
  if (!result.front.empty()) {
    const TorsionFrontMember& best = result.front[result.compromise];
    std::vector<Vec3> pts(match.setup().points.size());
    match.points_from(best.variables, pts);
    out["compromise"] = {{"index", result.compromise},
                         {"curvature", best.curvature},
                         {"torsion", best.torsion},
                         {"curve", curve_to_json(match.sampler().curve(pts))}};
    bound_report(result.variables, best.variables, out);
  }
  out["rounds"] = rounds_json(match, result.rounds, 3);
  if (result.map) {
    optim::Problem problem = curvature_torsion_problem(match);
    problem.variables = result.variables;
    out["map"] = map_json(*file.study.settings.map, *result.map, result.rounds.back().best,
                          std::vector<std::string>{"curvature", "torsion"}, problem);
  }
  out["nsga2"] = run_report_to_json(result.report);
  if (result.lm)
    out["polish"] = {{"iterations", result.lm->iterations},
                     {"evaluations", result.lm->evaluations},
                     {"termination", std::string(optim::termination_name(result.lm->termination))},
                     {"message", result.lm->message},
                     {"seconds", result.lm->seconds}};
  std::size_t evaluations = 0;
  for (const RecentreRound& r : result.rounds) evaluations += r.evaluations;
  out["evaluations"] = evaluations;
  out["seconds"] = result.seconds;
  out["study"] = torsion_match_study_to_json(file);
  return out;
}

std::string match_map_csv(const optim::SweepResult& map, std::span<const std::string> objectives) {
  std::string out = "x,y";
  for (const std::string& name : objectives) out += "," + name;
  out += "\n";
  const std::size_t nx = map.x_values.size(), k = objectives.size();
  HULA_ASSERT(map.values.size() == map.objective.size() * k, "match_map_csv: one name per objective");
  for (std::size_t i = 0; i < map.objective.size(); ++i) {
    // nlohmann's number form: the shortest text that reads back to the same double.
    out += Json(map.x_values[i % nx]).dump() + "," + Json(map.y_values[i / nx]).dump();
    for (std::size_t o = 0; o < k; ++o) {
      out += ',';
      if (std::isfinite(map.values[i * k + o])) out += Json(map.values[i * k + o]).dump();
    }
    out += '\n';
  }
  return out;
}

Json direct_reconstruction_summary(const studies::DirectReconstructionResult& r) {
  Json j;
  j["planar"] = r.planar;
  j["length"] = r.length;
  j["end_point_error"] = r.end_point_error;
  j["end_tangent_error"] = r.end_tangent_error;
  j["mean_curvature_deviation"] = r.mean_curvature_deviation;
  j["max_curvature_deviation"] = r.max_curvature_deviation;
  if (!r.planar) {
    j["mean_torsion_deviation"] = r.mean_torsion_deviation;
    j["max_torsion_deviation"] = r.max_torsion_deviation;
  }
  j["iterations"] = r.iterations;
  j["reconstructions"] = r.reconstructions;
  j["seconds"] = r.seconds;
  j["curvature_correction"] = r.curvature_correction;
  if (!r.torsion_correction.empty()) j["torsion_correction"] = r.torsion_correction;
  if (r.nurbs) {
    Json n;
    n["degree"] = r.nurbs->curve.degree();
    n["control_points"] = r.nurbs->curve.control_points().size();
    n["segments"] = r.nurbs->segments;
    n["max_deviation"] = r.nurbs->max_deviation;
    n["converged"] = r.nurbs->converged;
    j["nurbs"] = n;
  }
  return j;
}

}  // namespace hula::io
