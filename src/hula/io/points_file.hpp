// SPDX-License-Identifier: MIT
// Point files: the data points given to `hula interpolate --points`. Two
// formats, told apart by the first non-blank character ('[' means JSON):
//
//   JSON: an array of [x, y, z] or [x, y] arrays, e.g. [[0, 0], [40, 25], [80, -25]]
//   CSV:  one point per line, 2 or 3 comma-separated numbers (decimal or
//         exponent notation, optional leading '+'; nan/inf refused); spaces and tabs
//         around a number are ignored; blank lines and lines whose first
//         non-blank character is '#' are skipped; CRLF line ends are accepted.
//
// Points with two coordinates give a 2-D point set (z = 0, dimension 2); all
// points of a file must have the same number of coordinates.
#pragma once

#include <filesystem>
#include <string_view>
#include <vector>

#include "hula/core/vec.hpp"

namespace hula::io {

/// Points read from a file, with their dimension.
struct PointSet {
  /// The points in model units (z = 0 when dimension is 2).
  std::vector<Vec3> points;
  /// 2 when every point had two coordinates, else 3 (also 3 for an empty set).
  int dimension = 3;
};

/// Parses a JSON point array.
/// @throws hula::Error(Errc::ParseError) naming `points[i]` / `points[i][c]` and the
///   value (ErrorWhere.field "points", index, component), for invalid JSON (line, column),
///   a non-array, a point that is not 2 or 3 numbers, or mixed 2/3 components
/// @throws hula::Error(Errc::NonFiniteInput) if a number literal overflows a double
[[nodiscard]] PointSet parse_points_json(std::string_view text);

/// Parses CSV points.
/// @throws hula::Error(Errc::ParseError) naming the line and column (1-based,
///   ErrorWhere.line / column; index = the point's 0-based index) of a field that is not a
///   number, a line with other than 2 or 3 fields, or a line whose field count differs
///   from the first point's
/// @throws hula::Error(Errc::NonFiniteInput) for nan, inf or a value that overflows a double
[[nodiscard]] PointSet parse_points_csv(std::string_view text);

/// Parses either format (JSON when the first non-blank character is '[').
[[nodiscard]] PointSet parse_points(std::string_view text);

/// Reads a point file in either format.
/// @throws hula::Error(Errc::IoError) naming the path, or as parse_points
[[nodiscard]] PointSet read_points_file(const std::filesystem::path& path);

}  // namespace hula::io
