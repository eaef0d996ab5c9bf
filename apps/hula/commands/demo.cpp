// SPDX-License-Identifier: MIT
// `hula demo` (the default command): the thesis's example curves and their
// analysis as JSON —
//  * 7.1.2 / eq. 29: the chord-length cubic spline through (0,0,0), (40,25,0),
//    (80,-25,0), (120,0,0) with its cumulative chord lengths 47.17, 111.20, 158.37,
//    and the asymmetric variant with (80,-40,0);
//  * 7.1.2: the 6-point control polygon as a cubic B-spline with the ACIS knots
//    {0,0,0,0.33,0.66,1,1,1}, and with the double knot {0,0,0,0.33,0.33,1,1,1},
//    whose left/right derivative table at the double knot reproduces the layout
//    of Table 3 (C1 but not C2 there).
#include <cmath>

#include "commands/common.hpp"
#include "hula/core/error.hpp"
#include "hula/diffgeom/analysis.hpp"
#include "hula/io/curve_analysis_json.hpp"

namespace hula::cli {

namespace {

double round2(double x) { return std::round(x * 100.0) / 100.0; }

Json points_json(std::span<const Vec3> points) {
  Json a = Json::array();
  for (const Vec3& p : points) a.push_back(vec_to_json(p, 3));
  return a;
}

// The description of the curve with its largest curvature (diffgeom::analyse_curve's features).
Json curve_analysis(const nurbs::NurbsCurve& curve) {
  Json o = analyse(curve);
  diffgeom::AnalysisOptions options;
  options.samples = 2;
  options.features = true;
  const diffgeom::MaximumCurvature m = diffgeom::analyse_curve(curve, options).features->maximum_curvature;
  o["maximum_curvature"] = io::maximum_curvature_to_json(m);
  return o;
}

Json interpolation_example(const std::string& name, const std::vector<Vec3>& points) {
  const std::vector<double> chords = nurbs::cumulative_chord_lengths(points);
  nurbs::InterpolationOptions options;
  options.parameterisation = nurbs::Parameterisation::ChordLength;
  const nurbs::NurbsCurve curve = nurbs::interpolate_cubic(points, options);
  Json o = Json::object();
  o["name"] = name;
  o["points"] = points_json(points);
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
  o["curve"] = curve_analysis(curve);
  return o;
}

// The continuity at knot u as every door reports it (diffgeom::analyse_curve's knots, io::continuity_to_json).
Json continuity_at(const nurbs::NurbsCurve& curve, double u) {
  diffgeom::AnalysisOptions options;
  options.samples = 2;
  options.features = true;
  const diffgeom::CurveAnalysis analysis = diffgeom::analyse_curve(curve, options);
  for (const diffgeom::Continuity& k : analysis.features->knots)
    if (k.t == u) return io::continuity_to_json(k);
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
    r["just_before"] = vec_to_json(left[k], 3);
    r["at"] = vec_to_json(left[k], 3);
    r["just_after"] = vec_to_json(right[k], 3);
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
  o["control_polygon"] = points_json(polygon);
  Json k = Json::array();
  for (double u : acis) k.push_back(u);
  o["acis_knots"] = std::move(k);
  o["curve"] = curve_analysis(curve);
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

int run_demo() {
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
  print_json(doc);
  return kExitOk;
}

Command add_demo(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("demo", "Analyse the thesis's example curves (default command)");
  return {sub, [] { return run_demo(); }};
}

}  // namespace hula::cli
