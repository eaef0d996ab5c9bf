// SPDX-License-Identifier: MIT
#include "hula/io/fair_knots_study_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <optional>

#include "hula/core/error.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/json_read.hpp"

namespace hula::io {

using namespace studies;  // NOLINT(google-build-using-namespace): this file is the studies' codec

namespace {

using json::JsonPath;
using json::root_path;

// Runs a validate() and rewrites its error to name the study member `field`.
template <typename F>
void validate_as(const std::string& field, F&& check) {
  try {
    check();
  } catch (const Error& e) {
    ErrorWhere where = e.where();
    where.field = field;
    throw Error(e.code(), field + ": " + e.message(), where);
  }
}

double number_or(const Json& object, const JsonPath& path, std::string_view name, double fallback) {
  const Json* v = json::optional_member(object, name);
  return v != nullptr ? json::get_number(*v, path.member(name)) : fallback;
}

std::size_t count_or(const Json& object, const JsonPath& path, std::string_view name, std::size_t fallback,
                     long long lo, long long hi) {
  const Json* v = json::optional_member(object, name);
  return v != nullptr ? static_cast<std::size_t>(json::get_integer(*v, path.member(name), lo, hi)) : fallback;
}

void append_double(std::string& out, double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  out.append(buf, r.ptr);
}

}  // namespace

FairKnotsStudy fair_knots_study_from_json(const StudyDocument& document) {
  const Json& doc = document.body;
  check_members(doc, {"points", "start", "end", "energy", "method", "ga", "deterministic", "map", "parameters"});
  FairKnotsStudy study;
  study.header = document.header;

  const json::PointArray pts =
      json::get_points(json::require_member(doc, root_path(""), "points"), root_path("points"));
  study.setup.points = pts.points;
  study.setup.dimension = pts.dimension;
  if (const Json* s = json::optional_member(doc, "start")) study.setup.start = io::end_condition_from_json(*s, "start");
  if (const Json* e = json::optional_member(doc, "end")) study.setup.end = io::end_condition_from_json(*e, "end");
  if (const Json* e = json::optional_member(doc, "energy")) {
    const std::string name = json::get_string(*e, root_path("energy"));
    if (name == "bending") {
      study.setup.energy = FairingEnergy::Bending;
    } else if (name == "variation") {
      study.setup.energy = FairingEnergy::Variation;
    } else {
      throw Error(Errc::ParseError, "energy = " + json::quote(name) + " must be \"bending\" or \"variation\"",
                  root_path("energy").where);
    }
  }
  if (const Json* m = json::optional_member(doc, "method")) {
    const std::string name = json::get_string(*m, root_path("method"));
    if (name == "none") {
      study.method = FairingMethod::None;
    } else if (name == "ga") {
      study.method = FairingMethod::Ga;
    } else if (name == "deterministic") {
      study.method = FairingMethod::Deterministic;
    } else if (name == "both") {
      study.method = FairingMethod::Both;
    } else {
      throw Error(Errc::ParseError,
                  "method = " + json::quote(name) + " must be \"ga\", \"deterministic\", \"both\" or \"none\"",
                  root_path("method").where);
    }
  }
  study.setup.validate();  // its errors name points[i], start or end

  // GA settings.
  GaFairingOptions& ga = study.ga;
  if (const Json* g = json::optional_member(doc, "ga")) {
    const JsonPath p = root_path("ga");
    json::reject_unknown_members(*g, p,
                                 {"algorithm", "population", "generations", "crossover_probability",
                                  "mutation_probability", "boost_start", "boost_end", "resolution",
                                  "precision_fraction", "recentre_fraction", "recentre_improvement", "max_recentres"});
    if (const Json* a = json::optional_member(*g, "algorithm")) {
      const std::string name = json::get_string(*a, p.member("algorithm"));
      if (name == "real") {
        ga.algorithm = FairingGa::Real;
      } else if (name == "binary") {
        ga.algorithm = FairingGa::Binary;
      } else {
        throw Error(Errc::ParseError, "ga.algorithm = " + json::quote(name) + " must be \"real\" or \"binary\"",
                    p.member("algorithm").where);
      }
    }
    const std::size_t population = count_or(*g, p, "population", 50, 2, 100000);
    const std::size_t generations = count_or(*g, p, "generations", 50, 0, 1000000);
    ga.binary.population = ga.real.population = population;
    ga.binary.run.stop.generations = ga.real.run.stop.generations = generations;
    ga.binary.crossover_probability = number_or(*g, p, "crossover_probability", ga.binary.crossover_probability);
    ga.real.crossover_probability = number_or(*g, p, "crossover_probability", ga.real.crossover_probability);
    ga.binary.mutation_probability = number_or(*g, p, "mutation_probability", ga.binary.mutation_probability);
    if (json::optional_member(*g, "mutation_probability") != nullptr) {
      ga.real.mutation_probability = ga.binary.mutation_probability;
    }
    ga.binary.boost_start = number_or(*g, p, "boost_start", ga.binary.boost_start);
    ga.binary.boost_end = number_or(*g, p, "boost_end", ga.binary.boost_end);
    ga.resolution = number_or(*g, p, "resolution", ga.resolution);
    ga.precision_fraction = number_or(*g, p, "precision_fraction", ga.precision_fraction);
    ga.recentre_fraction = number_or(*g, p, "recentre_fraction", ga.recentre_fraction);
    ga.recentre_improvement = number_or(*g, p, "recentre_improvement", ga.recentre_improvement);
    ga.max_recentres = count_or(*g, p, "max_recentres", ga.max_recentres, 0, 1000);
  }
  ga.binary.run.seed = ga.real.run.seed = study.header.seed;
  ga.binary.run.threads = ga.real.run.threads = study.header.threads;
  validate_as("ga", [&] { ga.validate(); });

  if (const Json* d = json::optional_member(doc, "deterministic")) {
    const JsonPath p = root_path("deterministic");
    json::reject_unknown_members(*d, p, {"initial_step", "x_tolerance", "f_tolerance", "max_evaluations", "restarts"});
    optim::NelderMeadOptions& o = study.deterministic;
    o.initial_step = number_or(*d, p, "initial_step", o.initial_step);
    o.x_tolerance = number_or(*d, p, "x_tolerance", o.x_tolerance);
    o.f_tolerance = number_or(*d, p, "f_tolerance", o.f_tolerance);
    o.max_evaluations = count_or(*d, p, "max_evaluations", o.max_evaluations, 1, 100000000);
    o.restarts = count_or(*d, p, "restarts", o.restarts, 0, 1000);
  }
  validate_as("deterministic", [&] { study.deterministic.validate(); });

  if (const Json* m = json::optional_member(doc, "map")) {
    const JsonPath p = root_path("map");
    json::reject_unknown_members(*m, p, {"knots", "grid", "sections"});
    EnergyMapOptions o;
    if (const Json* k = json::optional_member(*m, "knots")) {
      const Json& arr = json::get_array(*k, p.member("knots"));
      if (arr.size() != 2) json::type_error(*k, p.member("knots"), "two parameter indices [i, j]");
      o.first = static_cast<std::size_t>(json::get_integer(arr[0], p.member("knots").element(0), 0, 1000000));
      o.second = static_cast<std::size_t>(json::get_integer(arr[1], p.member("knots").element(1), 0, 1000000));
    }
    o.grid = count_or(*m, p, "grid", o.grid, 2, 2000);
    o.validate(study.setup.points.size());
    study.map = o;
    if (const Json* v = json::optional_member(*m, "sections")) {
      study.sections = json::get_number_array(*v, p.member("sections"));
      // Each section must lie inside the map's range of k1 (the chord-length neighbours).
      const std::vector<double> chord = chord_length_parameters(study.setup);
      for (std::size_t i = 0; i < study.sections.size(); ++i) {
        try {
          (void)map_section(study.setup, chord, o, study.sections[i], 2);
        } catch (const Error& e) {
          const JsonPath at = p.member("sections").element(i);
          throw Error(Errc::InvalidOption, at.text + ": " + e.message(), at.where);
        }
      }
    }
  }

  if (const Json* v = json::optional_member(doc, "parameters")) {
    std::vector<double> p = json::get_number_array(*v, root_path("parameters"));
    check_parameters(study.setup, p);
    study.parameters = std::move(p);
  }
  return study;
}

Json fair_knots_study_to_json(const FairKnotsStudy& study) {
  StudyHeader h = study.header;
  h.kind = "fair-knots";
  Json out = header_to_json(h);
  Json points = Json::array();
  for (const Vec3& q : study.setup.points) {
    points.push_back(study.setup.dimension == 2 ? Json::array({q.x, q.y}) : Json::array({q.x, q.y, q.z}));
  }
  out["points"] = std::move(points);
  out["start"] = io::end_condition_to_json(study.setup.start, study.setup.dimension);
  out["end"] = io::end_condition_to_json(study.setup.end, study.setup.dimension);
  out["energy"] = fairing_energy_name(study.setup.energy);
  out["method"] = fairing_method_name(study.method);
  const GaFairingOptions& ga = study.ga;
  const bool binary = ga.algorithm == FairingGa::Binary;
  Json g = Json::object();
  g["algorithm"] = binary ? "binary" : "real";
  g["population"] = binary ? ga.binary.population : ga.real.population;
  g["generations"] = binary ? ga.binary.run.stop.generations : ga.real.run.stop.generations;
  g["crossover_probability"] = binary ? ga.binary.crossover_probability : ga.real.crossover_probability;
  if (binary) {
    g["mutation_probability"] = ga.binary.mutation_probability;
    g["boost_start"] = ga.binary.boost_start;
    g["boost_end"] = ga.binary.boost_end;
  } else if (ga.real.mutation_probability) {
    g["mutation_probability"] = *ga.real.mutation_probability;
  }
  g["resolution"] = ga.resolution;
  g["precision_fraction"] = ga.precision_fraction;
  g["recentre_fraction"] = ga.recentre_fraction;
  g["recentre_improvement"] = ga.recentre_improvement;
  g["max_recentres"] = ga.max_recentres;
  out["ga"] = std::move(g);
  const optim::NelderMeadOptions& d = study.deterministic;
  out["deterministic"] = Json{{"initial_step", d.initial_step},
                              {"x_tolerance", d.x_tolerance},
                              {"f_tolerance", d.f_tolerance},
                              {"max_evaluations", d.max_evaluations},
                              {"restarts", d.restarts}};
  if (study.map) {
    out["map"] = Json{{"knots", Json::array({study.map->first, study.map->second})}, {"grid", study.map->grid}};
    if (!study.sections.empty()) out["map"]["sections"] = study.sections;
  }
  if (study.parameters) out["parameters"] = *study.parameters;
  return out;
}

std::string energy_map_csv(const EnergyMap& map) {
  std::string out = "k1,k2,energy\n";
  for (std::size_t j = 0; j < map.k2.size(); ++j) {
    for (std::size_t i = 0; i < map.k1.size(); ++i) {
      append_double(out, map.k1[i]);
      out += ',';
      append_double(out, map.k2[j]);
      out += ',';
      const double e = map.energy[j * map.k1.size() + i];
      if (std::isfinite(e)) append_double(out, e);
      out += '\n';
    }
  }
  return out;
}

Json fairing_evaluation_to_json(const studies::ParameterEvaluation& e) {
  return Json{{"parameters", e.parameters},
              {"energy", e.energy},
              {"bending", e.bending},
              {"variation", e.variation},
              {"curve", curve_to_json(e.curve)}};
}

Json fairing_result_to_json(const studies::FairingResult& r, double chord_energy) {
  Json out = fairing_evaluation_to_json(r.best);
  out["improvement"] = chord_energy > 0.0 ? 1.0 - r.best.energy / chord_energy : 0.0;
  out["evaluations"] = r.evaluations;
  out["rounds"] = r.rounds;
  out["seconds"] = r.seconds;
  out["stopped"] = r.stopped();
  out["termination"] = std::string(optim::termination_name(r.termination));
  out["message"] = r.message;
  if (!r.bounds.lower.empty()) out["bounds"] = Json{{"lower", r.bounds.lower}, {"upper", r.bounds.upper}};
  return out;
}

Json fair_knots_result_to_json(const studies::FairKnotsStudy& study, const studies::FairKnotsOutcome& outcome) {
  const studies::KnotFairingSetup& setup = study.setup;
  const double chord_energy = outcome.chord_length.energy;
  Json out = Json::object();
  out["study"] = fair_knots_study_to_json(study);
  out["energy"] = studies::fairing_energy_name(setup.energy);
  out["chord_length"] = fairing_evaluation_to_json(outcome.chord_length);
  if (outcome.given) out["given"] = fairing_evaluation_to_json(*outcome.given);
  if (const std::optional<studies::EnergyMap>& map = outcome.map) {
    out["map"] = Json{{"knots", Json::array({map->first, map->second})},
                      {"grid", study.map->grid},
                      {"min", Json{{"energy", map->min_energy}, {"k1", map->min_k1}, {"k2", map->min_k2}}}};
    for (const studies::MapSection& sec : outcome.sections) {
      Json energies = Json::array();
      for (const double e : sec.energy) energies.push_back(std::isfinite(e) ? Json(e) : Json(nullptr));
      out["map"]["sections"].push_back(Json{{"k1", sec.k1}, {"k2", sec.k2}, {"energy", energies}});
    }
  }
  if (outcome.ga) out["ga"] = fairing_result_to_json(*outcome.ga, chord_energy);
  if (outcome.deterministic) out["deterministic"] = fairing_result_to_json(*outcome.deterministic, chord_energy);
  if (outcome.ga && outcome.deterministic) {
    const std::vector<double>& a = outcome.ga->best.parameters;
    const std::vector<double>& b = outcome.deterministic->best.parameters;
    double dp = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) dp = std::max(dp, std::abs(a[i] - b[i]));
    out["agreement"] = Json{{"relative_energy", outcome.ga->best.energy / outcome.deterministic->best.energy - 1.0},
                            {"max_parameter", dp}};
  }
  return out;
}

}  // namespace hula::io
