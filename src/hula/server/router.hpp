// SPDX-License-Identifier: MIT
// The route table: patterns like "/api/jobs/{id}" with a handler per method.
// A path that matches a pattern under another method gives 405, no pattern
// 404. The matched pattern (not the path, which may carry names) is what the
// request log records. Each route says where its handler runs (Runs).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "hula/server/http.hpp"

namespace hula::server {

using Handler = std::function<Response(const Request&)>;

/// Where a route's handler runs. Inline: on the HTTP I/O thread that read the request, for the short
/// routes (a health check, an analysis, a drag's PATCH: a millisecond of CPU, no thread hop). Worker: on
/// the server's request workers, for a route that can take seconds (it waits for a helper process or
/// its work grows with the files it is sent), so that it never holds an I/O thread other connections need.
enum class Runs { Inline, Worker };

class Router {
 public:
  /// Adds a route; `pattern` segments in braces capture one decoded path segment each.
  void add(std::string method, std::string pattern, Handler handler, Runs runs = Runs::Inline);

  /// The route of a request.
  struct Match {
    const Handler* handler;
    Runs runs;
  };

  /// The route a request goes to, with request.params filled (the handler is not called).
  /// @param pattern set to the matched pattern (or "" when none matched)
  /// @throws HttpError(404, "NotFound") when no pattern matches, (405, "MethodNotAllowed") when
  ///   only other methods do
  [[nodiscard]] Match match(Request& request, std::string& pattern) const;

 private:
  struct Route {
    std::string method;
    std::string pattern;
    std::vector<std::string> segments;
    Handler handler;
    Runs runs;
  };
  std::vector<Route> routes_;
};

}  // namespace hula::server
