// SPDX-License-Identifier: MIT
// The table writer of --format jsonl | csv | text (see table_text.hpp).
#include "hula/io/table_text.hpp"

#include <stdexcept>

#include "hula/io/json_write.hpp"

namespace hula::io {

namespace {

using json::Json;

// One-line JSON text of a value, without the newline.
std::string inline_json(const Json& value) {
  std::string text = format_json_line(value);
  text.pop_back();
  return text;
}

// A CSV cell: numbers as in JSON, null empty, strings quoted when they hold a comma, quote or line break.
std::string csv_cell(const Json& value) {
  if (value.is_null()) return {};
  if (value.is_string()) {
    const std::string& s = value.get_ref<const std::string&>();
    if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
    std::string quoted = "\"";
    for (const char c : s) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
  }
  return inline_json(value);
}

// The scalars of `value` in order (arrays flattened depth-first).
void flatten(const Json& value, std::vector<std::string>& cells) {
  if (value.is_array()) {
    for (const Json& v : value) flatten(v, cells);
    return;
  }
  cells.push_back(csv_cell(value));
}

std::string csv_row(const Table& table, const Json& row) {
  std::string line;
  bool first = true;
  for (const TableColumn& column : table.columns) {
    std::vector<std::string> cells;
    const Json& value = row.contains(column.key) ? row[column.key] : Json(nullptr);
    flatten(value, cells);
    const std::size_t width = column.names.empty() ? 1 : column.names.size();
    if (cells.size() > width)
      throw std::logic_error("table column " + column.key + " has " + std::to_string(cells.size()) + " values for " +
                             std::to_string(width) + " names");
    cells.resize(width);  // a null vector or a shorter point: empty cells
    for (const std::string& cell : cells) {
      if (!first) line += ',';
      line += cell;
      first = false;
    }
  }
  return line + '\n';
}

std::string text_row(const Table& table, const Json& row) {
  std::string line;
  bool first_cell = true;
  for (std::size_t c = 0; c < table.columns.size(); ++c) {
    const TableColumn& column = table.columns[c];
    const Json& value = row.contains(column.key) ? row[column.key] : Json(nullptr);
    if (c == 0) {
      line += column.key + " = " + inline_json(value) + ":";
      continue;
    }
    if (!column.labelled && value.is_array()) {
      for (const Json& element : value) line += " " + inline_json(element);
    } else {
      line += (first_cell ? " " : ", ") + column.key + " = " + inline_json(value);
    }
    first_cell = false;
  }
  return line + '\n';
}

// Number arrays of `value` (a member of a record) and their component count, else 0.
std::size_t number_array_size(const Json& value) {
  if (!value.is_array() || value.empty()) return 0;
  for (const Json& v : value)
    if (!v.is_number()) return 0;
  return value.size();
}

// The component count of the first non-null array of `column` in `doc` (3 when none is found).
std::size_t vector_size(const Json& column) {
  for (const Json& v : column)
    if (v.is_array()) return v.size();
  return 3;
}

}  // namespace

std::optional<TableFormat> table_format_from_name(std::string_view name) noexcept {
  if (name == "jsonl") return TableFormat::JsonLines;
  if (name == "csv") return TableFormat::Csv;
  if (name == "text") return TableFormat::Text;
  return std::nullopt;
}

std::string format_table(const Table& table, TableFormat format) {
  std::string out;
  if (format == TableFormat::Csv) {
    out += "#";
    for (const TableColumn& column : table.columns) {
      if (column.names.empty()) out += " " + column.key;
      for (const std::string& name : column.names) out += " " + name;
    }
    out += '\n';
  }
  for (const Json& row : table.rows) {
    switch (format) {
      case TableFormat::JsonLines:
        out += format_json_line(row);
        break;
      case TableFormat::Csv:
        out += csv_row(table, row);
        break;
      case TableFormat::Text:
        out += text_row(table, row);
        break;
    }
  }
  return out;
}

std::vector<std::string> axis_names(std::string_view prefix, std::size_t count) {
  static constexpr const char* kAxes[] = {"x", "y", "z"};
  std::vector<std::string> names;
  for (std::size_t i = 0; i < count; ++i)
    names.push_back(std::string(prefix) + (count <= 3 ? std::string(kAxes[i]) : std::to_string(i)));
  return names;
}

Table derivative_table(const Json& results, std::size_t dimension, std::size_t derivatives) {
  Table table;
  table.columns.push_back({.key = "t"});
  TableColumn values{.key = "derivatives", .labelled = false};
  for (std::size_t k = 0; k <= derivatives; ++k) {
    const std::string prefix = k == 0 ? std::string() : "d" + (k == 1 ? std::string() : std::to_string(k));
    for (std::string& name : axis_names(prefix, dimension)) values.names.push_back(std::move(name));
  }
  table.columns.push_back(std::move(values));
  table.rows = results;
  return table;
}

Table analysis_table(const Json& analysis) {
  // (record key, where its column is in the document, CSV prefix of a vector column or "" for a scalar)
  struct Source {
    const char* key;
    const Json* column;
    bool vector;
  };
  std::vector<Source> sources;
  const auto add = [&](const char* key, const Json* column, bool vector) {
    if (column != nullptr && column->is_array()) sources.push_back({key, column, vector});
  };
  const auto member = [](const Json& object, const char* name) -> const Json* {
    return object.is_object() && object.contains(name) ? &object[name] : nullptr;
  };
  add("t", member(analysis, "t"), false);
  add("s", member(analysis, "s"), false);
  add("point", member(analysis, "points"), true);
  if (const Json* frames = member(analysis, "frames"))
    for (const char* axis : {"T", "N", "B"}) add(axis, member(*frames, axis), true);
  for (const char* scalar : {"curvature", "torsion", "curvature_derivative", "speed"})
    add(scalar, member(analysis, scalar), false);
  if (const Json* bishop = member(analysis, "bishop"))
    for (const char* axis : {"U", "V"}) add(axis, member(*bishop, axis), true);

  Table table;
  std::size_t rows = 0;
  for (const Source& s : sources) {
    rows = std::max(rows, s.column->size());
    TableColumn column{.key = s.key};
    if (s.vector)
      column.names =
          axis_names(std::string_view(s.key) == "point" ? "" : std::string(s.key) + "_", vector_size(*s.column));
    table.columns.push_back(std::move(column));
  }
  for (std::size_t i = 0; i < rows; ++i) {
    Json row = Json::object();
    for (const Source& s : sources) row[s.key] = i < s.column->size() ? (*s.column)[i] : Json(nullptr);
    table.rows.push_back(std::move(row));
  }
  return table;
}

Table closest_table(const Json& results) {
  Table table;
  table.columns = {{.key = "point", .names = axis_names("p", 3)},
                   {.key = "t"},
                   {.key = "closest", .names = axis_names("", 3)},
                   {.key = "distance"}};
  table.rows = results;
  return table;
}

Table front_table(const Json& front) {
  Table table;
  std::size_t objectives = 0;
  std::size_t variables = 0;
  for (const Json& member : front) {
    objectives = std::max(objectives, member.value("objectives", Json::array()).size());
    variables = std::max(variables, member.value("variables", Json::array()).size());
  }
  TableColumn f{.key = "objectives"};
  TableColumn x{.key = "variables"};
  for (std::size_t i = 0; i < objectives; ++i) f.names.push_back("f" + std::to_string(i));
  for (std::size_t i = 0; i < variables; ++i) x.names.push_back("x" + std::to_string(i));
  table.columns = {std::move(f), std::move(x)};
  table.rows = front;
  return table;
}

Table records_table(const Json& records) {
  Table table;
  if (records.empty()) return table;
  for (const auto& [key, value] : records.front().items()) {
    if (value.is_object() || (value.is_array() && number_array_size(value) == 0)) continue;
    TableColumn column{.key = key};
    if (value.is_array()) column.names = axis_names(key + "_", value.size());
    table.columns.push_back(std::move(column));
  }
  for (const Json& record : records) {
    Json row = Json::object();
    for (const TableColumn& column : table.columns)
      row[column.key] = record.contains(column.key) ? record[column.key] : Json(nullptr);
    table.rows.push_back(std::move(row));
  }
  return table;
}

Table record_table(const Json& record) { return records_table(Json::array({record})); }

}  // namespace hula::io
