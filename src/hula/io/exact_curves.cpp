// SPDX-License-Identifier: MIT
// Exact-curve answers (exact_curves.hpp).
#include "hula/io/exact_curves.hpp"

#include <cmath>
#include <utility>
#include <variant>

#include "hula/core/error.hpp"
#include "hula/diffgeom/frenet.hpp"
#include "hula/intrinsic/log_aesthetic.hpp"
#include "hula/intrinsic/natural_curve.hpp"
#include "hula/io/clothoid_json.hpp"
#include "hula/io/json_read.hpp"

namespace hula::io {

Json write_exact_curve(const std::string& path, const curve::Curve& curve, const std::optional<double>& to_nurbs) {
  Json j = Json::object();
  j["path"] = path;
  if (to_nurbs) {
    const intrinsic::CurveToNurbsResult n = intrinsic::to_nurbs(curve, *to_nurbs);
    write_curve_file(path, n.curve);
    j["kind"] = "nurbs";
    j["tolerance"] = n.tolerance;
    j["max_deviation"] = n.max_deviation;
    j["control_points"] = n.curve.control_points().size();
  } else {
    write_curve_file(path, curve);
    j["kind"] = std::string(curve.kind_name());
  }
  return j;
}

curve::Curve natural_equation_curve(const curve::NaturalData& data) {
  return intrinsic::natural_curve(data, curve::kApproximationTolerance);
}

namespace {

// The point, tangent angle and curvature at arc length s along consecutive segments; `index` is the
// position of s in the request's `at`, for the error.
Json clothoid_sample(const std::vector<intrinsic::ClothoidSegment>& segments, double s, std::size_t index) {
  double total = 0.0;
  for (const auto& c : segments) total += c.length;
  if (!(s >= 0.0 && s <= total))
    throw Error(Errc::OutOfDomain, "--at " + format_number(s) + " is outside [0, " + format_number(total) + "]",
                ErrorWhere{.field = "at", .index = index});
  double local = s;
  std::size_t j = 0;
  while (j + 1 < segments.size() && local > segments[j].length) local -= segments[j++].length;
  const intrinsic::ClothoidSegment& c = segments[j];
  Json p = Json::object();
  p["s"] = s;
  p["point"] = point_to_json(c.point(local), 2);
  p["theta"] = c.angle(local);
  p["kappa"] = c.curvature(local);
  return p;
}

}  // namespace

ClothoidAnswer clothoid_answer(const ClothoidRequest& q) {
  ClothoidAnswer out;
  out.json = Json::object();
  const bool curvatures = q.start_curvature && q.end_curvature;
  if (q.biarc && q.continuity)
    throw Error(Errc::InvalidArgument, "a biarc is G1 by construction: give no continuity with it",
                ErrorWhere{.field = "continuity"});
  if (!q.points.empty()) {
    intrinsic::ClothoidSplineOptions o;
    o.closed = q.closed;
    o.continuity = q.continuity.value_or(2);
    if (q.spline_start_angle) o.start_angle = q.start_angle;
    if (q.spline_end_angle) o.end_angle = q.end_angle;
    o.start_curvature = q.start_curvature;
    o.end_curvature = q.end_curvature;
    const intrinsic::ClothoidSplineResult r =
        q.biarc ? intrinsic::fit_biarc_spline(q.points, o) : intrinsic::fit_clothoid_spline(q.points, o);
    out.segments = r.segments;
    out.json["kind"] = q.biarc ? "biarc" : (o.continuity == 1 ? "g1" : "g2");
    out.json.update(clothoid_spline_to_json(out.segments));
    out.json["iterations"] = r.iterations;
    out.json["through"] = q.points.size();
    out.json["closed"] = q.closed;
  } else {
    if (q.closed)
      throw Error(Errc::InvalidArgument, "closed needs points: a Hermite problem between two points is open",
                  ErrorWhere{.field = "closed"});
    if (q.start_curvature.has_value() != q.end_curvature.has_value()) {
      const char* missing = q.start_curvature ? "end_curvature" : "start_curvature";
      throw Error(Errc::InvalidArgument,
                  std::string(missing) +
                      " is missing: the G2 Hermite problem between two points takes both end "
                      "curvatures (one alone is for a spline through points)",
                  ErrorWhere{.field = missing});
    }
    if (q.continuity && *q.continuity != (curvatures ? 2 : 1))
      throw Error(Errc::InvalidArgument,
                  curvatures ? std::string("both end curvatures ask for the G2 spline: continuity 1 is not possible")
                             : std::string("continuity 2 between two points needs both end curvatures"),
                  ErrorWhere{.field = "continuity"});
    if (q.biarc) {
      if (curvatures)
        throw Error(Errc::InvalidArgument, "a biarc takes no end curvatures (its arcs' curvatures follow)",
                    ErrorWhere{.field = "start_curvature"});
      const std::array<intrinsic::ClothoidSegment, 2> b =
          intrinsic::fit_biarc(q.start_point, q.start_angle, q.end_point, q.end_angle);
      out.segments.assign(b.begin(), b.end());
      out.json["kind"] = "biarc";
      out.json.update(clothoid_spline_to_json(out.segments));
      out.json["iterations"] = 0;
    } else if (curvatures) {
      const intrinsic::ClothoidG2Result r = intrinsic::fit_clothoid_g2(q.start_point, q.start_angle, *q.start_curvature,
                                                                       q.end_point, q.end_angle, *q.end_curvature);
      out.segments.assign(r.segments.begin(), r.segments.end());
      out.json["kind"] = "g2";
      out.json.update(clothoid_spline_to_json(out.segments));
      out.json["iterations"] = r.iterations;
    } else {
      const intrinsic::ClothoidG1Result r =
          intrinsic::fit_clothoid_g1(q.start_point, q.start_angle, q.end_point, q.end_angle);
      out.segments.push_back(r.segment);
      out.json["kind"] = "g1";
      out.json.update(clothoid_spline_to_json(out.segments));
      out.json["iterations"] = r.iterations;
    }
  }
  if (!q.at.empty()) {
    Json points = Json::array();
    for (std::size_t i = 0; i < q.at.size(); ++i) points.push_back(clothoid_sample(out.segments, q.at[i], i));
    out.json["points"] = std::move(points);
  }
  return out;
}

ClothoidRequest clothoid_request_from_json(const Json& body) {
  namespace json = io::json;
  const json::JsonPath root;
  json::reject_unknown_members(body, root,
                               {"points", "closed", "fit", "start_point", "start_angle", "end_point", "end_angle",
                                "start_curvature", "end_curvature", "at"});
  ClothoidRequest q;
  const auto number = [&](const char* field) -> std::optional<double> {
    const Json* v = json::optional_member(body, field);
    if (v == nullptr) return std::nullopt;
    return json::get_number(*v, json::root_path(field));
  };
  const auto point = [&](const char* field) {
    return json::get_point(json::require_member(body, root, field), json::root_path(field)).first;
  };
  if (const Json* f = json::optional_member(body, "fit")) {
    const std::string fit = json::get_string(*f, json::root_path("fit"));
    if (fit == "biarc")
      q.biarc = true;
    else if (fit == "g1" || fit == "g2")
      q.continuity = fit == "g1" ? 1 : 2;
    else
      throw Error(Errc::ParseError, "fit = \"" + fit + "\" must be \"g1\", \"g2\" or \"biarc\"",
                  ErrorWhere{.field = "fit"});
  }
  if (const Json* c = json::optional_member(body, "closed")) {
    if (!c->is_boolean()) json::type_error(*c, json::root_path("closed"), "true or false");
    q.closed = c->get<bool>();
  }
  const std::optional<double> a0 = number("start_angle"), a1 = number("end_angle");
  if (const Json* pts = json::optional_member(body, "points")) {
    q.points = json::get_points(*pts, json::root_path("points")).points;
    for (const char* field : {"start_point", "end_point"})
      if (json::optional_member(body, field) != nullptr)
        throw Error(Errc::ParseError, std::string(field) + " is for the Hermite problem: not with points",
                    ErrorWhere{.field = field});
    q.spline_start_angle = a0.has_value();
    q.spline_end_angle = a1.has_value();
  } else {
    q.start_point = point("start_point");
    q.end_point = point("end_point");
    if (!a0) (void)json::require_member(body, root, "start_angle");
    if (!a1) (void)json::require_member(body, root, "end_angle");
  }
  q.start_curvature = number("start_curvature");
  q.end_curvature = number("end_curvature");
  q.start_angle = a0.value_or(0.0);
  q.end_angle = a1.value_or(0.0);
  if (const Json* at = json::optional_member(body, "at")) q.at = json::get_number_array(*at, json::root_path("at"));
  return q;
}

curve::Curve clothoid_curve(const std::vector<intrinsic::ClothoidSegment>& segments, double tolerance) {
  return intrinsic::natural_curve(intrinsic::clothoid_natural_data(segments, tolerance),
                                  curve::kApproximationTolerance);
}

LogAestheticAnswer log_aesthetic_answer(const LogAestheticRequest& q) {
  const intrinsic::LogAestheticCurve la{q.alpha, q.rho0, q.lambda, q.length};
  intrinsic::StartFrame start;
  start.point = q.start_point;
  start.tangent = {std::cos(q.start_angle), std::sin(q.start_angle), 0.0};
  start.normal = {-std::sin(q.start_angle), std::cos(q.start_angle), 0.0};
  curve::Curve c = intrinsic::natural_curve(la.natural_data(start, q.tolerance), curve::kApproximationTolerance);
  const std::vector<double> ss = q.at ? *q.at : std::vector<double>{0.0, 0.5 * la.length, la.length};
  std::vector<diffgeom::FrenetPoint> frames(ss.size());
  diffgeom::frenet(c, ss, frames);
  Json doc = Json::object();
  doc["alpha"] = la.alpha;
  doc["rho0"] = la.rho0;
  doc["lambda"] = la.lambda;
  doc["length"] = la.length;
  doc["max_length"] = std::isfinite(la.max_length()) ? Json(la.max_length()) : Json(nullptr);
  doc["curvature"] = std::get<curve::NaturalData>(c.data()).curvature;
  Json points = Json::array();
  for (const diffgeom::FrenetPoint& p : frames) {
    Json j = Json::object();
    j["s"] = p.t;
    j["point"] = point_to_json(p.position, 2);
    j["tangent"] = point_to_json(p.tangent, 2);
    j["kappa"] = p.signed_curvature;
    // dκ/ds of the signed curvature: |κ|' carries the sign of κ (κ > 0 for every log-aesthetic segment here).
    j["kappa_prime"] = p.frame_defined ? Json(p.curvature_derivative) : Json(nullptr);
    points.push_back(std::move(j));
  }
  doc["points"] = std::move(points);
  return {std::move(c), std::move(doc)};
}

}  // namespace hula::io
