// SPDX-License-Identifier: MIT
// JSON and text point-file readers (forms in points_file.hpp).
#include "hula/io/points_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "hula/core/error.hpp"
#include "hula/core/huge_pages.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/json_read.hpp"

namespace hula::io {
namespace {

bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// A field is described by its length, never quoted: the file may be any file a study names
// (/etc/passwd), and its content must not reach a message.
std::string field_text(std::string_view s) { return "the " + std::to_string(s.size()) + "-character field"; }

enum class Separator { Whitespace, Comma, Semicolon };

std::string separator_text(Separator s) {
  switch (s) {
    case Separator::Whitespace:
      return "whitespace";
    case Separator::Comma:
      return "commas";
    case Separator::Semicolon:
      return "semicolons";
  }
  return "whitespace";
}

// One field of a line: its text (blanks trimmed) and the 1-based column where it begins.
struct Field {
  std::string_view text;
  std::size_t column = 0;
};

// The fields of a line (comments already cut off) for a separator.
std::vector<Field> split_fields(std::string_view line, Separator sep) {
  std::vector<Field> out;
  if (sep == Separator::Whitespace) {
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && is_blank(line[i])) ++i;
      if (i == line.size()) break;
      const std::size_t b = i;
      while (i < line.size() && !is_blank(line[i])) ++i;
      out.push_back({line.substr(b, i - b), b + 1});
    }
    return out;
  }
  const char delimiter = sep == Separator::Comma ? ',' : ';';
  std::size_t start = 0;
  for (;;) {
    std::size_t end = line.find(delimiter, start);
    const bool last = end == std::string_view::npos;
    if (last) end = line.size();
    std::size_t b = start, e = end;
    while (b < e && is_blank(line[b])) ++b;
    while (e > b && is_blank(line[e - 1])) --e;
    out.push_back({line.substr(b, e - b), b + 1});
    if (last) break;
    start = end + 1;
  }
  return out;
}

// The number a field holds, if it is one (nan and inf included: they are refused later with
// their own message); `decimal_comma` reads a ',' as the decimal point.
struct Number {
  double value = 0.0;
  bool out_of_range = false;
};
std::optional<Number> read_number(std::string_view field, bool decimal_comma) {
  std::string buffer;
  if (decimal_comma && field.find(',') != std::string_view::npos) {
    buffer.assign(field);
    for (char& c : buffer)
      if (c == ',') c = '.';
    field = buffer;
  }
  // from_chars takes no leading '+'; accept it as spreadsheets write it.
  const std::string_view digits = field.size() > 1 && field[0] == '+' ? field.substr(1) : field;
  if (digits.empty()) return std::nullopt;
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
  if (ec == std::errc::result_out_of_range && ptr == digits.data() + digits.size()) return Number{0.0, true};
  if (ec != std::errc() || ptr != digits.data() + digits.size()) return std::nullopt;
  return Number{v, false};
}

// The separator of a data line: ';' if it holds one, else ',' if it holds one, else whitespace.
Separator separator_of(std::string_view line) {
  if (line.find(';') != std::string_view::npos) return Separator::Semicolon;
  if (line.find(',') != std::string_view::npos) return Separator::Comma;
  return Separator::Whitespace;
}

// The points read so far: one Vec3 each (z = 0 for 2-D rows), all rows of the same width.
struct Rows {
  std::vector<Vec3> points;
  std::size_t width = 0;  // 2 or 3 once the first point is read
};

// The Lednicer form (see points_file.hpp): a header, then a count line of two whole numbers
// NU, NL ≥ 2 with NU + NL the number of rows after it.
bool is_lednicer(const Rows& rows, std::size_t header_lines) {
  if (header_lines == 0 || rows.points.size() < 5 || rows.width != 2) return false;
  const double nu = rows.points[0].x, nl = rows.points[0].y;
  if (!(nu >= 2.0 && nl >= 2.0) || nu != std::floor(nu) || nl != std::floor(nl)) return false;
  return nu + nl == static_cast<double>(rows.points.size() - 1);
}

// The fast path for a data line after the first point: `width` finite numbers in from_chars'
// grammar, separated by `sep` (blanks around them), read straight into `p`. False for anything
// else (a '+', a decimal comma, a bad or non-finite field, another count): the general path then
// reads the line again and gives its value or its error. A number never spans a separator or a
// blank, so every line this accepts splits into the same fields with the same values.
bool scan_row(std::string_view line, Separator sep, std::size_t width, Vec3& p) {
  const char* c = line.data();
  const char* const end = c + line.size();
  double v[3] = {0.0, 0.0, 0.0};
  std::size_t n = 0;
  for (;;) {
    while (c != end && is_blank(*c)) ++c;
    if (sep == Separator::Whitespace && c == end) break;
    if (n == width) return false;
    const auto [ptr, ec] = std::from_chars(c, end, v[n]);
    if (ec != std::errc() || !std::isfinite(v[n])) return false;
    ++n;
    c = ptr;
    if (sep == Separator::Whitespace) {
      if (c != end && !is_blank(*c)) return false;
      continue;
    }
    while (c != end && is_blank(*c)) ++c;
    if (c == end) break;
    if (*c != (sep == Separator::Comma ? ',' : ';')) return false;
    ++c;
  }
  if (n != width) return false;
  p = Vec3{v[0], v[1], v[2]};
  return true;
}

// A number in from_chars' grammar that is plain: [-]digits[.digits] with at most 19 digits and 22
// decimals, whose value m / 10^d (m < 2^53 and 10^d exact in a double) is one correctly rounded division,
// so the same double from_chars gives (Clinger's fast path). Null for anything else, which from_chars
// then reads (an exponent, inf or nan, more digits, ".5", "5.").
const char* read_plain_number(const char* c, const char* end, double& v) {
  static constexpr double kExact[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                      1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
  const bool negative = c != end && *c == '-';
  const char* p = c + (negative ? 1 : 0);
  const auto is_digit = [](char d) { return static_cast<unsigned>(d - '0') < 10u; };
  std::uint64_t m = 0;
  const char* const first = p;
  while (p != end && is_digit(*p)) m = 10 * m + static_cast<unsigned>(*p++ - '0');
  if (p == first) return nullptr;
  const auto whole = p - first;
  std::ptrdiff_t decimals = 0;
  if (p != end && *p == '.') {
    const char* const point = ++p;
    while (p != end && is_digit(*p)) m = 10 * m + static_cast<unsigned>(*p++ - '0');
    decimals = p - point;
    if (decimals == 0) return nullptr;
  }
  if (p != end && (*p == 'e' || *p == 'E')) return nullptr;
  if (whole + decimals > 19 || decimals > 22 || m > (std::uint64_t{1} << 53)) return nullptr;
  const double x = static_cast<double>(m) / kExact[decimals];
  v = negative ? -x : x;
  return p;
}

// scan_row over the text itself: the data line starting at `pos` (ending at '\n' or the end of the
// text) read straight into `p`, without finding its end first. The position after the line, or npos
// when scan_row would not take it (a comment, a blank line and everything else go through the caller's
// general path, which finds the line's end and reads it again).
std::size_t scan_line(std::string_view text, std::size_t pos, Separator sep, std::size_t width, Vec3& p) {
  const char* c = text.data() + pos;
  const char* const end = text.data() + text.size();
  const auto at_eol = [&] { return c == end || *c == '\n'; };
  const char delimiter = sep == Separator::Comma ? ',' : ';';
  double v[3] = {0.0, 0.0, 0.0};
  std::size_t n = 0;
  for (;;) {
    while (c != end && is_blank(*c)) ++c;
    if (sep == Separator::Whitespace && at_eol()) break;
    if (n == width) return std::string_view::npos;
    if (const char* ptr = read_plain_number(c, end, v[n])) {
      c = ptr;
    } else {
      const auto [ptr2, ec] = std::from_chars(c, end, v[n]);
      if (ec != std::errc() || !std::isfinite(v[n])) return std::string_view::npos;
      c = ptr2;
    }
    ++n;
    if (sep == Separator::Whitespace) {
      if (!at_eol() && !is_blank(*c)) return std::string_view::npos;
      continue;
    }
    while (c != end && is_blank(*c)) ++c;
    if (at_eol()) break;
    if (*c != delimiter) return std::string_view::npos;
    ++c;
  }
  if (n != width) return std::string_view::npos;
  p = Vec3{v[0], v[1], v[2]};
  return static_cast<std::size_t>(c - text.data()) + 1;
}

// The text form; `fast` lets scan_row read the plain data lines.
PointSet parse_csv(std::string_view text, bool fast) {
  Rows rows;
  rows.points.reserve(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1);
  advise_huge_pages(rows.points.data(), rows.points.capacity() * sizeof(Vec3));
  std::optional<Separator> sep;
  std::size_t separator_line = 0;  // the line that set the separator
  std::size_t header_lines = 0;
  std::size_t line_no = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    if (fast && sep) {
      Vec3 p;
      if (const std::size_t next = scan_line(text, pos, *sep, rows.width, p); next != std::string_view::npos) {
        rows.points.push_back(p);
        ++line_no;
        pos = next;
        continue;
      }
    }
    std::size_t eol = text.find('\n', pos);
    if (eol == std::string_view::npos) eol = text.size();
    std::string_view line = text.substr(pos, eol - pos);
    ++line_no;
    pos = eol + 1;
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos) line = line.substr(0, hash);
    std::size_t first = 0;
    while (first < line.size() && is_blank(line[first])) ++first;
    if (first == line.size()) continue;
    if (fast && sep) {
      Vec3 p;
      if (scan_row(line, *sep, rows.width, p)) {
        rows.points.push_back(p);
        continue;
      }
    }

    const Separator line_sep = sep.value_or(separator_of(line));
    const std::vector<Field> fields = split_fields(line, line_sep);
    const bool decimal_comma = line_sep == Separator::Semicolon;
    // Before the first point, a line whose first field is not a number is a header line.
    if (rows.points.empty() && !read_number(fields.front().text, decimal_comma)) {
      ++header_lines;
      continue;
    }
    if (!sep) {
      sep = line_sep;
      separator_line = line_no;
    }
    const std::size_t index = rows.points.size();
    const auto how = [&] {
      return "fields separated by " + separator_text(*sep) +
             (line_no == separator_line ? std::string() : ", as on line " + std::to_string(separator_line));
    };
    double values[3] = {0.0, 0.0, 0.0};
    std::size_t count = 0;
    for (std::size_t c = 0; c < fields.size(); ++c) {
      const Field& f = fields[c];
      const ErrorWhere where{.field = "points", .index = index, .component = c, .line = line_no, .column = f.column};
      const std::string at = "line " + std::to_string(line_no) + ", column " + std::to_string(f.column);
      if (c == 3)
        throw Error(Errc::ParseError,
                    at + ": more than 3 numbers on a line (a point is x, y or x, y, z; " + how() + ")", where);
      if (f.text.empty())
        throw Error(Errc::ParseError, at + ": empty field where a number is expected (" + how() + ")", where);
      const std::optional<Number> n = read_number(f.text, decimal_comma);
      if (!n) throw Error(Errc::ParseError, at + ": " + field_text(f.text) + " is not a number (" + how() + ")", where);
      if (n->out_of_range)
        throw Error(Errc::NonFiniteInput, at + ": " + field_text(f.text) + " is outside the range of a double", where);
      if (!std::isfinite(n->value))
        throw Error(Errc::NonFiniteInput,
                    at + ": the field reads as " +
                        (std::isnan(n->value) ? "nan"
                         : n->value > 0       ? "inf"
                                              : "-inf") +
                        " where a finite number is expected",
                    where);
      values[count++] = n->value;
    }
    const ErrorWhere where{.field = "points", .index = index, .line = line_no, .column = first + 1};
    if (count < 2)
      throw Error(
          Errc::ParseError,
          "line " + std::to_string(line_no) + ": 1 number; a point needs 2 (x, y) or 3 (x, y, z) (" + how() + ")",
          where);
    if (!rows.points.empty() && count != rows.width)
      throw Error(Errc::ParseError,
                  "line " + std::to_string(line_no) + ": " + std::to_string(count) +
                      " numbers but the first point has " + std::to_string(rows.width) +
                      " (all points must be 2-D or all 3-D; " + how() + ")",
                  where);
    rows.width = count;
    rows.points.push_back(Vec3{values[0], values[1], values[2]});
  }
  if (rows.points.empty() && header_lines > 0)
    throw Error(Errc::ParseError,
                "no point: none of the " + std::to_string(header_lines) +
                    " non-blank lines starts with a number (a point is x, y or x, y, z)",
                ErrorWhere{.field = "points", .line = 1});

  PointSet out;
  out.dimension = rows.width == 2 ? 2 : 3;
  if (is_lednicer(rows, header_lines)) {
    const std::vector<Vec3>& r = rows.points;
    const auto upper = static_cast<std::size_t>(r[0].x);
    for (std::size_t i = upper; i >= 1; --i) out.points.push_back(r[i]);
    for (std::size_t i = upper + 1; i < r.size(); ++i) {
      if (i == upper + 1 && r[i] == out.points.back()) continue;  // the shared leading-edge point, once
      out.points.push_back(r[i]);
    }
  } else {
    out.points = std::move(rows.points);
  }
  return out;
}

}  // namespace

PointSet parse_points_json(std::string_view text) {
  const json::Json doc = json::parse_json_text(text, "point file");
  json::PointArray a = json::get_points(doc, json::root_path("points"));
  return PointSet{std::move(a.points), a.dimension};
}

PointSet parse_points_csv(std::string_view text) { return parse_csv(text, true); }

PointSet parse_points_csv_general(std::string_view text) { return parse_csv(text, false); }

PointSet parse_points(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size() && (is_blank(text[i]) || text[i] == '\n')) ++i;
  if (i < text.size() && text[i] == '[') return parse_points_json(text);
  return parse_points_csv(text);
}

PointSet read_points_file(const std::filesystem::path& path) {
  const std::string text = read_text_file(path, kMaxGeometryInputBytes);
  try {
    return parse_points(text);
  } catch (const Error& e) {
    throw Error(e.code(), path.string() + ": " + e.message(), e.where());
  }
}

}  // namespace hula::io
