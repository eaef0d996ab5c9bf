// SPDX-License-Identifier: MIT
// POST /api/law {"expression", "parameter"?, "at"?, "derivatives"?} →
// {"expression" (as printed by the law printer), "parameter", "dimension",
// "results": [{"t", "derivatives": [[value], [first], ...]}]} — `hula law
// EXPR --at ... --derivatives N` over HTTP (io/law_values.hpp).
#include "hula/io/json_read.hpp"
#include "hula/io/law_values.hpp"
#include "hula/law/parser.hpp"
#include "hula/server/routes/routes.hpp"

namespace hula::server::routes {

namespace {

Response evaluate_law(const Request& request) {
  namespace json = io::json;
  const Json body = request.json();
  const json::JsonPath root;
  json::reject_unknown_members(body, root, {"expression", "parameter", "at", "derivatives"});
  const std::string expression =
      json::get_string(json::require_member(body, root, "expression"), json::root_path("expression"));
  std::string parameter = "t";
  if (const Json* p = json::optional_member(body, "parameter"))
    parameter = json::get_string(*p, json::root_path("parameter"));
  int order = 0;
  if (const Json* d = json::optional_member(body, "derivatives"))
    order = static_cast<int>(json::get_integer(*d, json::root_path("derivatives"), 0, 16));
  std::vector<double> ts;
  if (const Json* at = json::optional_member(body, "at")) ts = json::get_number_array(*at, json::root_path("at"));
  law::Context ctx;
  law::ParseOptions po;
  po.parameters = {parameter};
  const law::Law l = law::parse(expression, ctx, po);
  Json out = Json::object();
  out["expression"] = law::print(l);
  out["parameter"] = parameter;
  out["dimension"] = l.dimension();
  out["results"] = io::law_results_to_json(ts, io::law_derivatives(l, parameter, ts, order), l.dimension(), order);
  return json_response(200, out);
}

}  // namespace

void add_law(Router& router, const Context&) { router.add("POST", "/api/law", evaluate_law); }

}  // namespace hula::server::routes
