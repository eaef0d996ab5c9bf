// SPDX-License-Identifier: MIT
// Summaries of a reconstruction and its fit (reconstruction_json.hpp).
#include "hula/io/reconstruction_json.hpp"

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

}  // namespace hula::io
