// SPDX-License-Identifier: MIT
// The streaming JSON text writer (json_text.hpp).
#include "hula/io/json_text.hpp"

#include <charconv>
#include <cmath>

#include "hula/io/json_write.hpp"

namespace hula::io {

void JsonText::newline() {
  out_ += '\n';
  out_.append(depth_, ' ');
}

JsonText& JsonText::begin_object() {
  raw("{");
  depth_ += 2;
  first_member_ = true;
  return *this;
}

JsonText& JsonText::end_object() {
  depth_ -= 2;
  // An empty object closes on its line; a member was written otherwise.
  if (pretty_ && !first_member_) newline();
  first_member_ = false;
  return raw("}");
}

JsonText& JsonText::member(std::string_view name) {
  if (!first_member_) raw(",");
  first_member_ = true;
  if (pretty_) newline();
  string(name);
  raw(pretty_ ? ": " : ":");
  // The member's value may open an object (which resets the flag); after it, the next member needs a comma.
  first_member_ = false;
  return *this;
}

JsonText& JsonText::number(double v) {
  append_json_number(out_, v);
  return *this;
}

JsonText& JsonText::integer(long long v) {
  char buffer[24];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, v);
  out_.append(buffer, end);
  return *this;
}

JsonText& JsonText::string(std::string_view text) {
  out_ += json::Json(std::string(text)).dump(-1, ' ', false, json::Json::error_handler_t::replace);
  return *this;
}

JsonText& JsonText::vec(const Vec3& v, bool defined) {
  if (!defined || !std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return null();
  raw("[").number(v.x).raw(pretty_ ? ", " : ",").number(v.y).raw(pretty_ ? ", " : ",").number(v.z);
  return raw("]");
}

JsonText& JsonText::value(const json::Json& v) {
  std::string text = pretty_ ? format_json(v) : format_json_line(v);
  text.pop_back();  // the final newline
  if (pretty_ && depth_ > 0) {
    // Indent the value's inner lines to the writer's depth.
    std::string indented;
    for (const char c : text) {
      indented += c;
      if (c == '\n') indented.append(depth_, ' ');
    }
    text = std::move(indented);
  }
  return raw(text);
}

std::string object_with_encoded_member(const json::Json& object, std::string_view name, std::string_view json_text) {
  std::string out;
  JsonText w(out, false);
  w.begin_object();
  for (const auto& [key, v] : object.items()) w.member(key).value(v);
  w.member(name).encoded(json_text);
  w.end_object();
  return out;
}

}  // namespace hula::io
