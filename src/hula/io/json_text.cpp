// SPDX-License-Identifier: MIT
// The streaming JSON text writer (json_text.hpp).
#include "hula/io/json_text.hpp"

#include <charconv>
#include <cmath>
#include <cstring>

#include "hula/io/json_write.hpp"
#include "hula/io/shortest_double.hpp"

namespace hula::io {

void JsonText::new_line(bool comma) {
  static constexpr std::string_view kBreak = ",\n                                                                ";
  const std::size_t from = comma ? 0 : 1;
  if (depth_ + 2 <= kBreak.size()) {
    out_.append(kBreak.data() + from, depth_ + 2 - from);
    return;
  }
  out_.append(kBreak.data() + from, 2 - from);
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
  if (pretty_ && !first_member_) new_line(false);
  first_member_ = false;
  return raw("}");
}

JsonText& JsonText::member(std::string_view name) {
  if (pretty_)
    new_line(!first_member_);
  else if (!first_member_)
    raw(",");
  first_member_ = true;
  string(name);
  raw(pretty_ ? ": " : ":");
  // The member's value may open an object (which resets the flag); after it, the next member needs a comma.
  first_member_ = false;
  return *this;
}

JsonText& JsonText::number(double v) {
  char text[kJsonNumberRoom];
  out_.append(text, write_json_number(text, v));
  return *this;
}

JsonText& JsonText::numbers(std::span<const double> values) {
  // Each number and its separator go into a local buffer, appended when it is nearly full; the
  // drain sees the text between pieces, as it would have between elements.
  char piece[4096];
  char* o = piece;
  *o++ = '[';
  const std::size_t separator = pretty_ ? 2 : 1;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (i > 0) {
      std::memcpy(o, ", ", 2);
      o += separator;
    }
    o = write_json_number(o, values[i]);
    if (o + 2 + kJsonNumberRoom > piece + sizeof piece) {
      out_.append(piece, o);
      o = piece;
      if (drain_ && out_.size() >= kDrainBytes) drain_(out_);
    }
  }
  *o++ = ']';
  out_.append(piece, o);
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
  const double xyz[3] = {v.x, v.y, v.z};
  return numbers(xyz);
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
