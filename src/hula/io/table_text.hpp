// SPDX-License-Identifier: MIT
// The one table writer of the command line's --format jsonl | csv | text: the
// records a command prints (samples of an analysis, results of eval and law
// --at, closest points, a Pareto front, a one-line summary) as JSON lines, CSV
// rows or text lines. The JSON document (--format json, the default) stays
// each command's own answer; a table is built from that document, so every
// format carries the same numbers.
//
// - jsonl: one record per line (format_json_line).
// - csv: a comment header "# name name ..." (names separated by spaces, so it
//   survives `cut -d, -f2-`), then one row per record; arrays are flattened
//   into one cell per number, null is an empty cell, numbers are written as in
//   JSON (shortest round trip, no -0.0), strings are quoted when they need it.
// - text: "first = value:" then the other cells, "name = value" separated by
//   commas, arrays on one line; an unlabelled column prints its elements alone
//   ("t = 0.5: [1.0, 2.0] [0.0, 1.0]", the form of `hula eval`).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hula/io/json_read.hpp"

namespace hula::io {

/// The table forms of --format (json is the command's own document).
enum class TableFormat { JsonLines, Csv, Text };

/// jsonl | csv | text, or nullopt for any other name (json included).
[[nodiscard]] std::optional<TableFormat> table_format_from_name(std::string_view name) noexcept;

/// One column: the record member `key`.
struct TableColumn {
  /// The member of each record.
  std::string key{};
  /// CSV header names, one per number the value flattens to; empty: the key (a scalar column).
  std::vector<std::string> names{};
  /// Text form: "key = value" (true) or the array's elements alone (false).
  bool labelled = true;
};

/// Records (JSON objects) and the columns they are printed with, in order.
struct Table {
  std::vector<TableColumn> columns{};
  json::Json rows = json::Json::array();
};

/// The text of `table` in `format`, one line per record (plus the CSV header), final newline.
/// @throws std::logic_error (a bug of the caller) if a record flattens to more CSV cells than its column names
[[nodiscard]] std::string format_table(const Table& table, TableFormat format);

/// `prefix` + x, y, z for the first `count` axes (more than 3: prefix + 0, 1, ...): "dx dy dz".
[[nodiscard]] std::vector<std::string> axis_names(std::string_view prefix, std::size_t count);

/// The results of `hula eval` and `hula law --at` ([{"t", "derivatives": [[C], [C'], ...]}]) as a table:
/// CSV columns t, x, y, z, dx, dy, dz, d2x, ...
[[nodiscard]] Table derivative_table(const json::Json& results, std::size_t dimension, std::size_t derivatives);

/// The per-sample columns of an analysis document (curve_analysis_json) as one record per sample:
/// t, s, point, T, N, B, curvature, torsion, curvature_derivative, speed, U, V (the members present);
/// fins, features and planarity stay in the JSON document.
[[nodiscard]] Table analysis_table(const json::Json& analysis);

/// The "results" of `hula closest` ([{"point", "t", "closest", "distance"}]): CSV columns
/// px, py, pz (empty z for a 2-D point), t, x, y, z, distance.
[[nodiscard]] Table closest_table(const json::Json& results);

/// A non-dominated front ([{"variables", "objectives"}]): CSV columns f0, f1, ..., x0, x1, ...
[[nodiscard]] Table front_table(const json::Json& front);

/// Records as a table of the scalar and number-array members of the first one (an array of n numbers
/// becomes key_x, key_y, key_z, or key_0, key_1, ...); objects and other arrays are left out.
[[nodiscard]] Table records_table(const json::Json& records);

/// One record as a one-row table of its scalar and number-array members (an array of n numbers
/// becomes key_x, key_y, key_z, or key_0, key_1, ...); objects and other arrays are left out.
[[nodiscard]] Table record_table(const json::Json& record);

}  // namespace hula::io
