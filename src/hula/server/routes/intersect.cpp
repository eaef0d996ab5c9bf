// SPDX-License-Identifier: MIT
// POST /api/intersect {"a": curve file, "b"?: curve file, "tolerance"?} →
// the points where the curves meet and their overlaps (without "b": where "a"
// meets itself); POST /api/distance {"a", "b", "tolerance"?} → the smallest
// distance and where it is reached. `hula intersect` / `hula distance` over
// HTTP: io::intersection_answer / distance_answer (nurbs::intersect,
// self_intersect, curve_distance and their codec). Law and natural curves are
// answered through their NURBS stand-in ("stand_in_deviation").
#include <optional>

#include "hula/io/intersection_json.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/json_read.hpp"
#include "hula/server/routes/routes.hpp"

namespace hula::server::routes {

namespace {

namespace json = io::json;

nurbs::IntersectOptions read_options(const Json& body) {
  nurbs::IntersectOptions o;
  if (const Json* t = json::optional_member(body, "tolerance")) {
    o.tolerance.resabs = json::get_number(*t, json::root_path("tolerance"));
    try {
      o.validate();
    } catch (const Error& e) {
      throw Error(e.code(), "tolerance = " + format_number(o.tolerance.resabs) + " must be > 0",
                  ErrorWhere{.field = "tolerance"});
    }
  }
  return o;
}

Response intersect(const Request& request) {
  const Json body = request.json();
  json::reject_unknown_members(body, json::JsonPath(), {"a", "b", "tolerance"});
  const curve::Curve a = read_curve_member(body, "a");
  std::optional<curve::Curve> b;
  if (json::optional_member(body, "b") != nullptr) b = read_curve_member(body, "b");
  return json_response(200, io::intersection_answer(a, b ? &*b : nullptr, read_options(body)));
}

Response distance(const Request& request) {
  const Json body = request.json();
  json::reject_unknown_members(body, json::JsonPath(), {"a", "b", "tolerance"});
  const curve::Curve a = read_curve_member(body, "a");
  const curve::Curve b = read_curve_member(body, "b");
  return json_response(200, io::distance_answer(a, b, read_options(body)));
}

}  // namespace

curve::Curve read_curve_member(const Json& body, const char* field) {
  const Json& value = json::require_member(body, json::JsonPath(), field);
  try {
    return io::curve_from_json(value);
  } catch (const Error& e) {
    ErrorWhere where = e.where();
    where.field = where.field.empty() ? std::string(field) : std::string(field) + "." + where.field;
    throw Error(e.code(), std::string(field) + ": " + e.message(), where);
  }
}

void add_intersect(Router& router, const Context&) {
  // Their work grows with the curves sent (up to the body limit): on the request workers.
  router.add("POST", "/api/intersect", intersect, Runs::Worker);
  router.add("POST", "/api/distance", distance, Runs::Worker);
}

}  // namespace hula::server::routes
