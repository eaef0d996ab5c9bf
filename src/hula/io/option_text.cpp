// SPDX-License-Identifier: MIT
// Text forms of numbers and end conditions (option_text.hpp).
#include "hula/io/option_text.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include "hula/core/error.hpp"

namespace hula::io {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
  return s;
}

double parse_number(std::string_view entry, const std::string& name, const ErrorWhere& where) {
  std::string_view s = trim(entry);
  // from_chars does not take a leading '+'; accept it as people write it.
  if (s.size() > 1 && s.front() == '+') s.remove_prefix(1);
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec == std::errc::result_out_of_range)
    throw Error(Errc::NonFiniteInput, name + " = \"" + std::string(entry) + "\" is outside the range of a double",
                where);
  if (s.empty() || ec != std::errc() || ptr != s.data() + s.size())
    throw Error(Errc::ParseError, name + " = \"" + std::string(entry) + "\" is not a number", where);
  if (!std::isfinite(v))
    throw Error(Errc::NonFiniteInput, name + " = \"" + std::string(entry) + "\" is not a finite number", where);
  return v;
}

}  // namespace

std::vector<double> parse_number_list(std::string_view text, std::string_view field) {
  std::vector<double> out;
  std::size_t start = 0;
  for (std::size_t i = 0;; ++i) {
    std::size_t comma = text.find(',', start);
    const bool last = comma == std::string_view::npos;
    if (last) comma = text.size();
    const std::string name = std::string(field) + "[" + std::to_string(i) + "]";
    out.push_back(parse_number(text.substr(start, comma - start), name, {.field = std::string(field), .index = i}));
    if (last) break;
    start = comma + 1;
  }
  return out;
}

nurbs::EndCondition parse_end_condition(std::string_view text, std::string_view field) {
  if (text == "natural") return nurbs::EndCondition::natural();
  if (text == "bessel") return nurbs::EndCondition::bessel();
  if (text == "not-a-knot") return nurbs::EndCondition::not_a_knot();
  if (text == "occt") return nurbs::EndCondition::occt();
  constexpr std::string_view kDirection = "direction:";
  if (text.substr(0, kDirection.size()) == kDirection) {
    const std::vector<double> d = parse_number_list(text.substr(kDirection.size()), std::string(field) + ".direction");
    if ((d.size() == 2 || d.size() == 3) && norm(Vec3{d[0], d[1], d.size() == 3 ? d[2] : 0.0}) > 0.0)
      return nurbs::EndCondition::direction({d[0], d[1], d.size() == 3 ? d[2] : 0.0});
    throw Error(Errc::ParseError,
                "--" + std::string(field) + " " + std::string(text) +
                    ": a direction needs 2 or 3 numbers, not all zero, got " + std::to_string(d.size()),
                {.field = std::string(field)});
  }
  constexpr std::string_view kClamped = "clamped:";
  if (text.substr(0, kClamped.size()) == kClamped) {
    const std::vector<double> d = parse_number_list(text.substr(kClamped.size()), std::string(field) + ".tangent");
    if (d.size() == 2 || d.size() == 3) return nurbs::EndCondition::clamped({d[0], d[1], d.size() == 3 ? d[2] : 0.0});
    throw Error(Errc::ParseError,
                std::string(field) + " = \"" + std::string(text) + "\": a clamped tangent needs 2 or 3 numbers, got " +
                    std::to_string(d.size()),
                {.field = std::string(field)});
  }
  throw Error(Errc::ParseError,
              std::string(field) + " = \"" + std::string(text) +
                  "\" is not an end condition (expected natural, bessel, not-a-knot, occt, direction:x,y,z or "
                  "clamped:x,y,z)",
              {.field = std::string(field)});
}

}  // namespace hula::io
