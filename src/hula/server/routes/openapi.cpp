// SPDX-License-Identifier: MIT
// GET /api/openapi.json: the OpenAPI 3.1 description of this API (openapi.json,
// embedded by CMake into openapi_text.cpp).
#include "hula/server/routes/routes.hpp"

namespace hula::server::routes {

void add_openapi(Router& router, const Context&) {
  router.add("GET", "/api/openapi.json", [](const Request&) {
    Response r;
    r.body = openapi_text();
    return r;
  });
}

}  // namespace hula::server::routes
