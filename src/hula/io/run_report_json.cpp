// SPDX-License-Identifier: MIT
// The run report codec (run_report_json.hpp).
#include "hula/io/run_report_json.hpp"

#include <cmath>
#include <limits>
#include <optional>

#include "hula/core/error.hpp"
#include "hula/io/json_read.hpp"

namespace hula::io {

Json run_report_to_json(const optim::RunReport& r, const RunIdentity& identity) {
  Json o = Json::object();
  o["termination"] = std::string(optim::termination_name(r.termination));
  o["message"] = r.message;
  o["generations"] = r.generations;
  o["evaluations"] = r.evaluations;
  o["failed_evaluations"] = r.failed_evaluations;
  o["seconds"] = r.seconds;
  if (identity.seed) o["seed"] = *identity.seed;
  if (identity.threads) o["threads"] = *identity.threads;
  if (identity.algorithm) o["algorithm"] = *identity.algorithm;
  if (identity.problem) o["problem"] = *identity.problem;
  return o;
}

optim::RunReport run_report_from_json(const Json& json) {
  const json::JsonPath root = json::root_path("report");
  if (!json.is_object()) throw Error(Errc::ParseError, "report: must be an object", {.field = "report"});
  optim::RunReport r;
  const std::string name =
      json::get_string(json::require_member(json, root, "termination"), root.member("termination"));
  const std::optional<optim::Termination> termination = optim::termination_from_name(name);
  if (!termination)
    throw Error(Errc::ParseError, "report.termination = " + json::quote(name) + " is not a termination name",
                {.field = "report.termination"});
  r.termination = *termination;
  if (const Json* m = json::optional_member(json, "message")) r.message = json::get_string(*m, root.member("message"));
  constexpr long long kMax = std::numeric_limits<long long>::max();
  const auto count = [&](const char* member) {
    return static_cast<std::size_t>(
        json::get_integer(json::require_member(json, root, member), root.member(member), 0, kMax));
  };
  r.generations = count("generations");
  r.evaluations = count("evaluations");
  r.failed_evaluations = count("failed_evaluations");
  r.seconds = json::get_number(json::require_member(json, root, "seconds"), root.member("seconds"));
  return r;
}

Json run_log_to_json(const optim::RunLog& log) {
  const auto number = [](double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); };
  Json generations = Json::array();
  for (const optim::GenerationLog& g : log.generations()) {
    Json individuals = Json::array();
    for (std::size_t i = 0; i < g.size(); ++i) {
      Json x = Json::array(), f = Json::array();
      for (std::size_t j = 0; j < g.dimension; ++j) x.push_back(number(g.variables[i * g.dimension + j]));
      for (std::size_t j = 0; j < g.objectives; ++j) f.push_back(number(g.objective_values[i * g.objectives + j]));
      individuals.push_back(Json{{"variables", std::move(x)},
                                 {"objectives", std::move(f)},
                                 {"violation", number(g.violation[i])},
                                 {"fitness", number(g.fitness[i])},
                                 {"failed", g.failed[i] != 0}});
    }
    generations.push_back(
        Json{{"generation", g.generation}, {"evaluations", g.evaluations}, {"individuals", std::move(individuals)}});
  }
  return Json{{"generations", std::move(generations)}};
}

Json study_report_to_json(const studies::StudyReport& report) {
  Json out = Json::object();
  out["study"] = report.kind;
  out["termination"] = report.cancelled ? "Cancelled" : "Completed";
  out["generations"] = report.generations;
  out["evaluations"] = report.evaluations;
  out["seconds"] = report.seconds;
  return out;
}

Json generation_event_json(const optim::GenerationLog& g, double elapsed) {
  const auto finite_or_null = [](double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); };
  Json e = Json::object();
  e["generation"] = g.generation;
  e["evaluations"] = g.evaluations;
  std::size_t best = g.size();
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (g.failed[i]) continue;
    if (best == g.size()) {
      best = i;
      continue;
    }
    const double vi = g.violation[i], vb = g.violation[best];
    if (vi < vb || (vi == vb && g.objective_values[i * g.objectives] < g.objective_values[best * g.objectives]))
      best = i;
  }
  Json best_objectives = Json::array();
  if (best < g.size())
    for (std::size_t k = 0; k < g.objectives; ++k)
      best_objectives.push_back(finite_or_null(g.objective_values[best * g.objectives + k]));
  e["best"] = std::move(best_objectives);
  if (g.objectives > 1) {
    // The first front of NSGA-II is fitness = rank 0.
    Json front = Json::array();
    for (std::size_t i = 0; i < g.size(); ++i) {
      if (g.failed[i] || g.fitness[i] != 0.0) continue;
      Json point = Json::array();
      for (std::size_t k = 0; k < g.objectives; ++k)
        point.push_back(finite_or_null(g.objective_values[i * g.objectives + k]));
      front.push_back(std::move(point));
    }
    e["front"] = std::move(front);
  }
  e["elapsed"] = elapsed;
  return e;
}

}  // namespace hula::io
