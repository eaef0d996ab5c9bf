// SPDX-License-Identifier: MIT
// Requests and responses of the routes (http.hpp): JSON bodies with a depth
// cap, error bodies and the error-code-to-status table.
#include "hula/server/http.hpp"

#include <new>
#include <string_view>

#include "hula/io/error_json.hpp"
#include "hula/io/json_read.hpp"

namespace hula::server {

HttpError::HttpError(unsigned status, std::string code, const std::string& message, Json where)
    : std::runtime_error(message), status_(status), code_(std::move(code)), where_(std::move(where)) {}

std::size_t json_nesting_depth(std::string_view text, std::size_t limit) noexcept {
  std::size_t depth = 0;
  std::size_t deepest = 0;
  bool in_string = false;
  bool escaped = false;
  for (const char c : text) {
    if (in_string) {
      if (escaped)
        escaped = false;
      else if (c == '\\')
        escaped = true;
      else if (c == '"')
        in_string = false;
      continue;
    }
    if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      if (++depth > deepest) deepest = depth;
      if (deepest > limit) return deepest;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

Json Request::json() const {
  if (body.empty()) throw Error(Errc::ParseError, "request body: expected a JSON document, got an empty body");
  // Counted on the text first, so a hostile nesting never reaches a recursive parser.
  const std::size_t depth = json_nesting_depth(body, json_depth_limit);
  if (depth > json_depth_limit)
    throw Error(Errc::ParseError, "request body: JSON nested deeper than the limit of " +
                                      std::to_string(json_depth_limit) + " arrays and objects");
  return io::json::parse_json_text(body, "request body");
}

Response json_response(unsigned status, const Json& body) {
  Response r;
  r.status = status;
  r.body = body.dump(-1, ' ', false, Json::error_handler_t::replace);
  return r;
}

unsigned http_status(Errc code) noexcept {
  switch (code) {
    case Errc::ParseError:
    case Errc::InvalidArgument:
    case Errc::InvalidOption:
    case Errc::NonFiniteInput:
      return 400;
    case Errc::TooFewPoints:
    case Errc::CoincidentPoints:
    case Errc::InvalidKnots:
    case Errc::InvalidDegree:
    case Errc::InvalidWeight:
    case Errc::OutOfDomain:
    case Errc::NumericalFailure:
    case Errc::ScaleOutOfRange:
    case Errc::HelperFailure:  // the exchange helper failed on the file the request named
      return 422;
    case Errc::Unsupported:  // the document's kernel backend has no such operation
      return 501;
    case Errc::DocumentCorrupt:  // the named document cannot be read as a document
      return 422;
    case Errc::DocumentLocked:  // another writer holds it (a CLI `doc run`); retry later
      return 423;
    case Errc::StorageFull:
      return 507;
    case Errc::IoError:
      return 500;
  }
  return 500;
}

Response error_response(const Error& error) {
  return json_response(http_status(error.code()), io::error_to_json(error));
}

HttpError out_of_memory_error(const std::bad_alloc& e) {
  const std::string what = e.what();
  return HttpError(503, "OutOfMemory",
                   "out of memory: " +
                       (what != std::bad_alloc().what()
                            ? what
                            : std::string("the request needs more memory than the server can allocate")) +
                       "; it was not completed and no document was changed");
}

Response error_response(const HttpError& error) {
  Json body = Json::object();
  body["code"] = error.code();
  body["message"] = error.what();
  body["where"] = error.where();
  Json out = Json::object();
  out["error"] = std::move(body);
  return json_response(error.status(), out);
}

namespace {

int hex_value(char c) noexcept {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

}  // namespace

std::string percent_decode(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '%') {
      out.push_back(text[i]);
      continue;
    }
    const int hi = i + 2 < text.size() ? hex_value(text[i + 1]) : -1;
    const int lo = i + 2 < text.size() ? hex_value(text[i + 2]) : -1;
    if (hi < 0 || lo < 0)
      throw HttpError(400, "BadRequest", "malformed percent escape at offset " + std::to_string(i) + " of the URL");
    const char c = static_cast<char>(hi * 16 + lo);
    if (c == '\0') throw HttpError(400, "BadRequest", "the URL decodes to a NUL character");
    out.push_back(c);
    i += 2;
  }
  return out;
}

std::map<std::string, std::string> parse_query(std::string_view query) {
  std::map<std::string, std::string> out;
  while (!query.empty()) {
    const std::size_t amp = query.find('&');
    const std::string_view pair = query.substr(0, amp);
    const std::size_t eq = pair.find('=');
    if (!pair.empty()) {
      const std::string key = percent_decode(pair.substr(0, eq));
      out[key] = eq == std::string_view::npos ? std::string() : percent_decode(pair.substr(eq + 1));
    }
    if (amp == std::string_view::npos) break;
    query.remove_prefix(amp + 1);
  }
  return out;
}

}  // namespace hula::server
