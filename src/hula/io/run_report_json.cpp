// SPDX-License-Identifier: MIT
// The run report codec (run_report_json.hpp).
#include "hula/io/run_report_json.hpp"

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

}  // namespace hula::io
