// SPDX-License-Identifier: MIT
// Summaries of a reconstruction and its fit (reconstruction_json.hpp).
#include "hula/io/reconstruction_json.hpp"

#include <string>

#include "hula/core/error.hpp"
#include "hula/io/json_read.hpp"
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

nlohmann::json fit_summary(const intrinsic::NurbsFitResult& fit) {
  nlohmann::json j = nlohmann::json::object();
  j["control_points"] = fit.curve.control_points().size();
  j["segments"] = fit.segments;
  j["tolerance"] = fit.tolerance;
  j["max_deviation"] = fit.max_deviation;
  return j;
}

namespace {

// A law of s read from a member, errors naming the member (and the law's position).
law::Law read_law(const nlohmann::ordered_json& body, const char* field, law::Context& ctx) {
  const std::string text =
      json::get_string(json::require_member(body, json::JsonPath(), field), json::root_path(field));
  law::ParseOptions po;
  po.parameters = {"s"};
  try {
    return law::parse(text, ctx, po);
  } catch (const Error& e) {
    ErrorWhere where = e.where();
    where.field = field;
    throw Error(e.code(), std::string(field) + " '" + text + "': " + e.message(), where);
  }
}

}  // namespace

CurvatureEditRequest curvature_edit_request_from_json(const nlohmann::ordered_json& body) {
  const json::JsonPath root;
  json::reject_unknown_members(body, root, {"kappa", "target", "tau", "hold", "max_handles_factor"});
  law::Context ctx;
  CurvatureEditRequest r;
  r.edit.curvature = read_law(body, "kappa", ctx);
  if (const nlohmann::ordered_json* t = json::optional_member(body, "target")) {
    const std::string name = json::get_string(*t, json::root_path("target"));
    if (name == "curvature")
      r.edit.target = studies::CurvatureTarget::Curvature;
    else if (name == "change")
      r.edit.target = studies::CurvatureTarget::Change;
    else
      throw Error(Errc::InvalidArgument, "target = \"" + name + "\": expected \"curvature\" or \"change\"",
                  ErrorWhere{.field = "target"});
  }
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
