// SPDX-License-Identifier: MIT
// format_json: a small recursive printer over nlohmann values (see json_write.hpp).
#include "hula/io/json_write.hpp"

#include <array>
#include <charconv>
#include <system_error>

#include "hula/io/shortest_double.hpp"

namespace hula::io {
namespace {

using json::Json;

template <class Int>
void put_integer(std::string& out, Int v) {
  std::array<char, 24> buffer{};
  const auto [end, ec] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), v);
  (void)ec;  // cannot fail: 24 characters hold every 64-bit integer
  out.append(buffer.data(), end);
}

bool is_scalar(const Json& v) { return !v.is_array() && !v.is_object(); }

void put_scalar(std::string& out, const Json& v) {
  switch (v.type()) {
    case Json::value_t::number_float:
      append_json_number(out, v.get_ref<const Json::number_float_t&>());
      return;
    case Json::value_t::number_integer:
      put_integer(out, v.get_ref<const Json::number_integer_t&>());
      return;
    case Json::value_t::number_unsigned:
      put_integer(out, v.get_ref<const Json::number_unsigned_t&>());
      return;
    default:
      out += v.dump(-1, ' ', false, Json::error_handler_t::replace);
  }
}

void put(std::string& out, const Json& v, std::size_t indent, bool compact) {
  if (is_scalar(v)) {
    put_scalar(out, v);
    return;
  }
  const bool array = v.is_array();
  if (v.empty()) {
    out += array ? "[]" : "{}";
    return;
  }
  bool inline_all = compact;
  if (array && !inline_all) {
    inline_all = true;
    for (const Json& e : v)
      if (!is_scalar(e)) {
        inline_all = false;
        break;
      }
  }
  out += array ? '[' : '{';
  bool first = true;
  for (auto it = v.begin(); it != v.end(); ++it) {
    if (!first) out += inline_all ? (compact ? "," : ", ") : ",";
    first = false;
    if (!inline_all) {
      out += '\n';
      out.append(indent + 2, ' ');
    }
    if (!array) {
      out += Json(it.key()).dump(-1, ' ', false, Json::error_handler_t::replace);
      out += compact ? ":" : ": ";
    }
    put(out, *it, indent + 2, compact);
  }
  if (!inline_all) {
    out += '\n';
    out.append(indent, ' ');
  }
  out += array ? ']' : '}';
}

}  // namespace

void append_json_number(std::string& out, double v) {
  char text[kJsonNumberRoom];
  out.append(text, write_json_number(text, v));
}

std::string format_json(const json::Json& value) {
  std::string out;
  put(out, value, 0, false);
  out += '\n';
  return out;
}

std::string format_json_line(const json::Json& value) {
  std::string out;
  put(out, value, 0, true);
  out += '\n';
  return out;
}

}  // namespace hula::io
