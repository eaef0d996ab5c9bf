// SPDX-License-Identifier: MIT
// The route table: patterns like "/api/jobs/{id}" with a handler per method.
// A path that matches a pattern under another method gives 405, no pattern
// 404. The matched pattern (not the path, which may carry names) is what the
// request log records.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "hula/server/http.hpp"

namespace hula::server {

using Handler = std::function<Response(const Request&)>;

class Router {
 public:
  /// Adds a route; `pattern` segments in braces capture one decoded path segment each.
  void add(std::string method, std::string pattern, Handler handler);

  /// The handler's response for a request, with request.params filled.
  /// @param pattern set to the matched pattern (or "" when none matched)
  /// @throws HttpError(404, "NotFound") when no pattern matches, (405, "MethodNotAllowed") when
  ///   only other methods do; whatever the handler throws
  [[nodiscard]] Response dispatch(Request& request, std::string& pattern) const;

 private:
  struct Route {
    std::string method;
    std::string pattern;
    std::vector<std::string> segments;
    Handler handler;
  };
  std::vector<Route> routes_;
};

}  // namespace hula::server
