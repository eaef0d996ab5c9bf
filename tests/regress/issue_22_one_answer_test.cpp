// SPDX-License-Identifier: MIT
// Regression tests of issue 22 (one engine behind every door), each named after the behaviour that failed:
//  - the server's analysis reported an inflection on a space curve (the sign of (r' × r'') · z), where
//    κ = 0.0045 and no inflection is defined;
//  - the server's analysis of a law helix reported its stand-in NURBS's knots (63) and curvature extrema
//    (270) where the helix has constant κ and no knot;
//  - a match study asking for distinct designs stored the last distinct design's curve as its result
//    instead of the best one's.
// Each goes through the code the doors call (io::analyse_curve_json, io::match_result_to_json).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hula/io/curve_analysis_json.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/match_study_file.hpp"
#include "hula/io/path_resolver.hpp"
#include "hula/io/study_file.hpp"
#include "hula/nurbs/closest_point.hpp"
#include "hula/studies/match_study.hpp"

namespace hula {
namespace {

using io::Json;

Json analysis_of(const curve::Curve& c) {
  return Json::parse(io::analyse_curve_json(c, io::analysis_request_defaults(), false, 1));
}

// checks the space Bézier of the issue: no inflection through the analysis every door writes
TEST(Issue22, SpaceCurveHasNoInflection) {
  const curve::Curve c = io::curve_from_json(Json::parse(
      R"({"kind": "bezier", "control_points": [[-155.86, 108.91, 0], [-20, 60, 0], [-4.14, 88.22, 0],
          [85.52, 0, 115.21]]})"));
  const Json a = analysis_of(c);
  EXPECT_FALSE(a["planarity"]["planar"].get<bool>());
  EXPECT_TRUE(a["features"]["inflections"].empty()) << a["features"]["inflections"].dump();
}

// checks the law helix vec(2 cos t, 2 sin t, t/2): no knot and no curvature or torsion extremum (κ = 2/4.25)
TEST(Issue22, LawHelixHasNoKnotsAndNoExtrema) {
  const curve::Curve c = curve::Curve::from_law("vec(2*cos(t), 2*sin(t), t/2)", "t", {0.0, 8 * std::numbers::pi});
  const Json a = analysis_of(c);
  EXPECT_TRUE(a["features"]["knots"].empty()) << a["features"]["knots"].size() << " knots";
  EXPECT_TRUE(a["features"]["curvature_extrema"].empty()) << a["features"]["curvature_extrema"].size();
  EXPECT_TRUE(a["features"]["torsion_extrema"].empty()) << a["features"]["torsion_extrema"].size();
  for (const Json& k : a["curvature"]) EXPECT_NEAR(k.get<double>(), 2 / 4.25, 1e-12);
}

// checks that the result curve of a GA match asked for distinct designs is the spline through the best points
// (it passes through every one of "best_points"), not through the last distinct design's
TEST(Issue22, MatchResultCurveIsTheBestDesigns) {
  const Json file = Json::parse(R"({
    "format": "hula-study", "version": 1, "study": "match-curvature", "seed": 3, "threads": 1,
    "points": [[0, 0], [5, 20], [40, 0]],
    "lower": [[0, 0], [30, 30], [0, 0]],
    "upper": [[0, 0], [35, 30], [0, 0]],
    "target": {"of_points": [[0, 0], [5, 20], [40, 0]], "mirror": true},
    "samples": 50, "method": "ga",
    "ga": {"algorithm": "real", "population": 20, "generations": 8, "distinct": 3, "distinct_radius": 0.05}})");
  io::MatchStudyFile study =
      io::match_study_from_json(io::study_from_json(file, "match-curvature"), io::relative_to("."));
  const studies::CurvatureMatch match(study.study.setup);
  const studies::MatchResult result = studies::run_curvature_match(match, study.study);
  ASSERT_GE(result.distinct.size(), 2u);
  const Json out = io::match_result_to_json(match, study, result);
  const curve::Curve c = io::curve_from_json(out["curve"]);
  const Json& best = out["best_points"];
  // The spline interpolates its data points at its data parameters: each best point is on the curve.
  for (std::size_t i = 0; i < best.size(); ++i) {
    const Vec3 p{best[i][0].get<double>(), best[i][1].get<double>(), 0.0};
    EXPECT_LT(nurbs::closest_point(c.nurbs(), p).distance, 1e-9) << "best point " << i << " is off the result curve";
  }
}

}  // namespace
}  // namespace hula
