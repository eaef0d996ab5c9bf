// SPDX-License-Identifier: MIT
// GET /api/health → {"status": "ok", "version": V}; the one route without a token.
#include "hula/server/routes/routes.hpp"

namespace hula::server::routes {

void add_health(Router& router, const Context& context) {
  router.add("GET", "/api/health", [version = context.version](const Request&) {
    Json body = Json::object();
    body["status"] = "ok";
    body["version"] = version;
    return json_response(200, body);
  });
}

}  // namespace hula::server::routes
