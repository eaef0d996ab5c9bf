// SPDX-License-Identifier: MIT
// The kernel's curve edits and interpolations over HTTP, each the answer of the
// io entry its command prints: POST /api/rebuild {"curve", "degree"?,
// "control_points", "samples"?} and POST /api/reduce-degree {"curve",
// "tolerance"} → io::edit_curve (`hula edit rebuild|reduce-degree`); POST
// /api/interpolate-closed {"points", "parameterisation"?, "parameters"?} →
// io::closed_interpolation_answer (`hula interpolate --closed`); POST
// /api/hermite-frenet, a Frenet handle file as the body →
// io::hermite_frenet_answer (`hula hermite-frenet`). The made curve is in the
// answer as a curve file ("curve"; the commands write it to -o instead).
#include "hula/io/curve_edits.hpp"

#include <string>

#include "hula/io/json_read.hpp"
#include "hula/server/routes/routes.hpp"

namespace hula::server::routes {

namespace {

namespace json = io::json;

// {"operation", the edit's report members..., "curve": the edited curve file}.
Response edit_response(const curve::Curve& c, const io::CurveEditRequest& request, const char* operation) {
  io::CurveEditAnswer answer = io::edit_curve(c, "curve", request);
  Json doc = Json::object();
  doc["operation"] = operation;
  doc.update(answer.report);
  doc["curve"] = io::curve_to_json(curve::Curve(std::move(answer.curves.front())));
  return json_response(200, doc);
}

std::size_t count_member(const Json& body, const char* field, std::size_t fallback) {
  const Json* v = json::optional_member(body, field);
  return v == nullptr ? fallback : static_cast<std::size_t>(json::get_integer(*v, json::root_path(field), 0, 1 << 24));
}

Response rebuild(const Request& request) {
  const Json body = request.json();
  json::reject_unknown_members(body, json::JsonPath(), {"curve", "degree", "control_points", "samples"});
  const curve::Curve c = read_curve_member(body, "curve");
  (void)json::require_member(body, json::JsonPath(), "control_points");
  io::CurveEditRequest q{.edit = io::CurveEdit::Rebuild};
  if (const Json* d = json::optional_member(body, "degree"))
    q.degree = static_cast<int>(json::get_integer(*d, json::root_path("degree"), 1, 64));
  q.control_points = count_member(body, "control_points", 0);
  q.samples = count_member(body, "samples", 0);
  return edit_response(c, q, "rebuild");
}

Response reduce_degree(const Request& request) {
  const Json body = request.json();
  json::reject_unknown_members(body, json::JsonPath(), {"curve", "tolerance"});
  const curve::Curve c = read_curve_member(body, "curve");
  const double tolerance =
      json::get_number(json::require_member(body, json::JsonPath(), "tolerance"), json::root_path("tolerance"));
  return edit_response(c, {.edit = io::CurveEdit::ReduceDegree, .tolerance = tolerance}, "reduce-degree");
}

// {the summary..., "curve": the made curve file}.
Response made_response(io::MadeCurveAnswer answer) {
  Json doc = std::move(answer.report);
  doc["curve"] = io::curve_to_json(curve::Curve(std::move(answer.curve)));
  return json_response(200, doc);
}

Response interpolate_closed(const Request& request) {
  const Json body = request.json();
  json::reject_unknown_members(body, json::JsonPath(), {"points", "parameterisation", "parameters"});
  json::PointArray points =
      json::get_points(json::require_member(body, json::JsonPath(), "points"), json::root_path("points"));
  std::vector<double> parameters;
  if (const Json* p = json::optional_member(body, "parameters"))
    parameters = json::get_number_array(*p, json::root_path("parameters"));
  std::string rule = "chord";
  if (const Json* p = json::optional_member(body, "parameterisation"))
    rule = json::get_string(*p, json::root_path("parameterisation"));
  return made_response(io::closed_interpolation_answer(
      {.points = std::move(points.points), .dimension = points.dimension}, parameters, rule));
}

Response hermite_frenet(const Request& request) { return made_response(io::hermite_frenet_answer(request.json())); }

}  // namespace

void add_curve_edits(Router& router, const Context&) {
  router.add("POST", "/api/rebuild", rebuild);
  router.add("POST", "/api/reduce-degree", reduce_degree);
  router.add("POST", "/api/interpolate-closed", interpolate_closed);
  router.add("POST", "/api/hermite-frenet", hermite_frenet);
}

}  // namespace hula::server::routes
