// SPDX-License-Identifier: MIT
// POST /api/reconstruct {"kappa", "tau", "length", "start_point"?,
// "start_frame"? {"tangent", "normal"}, "tolerance"?, "fit_tolerance"?, "at"?}
// → {"points": [{"s", "position", "T", "N", "B"}], "curve": the fitted NURBS
// as a curve file, "max_deviation", "integration", "fit"}: the curve with
// curvature κ(s) and torsion τ(s) (intrinsic::reconstruct, thesis 8.2.2), as
// `hula reconstruct` prints it, with its work bounded
// (intrinsic::kFrontEndMaxSteps, kFrontEndMaxSegments) so that a rough law is
// answered with an error naming kappa and the limit, never minutes of work.
//
// POST /api/documents/{name}/entities/{label}/curvature-edit {"kappa", "target"?,
// "tau"?, "hold"?, "max_handles_factor"?, "fit_tolerance"?} → {"revision",
// "changes", "edit"}: design by curvature on the entity's curve
// (oli::edit_curvature, one "edit curvature" undo step; the request and report
// codecs are io/reconstruction_json.hpp): its κ profile replaced or changed,
// its ends, end tangents (and, with "hold": "curvature", end curvatures) kept.
#include <optional>

#include "hula/intrinsic/natural_equations.hpp"
#include "hula/io/json_read.hpp"
#include "hula/io/reconstruction_json.hpp"
#include "hula/law/parser.hpp"
#include "hula/oli/curvature_edit.hpp"
#include "hula/server/routes/routes.hpp"

namespace hula::server::routes {

namespace {

namespace json = io::json;

law::Law read_law(const Json& body, const char* field, law::Context& ctx) {
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

Json vec_json(const Vec3& v) { return Json::array({v.x, v.y, v.z}); }

Response reconstruct(const Request& request) {
  const Json body = request.json();
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
  intrinsic::ReconstructionOptions options;
  if (const Json* t = json::optional_member(body, "tolerance"))
    options.tolerance = json::get_number(*t, json::root_path("tolerance"));
  options.max_steps = intrinsic::kFrontEndMaxSteps;
  intrinsic::NurbsFitOptions fit_options;
  fit_options.tolerance = intrinsic::kFrontEndFitTolerance;
  fit_options.relative = true;
  fit_options.max_segments = intrinsic::kFrontEndMaxSegments;
  if (const Json* t = json::optional_member(body, "fit_tolerance")) {
    fit_options.tolerance = json::get_number(*t, json::root_path("fit_tolerance"));
    try {
      fit_options.validate();
    } catch (const Error& e) {
      throw Error(e.code(), "fit_" + e.message(), ErrorWhere{.field = "fit_tolerance"});
    }
  }
  const intrinsic::IntrinsicCurve curve = intrinsic::reconstruct(kappa, tau, "s", length, start, options);
  std::vector<double> ss;
  if (const Json* at = json::optional_member(body, "at"))
    ss = json::get_number_array(*at, json::root_path("at"));
  else
    for (int i = 0; i <= 4; ++i) ss.push_back(i == 4 ? length : length * i / 4.0);
  Json points = Json::array();
  for (const intrinsic::FramePoint& p : curve.evaluate(ss)) {
    Json j = Json::object();
    j["s"] = p.s;
    j["position"] = vec_json(p.position);
    j["T"] = vec_json(p.tangent);
    j["N"] = vec_json(p.normal);
    j["B"] = vec_json(p.binormal);
    points.push_back(std::move(j));
  }
  const intrinsic::NurbsFitResult fit = intrinsic::fit_nurbs_converged(curve, fit_options);
  Json out = Json::object();
  out["points"] = std::move(points);
  out["curve"] = io::curve_to_json(fit.curve);
  out["max_deviation"] = fit.max_deviation;
  out["integration"] = io::integration_summary(curve);
  out["fit"] = io::fit_summary(fit);
  return json_response(200, out);
}

}  // namespace

void add_reconstruct(Router& router, const Context& context) {
  router.add("POST", "/api/reconstruct", reconstruct);
  DocumentRegistry& docs = context.documents;
  router.add("POST", "/api/documents/{name}/entities/{label}/curvature-edit", [&docs](const Request& request) {
    const io::CurvatureEditRequest edit = io::curvature_edit_request_from_json(request.json());
    const auto [doc, label] = entity_of(docs, request);
    std::optional<studies::CurvatureEditResult> result;
    const oli::Outcome o = doc->write([&](oli::Document& d) {
      return d.transact("edit curvature",
                        [&](oli::Edit& e) { result = oli::edit_curvature(e, label, edit.edit, edit.options); });
    });
    Json out = Json::parse(outcome_response(o, 200).body);  // rethrows the error of a refused edit
    out["edit"] = io::curvature_edit_to_json(*result);
    return json_response(200, out);
  });
}

}  // namespace hula::server::routes
