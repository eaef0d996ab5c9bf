// SPDX-License-Identifier: MIT
// Reader and writer of JSON curve files (format in json_curve.hpp and
// docs/formats.md). The reader checks types and shapes itself, naming the JSON
// path of the culprit, and leaves the geometric invariants (knot order, degree,
// weights) to the kernel constructors, whose errors already name the members
// "knots", "control_points", "weights" and "degree" with their indices.
#include "hula/io/json_curve.hpp"

#include <climits>
#include <utility>

#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/json_read.hpp"
#include "hula/io/json_write.hpp"
#include "hula/law/convert.hpp"
#include "hula/law/parser.hpp"

namespace hula::io {

using json::JsonPath;
using json::root_path;

std::string_view curve_kind_name(CurveKind kind) noexcept {
  switch (kind) {
    case CurveKind::Nurbs:
      return "nurbs";
    case CurveKind::Bezier:
      return "bezier";
    case CurveKind::Interpolated:
      return "interpolated";
    case CurveKind::Law:
      return "law";
  }
  return "nurbs";
}

std::string_view parameterisation_name(nurbs::Parameterisation rule) noexcept {
  switch (rule) {
    case nurbs::Parameterisation::Uniform:
      return "uniform";
    case nurbs::Parameterisation::ChordLength:
      return "chord";
    case nurbs::Parameterisation::Centripetal:
      return "centripetal";
  }
  return "chord";
}

nurbs::Parameterisation parameterisation_from_name(std::string_view name, std::string_view field) {
  if (name == "uniform") return nurbs::Parameterisation::Uniform;
  if (name == "chord") return nurbs::Parameterisation::ChordLength;
  if (name == "centripetal") return nurbs::Parameterisation::Centripetal;
  throw Error(Errc::ParseError,
              std::string(field) + " = " + json::quote(std::string(name)) +
                  " is not a parameterisation (expected \"uniform\", \"chord\" or \"centripetal\")",
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
                    " is not an end condition (expected \"natural\", \"bessel\", \"not-a-knot\", \"occt\" or "
                    "{\"tangent\": [x, y, z]})",
                path.where);
  }
  if (value.is_object()) {
    const Json& tangent = json::require_member(value, path, "tangent");
    return {K::Clamped, json::get_point(tangent, path.member("tangent")).first};
  }
  json::type_error(value, path,
                   "an end condition (\"natural\", \"bessel\", \"not-a-knot\", \"occt\" or {\"tangent\": [x, y, z]})");
}

namespace {

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

Json numbers_to_json(std::span<const double> values) {
  Json a = Json::array();
  for (double v : values) a.push_back(v);
  return a;
}

CurveFile read_nurbs(const Json& doc) {
  const JsonPath root;
  const auto degree =
      json::get_integer(json::require_member(doc, root, "degree"), root_path("degree"), INT_MIN, INT_MAX);
  std::vector<double> knots = json::get_number_array(json::require_member(doc, root, "knots"), root_path("knots"));
  json::PointArray cps =
      json::get_points(json::require_member(doc, root, "control_points"), root_path("control_points"));
  std::vector<double> weights;
  if (const Json* w = json::optional_member(doc, "weights"))
    weights = json::get_nonempty_number_array(
        *w, root_path("weights"), "give one weight per control point, or leave \"weights\" out for a polynomial curve");
  nurbs::NurbsCurve curve(static_cast<int>(degree), std::move(knots), std::move(cps.points), std::move(weights),
                          cps.dimension);
  return CurveFile{std::move(curve), CurveKind::Nurbs, std::nullopt, std::nullopt};
}

CurveFile read_bezier(const Json& doc) {
  const JsonPath root;
  json::PointArray cps =
      json::get_points(json::require_member(doc, root, "control_points"), root_path("control_points"));
  const std::size_t n = cps.points.size();
  if (n < 2)
    throw Error(Errc::TooFewPoints,
                "control_points has " + std::to_string(n) + " point(s); a Bézier curve needs at least 2",
                {.field = "control_points"});
  std::vector<double> weights;
  if (const Json* w = json::optional_member(doc, "weights"))
    weights = json::get_nonempty_number_array(
        *w, root_path("weights"), "give one weight per control point, or leave \"weights\" out for a polynomial curve");
  // Degree n - 1 on [0, 1]: n zeros followed by n ones (the Bernstein basis).
  std::vector<double> knots(2 * n, 0.0);
  for (std::size_t i = n; i < 2 * n; ++i) knots[i] = 1.0;
  if (n - 1 > static_cast<std::size_t>(nurbs::kMaxDegree))
    throw Error(Errc::InvalidDegree,
                "control_points has " + std::to_string(n) + " points: degree " + std::to_string(n - 1) +
                    " exceeds the largest supported degree " + std::to_string(nurbs::kMaxDegree),
                {.field = "control_points"});
  nurbs::NurbsCurve curve(static_cast<int>(n - 1), std::move(knots), std::move(cps.points), std::move(weights),
                          cps.dimension);
  return CurveFile{std::move(curve), CurveKind::Bezier, std::nullopt, std::nullopt};
}

CurveFile read_interpolated(const Json& doc) {
  const JsonPath root;
  InterpolationInputs in;
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
  nurbs::NurbsCurve curve = resolve(in, from_knots ? "knots" : "parameters");
  return CurveFile{std::move(curve), CurveKind::Interpolated, std::move(in), std::nullopt};
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
  }
  return "natural";
}

nurbs::InterpolationOptions InterpolationInputs::options() const {
  nurbs::InterpolationOptions o;
  o.parameterisation = parameterisation;
  o.parameters = parameters;
  o.start = start;
  o.end = end;
  o.dimension = dimension;
  return o;
}

nurbs::NurbsCurve resolve(const InterpolationInputs& inputs, std::string_view parameters_field) {
  try {
    return nurbs::interpolate_cubic(inputs.points, inputs.options());
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

namespace {
CurveFile read_law(const Json& doc) {
  const JsonPath root;
  LawCurve lc;
  lc.expression = json::get_string(json::require_member(doc, root, "expression"), root_path("expression"));
  if (const Json* p = json::optional_member(doc, "parameter"))
    lc.parameter = json::get_string(*p, root_path("parameter"));
  const std::vector<double> dom =
      json::get_number_array(json::require_member(doc, root, "domain"), root_path("domain"));
  if (dom.size() != 2 || !(dom[0] < dom[1]))
    throw Error(Errc::ParseError, "domain must be [start, end] with start < end, got " + json::describe(doc["domain"]),
                {.field = "domain"});
  lc.domain = {dom[0], dom[1]};
  law::ParseOptions options;
  options.parameters = {lc.parameter};
  law::Context ctx;
  try {
    options.validate();
    lc.law = law::parse(lc.expression, ctx, options);
  } catch (const Error& e) {
    ErrorWhere where = e.where();
    where.field = "expression";
    throw Error(Errc::ParseError, "expression: " + e.message(), where);
  }
  if (lc.law.dimension() == 1)
    throw Error(Errc::ParseError, "expression: a law curve must be a 2- or 3-vector (vec(x, y[, z])), got a scalar",
                {.field = "expression"});
  law::ToNurbsOptions to;
  to.tolerance = kLawCurveTolerance;
  law::ToNurbsResult approx = [&] {
    try {
      return law::to_nurbs(lc.law, lc.parameter, lc.domain.start, lc.domain.end, to);
    } catch (const Error& e) {
      // A law undefined inside its own domain is a bad file, not a numerical failure.
      if (e.code() != Errc::NumericalFailure || e.message().find("undefined") == std::string::npos) throw;
      throw Error(Errc::InvalidArgument,
                  "domain: " + e.message() + " (inside the domain [" + format_number(lc.domain.start) + ", " +
                      format_number(lc.domain.end) + "])",
                  {.field = "domain"});
    }
  }();
  lc.approximation_deviation = approx.max_deviation;
  return CurveFile{std::move(approx.curve), CurveKind::Law, std::nullopt, std::move(lc)};
}
}  // namespace

Json law_to_json(const LawCurve& curve) {
  Json doc = Json::object();
  doc["kind"] = "law";
  doc["expression"] = curve.expression;
  doc["parameter"] = curve.parameter;
  doc["domain"] = Json::array({curve.domain.start, curve.domain.end});
  return doc;
}

CurveFile curve_from_json(const Json& document) {
  if (!document.is_object()) json::type_error(document, JsonPath{}, "a JSON object with a \"kind\" member");
  const std::string kind = json::get_string(json::require_member(document, JsonPath{}, "kind"), root_path("kind"));
  if (kind == "nurbs") return read_nurbs(document);
  if (kind == "bezier") return read_bezier(document);
  if (kind == "interpolated") return read_interpolated(document);
  if (kind == "law") return read_law(document);
  throw Error(Errc::ParseError,
              "kind = " + json::quote(kind) +
                  " is not a known curve kind (expected \"nurbs\", \"bezier\", \"interpolated\" or \"law\")",
              {.field = "kind"});
}

CurveFile parse_curve_json(std::string_view text) { return curve_from_json(json::parse_json_text(text, "curve file")); }

CurveFile read_curve_file(const std::filesystem::path& path) { return parse_curve_json(read_text_file(path)); }

Json curve_to_json(const nurbs::NurbsCurve& curve) {
  Json doc = Json::object();
  doc["kind"] = "nurbs";
  doc["degree"] = curve.degree();
  doc["knots"] = numbers_to_json(curve.knots().values());
  doc["control_points"] = points_to_json(curve.control_points(), curve.dimension());
  doc["weights"] = curve.is_rational() ? numbers_to_json(curve.weights()) : Json(nullptr);
  return doc;
}

Json interpolated_to_json(const InterpolationInputs& inputs) {
  Json doc = Json::object();
  doc["kind"] = "interpolated";
  doc["points"] = points_to_json(inputs.points, inputs.dimension);
  doc["parameterisation"] = std::string(parameterisation_name(inputs.parameterisation));
  if (!inputs.parameters.empty()) doc["parameters"] = numbers_to_json(inputs.parameters);
  doc["start"] = end_condition_to_json(inputs.start, inputs.dimension);
  doc["end"] = end_condition_to_json(inputs.end, inputs.dimension);
  return doc;
}

std::string to_file_text(const Json& document) { return format_json(document); }

void write_curve_file(const std::filesystem::path& path, const nurbs::NurbsCurve& curve) {
  write_file_atomically(path, to_file_text(curve_to_json(curve)));
}

void write_interpolated_file(const std::filesystem::path& path, const InterpolationInputs& inputs) {
  write_file_atomically(path, to_file_text(interpolated_to_json(inputs)));
}

}  // namespace hula::io
