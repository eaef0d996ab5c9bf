// SPDX-License-Identifier: MIT
// Checked JSON accessors with path-naming errors (see json_read.hpp).
#include "hula/io/json_read.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <utility>
#include <vector>

namespace hula::io::json {

JsonPath JsonPath::member(std::string_view name) const {
  JsonPath out = *this;
  if (text.empty()) {
    out.text = std::string(name);
    out.where.field = std::string(name);
  } else {
    out.text += "." + std::string(name);
  }
  return out;
}

JsonPath JsonPath::element(std::size_t i) const {
  JsonPath out = *this;
  out.text += "[" + std::to_string(i) + "]";
  if (!out.where.index)
    out.where.index = i;
  else if (!out.where.component)
    out.where.component = i;
  return out;
}

JsonPath root_path(std::string_view field) {
  JsonPath p;
  p.text = std::string(field);
  p.where.field = std::string(field);
  return p;
}

std::string describe(const Json& value) {
  // Containers are described by size, never stringified: a deeply nested or
  // huge value must cost nothing to mention, and a file's content is not echoed.
  if (value.is_array()) return "an array of " + std::to_string(value.size()) + " elements";
  if (value.is_object()) return "an object of " + std::to_string(value.size()) + " members";
  if (value.is_string()) {
    const auto& s = value.get_ref<const std::string&>();
    constexpr std::size_t kMaxQuoted = 16;
    if (s.size() <= kMaxQuoted) return Json(s).dump(-1, ' ', false, Json::error_handler_t::replace);
    return Json(s.substr(0, kMaxQuoted)).dump(-1, ' ', false, Json::error_handler_t::replace) + " (" +
           std::to_string(s.size()) + " characters)";
  }
  return value.dump(-1, ' ', false, Json::error_handler_t::replace);  // a number, true, false or null
}

std::string quote(std::string_view text) { return describe(Json(std::string(text))); }

void check_json_shape(std::string_view text, std::string_view what, std::size_t max_depth) {
  // One pass over the bytes, strings skipped: the nesting depth is known
  // before nlohmann builds (and later destroys and prints) the value.
  std::size_t depth = 0, line = 1, column = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    ++column;
    if (c == '\n') {
      ++line;
      column = 0;
    }
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
      if (++depth > max_depth)
        throw Error(Errc::ParseError,
                    std::string(what) + " nests arrays and objects deeper than the limit of " +
                        std::to_string(max_depth) + " levels (at line " + std::to_string(line) + ", column " +
                        std::to_string(column) + ")",
                    {.line = line, .column = column});
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
}

namespace {

// Where a number literal of `text` overflows a double (1e999): its JSON path, line and column, found by
// one pass over the bytes that follows objects (member names) and arrays (indices). nlohmann refuses
// such a literal without saying where; this names it as every other bad value is named. Empty when no
// literal overflows (the caller then reports without a position).
struct Overflow {
  JsonPath path;
  std::string literal;
};

std::optional<Overflow> find_overflowing_number(std::string_view text) {
  struct Frame {
    bool object = false;
    bool expect_key = false;
    std::string key;
    std::size_t index = 0;
  };
  std::vector<Frame> frames;
  std::size_t line = 1, column = 0;
  const auto advance = [&](char c) {
    ++column;
    if (c == '\n') {
      ++line;
      column = 0;
    }
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    advance(c);
    if (c == '"') {
      std::string raw;
      for (++i; i < text.size() && text[i] != '"'; ++i) {
        advance(text[i]);
        if (text[i] == '\\' && i + 1 < text.size()) {
          raw.push_back(text[i]);
          advance(text[++i]);
        }
        raw.push_back(text[i]);
      }
      if (i < text.size()) advance(text[i]);
      if (!frames.empty() && frames.back().object && frames.back().expect_key) {
        frames.back().key = std::move(raw);
        frames.back().expect_key = false;
      }
    } else if (c == '{' || c == '[') {
      frames.push_back({.object = c == '{', .expect_key = c == '{', .key = {}, .index = 0});
    } else if (c == '}' || c == ']') {
      if (!frames.empty()) frames.pop_back();
    } else if (c == ',') {
      if (!frames.empty()) {
        if (frames.back().object)
          frames.back().expect_key = true;
        else
          ++frames.back().index;
      }
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      const std::size_t start = i, start_line = line, start_column = column;
      while (i + 1 < text.size() && std::string_view("0123456789+-.eE").find(text[i + 1]) != std::string_view::npos)
        advance(text[++i]);
      const std::string literal(text.substr(start, i - start + 1));
      if (std::isfinite(std::strtod(literal.c_str(), nullptr))) continue;
      JsonPath path;
      for (const Frame& f : frames) path = f.object ? path.member(f.key) : path.element(f.index);
      path.where.line = start_line;
      path.where.column = start_column;
      return Overflow{std::move(path), literal};
    }
  }
  return std::nullopt;
}

}  // namespace

Json parse_json_text(std::string_view text, std::string_view what) {
  check_json_shape(text, what, kMaxJsonDepth);
  try {
    return Json::parse(text.begin(), text.end());
  } catch (const Json::parse_error& e) {
    // Translate the byte offset (1-based, of the offending character) into line and column.
    const std::size_t offset = e.byte == 0 ? 0 : std::min<std::size_t>(e.byte - 1, text.size());
    std::size_t line = 1, column = 1;
    for (std::size_t i = 0; i < offset; ++i) {
      if (text[i] == '\n') {
        ++line;
        column = 1;
      } else {
        ++column;
      }
    }
    std::string reason = e.what();
    // nlohmann's message is "[json.exception.parse_error.101] parse error at line L, column C: <reason>; last
    // read: '<token>'". The token is the input's own text (a whole line of /etc/passwd, say): not echoed.
    if (const auto colon = reason.find(": "); colon != std::string::npos) reason = reason.substr(colon + 2);
    if (const auto last = reason.find("; last read"); last != std::string::npos) reason.resize(last);
    throw Error(Errc::ParseError,
                std::string(what) + " is not valid JSON at line " + std::to_string(line) + ", column " +
                    std::to_string(column) + ": " + reason,
                {.line = line, .column = column});
  } catch (const Json::out_of_range& e) {
    // nlohmann refuses literals that overflow a double (e.g. 1e999) before any path is known; its
    // message quotes the literal, which is a number: kept, cut to a few characters.
    std::string reason = e.what();
    if (const auto bracket = reason.find("] "); bracket != std::string::npos) reason = reason.substr(bracket + 2);
    constexpr std::size_t kMaxReason = 48;
    if (reason.size() > kMaxReason) reason = reason.substr(0, kMaxReason) + "...";
    if (std::optional<Overflow> at = find_overflowing_number(text)) {
      std::string literal = at->literal.size() > kMaxReason ? at->literal.substr(0, kMaxReason) + "..." : at->literal;
      const std::string name = at->path.text.empty() ? std::string("the document") : at->path.text;
      throw Error(Errc::NonFiniteInput,
                  std::string(what) + ": " + name + " = " + literal + " (line " + std::to_string(*at->path.where.line) +
                      ", column " + std::to_string(*at->path.where.column) + ") is outside the range of a double",
                  at->path.where);
    }
    throw Error(Errc::NonFiniteInput, std::string(what) + " holds a number that is not a finite double: " + reason);
  } catch (const Json::exception&) {
    throw Error(Errc::ParseError, std::string(what) + " cannot be read as JSON");
  }
}

void type_error(const Json& value, const JsonPath& path, std::string_view expected) {
  const std::string name = path.text.empty() ? std::string("document") : path.text;
  throw Error(Errc::ParseError, name + " = " + describe(value) + " must be " + std::string(expected), path.where);
}

double get_number(const Json& value, const JsonPath& path) {
  if (!value.is_number()) type_error(value, path, "a number");
  const double v = value.get<double>();
  // JSON has no NaN or infinity and the parser rejects overflowing literals; kept for documents built in code.
  if (!std::isfinite(v))
    throw Error(Errc::NonFiniteInput, path.text + " = " + describe(value) + " is not a finite double", path.where);
  return v;
}

long long get_integer(const Json& value, const JsonPath& path, long long lo, long long hi) {
  long long v = 0;
  if (value.is_number_unsigned()) {
    const auto u = value.get<unsigned long long>();
    if (u > static_cast<unsigned long long>(hi)) type_error(value, path, "an integer <= " + std::to_string(hi));
    v = static_cast<long long>(u);
  } else if (value.is_number_integer()) {
    v = value.get<long long>();
  } else if (value.is_number_float()) {
    const double d = value.get<double>();
    if (!(d == std::floor(d)) || !(std::fabs(d) < 9e15)) type_error(value, path, "an integer");
    v = static_cast<long long>(d);
  } else {
    type_error(value, path, "an integer");
  }
  if (v < lo || v > hi)
    type_error(value, path, "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return v;
}

std::string get_string(const Json& value, const JsonPath& path) {
  if (!value.is_string()) type_error(value, path, "a string");
  return value.get<std::string>();
}

const Json& get_array(const Json& value, const JsonPath& path) {
  if (!value.is_array()) type_error(value, path, "an array");
  return value;
}

std::vector<double> get_number_array(const Json& value, const JsonPath& path) {
  const Json& array = get_array(value, path);
  std::vector<double> out;
  out.reserve(array.size());
  for (std::size_t i = 0; i < array.size(); ++i) out.push_back(get_number(array[i], path.element(i)));
  return out;
}

std::vector<double> get_nonempty_number_array(const Json& value, const JsonPath& path, std::string_view needed) {
  std::vector<double> out = get_number_array(value, path);
  if (out.empty()) throw Error(Errc::ParseError, path.text + " is empty: " + std::string(needed), path.where);
  return out;
}

const Json& require_member(const Json& object, const JsonPath& parent, std::string_view name) {
  const auto it = object.find(std::string(name));
  if (it == object.end()) {
    const JsonPath p = parent.member(name);
    throw Error(
        Errc::ParseError,
        "missing member \"" + std::string(name) + "\"" + (parent.text.empty() ? std::string() : " in " + parent.text),
        p.where);
  }
  return *it;
}

const Json* optional_member(const Json& object, std::string_view name) {
  const auto it = object.find(std::string(name));
  if (it == object.end() || it->is_null()) return nullptr;
  return &*it;
}

void reject_unknown_members(const Json& object, const JsonPath& path, std::span<const std::string_view> allowed) {
  if (!object.is_object()) type_error(object, path, "an object");
  for (const auto& [key, value] : object.items()) {
    if (std::find(allowed.begin(), allowed.end(), std::string_view(key)) != allowed.end()) continue;
    std::string expected;
    for (std::string_view a : allowed) expected += (expected.empty() ? "" : ", ") + std::string(a);
    const JsonPath at = path.member(key);
    throw Error(Errc::ParseError, at.text + ": unknown member (expected one of " + expected + ")", at.where);
  }
}

std::pair<Vec3, int> get_point(const Json& value, const JsonPath& path) {
  if (!value.is_array() || (value.size() != 2 && value.size() != 3))
    type_error(value, path, "an array of 2 or 3 numbers ([x, y] or [x, y, z])");
  Vec3 p;
  for (std::size_t c = 0; c < value.size(); ++c) p[c] = get_number(value[c], path.element(c));
  return {p, static_cast<int>(value.size())};
}

PointArray get_points(const Json& value, const JsonPath& path) {
  const Json& array = get_array(value, path);
  PointArray out;
  out.points.reserve(array.size());
  for (std::size_t i = 0; i < array.size(); ++i) {
    const JsonPath pi = path.element(i);
    auto [p, count] = get_point(array[i], pi);
    if (i == 0) {
      out.dimension = count;
    } else if (count != out.dimension) {
      throw Error(Errc::ParseError,
                  pi.text + " has " + std::to_string(count) + " components but " + path.text + "[0] has " +
                      std::to_string(out.dimension) + " (all points must be 2-D or all 3-D)",
                  pi.where);
    }
    out.points.push_back(p);
  }
  return out;
}

}  // namespace hula::io::json
