// SPDX-License-Identifier: MIT
// The curve-file fast path (curve_text_scan.hpp): one pass over the bytes.
#include "hula/io/curve_text_scan.hpp"

#include <charconv>
#include <climits>
#include <cstring>
#include <system_error>
#include <utility>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/core/vec.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::io {

namespace {

bool is_digit(char c) { return c >= '0' && c <= '9'; }

// A cursor over the text; every reader returns false at the first byte that is not the plain shape.
class Scanner {
 public:
  explicit Scanner(std::string_view text) : p_(text.data()), end_(text.data() + text.size()) {}

  void skip_space() {
    while (p_ < end_ && (*p_ == ' ' || *p_ == '\n' || *p_ == '\r' || *p_ == '\t')) ++p_;
  }
  bool at_end() {
    skip_space();
    return p_ == end_;
  }
  // The next byte (after white space) is c, and is consumed.
  bool take(char c) {
    skip_space();
    if (p_ == end_ || *p_ != c) return false;
    ++p_;
    return true;
  }
  // The next byte (after white space) is c; not consumed.
  bool next_is(char c) {
    skip_space();
    return p_ != end_ && *p_ == c;
  }
  // A string of printable ASCII without escapes.
  bool string(std::string_view& out) {
    if (!take('"')) return false;
    const char* start = p_;
    while (p_ < end_ && *p_ != '"') {
      const auto c = static_cast<unsigned char>(*p_);
      if (c == '\\' || c < 0x20 || c >= 0x80) return false;
      ++p_;
    }
    if (p_ == end_) return false;
    out = std::string_view(start, static_cast<std::size_t>(p_ - start));
    ++p_;
    return true;
  }
  bool null() {
    skip_space();
    if (end_ - p_ < 4 || std::memcmp(p_, "null", 4) != 0) return false;
    p_ += 4;
    return true;
  }
  // A number in JSON's grammar, read as nlohmann reads it: an integer literal as a 64-bit integer
  // (then converted, so "-0" is +0.0), anything else correctly rounded; out-of-range literals fail.
  bool number(double& value, bool& integral) {
    skip_space();
    const char* start = p_;
    if (p_ < end_ && *p_ == '-') ++p_;
    if (p_ == end_) return false;
    if (*p_ == '0') {
      ++p_;
    } else if (*p_ >= '1' && *p_ <= '9') {
      while (p_ < end_ && is_digit(*p_)) ++p_;
    } else {
      return false;
    }
    integral = true;
    if (p_ < end_ && *p_ == '.') {
      ++p_;
      integral = false;
      if (p_ == end_ || !is_digit(*p_)) return false;
      while (p_ < end_ && is_digit(*p_)) ++p_;
    }
    if (p_ < end_ && (*p_ == 'e' || *p_ == 'E')) {
      ++p_;
      integral = false;
      if (p_ < end_ && (*p_ == '+' || *p_ == '-')) ++p_;
      if (p_ == end_ || !is_digit(*p_)) return false;
      while (p_ < end_ && is_digit(*p_)) ++p_;
    }
    if (integral) {
      long long i = 0;
      if (const auto r = std::from_chars(start, p_, i); r.ec == std::errc{} && r.ptr == p_) {
        value = static_cast<double>(i);
        return true;
      }
      unsigned long long u = 0;
      if (const auto r = std::from_chars(start, p_, u); r.ec == std::errc{} && r.ptr == p_) {
        value = static_cast<double>(u);
        return true;
      }
    }
    const auto r = std::from_chars(start, p_, value);
    return r.ec == std::errc{} && r.ptr == p_;
  }
  // [n, n, ...], not empty.
  bool numbers(std::vector<double>& out) {
    if (!take('[')) return false;
    double v = 0.0;
    bool integral = false;
    do {
      if (!number(v, integral)) return false;
      out.push_back(v);
    } while (take(','));
    return take(']');
  }
  // [[x, y(, z)], ...], not empty, every point with the same component count.
  bool points(std::vector<Vec3>& out, int& dimension) {
    if (!take('[')) return false;
    dimension = 0;
    do {
      if (!take('[')) return false;
      double c[3] = {0.0, 0.0, 0.0};
      int count = 0;
      bool integral = false;
      do {
        if (count == 3 || !number(c[count], integral)) return false;
        ++count;
      } while (take(','));
      if (!take(']') || count < 2 || (dimension != 0 && count != dimension)) return false;
      dimension = count;
      out.push_back({c[0], c[1], c[2]});
    } while (take(','));
    return take(']');
  }

 private:
  const char* p_;
  const char* end_;
};

struct PlainCurve {
  bool format = false, version = false, kind = false, degree = false, knots = false, control_points = false,
       weights = false;
  bool bezier = false;
  int degree_value = 0;
  std::vector<double> knot_values, weight_values;
  std::vector<Vec3> poles;
  int dimension = 0;
};

// One member's value into `c`; false when the member is unknown, repeated or not plain.
bool read_member(Scanner& s, std::string_view key, PlainCurve& c) {
  const auto first = [](bool& seen) { return !std::exchange(seen, true); };
  double v = 0.0;
  bool integral = false;
  if (key == "format") {
    std::string_view name;
    return first(c.format) && s.string(name) && name == kCurveFormat;
  }
  if (key == "version")
    return first(c.version) && s.number(v, integral) && integral && v >= 1.0 && v <= kCurveFormatVersion;
  if (key == "kind") {
    std::string_view kind;
    if (!first(c.kind) || !s.string(kind)) return false;
    c.bezier = kind == "bezier";
    return c.bezier || kind == "nurbs";
  }
  if (key == "degree") {
    if (!first(c.degree) || !s.number(v, integral) || !integral || v < INT_MIN || v > INT_MAX) return false;
    c.degree_value = static_cast<int>(v);
    return true;
  }
  if (key == "knots") return first(c.knots) && s.numbers(c.knot_values);
  if (key == "control_points") {
    // hula writes the knots first: n + 1 = knots − degree − 1 poles are then expected (a hint only), so a
    // million poles are not grown by doubling (copies and page faults).
    if (c.knots && c.degree && c.degree_value >= 0 &&
        c.knot_values.size() > static_cast<std::size_t>(c.degree_value) + 1)
      c.poles.reserve(c.knot_values.size() - static_cast<std::size_t>(c.degree_value) - 1);
    return first(c.control_points) && s.points(c.poles, c.dimension);
  }
  if (key == "weights") {
    if (!c.poles.empty()) c.weight_values.reserve(c.poles.size());
    return first(c.weights) && (s.next_is('n') ? s.null() : s.numbers(c.weight_values));
  }
  return false;
}

}  // namespace

std::optional<curve::Curve> scan_plain_curve_text(std::string_view text) {
  Scanner s(text);
  PlainCurve c;
  if (!s.take('{')) return std::nullopt;
  do {
    std::string_view key;
    if (!s.string(key) || !s.take(':') || !read_member(s, key, c)) return std::nullopt;
  } while (s.take(','));
  if (!s.take('}') || !s.at_end()) return std::nullopt;
  if (!c.kind || !c.control_points || (c.bezier ? c.degree || c.knots : !c.degree || !c.knots)) return std::nullopt;
  try {
    if (c.bezier) {
      curve::BezierData data;
      data.control_points = std::move(c.poles);
      data.dimension = c.dimension;
      data.weights = std::move(c.weight_values);
      return curve::Curve::bezier(std::move(data));
    }
    return curve::Curve(nurbs::NurbsCurve(c.degree_value, std::move(c.knot_values), std::move(c.poles),
                                          std::move(c.weight_values), c.dimension));
  } catch (const Error&) {
    return std::nullopt;  // the general reader reads it again and says what is wrong
  }
}

}  // namespace hula::io
