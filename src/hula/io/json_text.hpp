// SPDX-License-Identifier: MIT
// A streaming JSON text writer for large values (an analysis of a million
// samples, the columns of a viewport's analysis): numbers go straight into one
// buffer instead of a node each in a JSON tree. Compact (the HTTP body) or in
// the layout of format_json (the CLI's: 2-space indentation, arrays of
// scalars on one line). Numbers are written as format_json writes them
// (append_json_number: the shortest text that reads back to the same double,
// -0.0 as 0.0, non-finite numbers as null). A writer given a drain hands its
// buffer over every kDrainBytes, so a file of any size is written in bounded
// memory. JsonTree has the same interface and builds a JSON value instead, so
// one template (the curve files' writer) serves both.
#pragma once

#include <cmath>
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/io/json_read.hpp"

namespace hula::io {

/// Writes JSON text into a string. The caller nests begin/end calls correctly; member() comes before
/// each member value of an object.
class JsonText {
 public:
  /// @param out the buffer appended to
  /// @param pretty format_json's layout when true, else compact
  JsonText(std::string& out, bool pretty) : out_(out), pretty_(pretty) {}
  /// A writer that calls `drain(out)` between array elements once `out` holds kDrainBytes or more;
  /// the drain consumes the text and clears `out`.
  JsonText(std::string& out, bool pretty, std::function<void(std::string&)> drain)
      : out_(out), pretty_(pretty), drain_(std::move(drain)) {}

  /// How much text a draining writer buffers.
  static constexpr std::size_t kDrainBytes = std::size_t{1} << 20;

  JsonText& begin_object();
  JsonText& end_object();
  /// The key of the next member (escaped as JSON).
  JsonText& member(std::string_view name);
  /// An array of n scalars (one line), element(i) writing the i-th.
  template <class F>
  JsonText& scalars(std::size_t n, F&& element) {
    return array(n, false, static_cast<F&&>(element));
  }
  /// An array of n containers (one per line when pretty), element(i) writing the i-th.
  template <class F>
  JsonText& containers(std::size_t n, F&& element) {
    return array(n, true, static_cast<F&&>(element));
  }
  JsonText& number(double v);
  /// An array of numbers (one line): scalars(values.size(), number(values[i])) laid out in pieces of
  /// a few kilobytes rather than one append per character group.
  JsonText& numbers(std::span<const double> values);
  /// The number, or null when `defined` is false.
  JsonText& number_or_null(double v, bool defined) { return defined ? number(v) : null(); }
  JsonText& integer(long long v);
  JsonText& boolean(bool v) { return raw(v ? "true" : "false"); }
  JsonText& null() { return raw("null"); }
  JsonText& string(std::string_view text);
  /// [x, y, z], or null when `defined` is false or a coordinate is not finite.
  JsonText& vec(const Vec3& v, bool defined = true);
  /// A JSON value as format_json (or compactly) writes it.
  JsonText& value(const json::Json& v);
  /// JSON text already encoded (by this writer or format_json_line), written as it is.
  JsonText& encoded(std::string_view json_text) { return raw(json_text); }

 private:
  template <class F>
  JsonText& array(std::size_t n, bool containers, F&& element) {
    raw("[");
    const bool lines = pretty_ && containers && n > 0;
    if (lines) depth_ += 2;
    for (std::size_t i = 0; i < n; ++i) {
      if (lines)
        new_line(i > 0);
      else if (i > 0)
        raw(pretty_ ? ", " : ",");
      element(i);
      if (drain_ && out_.size() >= kDrainBytes) drain_(out_);
    }
    if (lines) {
      depth_ -= 2;
      new_line(false);
    }
    return raw("]");
  }
  JsonText& raw(std::string_view text) {
    out_ += text;
    return *this;
  }
  /// A line break and the indentation of depth_, after a comma when `comma` (one append).
  void new_line(bool comma);

  std::string& out_;
  bool pretty_;
  std::function<void(std::string&)> drain_;
  std::size_t depth_ = 0;
  bool first_member_ = true;
};

/// Builds a JSON value through JsonText's interface (same calls, same values: a non-finite number
/// is null), for code written once against both.
class JsonTree {
 public:
  /// @param root the value built (replaced by the first value written)
  explicit JsonTree(json::Json& root) : stack_{&root} {}

  JsonTree& begin_object() {
    stack_.push_back(&place(json::Json::object()));
    return *this;
  }
  JsonTree& end_object() {
    stack_.pop_back();
    return *this;
  }
  JsonTree& member(std::string_view name) {
    key_ = name;
    return *this;
  }
  template <class F>
  JsonTree& scalars(std::size_t n, F&& element) {
    return array(n, element);
  }
  template <class F>
  JsonTree& containers(std::size_t n, F&& element) {
    return array(n, element);
  }
  JsonTree& numbers(std::span<const double> values) {
    const auto element = [&](std::size_t i) { number(values[i]); };
    return array(values.size(), element);
  }
  JsonTree& number(double v) {
    place(std::isfinite(v) ? json::Json(v) : json::Json(nullptr));
    return *this;
  }
  JsonTree& integer(long long v) {
    place(json::Json(v));
    return *this;
  }
  JsonTree& boolean(bool v) {
    place(json::Json(v));
    return *this;
  }
  JsonTree& null() {
    place(json::Json(nullptr));
    return *this;
  }
  JsonTree& string(std::string_view text) {
    place(json::Json(std::string(text)));
    return *this;
  }
  JsonTree& value(const json::Json& v) {
    place(v);
    return *this;
  }

 private:
  template <class F>
  JsonTree& array(std::size_t n, F& element) {
    json::Json& a = place(json::Json::array());
    a.get_ref<json::Json::array_t&>().reserve(n);
    stack_.push_back(&a);
    for (std::size_t i = 0; i < n; ++i) element(i);
    stack_.pop_back();
    return *this;
  }
  // Puts v at the current place: the root first, then the pending member of an object or the end of
  // an array. The containers on the stack are not moved while they are open (an array's room is
  // reserved; an object's members are added after its open children close).
  json::Json& place(json::Json v) {
    json::Json& top = *stack_.back();
    if (!root_written_) {
      root_written_ = true;
      top = std::move(v);
      return top;
    }
    if (top.is_array()) {
      top.push_back(std::move(v));
      return top.back();
    }
    json::Json& slot = top[key_];
    slot = std::move(v);
    return slot;
  }

  std::vector<json::Json*> stack_;
  std::string key_;
  bool root_written_ = false;
};

/// The members of `object` followed by the member `name` whose value is the JSON text `json_text`,
/// compactly: a reply that carries an analysis written by curve_analysis_json next to a JSON value.
[[nodiscard]] std::string object_with_encoded_member(const json::Json& object, std::string_view name,
                                                     std::string_view json_text);

}  // namespace hula::io
