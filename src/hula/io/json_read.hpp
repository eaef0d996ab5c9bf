// SPDX-License-Identifier: MIT
// Checked accessors for reading JSON documents (used by io and by the study
// readers): every failure throws
// hula::Error naming the JSON path (e.g. `control_points[3][1]`) and the value
// found, with ErrorWhere.field = the top-level member and index / component =
// the first / second array index on the path.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/core/vec.hpp"

namespace hula::io::json {

using Json = nlohmann::ordered_json;

/// A position in a JSON document: its printable path and its ErrorWhere.
struct JsonPath {
  std::string text;
  ErrorWhere where;

  /// Path of a member of the document root (or of a nested object, appended with '.').
  [[nodiscard]] JsonPath member(std::string_view name) const;
  /// Path of an array element: fills where.index, then where.component.
  [[nodiscard]] JsonPath element(std::size_t i) const;
};

/// The root path named `field` (e.g. "control_points"), or "" for the document itself.
[[nodiscard]] JsonPath root_path(std::string_view field);

/// Deepest nesting of arrays and objects a document may have. Our formats
/// need at most 6; the cap keeps recursion in nlohmann and in callers bounded.
inline constexpr std::size_t kMaxJsonDepth = 64;

/// A short printable rendering of a JSON value for messages: a number, true,
/// false or null as written, a string's first 16 characters, and an array or
/// object by its size only (never stringified, whatever its depth or size).
[[nodiscard]] std::string describe(const Json& value);

/// A string for a message: quoted, cut to its first 16 characters (the length
/// is given when longer), so a value typed into a file is never echoed whole.
[[nodiscard]] std::string quote(std::string_view text);

/// Refuses text whose arrays and objects nest deeper than `max_depth` (one
/// pass over the bytes, strings skipped), before any parser recurses into it.
/// @throws hula::Error(Errc::ParseError) naming the limit, the line and the column
void check_json_shape(std::string_view text, std::string_view what, std::size_t max_depth = kMaxJsonDepth);

/// Parses JSON text; syntax errors become Errc::ParseError with line and column, a
/// number literal that overflows a double (1e999) Errc::NonFiniteInput. Nesting
/// deeper than kMaxJsonDepth is refused first (check_json_shape). Messages never
/// quote the input's text.
/// @param what the kind of document for the message ("curve file")
[[nodiscard]] Json parse_json_text(std::string_view text, std::string_view what);

/// Throws ParseError "<path> = <value> must be <expected>".
[[noreturn]] void type_error(const Json& value, const JsonPath& path, std::string_view expected);

/// A finite number (integer or floating point) at `path`.
[[nodiscard]] double get_number(const Json& value, const JsonPath& path);
/// An integer at `path` in [lo, hi] (integral floating-point values are accepted).
[[nodiscard]] long long get_integer(const Json& value, const JsonPath& path, long long lo, long long hi);
/// A string at `path`.
[[nodiscard]] std::string get_string(const Json& value, const JsonPath& path);
/// An array at `path`.
[[nodiscard]] const Json& get_array(const Json& value, const JsonPath& path);
/// An array of finite numbers at `path`.
[[nodiscard]] std::vector<double> get_number_array(const Json& value, const JsonPath& path);
/// A non-empty array of finite numbers at `path` (where a value is required,
/// `[]` is refused by name rather than read as "absent").
/// @throws hula::Error(Errc::ParseError) "<path> is empty: <needed>"
[[nodiscard]] std::vector<double> get_nonempty_number_array(const Json& value, const JsonPath& path,
                                                            std::string_view needed);
/// Member `name` of object `object` (at `parent`), or throws ParseError "missing member".
[[nodiscard]] const Json& require_member(const Json& object, const JsonPath& parent, std::string_view name);
/// Member `name` or nullptr when absent or null.
[[nodiscard]] const Json* optional_member(const Json& object, std::string_view name);
/// Refuses an object that is not an object or has a member outside `allowed`
/// (a misspelt setting must not be silently ignored).
/// @throws hula::Error(Errc::ParseError) "<path>.<name>: unknown member (expected one of a, b, ...)"
void reject_unknown_members(const Json& object, const JsonPath& path, std::span<const std::string_view> allowed);
inline void reject_unknown_members(const Json& object, const JsonPath& path,
                                   std::initializer_list<std::string_view> allowed) {
  reject_unknown_members(object, path, std::span<const std::string_view>(allowed.begin(), allowed.size()));
}

/// Points as arrays of 2 or 3 numbers, all with the same count.
struct PointArray {
  std::vector<Vec3> points;
  int dimension = 3;
};
/// Reads an array of [x, y] or [x, y, z] arrays at `path`; an empty array is
/// accepted (the caller checks counts). Mixed component counts name the index.
[[nodiscard]] PointArray get_points(const Json& value, const JsonPath& path);
/// One [x, y] or [x, y, z] array; z = 0 for two components.
/// @returns the point and its component count
[[nodiscard]] std::pair<Vec3, int> get_point(const Json& value, const JsonPath& path);

}  // namespace hula::io::json
