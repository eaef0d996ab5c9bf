// SPDX-License-Identifier: MIT
// error_to_json: hula::Error -> {"error": {"code", "message", "where"}}.
#include "hula/io/error_json.hpp"

#include <string>

namespace hula::io {

nlohmann::ordered_json error_to_json(const Error& error) {
  const ErrorWhere& w = error.where();
  nlohmann::ordered_json where = nlohmann::ordered_json::object();
  if (!w.field.empty()) where["field"] = w.field;
  if (w.index) where["index"] = *w.index;
  if (w.component) where["component"] = *w.component;
  if (w.line) where["line"] = *w.line;
  if (w.column) where["column"] = *w.column;
  nlohmann::ordered_json body;
  body["code"] = std::string(errc_name(error.code()));
  body["message"] = error.message();
  body["where"] = std::move(where);
  nlohmann::ordered_json out;
  out["error"] = std::move(body);
  return out;
}

}  // namespace hula::io
