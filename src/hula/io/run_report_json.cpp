// SPDX-License-Identifier: MIT
// The run report codec (run_report_json.hpp).
#include "hula/io/run_report_json.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

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
  // Built in place (reserved arrays, members moved in): a long study's log has tens of thousands of
  // individuals, and every door that shows a study shows its log.
  const auto number = [](double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); };
  const auto numbers = [&](const std::vector<double>& values, std::size_t first, std::size_t count) {
    Json out = Json::array();
    auto& array = out.get_ref<Json::array_t&>();
    array.reserve(count);
    for (std::size_t j = 0; j < count; ++j) array.push_back(number(values[first + j]));
    return out;
  };
  Json generations = Json::array();
  auto& list = generations.get_ref<Json::array_t&>();
  list.reserve(log.generations().size());
  for (const optim::GenerationLog& g : log.generations()) {
    Json individuals = Json::array();
    auto& members = individuals.get_ref<Json::array_t&>();
    members.reserve(g.size());
    for (std::size_t i = 0; i < g.size(); ++i) {
      Json individual = Json::object();
      individual["variables"] = numbers(g.variables, i * g.dimension, g.dimension);
      individual["objectives"] = numbers(g.objective_values, i * g.objectives, g.objectives);
      individual["violation"] = number(g.violation[i]);
      individual["fitness"] = number(g.fitness[i]);
      individual["failed"] = g.failed[i] != 0;
      members.push_back(std::move(individual));
    }
    Json generation = Json::object();
    generation["generation"] = g.generation;
    generation["evaluations"] = g.evaluations;
    generation["individuals"] = std::move(individuals);
    list.push_back(std::move(generation));
  }
  Json out = Json::object();
  out["generations"] = std::move(generations);
  return out;
}

namespace {

// A number, or NaN for null (run_log_to_json writes every non-finite value as null).
double number_or_nan(const Json& value, const json::JsonPath& path) {
  if (value.is_null()) return std::numeric_limits<double>::quiet_NaN();
  return json::get_number(value, path);
}

// Appends the numbers (or nulls) of the array member `name` of `individual`; returns how many.
std::size_t append_numbers(const Json& individual, const json::JsonPath& at, const char* name,
                           std::vector<double>& out) {
  const json::JsonPath path = at.member(name);
  const Json& array = json::get_array(json::require_member(individual, at, name), path);
  for (std::size_t j = 0; j < array.size(); ++j)
    out.push_back(array[j].is_number() ? array[j].get<double>() : number_or_nan(array[j], path.element(j)));
  return array.size();
}

}  // namespace

optim::RunLog run_log_from_json(const Json& json) {
  const json::JsonPath root = json::root_path("log");
  if (!json.is_object()) json::type_error(json, root, "an object {\"generations\": [...]}");
  json::reject_unknown_members(json, root, {"generations"});
  const json::JsonPath generations_path = root.member("generations");
  const Json& generations = json::get_array(json::require_member(json, root, "generations"), generations_path);
  constexpr long long kMax = std::numeric_limits<long long>::max();
  optim::RunLog log;
  for (std::size_t k = 0; k < generations.size(); ++k) {
    const json::JsonPath at = generations_path.element(k);
    const Json& g = generations[k];
    if (!g.is_object()) json::type_error(g, at, "an object");
    json::reject_unknown_members(g, at, {"generation", "evaluations", "individuals"});
    optim::GenerationLog out;
    out.generation = static_cast<std::size_t>(
        json::get_integer(json::require_member(g, at, "generation"), at.member("generation"), 0, kMax));
    out.evaluations = static_cast<std::size_t>(
        json::get_integer(json::require_member(g, at, "evaluations"), at.member("evaluations"), 0, kMax));
    const json::JsonPath individuals_path = at.member("individuals");
    const Json& individuals = json::get_array(json::require_member(g, at, "individuals"), individuals_path);
    const std::size_t n = individuals.size();
    out.violation.reserve(n);
    out.fitness.reserve(n);
    out.failed.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      const json::JsonPath ip = individuals_path.element(i);
      const Json& individual = individuals[i];
      if (!individual.is_object()) json::type_error(individual, ip, "an object");
      json::reject_unknown_members(individual, ip, {"variables", "objectives", "violation", "fitness", "failed"});
      const std::size_t dimension = append_numbers(individual, ip, "variables", out.variables);
      const std::size_t objectives = append_numbers(individual, ip, "objectives", out.objective_values);
      if (i == 0) {
        out.dimension = dimension;
        out.objectives = objectives;
      } else if (dimension != out.dimension || objectives != out.objectives) {
        const bool variables = dimension != out.dimension;
        const json::JsonPath path = ip.member(variables ? "variables" : "objectives");
        throw Error(Errc::ParseError,
                    path.text + " has " + std::to_string(variables ? dimension : objectives) +
                        " values where individual 0 has " + std::to_string(variables ? out.dimension : out.objectives),
                    path.where);
      }
      out.violation.push_back(number_or_nan(json::require_member(individual, ip, "violation"), ip.member("violation")));
      out.fitness.push_back(number_or_nan(json::require_member(individual, ip, "fitness"), ip.member("fitness")));
      const Json& failed = json::require_member(individual, ip, "failed");
      if (!failed.is_boolean()) json::type_error(failed, ip.member("failed"), "true or false");
      out.failed.push_back(failed.get<bool>() ? 1 : 0);
    }
    log.append(std::move(out));
  }
  return log;
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
