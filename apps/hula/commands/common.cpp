// SPDX-License-Identifier: MIT
// Shared helpers of the `hula` commands (see common.hpp).
#include "commands/common.hpp"

#include <charconv>
#include <cmath>
#include <iostream>
#include <limits>

#include "hula/core/error.hpp"
#include "hula/core/tolerance.hpp"
#include "hula/diffgeom/planarity.hpp"
#include "hula/intrinsic/natural_curve.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/curve_analysis_json.hpp"
#include "hula/io/json_write.hpp"
#include "hula/nurbs/arc_length.hpp"

namespace hula::cli {

void print_json(const Json& document) { io::write_stdout(io::format_json(document)); }

void print_result(const Json& document, std::string_view output) {
  if (!io::is_std_stream(std::filesystem::path(output))) print_json(document);
}

void print_text(std::string_view text) { io::write_stdout(text); }

OutputFormat output_format_from_name(std::string_view name) {
  if (name == "json") return OutputFormat::JsonDocument;
  if (name == "jsonl") return OutputFormat::JsonLines;
  if (name == "csv") return OutputFormat::Csv;
  if (name == "text") return OutputFormat::Text;
  throw CLI::ValidationError("--format " + std::string(name), "must be json, jsonl, csv or text");
}

namespace {
// At most a few characters of what the user typed, for messages.
std::string shown(std::string_view text) {
  constexpr std::size_t kMax = 24;
  return text.size() <= kMax ? std::string(text) : std::string(text.substr(0, kMax)) + "...";
}

std::string range_text(long long lo, long long hi) {
  if (hi == std::numeric_limits<long long>::max()) return ">= " + std::to_string(lo);
  return "in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
}
}  // namespace

long long parse_integer_option(std::string_view text, std::string_view flag, long long lo, long long hi, bool even) {
  const std::string rule = std::string("must be ") + (even ? "an even number " : "an integer ") + range_text(lo, hi);
  std::string_view s = text;
  if (s.size() > 1 && s.front() == '+') s.remove_prefix(1);
  long long v = 0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  const std::string head = std::string(flag) + " " + shown(text);
  if (ec == std::errc::result_out_of_range)
    throw CLI::ValidationError(head, "outside the signed 64-bit range; " + rule);
  if (s.empty() || ec != std::errc() || ptr != s.data() + s.size())
    throw CLI::ValidationError(head, "not an integer; " + rule);
  if (v < lo || v > hi || (even && v % 2 != 0)) throw CLI::ValidationError(head, rule);
  return v;
}

double parse_real_option(std::string_view text, std::string_view flag, double lo, double hi, bool lo_open) {
  const auto fmt = [](double x) { return format_number(x); };
  std::string rule;
  if (hi == std::numeric_limits<double>::max())
    rule = std::string("must be a number ") + (lo_open ? "> " : ">= ") + fmt(lo);
  else
    rule = std::string("must be a number in ") + (lo_open ? "(" : "[") + fmt(lo) + ", " + fmt(hi) + "]";
  std::string_view s = text;
  if (s.size() > 1 && s.front() == '+') s.remove_prefix(1);
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  const std::string head = std::string(flag) + " " + shown(text);
  if (ec == std::errc::result_out_of_range) throw CLI::ValidationError(head, "outside the range of a double; " + rule);
  if (s.empty() || ec != std::errc() || ptr != s.data() + s.size())
    throw CLI::ValidationError(head, "not a number; " + rule);
  if (!std::isfinite(v) || v < lo || v > hi || (lo_open && v == lo)) throw CLI::ValidationError(head, rule);
  return v;
}

CLI::Option* add_real_option(CLI::App* sub, const std::string& flags, std::optional<double>& target, double lo,
                             double hi, bool lo_open, const std::string& help) {
  const std::string flag = "--" + flags.substr(flags.rfind("--") + 2);
  return sub
      ->add_option_function<std::string>(
          flags,
          [&target, flag, lo, hi, lo_open](const std::string& text) {
            target = parse_real_option(text, flag, lo, hi, lo_open);
          },
          help)
      ->type_name("NUMBER");
}

void add_exact_output_options(CLI::App* sub, std::string& output, std::optional<double>& to_nurbs, double& tolerance) {
  CLI::Option* out =
      sub->add_option("-o,--output", output,
                      "Write the curve file: the exact curve by its laws (kind natural), or its NURBS with --to-nurbs");
  add_real_option(sub, "--to-nurbs", to_nurbs, 0.0, 1.0, true,
                  "With -o: write the NURBS within this distance of the curve (model units) instead of the laws")
      ->needs(out);
  sub->add_option("--tolerance", tolerance,
                  "Position tolerance of the integration of the exact curve, in [1e-13, 1e-2] (default 1e-10)");
}

Json write_exact_curve(const std::string& path, const curve::Curve& curve, const std::optional<double>& to_nurbs) {
  Json j = Json::object();
  j["path"] = path;
  if (to_nurbs) {
    const intrinsic::CurveToNurbsResult n = intrinsic::to_nurbs(curve, *to_nurbs);
    io::write_curve_file(path, n.curve);
    j["kind"] = "nurbs";
    j["tolerance"] = n.tolerance;
    j["max_deviation"] = n.max_deviation;
    j["control_points"] = n.curve.control_points().size();
  } else {
    io::write_curve_file(path, curve);
    j["kind"] = std::string(curve.kind_name());
  }
  return j;
}

Json vec_to_json(const Vec3& v, int dimension) {
  Json a = Json::array({v.x, v.y});
  if (dimension != 2) a.push_back(v.z);
  return a;
}

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

Json analyse(const nurbs::NurbsCurve& curve) {
  const int dim = curve.dimension();
  const nurbs::Interval dom = curve.domain();
  Json o = Json::object();
  o["degree"] = curve.degree();
  o["dimension"] = dim;
  o["rational"] = curve.is_rational();
  o["domain"] = Json::array({dom.start, dom.end});
  Json knots = Json::array();
  for (double u : curve.knots().values()) knots.push_back(u);
  o["knots"] = std::move(knots);
  Json points = Json::array();
  for (const Vec3& p : curve.control_points()) points.push_back(vec_to_json(p, dim));
  o["control_points"] = std::move(points);
  if (curve.is_rational()) {
    Json w = Json::array();
    for (double v : curve.weights()) w.push_back(v);
    o["weights"] = std::move(w);
  } else {
    o["weights"] = nullptr;
  }
  o["length"] = nurbs::arc_length(curve);
  const Vec3 d0 = curve.derivatives(dom.start, 1)[1];
  const Vec3 d1 = curve.derivatives(dom.end, 1)[1];
  Json tangents = Json::object();
  tangents["start"] = vec_to_json(d0, dim);
  tangents["end"] = vec_to_json(d1, dim);
  o["end_derivatives"] = std::move(tangents);
  // Unit tangents where |C'| is above rounding noise relative to the derivative's scale; null otherwise.
  const auto unit = [&](const Vec3& d) {
    const double scale = curve.model_size() / dom.length();
    return norm(d) > 1e-12 * scale ? vec_to_json(normalized(d), dim) : Json(nullptr);
  };
  Json units = Json::object();
  units["start"] = unit(d0);
  units["end"] = unit(d1);
  o["end_tangents"] = std::move(units);
  o["planarity"] = io::planarity_to_json(diffgeom::planarity(curve));
  return o;
}

}  // namespace hula::cli
