// SPDX-License-Identifier: MIT
// JSON and CSV point-file readers (format in points_file.hpp).
#include "hula/io/points_file.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/json_read.hpp"

namespace hula::io {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

// A field is described by its length, never quoted: the "CSV" may be any file
// a study names (/etc/passwd), and its content must not reach a message.
std::string field_text(std::string_view s) { return "the " + std::to_string(s.size()) + "-character field"; }

}  // namespace

PointSet parse_points_json(std::string_view text) {
  const json::Json doc = json::parse_json_text(text, "point file");
  json::PointArray a = json::get_points(doc, json::root_path("points"));
  return PointSet{std::move(a.points), a.dimension};
}

PointSet parse_points_csv(std::string_view text) {
  PointSet out;
  int expected = 0;  // component count of the first point
  std::size_t line_no = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) eol = text.size();
    const std::string_view line = text.substr(pos, eol - pos);
    ++line_no;
    pos = eol + 1;

    std::size_t first = 0;
    while (first < line.size() && is_blank(line[first])) ++first;
    if (first == line.size() || line[first] == '#') continue;

    const std::size_t index = out.points.size();
    Vec3 p;
    int count = 0;
    std::size_t field_start = 0;
    for (;;) {
      std::size_t field_end = line.find(',', field_start);
      const bool last = field_end == std::string_view::npos;
      if (last) field_end = line.size();
      // Trim blanks around the field; the column reported is where the field's text begins.
      std::size_t b = field_start, e = field_end;
      while (b < e && is_blank(line[b])) ++b;
      while (e > b && is_blank(line[e - 1])) --e;
      const std::string_view field = line.substr(b, e - b);
      const ErrorWhere where{.field = "points",
                             .index = index,
                             .component = static_cast<std::size_t>(count),
                             .line = line_no,
                             .column = b + 1};
      const std::string at = "line " + std::to_string(line_no) + ", column " + std::to_string(b + 1);
      if (count == 3)
        throw Error(Errc::ParseError, at + ": more than 3 numbers on a line (a point is x, y or x, y, z)", where);
      // from_chars takes no leading '+'; accept it as spreadsheets write it.
      const std::string_view digits = field.size() > 1 && field[0] == '+' ? field.substr(1) : field;
      double v = 0.0;
      const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
      if (field.empty()) throw Error(Errc::ParseError, at + ": empty field where a number is expected", where);
      if (ec == std::errc::result_out_of_range)
        throw Error(Errc::NonFiniteInput, at + ": " + field_text(field) + " is outside the range of a double", where);
      if (ec != std::errc() || ptr != digits.data() + digits.size())
        throw Error(Errc::ParseError, at + ": " + field_text(field) + " is not a number", where);
      if (!std::isfinite(v))
        throw Error(Errc::NonFiniteInput,
                    at + ": the field reads as " +
                        (std::isnan(v) ? "nan"
                         : v > 0       ? "inf"
                                       : "-inf") +
                        " where a finite number is expected",
                    where);
      p[static_cast<std::size_t>(count)] = v;
      ++count;
      if (last) break;
      field_start = field_end + 1;
    }
    const ErrorWhere where{.field = "points", .index = index, .line = line_no, .column = first + 1};
    if (count < 2)
      throw Error(Errc::ParseError,
                  "line " + std::to_string(line_no) + ": 1 number; a point needs 2 (x, y) or 3 (x, y, z)", where);
    if (expected == 0) {
      expected = count;
    } else if (count != expected) {
      throw Error(Errc::ParseError,
                  "line " + std::to_string(line_no) + ": " + std::to_string(count) +
                      " numbers but the first point has " + std::to_string(expected) +
                      " (all points must be 2-D or all 3-D)",
                  where);
    }
    out.points.push_back(p);
  }
  out.dimension = expected == 2 ? 2 : 3;
  return out;
}

PointSet parse_points(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size() && (is_blank(text[i]) || text[i] == '\n')) ++i;
  if (i < text.size() && text[i] == '[') return parse_points_json(text);
  return parse_points_csv(text);
}

PointSet read_points_file(const std::filesystem::path& path) { return parse_points(read_text_file(path)); }

}  // namespace hula::io
