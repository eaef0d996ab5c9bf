// SPDX-License-Identifier: MIT
// The HTTP-library-neutral request and response of the server's routes
// (server/routes/*.cpp): a route sees the method, the decoded path
// parameters, the query and the body, and returns a status with a JSON body,
// a file or an event stream. Boost.Beast stays in server.cpp, so routes only
// translate JSON to calls of the modules below. Errors are
// {"error": {"code", "message", "where"}} (io/error_json.hpp) with the status
// of http_status(Errc), or an HttpError for the protocol's own refusals
// (401, 403, 404, 405, 413, 429, ...).
#pragma once

#include <cstddef>
#include <map>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/io/json_curve.hpp"

namespace hula::server {

using Json = io::Json;

class EventLog;

/// A request as a route sees it.
struct Request {
  /// "GET", "POST", ...
  std::string method{};
  /// The path without the query, as sent (percent-encoded).
  std::string path{};
  /// Decoded query parameters.
  std::map<std::string, std::string> query{};
  /// Decoded path parameters captured by the route pattern, in order ({name}, {label}, {id}).
  std::vector<std::string> params{};
  /// The raw body.
  std::string body{};
  /// Deepest nesting of arrays and objects accepted in a JSON body.
  std::size_t json_depth_limit = 64;

  /// The body parsed as JSON.
  /// @throws hula::Error(Errc::ParseError) for an empty body, invalid JSON (line, column) or
  ///   nesting deeper than json_depth_limit
  [[nodiscard]] Json json() const;
};

/// What a route answers.
struct Response {
  unsigned status = 200;
  std::string content_type = "application/json";
  std::string body{};
  /// Extra headers (Set-Cookie, Location, Cache-Control).
  std::vector<std::pair<std::string, std::string>> headers{};
  /// When set, the response is a text/event-stream of this log (body ignored).
  std::shared_ptr<EventLog> events{};
  /// The first event of `events` to send (0: the whole log, as for a job; a document's stream
  /// starts at the subscription).
  std::size_t events_from = 0;
};

/// A refusal by the protocol layer (not by a module): status, stable code, message.
class HttpError : public std::runtime_error {
 public:
  HttpError(unsigned status, std::string code, const std::string& message, Json where = Json::object());
  [[nodiscard]] unsigned status() const noexcept { return status_; }
  [[nodiscard]] const std::string& code() const noexcept { return code_; }
  [[nodiscard]] const Json& where() const noexcept { return where_; }

 private:
  unsigned status_;
  std::string code_;
  Json where_;
};

/// A JSON response.
[[nodiscard]] Response json_response(unsigned status, const Json& body);

/// The HTTP status for an error code: 400 for malformed or out-of-range input
/// (ParseError, InvalidArgument, InvalidOption, NonFiniteInput), 422 for input
/// that is well formed but geometrically or numerically impossible (knots,
/// degree, weights, points, domain, scale, NumericalFailure), 500 for IoError
/// (the server's own files).
[[nodiscard]] unsigned http_status(Errc code) noexcept;

/// {"error": {...}} with http_status(error.code()).
[[nodiscard]] Response error_response(const Error& error);
/// {"error": {...}} of a protocol refusal.
[[nodiscard]] Response error_response(const HttpError& error);
/// The refusal of a request that ran out of memory (std::bad_alloc, or the exchange helper's
/// oli::ExchangeOutOfMemory whose what() is quoted): 503 "OutOfMemory", as in docs/server.md's error
/// table; a document change it was making is rolled back.
[[nodiscard]] HttpError out_of_memory_error(const std::bad_alloc& e);

/// Decodes %XX escapes (and nothing else: '+' stays '+').
/// @throws HttpError(400, "BadRequest") for a malformed escape or a decoded NUL
[[nodiscard]] std::string percent_decode(std::string_view text);

/// Splits "a=1&b=2" into decoded pairs (a later repeat wins).
[[nodiscard]] std::map<std::string, std::string> parse_query(std::string_view query);

/// Deepest nesting of arrays and objects in JSON text (strings skipped), stopping once past `limit`.
[[nodiscard]] std::size_t json_nesting_depth(std::string_view text, std::size_t limit) noexcept;

}  // namespace hula::server
