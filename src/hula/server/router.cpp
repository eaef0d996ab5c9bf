// SPDX-License-Identifier: MIT
// Route matching by path segments (router.hpp).
#include "hula/server/router.hpp"

#include <string_view>

namespace hula::server {

namespace {

std::vector<std::string> split_path(std::string_view path) {
  std::vector<std::string> out;
  if (path.starts_with('/')) path.remove_prefix(1);
  while (true) {
    const std::size_t slash = path.find('/');
    out.emplace_back(path.substr(0, slash));
    if (slash == std::string_view::npos) break;
    path.remove_prefix(slash + 1);
  }
  return out;
}

bool is_capture(const std::string& segment) noexcept {
  return segment.size() > 2 && segment.front() == '{' && segment.back() == '}';
}

}  // namespace

void Router::add(std::string method, std::string pattern, Handler handler, Runs runs) {
  std::vector<std::string> segments = split_path(pattern);
  routes_.push_back({std::move(method), std::move(pattern), std::move(segments), std::move(handler), runs});
}

Router::Match Router::match(Request& request, std::string& pattern) const {
  const std::vector<std::string> segments = split_path(request.path);
  bool other_method = false;
  for (const Route& r : routes_) {
    if (r.segments.size() != segments.size()) continue;
    std::vector<std::string> params;
    bool match = true;
    for (std::size_t i = 0; i < segments.size() && match; ++i) {
      if (is_capture(r.segments[i]))
        params.push_back(percent_decode(segments[i]));
      else
        match = r.segments[i] == segments[i];
    }
    if (!match) continue;
    if (r.method != request.method) {
      other_method = true;
      continue;
    }
    pattern = r.pattern;
    request.params = std::move(params);
    return Match{&r.handler, r.runs};
  }
  pattern.clear();
  if (other_method) throw HttpError(405, "MethodNotAllowed", request.method + " is not allowed on " + request.path);
  throw HttpError(404, "NotFound", "no route for " + request.method + " " + request.path);
}

}  // namespace hula::server
