// SPDX-License-Identifier: MIT
// One-shot answers about curve values (curve_queries.hpp).
#include "hula/io/curve_queries.hpp"

#include <array>
#include <cmath>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/diffgeom/analysis.hpp"
#include "hula/diffgeom/continuity.hpp"
#include "hula/diffgeom/energy.hpp"
#include "hula/diffgeom/planarity.hpp"
#include "hula/io/curve_analysis_json.hpp"
#include "hula/nurbs/arc_length.hpp"
#include "hula/nurbs/closest_point.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/nurbs/piece_evaluator.hpp"

namespace hula::io {

namespace {

using Description = DescriptionWriter::Computed;

Description describe(const nurbs::NurbsCurve& curve) {
  const nurbs::Interval dom = curve.domain();
  Description d;
  d.length = nurbs::arc_length(curve);
  // The end derivatives from the end spans alone (a million-span curve's cache is not built for two points).
  nurbs::PieceEvaluator ends(curve);
  std::array<Vec3, 2> at;
  ends.derivatives(std::span<const double>(&dom.start, 1), 1, at);
  d.start_derivative = at[1];
  ends.derivatives(std::span<const double>(&dom.end, 1), 1, at);
  d.end_derivative = at[1];
  // Unit tangents where |C'| is above rounding noise relative to the derivative's scale; null otherwise.
  const double scale = curve.model_size() / dom.length();
  d.start_unit = norm(d.start_derivative) > 1e-12 * scale;
  d.end_unit = norm(d.end_derivative) > 1e-12 * scale;
  d.planarity = planarity_to_json(diffgeom::planarity(curve));
  return d;
}

// The description's members, written once for a JSON value (JsonTree) and for streamed text (JsonText).
template <class W>
void write_description(W& w, const nurbs::NurbsCurve& curve, const Description& d) {
  const int dim = curve.dimension();
  const auto point = [&](const Vec3& p) {
    w.scalars(dim == 2 ? 2 : 3, [&](std::size_t i) { w.number(i == 0 ? p.x : i == 1 ? p.y : p.z); });
  };
  const auto numbers = [&](std::span<const double> values) {
    w.scalars(values.size(), [&](std::size_t i) { w.number(values[i]); });
  };
  const nurbs::Interval dom = curve.domain();
  w.member("degree").integer(curve.degree());
  w.member("dimension").integer(dim);
  w.member("rational").boolean(curve.is_rational());
  const std::array<double, 2> domain{dom.start, dom.end};
  w.member("domain");
  numbers(domain);
  w.member("knots");
  numbers(curve.knots().values());
  const std::span<const Vec3> poles = curve.control_points();
  w.member("control_points").containers(poles.size(), [&](std::size_t i) { point(poles[i]); });
  if (curve.is_rational()) {
    w.member("weights");
    numbers(curve.weights());
  } else {
    w.member("weights").null();
  }
  w.member("length").number(d.length);
  w.member("end_derivatives").begin_object();
  w.member("start");
  point(d.start_derivative);
  w.member("end");
  point(d.end_derivative);
  w.end_object();
  w.member("end_tangents").begin_object();
  for (const auto& [name, v, defined] :
       {std::tuple{"start", d.start_derivative, d.start_unit}, std::tuple{"end", d.end_derivative, d.end_unit}}) {
    w.member(name);
    if (defined)
      point(normalized(v));
    else
      w.null();
  }
  w.end_object();
  w.member("planarity").value(d.planarity);
}

}  // namespace

Json curve_description_json(const nurbs::NurbsCurve& curve) {
  const Description d = describe(curve);
  Json o;
  JsonTree w(o);
  w.begin_object();
  write_description(w, curve, d);
  w.end_object();
  return o;
}

DescriptionWriter::DescriptionWriter(const nurbs::NurbsCurve& curve) : curve_(curve), computed_(describe(curve)) {}

void DescriptionWriter::write_members(JsonText& w) const { write_description(w, curve_, computed_); }

namespace {

// The features of a curve as every door reports them (two samples: only the features are read).
diffgeom::CurveAnalysis features_of(const nurbs::NurbsCurve& curve) {
  diffgeom::AnalysisOptions options;
  options.samples = 2;
  options.features = true;
  return diffgeom::analyse_curve(curve, options);
}

}  // namespace

Json curve_description_with_maximum_curvature_json(const nurbs::NurbsCurve& curve) {
  Json o = curve_description_json(curve);
  o["maximum_curvature"] = maximum_curvature_to_json(features_of(curve).features->maximum_curvature);
  return o;
}

Json closest_answer(const curve::Curve& curve, std::span<const Vec3> points, std::span<const int> dimensions) {
  HULA_ASSERT(points.size() == dimensions.size(), "one dimension per point");
  const nurbs::NurbsCurve& c = curve.nurbs();
  const int dim = c.dimension();
  Json results = Json::array();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const nurbs::ClosestPointResult r = nurbs::closest_point(c, points[i]);
    Json j = Json::object();
    j["point"] = point_to_json(points[i], dimensions[i]);
    j["t"] = r.t;
    j["closest"] = point_to_json(r.point, dim);
    j["distance"] = r.distance;
    results.push_back(std::move(j));
  }
  Json doc = Json::object();
  if (curve.law() != nullptr) doc["law_stand_in_deviation"] = curve.approximation_deviation();
  doc["results"] = std::move(results);
  return doc;
}

namespace {

Json axes(const Vec3& v) { return Json::array({v.x, v.y, v.z}); }

Json number_or_null(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

Json order_name(char prefix, int k) { return k < 0 ? Json(nullptr) : Json(std::string(1, prefix) + std::to_string(k)); }

Json energy_json(const diffgeom::EnergyResult& r) {
  Json j = Json::object();
  j["value"] = r.value;
  j["error_estimate"] = r.error_estimate;
  j["converged"] = r.converged;
  return j;
}

}  // namespace

Json deviation_answer(const curve::Curve& a, const curve::Curve& b, const nurbs::DeviationOptions& options,
                      std::string_view mode_name) {
  const nurbs::DeviationResult r = nurbs::deviation(a.nurbs(), b.nurbs(), options);
  Json doc = Json::object();
  doc["mode"] = std::string(mode_name);
  doc["samples"] = r.samples;
  doc["max"] = r.max;
  doc["max_at"] = r.at;
  doc["mean"] = r.mean;
  doc["rms"] = r.rms;
  doc["mean_axis"] = axes(r.mean_axis);
  doc["max_axis"] = axes(r.max_axis);
  return doc;
}

Json join_continuity_answer(const curve::Curve& a, const curve::Curve& b) {
  const diffgeom::Continuity c = diffgeom::join_continuity(a.nurbs(), b.nurbs());
  const int dim = std::max(a.nurbs().dimension(), b.nurbs().dimension());
  Json left = Json::array(), right = Json::array();
  for (std::size_t k = 0; k < 4; ++k) {
    left.push_back(point_to_json(c.left[k], dim));
    right.push_back(point_to_json(c.right[k], dim));
  }
  Json doc = Json::object();
  doc["parametric"] = order_name('C', c.parametric);
  doc["geometric"] = order_name('G', c.geometric);
  doc["tangent_angle"] = number_or_null(c.tangent_angle);
  doc["curvature_left"] = number_or_null(c.curvature_left);
  doc["curvature_right"] = number_or_null(c.curvature_right);
  doc["left"] = std::move(left);
  doc["right"] = std::move(right);
  return doc;
}

int continuity_order_from_name(std::string_view text, int lowest, std::string_view field) {
  std::string_view digits = text;
  if (!digits.empty() && (digits.front() == 'G' || digits.front() == 'g')) digits.remove_prefix(1);
  if (digits.size() == 1 && digits.front() >= '0' && digits.front() <= '3') {
    const int k = digits.front() - '0';
    if (k >= lowest) return k;
  }
  throw Error(
      Errc::InvalidOption,
      std::string(field) + " must be one of G" + std::to_string(lowest) + " … G3, got '" + std::string(text) + "'",
      {.field = std::string(field)});
}

diffgeom::CurveEnd curve_end_from_name(std::string_view text, std::string_view field) {
  if (text == "start") return diffgeom::CurveEnd::Start;
  if (text == "end") return diffgeom::CurveEnd::End;
  throw Error(Errc::InvalidOption, std::string(field) + " must be start or end, got '" + std::string(text) + "'",
              {.field = std::string(field)});
}

CurveJoinAnswer match_answer(const curve::Curve& a, const curve::Curve& b, const diffgeom::MatchOptions& options) {
  diffgeom::MatchResult r = diffgeom::match_end(a.nurbs(), b.nurbs(), options);
  Json doc = Json::object();
  doc["requested"] = order_name('G', options.continuity);
  doc["geometric"] = order_name('G', r.continuity.geometric);
  doc["parametric"] = order_name('C', r.continuity.parametric);
  doc["tangent_angle"] = number_or_null(r.continuity.tangent_angle);
  doc["curvature_left"] = number_or_null(r.continuity.curvature_left);
  doc["curvature_right"] = number_or_null(r.continuity.curvature_right);
  doc["moved"] = r.moved;
  doc["inserted_knots"] = r.inserted_knots;
  doc["degree_elevation"] = r.degree_elevation;
  doc["target_parameter"] = r.target_parameter;
  doc["degree"] = r.curve.degree();
  doc["control_points"] = r.curve.control_points().size();
  return {std::move(r.curve), std::move(doc)};
}

CurveJoinAnswer blend_answer(const curve::Curve& a, const curve::Curve& b, const diffgeom::BlendOptions& options) {
  diffgeom::BlendResult r = diffgeom::blend(a.nurbs(), b.nurbs(), options);
  auto side = [](const diffgeom::Continuity& c) {
    Json j = Json::object();
    j["geometric"] = order_name('G', c.geometric);
    j["parametric"] = order_name('C', c.parametric);
    return j;
  };
  Json doc = Json::object();
  doc["requested"] = order_name('G', options.continuity);
  doc["start"] = side(r.start);
  doc["end"] = side(r.end);
  doc["scale"] = r.scale;
  doc["curvature_variation"] = energy_json(r.curvature_variation);
  doc["curvature_extrema"] = r.curvature_extrema;
  doc["degree"] = r.curve.degree();
  doc["control_points"] = r.curve.control_points().size();
  return {std::move(r.curve), std::move(doc)};
}

Json energy_answer(const curve::Curve& curve) {
  Json doc = Json::object();
  doc["bending"] = energy_json(diffgeom::bending_energy(curve.nurbs()));
  doc["curvature_variation"] = energy_json(diffgeom::curvature_variation_energy(curve.nurbs()));
  return doc;
}

namespace {

double round2(double x) { return std::round(x * 100.0) / 100.0; }

Json interpolation_example(const std::string& name, const std::vector<Vec3>& points) {
  const std::vector<double> chords = nurbs::cumulative_chord_lengths(points);
  nurbs::InterpolationOptions options;
  options.parameterisation = nurbs::Parameterisation::ChordLength;
  const nurbs::NurbsCurve curve = nurbs::interpolate_cubic(points, options);
  Json o = Json::object();
  o["name"] = name;
  o["points"] = points_to_json(points, 3);
  o["parameterisation"] = "chord";
  o["start"] = "natural";
  o["end"] = "natural";
  Json c = Json::array(), c2 = Json::array();
  for (double L : chords) {
    c.push_back(L);
    c2.push_back(round2(L));
  }
  o["cumulative_chord_lengths"] = std::move(c);
  o["cumulative_chord_lengths_rounded"] = std::move(c2);
  o["curve"] = curve_description_with_maximum_curvature_json(curve);
  return o;
}

// The continuity at knot u as every door reports it (diffgeom::analyse_curve's knots, continuity_to_json).
Json continuity_at(const nurbs::NurbsCurve& curve, double u) {
  const diffgeom::CurveAnalysis analysis = features_of(curve);
  for (const diffgeom::Continuity& k : analysis.features->knots)
    if (k.t == u) return continuity_to_json(k);
  throw Error(Errc::InvalidArgument, "no knot at t = " + format_number(u), {.field = "knot"});
}

// Table 3 layout: derivatives of order 0..3 just before (left limit), at (the
// left value, as ACIS evaluates at a knot and Table 3 shows), just after (right limit).
Json derivative_table(const nurbs::NurbsCurve& curve, double u) {
  const auto left = curve.derivatives(u, 3, {.side = nurbs::Side::Left});
  const auto right = curve.derivatives(u, 3, {.side = nurbs::Side::Right});
  static const char* const kNames[] = {"position", "first derivative", "second derivative", "third derivative"};
  Json rows = Json::array();
  for (std::size_t k = 0; k < 4; ++k) {
    Json r = Json::object();
    r["order"] = k;
    r["quantity"] = kNames[k];
    r["just_before"] = point_to_json(left[k], 3);
    r["at"] = point_to_json(left[k], 3);
    r["just_after"] = point_to_json(right[k], 3);
    rows.push_back(std::move(r));
  }
  Json o = Json::object();
  o["t"] = u;
  o["note"] =
      "just_before = limit from below (Side::Left), at = value at the knot from the left as in ACIS and "
      "thesis Table 3, just_after = limit from above (Side::Right)";
  o["rows"] = std::move(rows);
  return o;
}

Json polygon_example(const std::string& name, const std::vector<Vec3>& polygon, const std::vector<double>& acis,
                     bool with_table) {
  const nurbs::NurbsCurve curve(nurbs::KnotVector::from_acis(acis, 3), polygon);
  Json o = Json::object();
  o["name"] = name;
  o["control_polygon"] = points_to_json(polygon, 3);
  Json k = Json::array();
  for (double u : acis) k.push_back(u);
  o["acis_knots"] = std::move(k);
  o["curve"] = curve_description_with_maximum_curvature_json(curve);
  if (with_table) {
    o["derivative_table"] = derivative_table(curve, 0.33);
    o["continuity"] = continuity_at(curve, 0.33);
  } else {
    Json c = Json::array();
    for (double u : {0.33, 0.66}) c.push_back(continuity_at(curve, u));
    o["continuity"] = std::move(c);
  }
  return o;
}

}  // namespace

Json thesis_examples_json() {
  Json examples = Json::array();
  examples.push_back(interpolation_example("thesis 7.1.2: chord-length cubic spline, symmetric points",
                                           {{0, 0, 0}, {40, 25, 0}, {80, -25, 0}, {120, 0, 0}}));
  examples.push_back(interpolation_example("thesis 7.1.2: chord-length cubic spline, asymmetric points",
                                           {{0, 0, 0}, {40, 25, 0}, {80, -40, 0}, {120, 0, 0}}));
  const std::vector<Vec3> polygon = {{0, 0, 0}, {10, 25, 0}, {25, 25, 0}, {40, -10, 0}, {60, 0, 0}, {60, 10, 0}};
  examples.push_back(polygon_example("thesis 7.1.2: cubic B-spline, ACIS knots {0,0,0,0.33,0.66,1,1,1}", polygon,
                                     {0, 0, 0, 0.33, 0.66, 1, 1, 1}, false));
  examples.push_back(polygon_example("thesis 7.1.2 / Table 3: double knot {0,0,0,0.33,0.33,1,1,1}", polygon,
                                     {0, 0, 0, 0.33, 0.33, 1, 1, 1}, true));
  Json doc = Json::object();
  doc["demo"] = "HulaHoops thesis examples";
  doc["examples"] = std::move(examples);
  return doc;
}

}  // namespace hula::io
