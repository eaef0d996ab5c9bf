// SPDX-License-Identifier: MIT
// The curves made from a curve, over HTTP, each the answer of the io entry its
// command prints: POST /api/offset {"curve", "distance", "tolerance"?,
// "trim"?} → io::offset_answer (`hula offset`); POST /api/helical-offset
// {"curve", "distance", "twist"?, "frame"?, "tolerance"?} →
// io::helical_offset_answer (`hula helical-offset`); POST /api/orthotomic
// {"curve", "pole", "k"?, "tolerance"?} → io::orthotomic_answer (`hula
// orthotomic`); POST /api/polar {"curve", "centre", "radius"?, "tolerance"?}
// → io::polar_answer (`hula polar`). The made curve is in the answer as a
// curve file ("curve"; the commands write it to -o instead).
#include <string>

#include "hula/io/json_read.hpp"
#include "hula/io/offset_json.hpp"
#include "hula/server/routes/routes.hpp"

namespace hula::server::routes {

namespace {

namespace json = io::json;

double number_member(const Json& body, const char* field, double fallback) {
  const Json* v = json::optional_member(body, field);
  return v == nullptr ? fallback : json::get_number(*v, json::root_path(field));
}

// A law text member: a string, or a number (written as the CLI would read it back).
std::string law_member(const Json& body, const char* field, const char* fallback) {
  const Json* v = json::optional_member(body, field);
  if (v == nullptr) return fallback;
  if (v->is_number()) return format_number(json::get_number(*v, json::root_path(field)));
  return json::get_string(*v, json::root_path(field));
}

Response offset(const Request& request) {
  const Json body = request.json();
  json::reject_unknown_members(body, json::JsonPath(), {"curve", "distance", "tolerance", "trim"});
  const curve::Curve c = read_curve_member(body, "curve");
  const double distance =
      json::get_number(json::require_member(body, json::JsonPath(), "distance"), json::root_path("distance"));
  diffgeom::OffsetOptions options;
  options.tolerance = number_member(body, "tolerance", options.tolerance);
  if (const Json* trim = json::optional_member(body, "trim")) {
    if (!trim->is_boolean())
      throw Error(Errc::InvalidArgument, "trim must be true or false", ErrorWhere{.field = "trim"});
    options.trim = trim->get<bool>();
  }
  return json_response(200, io::offset_answer(c, distance, options));
}

Response helical_offset(const Request& request) {
  const Json body = request.json();
  json::reject_unknown_members(body, json::JsonPath(), {"curve", "distance", "twist", "frame", "tolerance"});
  const curve::Curve c = read_curve_member(body, "curve");
  (void)json::require_member(body, json::JsonPath(), "distance");
  diffgeom::HelicalOffsetOptions options;
  if (const Json* f = json::optional_member(body, "frame")) {
    const std::string name = json::get_string(*f, json::root_path("frame"));
    const auto frame = diffgeom::offset_frame_from_name(name);
    if (!frame)
      throw Error(Errc::InvalidOption, "frame must be frenet or bishop, got '" + name + "'", {.field = "frame"});
    options.frame = *frame;
  }
  options.tolerance = number_member(body, "tolerance", options.tolerance);
  return json_response(
      200, io::helical_offset_answer(c, law_member(body, "distance", ""), law_member(body, "twist", "0"), options));
}

Vec3 point_member(const Json& body, const char* field) {
  return json::get_point(json::require_member(body, json::JsonPath(), field), json::root_path(field)).first;
}

diffgeom::MappingOptions mapping_options(const Json& body) {
  diffgeom::MappingOptions o;
  o.tolerance = number_member(body, "tolerance", o.tolerance);
  return o;
}

Response orthotomic(const Request& request) {
  const Json body = request.json();
  json::reject_unknown_members(body, json::JsonPath(), {"curve", "pole", "k", "tolerance"});
  const curve::Curve c = read_curve_member(body, "curve");
  return json_response(
      200, io::orthotomic_answer(c, point_member(body, "pole"), number_member(body, "k", 2.0), mapping_options(body)));
}

Response polar(const Request& request) {
  const Json body = request.json();
  json::reject_unknown_members(body, json::JsonPath(), {"curve", "centre", "radius", "tolerance"});
  const curve::Curve c = read_curve_member(body, "curve");
  return json_response(200, io::polar_answer(c, point_member(body, "centre"), number_member(body, "radius", 1.0),
                                             mapping_options(body)));
}

}  // namespace

void add_constructions(Router& router, const Context&) {
  router.add("POST", "/api/offset", offset);
  router.add("POST", "/api/helical-offset", helical_offset);
  router.add("POST", "/api/orthotomic", orthotomic);
  router.add("POST", "/api/polar", polar);
}

}  // namespace hula::server::routes
