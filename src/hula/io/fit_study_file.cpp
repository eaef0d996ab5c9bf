// SPDX-License-Identifier: MIT
// Codec of the "fit" study (see fit_study_file.hpp).
#include "hula/io/fit_study_file.hpp"

#include <string>

#include "hula/core/error.hpp"
#include "hula/io/json_read.hpp"
#include "hula/io/points_file.hpp"

namespace hula::io {

namespace jr = json;

FitStudy fit_study_from_json(const StudyDocument& document, const PathResolver& resolver) {
  const Json& body = document.body;
  check_members(body, {"points", "class", "tolerance", "degree", "min_degree", "ordered", "fair"});
  FitStudy s;
  s.header = document.header;
  s.header.kind = "fit";
  const Json& pts = jr::require_member(body, jr::root_path(""), "points");
  if (pts.is_string()) {
    s.points_file = pts.get<std::string>();
    s.points = read_points_file(resolver(s.points_file, "points")).points;
  } else {
    s.points = jr::get_points(pts, jr::root_path("points")).points;
  }
  const Json* cls = jr::optional_member(body, "class");
  const Json* tol = jr::optional_member(body, "tolerance");
  if (cls != nullptr && tol != nullptr)
    throw Error(Errc::ParseError, "class, tolerance: give one of them, not both", ErrorWhere{.field = "tolerance"});
  if (cls != nullptr) {
    const std::string c = jr::get_string(*cls, jr::root_path("class"));
    if (c == "A")
      s.options.tolerance = studies::kClassATolerance;
    else if (c == "B")
      s.options.tolerance = studies::kClassBTolerance;
    else
      throw Error(Errc::ParseError, "class: expected \"A\" or \"B\", got " + jr::quote(c),
                  ErrorWhere{.field = "class"});
  }
  if (tol != nullptr) s.options.tolerance = jr::get_number(*tol, jr::root_path("tolerance"));
  if (const Json* d = jr::optional_member(body, "degree"))
    s.options.degree = static_cast<int>(jr::get_integer(*d, jr::root_path("degree"), 3, 9));
  if (const Json* d = jr::optional_member(body, "min_degree"))
    s.options.min_degree = static_cast<int>(jr::get_integer(*d, jr::root_path("min_degree"), 3, 9));
  auto flag = [&](std::string_view name, bool fallback) {
    const Json* v = jr::optional_member(body, name);
    if (v == nullptr) return fallback;
    if (!v->is_boolean()) jr::type_error(*v, jr::root_path(name), "true or false");
    return v->get<bool>();
  };
  s.options.ordered = flag("ordered", false);
  s.options.fair = flag("fair", true);
  s.options.validate();
  return s;
}

Json fit_study_to_json(const FitStudy& study) {
  Json j = header_to_json(study.header);
  if (!study.points_file.empty()) {
    j["points"] = study.points_file;
  } else {
    Json a = Json::array();
    for (const Vec3& p : study.points) a.push_back(Json::array({p.x, p.y, p.z}));
    j["points"] = a;
  }
  j["tolerance"] = study.options.tolerance;
  j["degree"] = study.options.degree;
  j["min_degree"] = study.options.min_degree;
  j["ordered"] = study.options.ordered;
  j["fair"] = study.options.fair;
  return j;
}

namespace {

Json report_to_json(const studies::ScanCurveReport& r) {
  Json j = Json::object();
  j["max_deviation"] = r.max_deviation;
  j["mean_deviation"] = r.mean_deviation;
  j["control_points"] = r.control_points;
  j["inflections"] = r.inflections;
  j["curvature_extrema"] = r.curvature_extrema;
  j["curvature_variation"] = r.curvature_variation;
  j["bending"] = r.bending;
  return j;
}

}  // namespace

Json fit_result_to_json(const studies::ScanFitResult& result, const studies::ScanFitOptions& options) {
  Json j = Json::object();
  j["tolerance"] = options.tolerance;
  j["points"] = result.deviations.size();
  j["kept"] = result.order.size();
  j["strays"] = result.strays;
  j["noise_scale"] = result.noise_scale;
  j["biweight_scale"] = result.biweight_scale;
  j["smoothing"] = result.smoothing;
  j["fits"] = result.fits;
  j["ordering"] = studies::order_source_name(result.ordering);
  j["closed"] = result.closed;
  j["degree"] = result.faired.degree();
  j["before"] = report_to_json(result.before);
  j["after"] = report_to_json(result.after);
  return j;
}

}  // namespace hula::io
