// SPDX-License-Identifier: MIT
// POST /api/law {"expression", "parameter"?, "at"?, "derivatives"?} →
// {"expression" (as printed by the law printer), "parameter", "dimension",
// "results": [{"t", "derivatives": [[value], [first], ...]}]} — `hula law
// EXPR --at ... --derivatives N` over HTTP (io::law_request_json).
#include "hula/io/law_values.hpp"
#include "hula/server/routes/routes.hpp"

namespace hula::server::routes {

namespace {

Response evaluate_law(const Request& request) { return json_response(200, io::law_request_json(request.json())); }

}  // namespace

void add_law(Router& router, const Context&) { router.add("POST", "/api/law", evaluate_law); }

}  // namespace hula::server::routes
