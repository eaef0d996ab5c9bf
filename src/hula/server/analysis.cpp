// SPDX-License-Identifier: MIT
// The viewport analysis of a curve (analysis.hpp).
#include "hula/server/analysis.hpp"

#include <cmath>
#include <optional>
#include <string_view>

#include "hula/diffgeom/continuity.hpp"
#include "hula/diffgeom/features.hpp"
#include "hula/diffgeom/frenet.hpp"
#include "hula/io/json_read.hpp"
#include "hula/nurbs/arc_length.hpp"

namespace hula::server {

namespace {

namespace json = io::json;

Json number(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

Json vec(const Vec3& v) {
  if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return nullptr;
  return Json::array({v.x, v.y, v.z});
}

diffgeom::FinKind fin_kind(const std::string& name, std::size_t index) {
  if (const std::optional<diffgeom::FinKind> k = diffgeom::fin_kind_from_name(name)) return *k;
  throw Error(Errc::InvalidOption,
              "fins[" + std::to_string(index) + "] = \"" + name +
                  "\" is not a fin (curvature, torsion, normal, binormal, bishop-u, bishop-v, combescure)",
              ErrorWhere{.field = "fins", .index = index});
}

}  // namespace

AnalysisRequest analysis_request_from_json(const Json& body) {
  const json::JsonPath root;
  json::reject_unknown_members(body, root, {"samples", "by", "fins", "scale", "features"});
  AnalysisRequest r;
  if (const Json* n = json::optional_member(body, "samples"))
    r.samples = static_cast<int>(json::get_integer(*n, json::root_path("samples"), 2, 100000));
  if (const Json* by = json::optional_member(body, "by")) {
    const std::string b = json::get_string(*by, json::root_path("by"));
    if (b == "parameter")
      r.by = SampleBy::Parameter;
    else if (b == "arclength")
      r.by = SampleBy::ArcLength;
    else
      throw Error(Errc::InvalidOption, "by = \"" + b + "\" is not \"parameter\" or \"arclength\"",
                  ErrorWhere{.field = "by"});
  }
  if (const Json* fins = json::optional_member(body, "fins")) {
    const Json& list = json::get_array(*fins, json::root_path("fins"));
    for (std::size_t i = 0; i < list.size(); ++i)
      r.fins.push_back(fin_kind(json::get_string(list[i], json::root_path("fins").element(i)), i));
  }
  if (const Json* s = json::optional_member(body, "scale")) r.scale = json::get_number(*s, json::root_path("scale"));
  if (const Json* f = json::optional_member(body, "features")) {
    if (!f->is_boolean()) json::type_error(*f, json::root_path("features"), "true or false");
    r.features = f->get<bool>();
  }
  return r;
}

Json analyse(const curve::Curve& subject, const AnalysisRequest& request) {
  const nurbs::NurbsCurve& curve = subject.nurbs();
  const auto n = static_cast<std::size_t>(request.samples);
  const nurbs::Interval domain = curve.domain();
  std::vector<double> ts(n);
  if (request.by == SampleBy::Parameter) {
    for (std::size_t i = 0; i < n; ++i)
      ts[i] = i + 1 == n ? domain.end
                         : domain.start + domain.length() * static_cast<double>(i) / static_cast<double>(n - 1);
  } else {
    const double length = nurbs::arc_length(curve);
    for (std::size_t i = 0; i < n; ++i)
      ts[i] = i == 0 ? domain.start
              : i + 1 == n
                  ? domain.end
                  : nurbs::parameter_at_length(curve, length * static_cast<double>(i) / static_cast<double>(n - 1));
  }
  std::vector<diffgeom::FrenetPoint> frames(n);
  diffgeom::frenet(curve, ts, frames);
  Json t = Json::array(), points = Json::array(), T = Json::array(), N = Json::array(), B = Json::array();
  Json kappa = Json::array(), tau = Json::array(), speed = Json::array();
  for (const diffgeom::FrenetPoint& f : frames) {
    t.push_back(f.t);
    points.push_back(vec(f.position));
    T.push_back(f.tangent_defined ? vec(f.tangent) : Json(nullptr));
    N.push_back(f.frame_defined ? vec(f.normal) : Json(nullptr));
    B.push_back(f.frame_defined ? vec(f.binormal) : Json(nullptr));
    kappa.push_back(f.tangent_defined ? number(f.curvature) : Json(nullptr));
    tau.push_back(f.torsion_defined ? number(f.torsion) : Json(nullptr));
    speed.push_back(number(f.speed));
  }
  Json out = Json::object();
  out["t"] = std::move(t);
  out["points"] = std::move(points);
  Json frames_json = Json::object();
  frames_json["T"] = std::move(T);
  frames_json["N"] = std::move(N);
  frames_json["B"] = std::move(B);
  out["frames"] = std::move(frames_json);
  out["curvature"] = std::move(kappa);
  out["torsion"] = std::move(tau);
  out["speed"] = std::move(speed);
  Json fins = Json::array();
  for (const diffgeom::FinKind kind : request.fins) {
    diffgeom::FinOptions o;
    o.kind = kind;
    o.scale = request.scale;
    o.density = request.samples;
    const diffgeom::Fins f = diffgeom::fins(subject, o);  // exact from the law of a law curve
    Json comb = Json::object();
    comb["kind"] = std::string(diffgeom::fin_kind_name(kind));
    Json ft = Json::array(), base = Json::array(), tip = Json::array();
    for (std::size_t i = 0; i < f.t.size(); ++i) {
      ft.push_back(f.t[i]);
      base.push_back(vec(f.base[i]));
      tip.push_back(f.defined[i] ? vec(f.tip[i]) : Json(nullptr));
    }
    comb["t"] = std::move(ft);
    comb["base"] = std::move(base);
    comb["tip"] = std::move(tip);
    fins.push_back(std::move(comb));
  }
  out["fins"] = std::move(fins);
  if (request.features) {
    Json features = Json::object();
    Json inflections = Json::array();
    for (const diffgeom::Feature& f : diffgeom::inflections(curve)) {
      Json j = Json::object();
      j["t"] = f.t;
      j["point"] = vec(f.position);
      inflections.push_back(std::move(j));
    }
    features["inflections"] = std::move(inflections);
    Json extrema = Json::array();
    for (const diffgeom::Feature& f : diffgeom::curvature_extrema(curve)) {
      Json j = Json::object();
      j["kind"] = std::string(diffgeom::feature_kind_name(f.kind));
      j["t"] = f.t;
      j["point"] = vec(f.position);
      j["curvature"] = number(f.curvature);
      extrema.push_back(std::move(j));
    }
    features["curvature_extrema"] = std::move(extrema);
    Json knots = Json::array();
    for (const diffgeom::Continuity& c : diffgeom::knot_continuity(curve)) {
      Json j = Json::object();
      j["t"] = c.t;
      j["multiplicity"] = c.multiplicity;
      j["parametric"] = c.parametric;
      j["geometric"] = c.geometric;
      j["tangent_angle"] = number(c.tangent_angle);
      knots.push_back(std::move(j));
    }
    features["knots"] = std::move(knots);
    out["features"] = std::move(features);
  }
  return out;
}

}  // namespace hula::server
