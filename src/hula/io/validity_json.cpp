// SPDX-License-Identifier: MIT
// Validity requirements and reports as JSON (see the header).
#include "hula/io/validity_json.hpp"

#include <string>

#include "hula/core/error.hpp"

namespace hula::io {

namespace jr = json;

namespace {

bool get_bool(const Json& value, const jr::JsonPath& path) {
  if (!value.is_boolean()) jr::type_error(value, path, "true or false");
  return value.get<bool>();
}

}  // namespace

studies::ValidityRequirements validity_from_json(const Json& value, const jr::JsonPath& path) {
  if (!value.is_object()) jr::type_error(value, path, "an object");
  jr::reject_unknown_members(value, path,
                             {"no_self_intersection", "min_speed", "monotone_curvature", "handling", "penalty"});
  studies::ValidityRequirements r;
  if (const Json* v = jr::optional_member(value, "no_self_intersection"))
    r.no_self_intersection = get_bool(*v, path.member("no_self_intersection"));
  if (const Json* v = jr::optional_member(value, "min_speed"))
    r.min_speed = jr::get_number(*v, path.member("min_speed"));
  if (const Json* v = jr::optional_member(value, "monotone_curvature"))
    r.monotone_curvature = get_bool(*v, path.member("monotone_curvature"));
  if (const Json* v = jr::optional_member(value, "handling")) {
    const std::string h = jr::get_string(*v, path.member("handling"));
    if (h == "feasibility")
      r.handling = optim::ConstraintHandling::FeasibilityRules;
    else if (h == "penalty")
      r.handling = optim::ConstraintHandling::Penalty;
    else
      throw Error(Errc::ParseError, "validity.handling = " + jr::quote(h) + ": expected \"feasibility\" or \"penalty\"",
                  {.field = "validity.handling"});
  }
  if (const Json* v = jr::optional_member(value, "penalty")) r.penalty = jr::get_number(*v, path.member("penalty"));
  r.validate();
  return r;
}

Json validity_to_json(const studies::ValidityRequirements& r) {
  Json out = Json::object();
  out["no_self_intersection"] = r.no_self_intersection;
  out["min_speed"] = r.min_speed;
  out["monotone_curvature"] = r.monotone_curvature;
  out["handling"] = r.handling == optim::ConstraintHandling::Penalty ? "penalty" : "feasibility";
  out["penalty"] = r.penalty;
  return out;
}

Json validity_check_to_json(const studies::ValidityCheck& check, const studies::ValidityRequirements& r) {
  Json out = Json::object();
  out["valid"] = check.valid();
  out["reasons"] = check.reasons;
  if (r.no_self_intersection) out["self_intersections"] = check.self_intersections;
  if (r.min_speed > 0.0) out["min_speed_ratio"] = check.speed_ratio;
  if (r.monotone_curvature) out["curvature_extrema"] = check.curvature_extrema;
  return out;
}

}  // namespace hula::io
