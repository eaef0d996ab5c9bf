// SPDX-License-Identifier: MIT
// Point files: the data points every command reads (`hula interpolate`,
// `approximate`, `fit`, `doc add`, a "fit" study's `points`, the server's import,
// Python). Two forms, told apart by the first non-blank character ('[' means JSON):
//
//   JSON: an array of [x, y, z] or [x, y] arrays, e.g. [[0, 0], [40, 25], [80, -25]]
//   text: one point per line, 2 or 3 numbers (decimal or exponent notation, optional
//         leading '+'; nan/inf refused) separated by whitespace (spaces, tabs), by commas
//         or by semicolons. The separator is the first data line's: a ';' on it means
//         semicolons (a field may then write its decimal point as a comma, 1,5;2,25),
//         else a ',' means commas, else whitespace; every line must use it. Blanks around
//         a field are ignored; blank lines and text after a '#' are skipped; CRLF line ends
//         are accepted. Lines before the first point whose first field is not a number are a
//         header (column names "x,y,z", an airfoil's name line, a few lines of provenance)
//         and are skipped; after the first point every line must be a point.
//
// Airfoil coordinate files are read as every airfoil tool ships them: the Selig form (a
// name line, then x y from the trailing edge over one surface and back over the other) is
// a header and points; the Lednicer form (a name line, then a line "NU. NL." with the
// point counts of the upper and lower surfaces, then the upper surface from the leading
// edge to the trailing edge, then the lower one, blank lines between) is recognised by its
// count line (two whole numbers ≥ 2, after a header, that add up to the number of points
// that follow) and returned in Selig order: the upper surface reversed, then the lower one,
// the leading-edge point once when both surfaces start with the same point.
//
// Points with two coordinates give a 2-D point set (z = 0, dimension 2); all points of a
// file must have the same number of coordinates.
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

/// Parses text points (whitespace, comma or semicolon separated; see the file comment).
/// @throws hula::Error(Errc::ParseError) naming the line and column (1-based,
///   ErrorWhere.line / column; index = the point's 0-based index) and the separator in use
///   for a field that is not a number, a line with other than 2 or 3 fields, a line whose
///   field count differs from the first point's, or a file with no point
/// @throws hula::Error(Errc::NonFiniteInput) for nan, inf or a value that overflows a double
[[nodiscard]] PointSet parse_points_csv(std::string_view text);

/// parse_points_csv without its fast path (data lines after the first point read by std::from_chars
/// straight into the points): every line split into fields and read one by one. Same result, same
/// errors; the reference the fast path is tested against.
[[nodiscard]] PointSet parse_points_csv_general(std::string_view text);

/// Parses either form (JSON when the first non-blank character is '[').
[[nodiscard]] PointSet parse_points(std::string_view text);

/// Reads a point file in either form; any extension (.csv, .txt, .dat, .xyz, .json, …), of at most
/// kMaxGeometryInputBytes.
/// @throws hula::Error(Errc::IoError) naming the path, or as parse_points with the path
///   before the message ("wing.dat: line 4, column 3: …")
[[nodiscard]] PointSet read_points_file(const std::filesystem::path& path);

}  // namespace hula::io
