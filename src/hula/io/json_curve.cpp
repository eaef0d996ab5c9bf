// SPDX-License-Identifier: MIT
// Reader and writer of JSON curve files (format in json_curve.hpp and
// docs/formats.md). The reader checks types and shapes itself, naming the JSON
// path of the culprit, and leaves the geometric invariants (knot order, degree,
// weights) to the kernel constructors, whose errors already name the members
// "knots", "control_points", "weights" and "degree" with their indices.
#include "hula/io/json_curve.hpp"

#include <array>
#include <climits>
#include <optional>
#include <span>
#include <utility>
#include <variant>

#include "hula/core/error.hpp"
#include "hula/intrinsic/natural_curve.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/curve_text_scan.hpp"
#include "hula/io/json_read.hpp"
#include "hula/io/json_text.hpp"
#include "hula/io/json_write.hpp"

namespace hula::io {

using json::JsonPath;
using json::root_path;

std::string_view parameterisation_name(nurbs::Parameterisation rule) noexcept {
  switch (rule) {
    case nurbs::Parameterisation::Uniform:
      return "uniform";
    case nurbs::Parameterisation::ChordLength:
      return "chord";
    case nurbs::Parameterisation::Centripetal:
      return "centripetal";
    case nurbs::Parameterisation::Foley:
      return "foley";
  }
  return "chord";
}

nurbs::Parameterisation parameterisation_from_name(std::string_view name, std::string_view field) {
  if (name == "uniform") return nurbs::Parameterisation::Uniform;
  if (name == "chord") return nurbs::Parameterisation::ChordLength;
  if (name == "centripetal") return nurbs::Parameterisation::Centripetal;
  if (name == "foley") return nurbs::Parameterisation::Foley;
  throw Error(Errc::ParseError,
              std::string(field) + " = " + json::quote(std::string(name)) +
                  " is not a parameterisation (expected \"uniform\", \"chord\", \"centripetal\" or \"foley\")",
              {.field = std::string(field)});
}

nurbs::EndCondition end_condition_from_json(const Json& value, std::string_view field) {
  const JsonPath path = root_path(field);
  using K = nurbs::EndCondition::Kind;
  if (value.is_string()) {
    const auto name = value.get<std::string>();
    if (name == "natural") return {K::Natural, {}};
    if (name == "bessel") return {K::Bessel, {}};
    if (name == "not-a-knot") return {K::NotAKnot, {}};
    if (name == "occt") return {K::Occt, {}};
    throw Error(Errc::ParseError,
                path.text + " = " + json::describe(value) +
                    " is not an end condition (expected \"natural\", \"bessel\", \"not-a-knot\", \"occt\", "
                    "{\"tangent\": [x, y, z]} or {\"direction\": [x, y, z]})",
                path.where);
  }
  if (value.is_object()) {
    if (const Json* direction = json::optional_member(value, "direction")) {
      const Vec3 d = json::get_point(*direction, path.member("direction")).first;
      if (!(norm(d) > 0.0))
        throw Error(Errc::InvalidArgument,
                    path.member("direction").text + " is a zero vector (a direction needs a length)",
                    path.member("direction").where);
      return {K::Direction, d};
    }
    const Json& tangent = json::require_member(value, path, "tangent");
    return {K::Clamped, json::get_point(tangent, path.member("tangent")).first};
  }
  json::type_error(value, path,
                   "an end condition (\"natural\", \"bessel\", \"not-a-knot\", \"occt\", {\"tangent\": [x, y, z]} or "
                   "{\"direction\": [x, y, z]})");
}

Json point_to_json(const Vec3& p, int dimension) {
  Json a = Json::array({p.x, p.y});
  if (dimension != 2) a.push_back(p.z);
  return a;
}

Json points_to_json(std::span<const Vec3> points, int dimension) {
  Json a = Json::array();
  for (const Vec3& p : points) a.push_back(point_to_json(p, dimension));
  return a;
}

namespace {

curve::Curve read_nurbs(const Json& doc) {
  const JsonPath root;
  const auto degree =
      json::get_integer(json::require_member(doc, root, "degree"), root_path("degree"), INT_MIN, INT_MAX);
  std::vector<double> knots = json::get_number_array(json::require_member(doc, root, "knots"), root_path("knots"));
  json::PointArray cps =
      json::get_points(json::require_member(doc, root, "control_points"), root_path("control_points"));
  std::vector<double> weights;
  if (const Json* w = json::optional_member(doc, "weights"); w && !w->is_null())
    weights = json::get_nonempty_number_array(
        *w, root_path("weights"), "give one weight per control point, or leave \"weights\" out for a polynomial curve");
  return nurbs::NurbsCurve(static_cast<int>(degree), std::move(knots), std::move(cps.points), std::move(weights),
                           cps.dimension);
}

curve::Curve read_bezier(const Json& doc) {
  const JsonPath root;
  json::PointArray cps =
      json::get_points(json::require_member(doc, root, "control_points"), root_path("control_points"));
  curve::BezierData data;
  data.control_points = std::move(cps.points);
  data.dimension = cps.dimension;
  if (const Json* w = json::optional_member(doc, "weights"); w && !w->is_null())
    data.weights = json::get_nonempty_number_array(
        *w, root_path("weights"), "give one weight per control point, or leave \"weights\" out for a polynomial curve");
  return curve::Curve::bezier(std::move(data));
}

std::vector<double> optional_parameters(const Json& doc) {
  if (const Json* p = json::optional_member(doc, "parameters"))
    return json::get_number_array(*p, root_path("parameters"));
  return {};
}

curve::Curve read_interpolated(const Json& doc) {
  const JsonPath root;
  curve::InterpolatedData in;
  json::PointArray pts = json::get_points(json::require_member(doc, root, "points"), root_path("points"));
  in.points = std::move(pts.points);
  in.dimension = pts.dimension;
  if (const Json* rule = json::optional_member(doc, "parameterisation"))
    in.parameterisation = parameterisation_from_name(json::get_string(*rule, root_path("parameterisation")));
  std::vector<double> parameters, knots;
  const Json* jp = json::optional_member(doc, "parameters");
  const Json* jk = json::optional_member(doc, "knots");
  if (jp)
    parameters = json::get_nonempty_number_array(*jp, root_path("parameters"),
                                                 "give one parameter per point, or leave \"parameters\" out");
  if (jk)
    knots = json::get_nonempty_number_array(*jk, root_path("knots"), "give one knot per point, or leave \"knots\" out");
  if (jp && jk) {
    // "knots" is the thesis's interpolate-knots: the same quantity as "parameters".
    if (knots.size() != parameters.size())
      throw Error(Errc::ParseError,
                  "knots has " + std::to_string(knots.size()) + " values but parameters has " +
                      std::to_string(parameters.size()) + "; give one of them, or both equal",
                  {.field = "knots"});
    for (std::size_t i = 0; i < knots.size(); ++i)
      if (knots[i] != parameters[i])
        throw Error(Errc::ParseError,
                    "knots[" + std::to_string(i) + "] = " + format_number(knots[i]) + " differs from parameters[" +
                        std::to_string(i) + "] = " + format_number(parameters[i]) +
                        "; they mean the same thing: give one of them, or both equal",
                    {.field = "knots", .index = i});
  }
  const bool from_knots = jk && !jp;
  in.parameters = from_knots ? std::move(knots) : std::move(parameters);
  if (const Json* s = json::optional_member(doc, "start")) in.start = end_condition_from_json(*s, "start");
  if (const Json* e = json::optional_member(doc, "end")) in.end = end_condition_from_json(*e, "end");
  return interpolated_curve(std::move(in), from_knots ? "knots" : "parameters");
}

curve::Curve read_hermite(const Json& doc) {
  const JsonPath root;
  curve::HermiteData h;
  json::PointArray pts = json::get_points(json::require_member(doc, root, "points"), root_path("points"));
  h.points = std::move(pts.points);
  h.dimension = pts.dimension;
  h.tangents = json::get_points(json::require_member(doc, root, "tangents"), root_path("tangents")).points;
  if (const Json* d2 = json::optional_member(doc, "second_derivatives"); d2 && !d2->is_null())
    h.second_derivatives = json::get_points(*d2, root_path("second_derivatives")).points;
  h.parameters = optional_parameters(doc);
  return curve::Curve::hermite(std::move(h));
}

curve::Curve read_law(const Json& doc) {
  const JsonPath root;
  std::string expression = json::get_string(json::require_member(doc, root, "expression"), root_path("expression"));
  std::string parameter = "t";
  if (const Json* p = json::optional_member(doc, "parameter")) parameter = json::get_string(*p, root_path("parameter"));
  const std::vector<double> dom =
      json::get_number_array(json::require_member(doc, root, "domain"), root_path("domain"));
  if (dom.size() != 2 || !(dom[0] < dom[1]))
    throw Error(Errc::ParseError, "domain must be [start, end] with start < end, got " + json::describe(doc["domain"]),
                {.field = "domain"});
  return curve::Curve::from_law(std::move(expression), std::move(parameter), {dom[0], dom[1]});
}

curve::Curve read_natural(const Json& doc) {
  const JsonPath root;
  curve::NaturalData n;
  n.curvature = json::get_string(json::require_member(doc, root, "curvature"), root_path("curvature"));
  if (const Json* t = json::optional_member(doc, "torsion")) n.torsion = json::get_string(*t, root_path("torsion"));
  if (const Json* p = json::optional_member(doc, "parameter"))
    n.parameter = json::get_string(*p, root_path("parameter"));
  n.length = json::get_number(json::require_member(doc, root, "length"), root_path("length"));
  // Files written before the integration tolerance was stored read with the default.
  if (const Json* t = json::optional_member(doc, "tolerance"))
    n.tolerance = json::get_number(*t, root_path("tolerance"));
  if (const Json* start = json::optional_member(doc, "start")) {
    const JsonPath sp = root_path("start");
    if (!start->is_object()) json::type_error(*start, sp, "an object {\"point\", \"tangent\", \"normal\"}");
    if (const Json* v = json::optional_member(*start, "point"))
      n.start_point = json::get_point(*v, sp.member("point")).first;
    if (const Json* v = json::optional_member(*start, "tangent"))
      n.start_tangent = json::get_point(*v, sp.member("tangent")).first;
    if (const Json* v = json::optional_member(*start, "normal"))
      n.start_normal = json::get_point(*v, sp.member("normal")).first;
  }
  return intrinsic::natural_curve(n, curve::kApproximationTolerance);
}

void check_format(const Json& doc) {
  if (const Json* f = json::optional_member(doc, "format")) {
    const std::string name = json::get_string(*f, root_path("format"));
    if (name != kCurveFormat)
      throw Error(
          Errc::ParseError,
          "format = " + json::describe(*f) + " is not a curve file (expected \"" + std::string(kCurveFormat) + "\")",
          {.field = "format"});
  }
  if (const Json* v = json::optional_member(doc, "version")) {
    if (!v->is_number_integer() || v->get<long long>() < 1 || v->get<long long>() > kCurveFormatVersion)
      throw Error(Errc::ParseError,
                  "version = " + json::describe(*v) + " is not a curve-file version this build reads (1 to " +
                      std::to_string(kCurveFormatVersion) + ")",
                  {.field = "version"});
  }
}

}  // namespace

Json end_condition_to_json(const nurbs::EndCondition& end, int dimension) {
  using K = nurbs::EndCondition::Kind;
  switch (end.kind) {
    case K::Natural:
      return "natural";
    case K::Bessel:
      return "bessel";
    case K::NotAKnot:
      return "not-a-knot";
    case K::Occt:
      return "occt";
    case K::Clamped: {
      Json o = Json::object();
      o["tangent"] = point_to_json(end.derivative, dimension == 2 && end.derivative.z == 0.0 ? 2 : 3);
      return o;
    }
    case K::Direction: {
      Json o = Json::object();
      o["direction"] = point_to_json(end.derivative, dimension == 2 && end.derivative.z == 0.0 ? 2 : 3);
      return o;
    }
  }
  return "natural";
}

curve::Curve interpolated_curve(curve::InterpolatedData data, std::string_view parameters_field) {
  try {
    return curve::Curve::interpolated(std::move(data));
  } catch (const Error& e) {
    if (e.where().field != "parameters" || parameters_field == "parameters") throw;
    // Rename the member in the message and location so it names what the user wrote.
    std::string message = e.message();
    const std::string from = "parameters", to(parameters_field);
    for (std::size_t at = message.find(from); at != std::string::npos; at = message.find(from, at + to.size()))
      message.replace(at, from.size(), to);
    ErrorWhere where = e.where();
    where.field = to;
    throw Error(e.code(), message, where);
  }
}

curve::Curve curve_from_json(const Json& document) {
  if (!document.is_object()) json::type_error(document, JsonPath{}, "a JSON object with a \"kind\" member");
  check_format(document);
  const std::string kind = json::get_string(json::require_member(document, JsonPath{}, "kind"), root_path("kind"));
  if (kind == "nurbs") return read_nurbs(document);
  if (kind == "bezier") return read_bezier(document);
  if (kind == "interpolated") return read_interpolated(document);
  if (kind == "hermite") return read_hermite(document);
  if (kind == "law") return read_law(document);
  if (kind == "natural") return read_natural(document);
  throw Error(Errc::ParseError,
              "kind = " + json::quote(kind) +
                  " is not a known curve kind (expected \"nurbs\", \"bezier\", \"interpolated\", \"hermite\", "
                  "\"law\" or \"natural\")",
              {.field = "kind"});
}

curve::Curve parse_curve_json(std::string_view text) {
  // The plain files hula writes are read straight into the kernel's arrays; anything else (and every
  // error) goes through the JSON value, whose reader names what is wrong.
  if (std::optional<curve::Curve> plain = scan_plain_curve_text(text)) return std::move(*plain);
  return curve_from_json(json::parse_json_text(text, "curve file"));
}

curve::Curve read_curve_file(const std::filesystem::path& path) {
  return parse_curve_json(read_text_file(path, kMaxGeometryInputBytes));
}

namespace {
// The curve file, written once for both JSON values (JsonTree: curve_to_json) and streamed text
// (JsonText: write_curve_file, which writes a million-point curve without building a value).
template <class W>
void write_point(W& w, const Vec3& p, int dimension) {
  const std::array<double, 3> xyz{p.x, p.y, p.z};
  w.numbers(std::span<const double>(xyz.data(), dimension == 2 ? 2 : 3));
}

template <class W>
void write_points(W& w, std::span<const Vec3> points, int dimension) {
  w.containers(points.size(), [&](std::size_t i) { write_point(w, points[i], dimension); });
}

template <class W>
void write_numbers(W& w, std::span<const double> values) {
  w.numbers(values);
}

template <class W>
struct DataWriter {
  W& w;
  int dimension;
  void operator()(const curve::NurbsData& d) const {
    const nurbs::NurbsCurve& c = d.curve;
    w.member("degree").integer(c.degree());
    write_numbers(w.member("knots"), c.knots().values());
    write_points(w.member("control_points"), c.control_points(), c.dimension());
    if (c.is_rational())
      write_numbers(w.member("weights"), c.weights());
    else
      w.member("weights").null();
  }
  void operator()(const curve::BezierData& d) const {
    write_points(w.member("control_points"), d.control_points, d.dimension);
    if (d.weights.empty())
      w.member("weights").null();
    else
      write_numbers(w.member("weights"), d.weights);
  }
  void operator()(const curve::InterpolatedData& d) const {
    write_points(w.member("points"), d.points, d.dimension);
    w.member("parameterisation").string(parameterisation_name(d.parameterisation));
    if (!d.parameters.empty()) write_numbers(w.member("parameters"), d.parameters);
    w.member("start").value(end_condition_to_json(d.start, d.dimension));
    w.member("end").value(end_condition_to_json(d.end, d.dimension));
  }
  void operator()(const curve::HermiteData& d) const {
    write_points(w.member("points"), d.points, d.dimension);
    write_points(w.member("tangents"), d.tangents, d.dimension);
    if (!d.second_derivatives.empty()) write_points(w.member("second_derivatives"), d.second_derivatives, d.dimension);
    if (!d.parameters.empty()) write_numbers(w.member("parameters"), d.parameters);
  }
  void operator()(const curve::LawData& d) const {
    w.member("expression").string(d.expression);
    w.member("parameter").string(d.parameter);
    const std::array<double, 2> domain{d.domain.start, d.domain.end};
    write_numbers(w.member("domain"), domain);
  }
  void operator()(const curve::NaturalData& d) const {
    w.member("curvature").string(d.curvature);
    w.member("torsion").string(d.torsion);
    w.member("parameter").string(d.parameter);
    w.member("length").number(d.length);
    w.member("start").begin_object();
    write_point(w.member("point"), d.start_point, 3);
    write_point(w.member("tangent"), d.start_tangent, 3);
    write_point(w.member("normal"), d.start_normal, 3);
    w.end_object();
    w.member("tolerance").number(d.tolerance);
  }
};

template <class W>
void write_curve(W& w, const curve::Curve& curve) {
  w.begin_object();
  w.member("format").string(kCurveFormat);
  w.member("version").integer(kCurveFormatVersion);
  w.member("kind").string(curve.kind_name());
  std::visit(DataWriter<W>{w, curve.dimension()}, curve.data());
  w.end_object();
}
}  // namespace

Json curve_to_json(const curve::Curve& curve) {
  Json doc;
  JsonTree tree(doc);
  write_curve(tree, curve);
  return doc;
}

std::string to_file_text(const Json& document) { return format_json(document); }

std::string curve_file_text(const curve::Curve& curve) {
  std::string text;
  JsonText w(text, true);
  write_curve(w, curve);
  text += '\n';
  return text;
}

void write_curve_file(const std::filesystem::path& path, const curve::Curve& curve) {
  if (is_std_stream(path)) {
    // Standard output cannot be taken back: the size is checked before the first byte.
    const std::string text = curve_file_text(curve);
    check_readable_size(text.size(), path, "path");
    write_file_atomically(path, text);
    return;
  }
  // A file is streamed through its temporary: past the readers' limit the write stops and the
  // temporary is removed (OutputFile), leaving the target as it was.
  OutputFile file(path, "path");
  std::size_t written = 0;
  const auto drain = [&](std::string& text) {
    written += text.size();
    check_readable_size(written, path, "path");
    file.stream().write(text.data(), static_cast<std::streamsize>(text.size()));
    text.clear();
  };
  std::string buffer;
  buffer.reserve(JsonText::kDrainBytes + (JsonText::kDrainBytes >> 2));
  JsonText w(buffer, true, drain);
  write_curve(w, curve);
  buffer += '\n';
  drain(buffer);
  file.commit();
}

}  // namespace hula::io
