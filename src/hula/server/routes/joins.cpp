// SPDX-License-Identifier: MIT
// Two curves joined, over HTTP, each the answer of the io entry its command
// prints: POST /api/match {"a", "b", "continuity"?, "end"?, "to_end"? | "at"?,
// "tangent_scale"?} → io::match_answer (`hula match`: A with its end made Gk
// to B); POST /api/blend {"a", "b", "continuity"?, "end"?, "to_end"?} →
// io::blend_answer (`hula blend`: the fair Hermite curve between the ends).
// The made curve is in the answer as a curve file ("curve"; the commands write
// it to -o instead); the document is not touched (the page stores the curve
// with one PUT or POST, one undo step).
#include <string>

#include "hula/io/curve_queries.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/json_read.hpp"
#include "hula/server/routes/routes.hpp"

namespace hula::server::routes {

namespace {

namespace json = io::json;

std::string text_member(const Json& body, const char* field, const char* fallback) {
  const Json* v = json::optional_member(body, field);
  return v == nullptr ? std::string(fallback) : json::get_string(*v, json::root_path(field));
}

Json answer_json(io::CurveJoinAnswer answer) {
  Json doc = Json::object();
  doc["curve"] = io::curve_to_json(curve::Curve(std::move(answer.curve)));
  doc.update(answer.report);
  return doc;
}

Response match(const Request& request) {
  const Json body = request.json();
  json::reject_unknown_members(body, json::JsonPath(),
                               {"a", "b", "continuity", "end", "to_end", "at", "tangent_scale"});
  diffgeom::MatchOptions options;
  options.continuity = io::continuity_order_from_name(text_member(body, "continuity", "G2"), 0, "continuity");
  options.end = io::curve_end_from_name(text_member(body, "end", "end"), "end");
  options.target_end = io::curve_end_from_name(text_member(body, "to_end", "start"), "to_end");
  if (const Json* at = json::optional_member(body, "at")) {
    if (json::optional_member(body, "to_end") != nullptr)
      throw Error(Errc::InvalidArgument, "at and to_end exclude each other: match to B's end or to B at a parameter",
                  {.field = "at"});
    options.use_parameter = true;
    options.at = json::get_number(*at, json::root_path("at"));
  }
  if (const Json* s = json::optional_member(body, "tangent_scale"))
    options.tangent_scale = json::get_number(*s, json::root_path("tangent_scale"));
  const curve::Curve a = read_curve_member(body, "a");
  const curve::Curve b = read_curve_member(body, "b");
  return json_response(200, answer_json(io::match_answer(a, b, options)));
}

Response blend(const Request& request) {
  const Json body = request.json();
  json::reject_unknown_members(body, json::JsonPath(), {"a", "b", "continuity", "end", "to_end"});
  diffgeom::BlendOptions options;
  options.continuity = io::continuity_order_from_name(text_member(body, "continuity", "G2"), 1, "continuity");
  options.end = io::curve_end_from_name(text_member(body, "end", "end"), "end");
  options.target_end = io::curve_end_from_name(text_member(body, "to_end", "start"), "to_end");
  const curve::Curve a = read_curve_member(body, "a");
  const curve::Curve b = read_curve_member(body, "b");
  return json_response(200, answer_json(io::blend_answer(a, b, options)));
}

}  // namespace

void add_joins(Router& router, const Context&) {
  // The blend's scale search integrates ∫κ'² ds some thirty times: on the request workers, as match beside it.
  router.add("POST", "/api/match", match, Runs::Worker);
  router.add("POST", "/api/blend", blend, Runs::Worker);
}

}  // namespace hula::server::routes
