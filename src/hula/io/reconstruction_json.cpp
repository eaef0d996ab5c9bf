// SPDX-License-Identifier: MIT
// Summaries of a reconstruction and its fit (reconstruction_json.hpp).
#include "hula/io/reconstruction_json.hpp"

#include <string>

#include "hula/core/error.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/json_read.hpp"
#include "hula/io/reconstruction_answer.hpp"
#include "hula/law/parser.hpp"

namespace hula::io {

nlohmann::json integration_summary(const intrinsic::IntrinsicCurve& curve) {
  nlohmann::json j = nlohmann::json::object();
  switch (curve.method()) {
    case intrinsic::IntegrationKind::PlanarExactAngle:
      j["method"] = "planar-exact-angle";
      break;
    case intrinsic::IntegrationKind::PlanarNumericAngle:
      j["method"] = "planar-numeric-angle";
      break;
    case intrinsic::IntegrationKind::FrenetSerret:
      j["method"] = "frenet-serret";
      break;
  }
  j["steps"] = curve.nodes().size() - 1;
  j["rejected_steps"] = curve.rejected_steps();
  j["breakpoints"] = curve.breakpoints().size();
  return j;
}

law::Law natural_equation_law(const std::string& text, law::Context& context, const std::string& field,
                              const std::string& shown) {
  law::ParseOptions po;
  po.parameters = {"s"};
  try {
    return law::parse(text, context, po);
  } catch (const Error& e) {
    ErrorWhere where = e.where();
    where.field = field;
    throw Error(e.code(), shown + " '" + text + "': " + e.message(), where);
  }
}

nlohmann::ordered_json frame_points_json(std::span<const intrinsic::FramePoint> points) {
  const auto vec = [](const Vec3& v) { return nlohmann::ordered_json::array({v.x, v.y, v.z}); };
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const intrinsic::FramePoint& p : points)
    out.push_back(nlohmann::ordered_json{{"s", p.s},
                                         {"position", vec(p.position)},
                                         {"T", vec(p.tangent)},
                                         {"N", vec(p.normal)},
                                         {"B", vec(p.binormal)}});
  return out;
}

nlohmann::json fit_summary(const intrinsic::NurbsFitResult& fit) {
  nlohmann::json j = nlohmann::json::object();
  j["control_points"] = fit.curve.control_points().size();
  j["segments"] = fit.segments;
  j["tolerance"] = fit.tolerance;
  j["max_deviation"] = fit.max_deviation;
  return j;
}

namespace {

using Json = nlohmann::ordered_json;
namespace json = io::json;

law::Law read_law(const Json& body, const char* field, law::Context& ctx) {
  const std::string text =
      json::get_string(json::require_member(body, json::JsonPath(), field), json::root_path(field));
  return natural_equation_law(text, ctx, field, field);
}

}  // namespace

nlohmann::ordered_json reconstruction_request_json(const nlohmann::ordered_json& body) {
  const json::JsonPath root;
  json::reject_unknown_members(
      body, root, {"kappa", "tau", "length", "start_point", "start_frame", "tolerance", "fit_tolerance", "at"});
  law::Context ctx;
  const law::Law kappa = read_law(body, "kappa", ctx);
  const law::Law tau = read_law(body, "tau", ctx);
  const double length = json::get_number(json::require_member(body, root, "length"), json::root_path("length"));
  intrinsic::StartFrame start;
  if (const Json* p = json::optional_member(body, "start_point"))
    start.point = json::get_point(*p, json::root_path("start_point")).first;
  if (const Json* f = json::optional_member(body, "start_frame")) {
    const json::JsonPath path = json::root_path("start_frame");
    json::reject_unknown_members(*f, path, {"tangent", "normal"});
    start.tangent = json::get_point(json::require_member(*f, path, "tangent"), path.member("tangent")).first;
    start.normal = json::get_point(json::require_member(*f, path, "normal"), path.member("normal")).first;
  }
  ReconstructionQuery q{.kappa = kappa, .tau = tau, .length = length, .start = start};
  if (const Json* t = json::optional_member(body, "tolerance"))
    q.tolerance = json::get_number(*t, json::root_path("tolerance"));
  q.fit = front_end_fit_options(intrinsic::kFrontEndFitTolerance);
  if (const Json* t = json::optional_member(body, "fit_tolerance")) {
    q.fit.tolerance = json::get_number(*t, json::root_path("fit_tolerance"));
    try {
      q.fit.validate();
    } catch (const Error& e) {
      throw Error(e.code(), "fit_" + e.message(), ErrorWhere{.field = "fit_tolerance"});
    }
  }
  if (const Json* at = json::optional_member(body, "at")) q.at = json::get_number_array(*at, json::root_path("at"));
  ReconstructionAnswer answer = reconstruction_answer(q);
  Json out = Json::object();
  out["points"] = std::move(answer.points);
  out["curve"] = curve_to_json(answer.fit->curve);
  out["max_deviation"] = answer.fit->max_deviation;
  out["integration"] = std::move(answer.integration);
  out["fit"] = std::move(answer.fit_summary);
  return out;
}

CurvatureEditRequest curvature_edit_request_from_json(const nlohmann::ordered_json& body) {
  const json::JsonPath root;
  json::reject_unknown_members(body, root, {"kappa", "target", "tau", "hold", "max_handles_factor"});
  law::Context ctx;
  CurvatureEditRequest r;
  r.edit.curvature = read_law(body, "kappa", ctx);
  if (const Json* t = json::optional_member(body, "target"))
    r.edit.target = studies::curvature_target_from_name(json::get_string(*t, json::root_path("target")), "target");
  if (body.contains("tau")) r.edit.torsion = read_law(body, "tau", ctx);
  if (const nlohmann::ordered_json* h = json::optional_member(body, "hold"))
    r.options.hold = studies::end_hold_from_name(json::get_string(*h, json::root_path("hold")), "hold");
  if (const nlohmann::ordered_json* f = json::optional_member(body, "max_handles_factor"))
    r.options.max_handles_factor = json::get_number(*f, json::root_path("max_handles_factor"));
  r.options.reconstruction.max_steps = intrinsic::kFrontEndMaxSteps;
  r.options.validate();
  return r;
}

nlohmann::ordered_json curvature_edit_to_json(const studies::CurvatureEditResult& r) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  j["kind"] = std::string(r.curve.kind_name());
  j["handles_before"] = r.handles_before;
  j["handles_after"] = r.handles_after;
  j["planar"] = r.planar;
  j["length_before"] = r.length_before;
  j["length_after"] = r.length_after;
  j["reconstructed"] = r.reconstructed;
  j["max_curvature_deviation"] = r.max_curvature_deviation;
  j["mean_curvature_deviation"] = r.mean_curvature_deviation;
  j["reconstruction_max_deviation"] = r.reconstruction_max_deviation;
  j["reconstruction_mean_deviation"] = r.reconstruction_mean_deviation;
  j["iterations"] = r.iterations;
  j["start_point_error"] = r.start_point_error;
  j["end_point_error"] = r.end_point_error;
  j["start_tangent_error"] = r.start_tangent_error;
  j["end_tangent_error"] = r.end_tangent_error;
  j["start_curvature_error"] = r.start_curvature_error;
  j["end_curvature_error"] = r.end_curvature_error;
  j["inflections_before"] = r.inflections_before;
  j["inflections_after"] = r.inflections_after;
  j["seconds"] = r.seconds;
  return j;
}

}  // namespace hula::io
