// SPDX-License-Identifier: MIT
// A streaming JSON text writer for large values (an analysis of a million
// samples, the columns of a viewport's analysis): numbers go straight into one
// buffer instead of a node each in a JSON tree. Compact (the HTTP body) or in
// the layout of format_json (the CLI's: 2-space indentation, arrays of
// scalars on one line). Numbers are the shortest text that reads back to the
// same double (std::to_chars), with ".0" on integral values as format_json
// writes them; -0.0 is written 0.0; non-finite numbers are null.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

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
      if (i > 0) raw(pretty_ && !lines ? ", " : ",");
      if (lines) newline();
      element(i);
    }
    if (lines) {
      depth_ -= 2;
      newline();
    }
    return raw("]");
  }
  JsonText& raw(std::string_view text) {
    out_ += text;
    return *this;
  }
  void newline();

  std::string& out_;
  bool pretty_;
  std::size_t depth_ = 0;
  bool first_member_ = true;
};

/// The members of `object` followed by the member `name` whose value is the JSON text `json_text`,
/// compactly: a reply that carries an analysis written by curve_analysis_json next to a JSON value.
[[nodiscard]] std::string object_with_encoded_member(const json::Json& object, std::string_view name,
                                                     std::string_view json_text);

}  // namespace hula::io
