// SPDX-License-Identifier: MIT
// The fairing preview's request and ghost as JSON (fair_preview_json.hpp).
#include "hula/io/fair_preview_json.hpp"

#include <string>
#include <vector>

#include "hula/io/json_read.hpp"

namespace hula::io {

FairPreviewRequest fair_preview_request_from_json(const Json& body) {
  const json::JsonPath root;
  json::reject_unknown_members(body, root, {"tolerance", "method", "budget", "hold", "analysis", "curve"});
  FairPreviewRequest r;
  r.options.tolerance = json::get_number(json::require_member(body, root, "tolerance"), root.member("tolerance"));
  if (const Json* m = json::optional_member(body, "method"))
    r.options.method = studies::assistant_method_from_name(json::get_string(*m, root.member("method")));
  if (const Json* b = json::optional_member(body, "budget"))
    r.options.time_budget_seconds = json::get_number(*b, root.member("budget"));
  if (const Json* h = json::optional_member(body, "hold"))
    r.options.hold = studies::assistant_hold_from_name(json::get_string(*h, root.member("hold")));
  if (const Json* a = json::optional_member(body, "analysis")) r.analysis = *a;
  if (const Json* c = json::optional_member(body, "curve")) r.curve = curve_from_json(*c);
  r.options.validate();
  return r;
}

Json fair_preview_to_json(const studies::AssistantResult& r, const studies::AssistantOptions& options,
                          std::uint64_t revision) {
  Json out = Json::object();
  out["revision"] = revision;
  out["method"] = std::string(studies::assistant_method_name(options.method));
  out["tolerance"] = options.tolerance;
  out["curve"] = curve_to_json(r.curve);
  out["energy_before"] = r.energy_before;
  out["energy_after"] = r.energy_after;
  out["max_deviation"] = r.max_deviation;
  out["data_points"] = points_to_json(r.data_points, 3);
  out["faired_points"] = points_to_json(r.faired_points, 3);
  out["iterations"] = r.iterations;
  out["stopped"] = r.stopped;
  out["seconds"] = r.seconds;
  out["hold"] = std::string(studies::assistant_hold_name(options.hold));
  return out;
}

}  // namespace hula::io
