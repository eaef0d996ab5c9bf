// SPDX-License-Identifier: MIT
// Validity requirements (thesis ch. 10 further work: a curve that doubles back
// on itself is not a valid solution): the checks on closed forms (a cubic loop
// closing at 1/2 ∓ √15/10, a cubic with a cusp at t = 1/2, a parabola whose
// curvature peaks at its vertex), and the match-curvature study with and
// without them — its unconstrained optimum is a looped spline, which the
// required study refuses or avoids; each result's loop, or its absence, is
// confirmed by crossings of a dense polyline of the result curve, independent
// of nurbs::self_intersect. Also the "validity" member of the study file.
#include "hula/studies/validity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "hula/io/match_study_file.hpp"
#include "hula/io/validity_json.hpp"
#include "hula/nurbs/bezier.hpp"
#include "hula/studies/curvature_torsion_match.hpp"
#include "hula/studies/match_study.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::studies {
namespace {

nurbs::NurbsCurve bezier(std::vector<Vec3> P) { return nurbs::make_bezier(P, {}, 2); }

// Crossings of non-adjacent segments of a 2000-segment polyline of the curve (the independent loop count).
std::size_t polyline_self_crossings(const nurbs::NurbsCurve& c) {
  const int n = 2000;
  std::vector<Vec3> p(n + 1);
  for (int k = 0; k <= n; ++k)
    p[static_cast<std::size_t>(k)] =
        c.evaluate(k == n ? c.domain().end : c.domain().start + c.domain().length() * k / n);
  std::size_t count = 0;
  for (std::size_t i = 0; i + 1 < p.size(); ++i)
    for (std::size_t j = i + 2; j + 1 < p.size(); ++j) {
      const Vec3 d1 = p[i + 1] - p[i], d2 = p[j + 1] - p[j], r = p[j] - p[i];
      const double den = d1.x * d2.y - d1.y * d2.x;
      if (den == 0.0) continue;
      const double u = (r.x * d2.y - r.y * d2.x) / den, v = (r.x * d1.y - r.y * d1.x) / den;
      if (u >= 0.0 && u <= 1.0 && v >= 0.0 && v <= 1.0) ++count;
    }
  return count;
}

// checks: the loop P = (0,0), (2,1), (−1,1), (1,0) meets itself at x(s) = x(t) for s, t = 1/2 ∓ √15/10 (the roots of
// x(u) = 1/2 besides u = 1/2), at (1/2, 3/10).
TEST(Validity, LoopIsRefusedWhereItCloses) {
  const nurbs::NurbsCurve loop = bezier({{0, 0, 0}, {2, 1, 0}, {-1, 1, 0}, {1, 0, 0}});
  const ValidityCheck c = check_validity(loop, {.no_self_intersection = true});
  EXPECT_FALSE(c.valid());
  EXPECT_EQ(c.self_intersections, 1U);
  ASSERT_EQ(c.reasons.size(), 1U);
  EXPECT_NE(c.reasons[0].find("meets itself at (0.5, 0.3)"), std::string::npos) << c.reasons[0];
  EXPECT_NE(c.reasons[0].find("t = " + std::to_string(0.5 - std::sqrt(15.0) / 10).substr(0, 7)), std::string::npos)
      << c.reasons[0];
  EXPECT_EQ(polyline_self_crossings(loop), 1U);
  // Nothing required: nothing measured, valid.
  EXPECT_TRUE(check_validity(loop, {}).valid());
}

// checks: P = (0,0), (1,1), (0,1), (1,0) has C'(t) = 3((1 − 2t)², (1 − t)² − t²) = 0 at t = 1/2: a cusp, refused by
// min_speed; it does not meet itself (the cusp's tip is not a crossing).
TEST(Validity, CuspIsRefusedBySpeed) {
  const nurbs::NurbsCurve cusp = bezier({{0, 0, 0}, {1, 1, 0}, {0, 1, 0}, {1, 0, 0}});
  const ValidityCheck c = check_validity(cusp, {.no_self_intersection = true, .min_speed = 0.05});
  EXPECT_EQ(c.self_intersections, 0U);
  EXPECT_LT(c.speed_ratio, 1e-12);
  EXPECT_EQ(c.slowest_at, 0.5);
  ASSERT_EQ(c.reasons.size(), 1U);
  EXPECT_NE(c.reasons[0].find("cusp"), std::string::npos) << c.reasons[0];
  // A straight segment runs at its mean speed everywhere.
  EXPECT_NEAR(check_validity(bezier({{0, 0, 0}, {3, 4, 0}}), {.min_speed = 0.5}).speed_ratio, 1.0, 1e-15);
}

// checks: y = x² has its curvature maximum at the vertex: not monotone on [−1, 1], monotone on [0, 1] (closed form).
TEST(Validity, MonotoneCurvature) {
  const ValidityRequirements r{.monotone_curvature = true};
  const ValidityCheck whole = check_validity(bezier({{-1, 1, 0}, {0, -1, 0}, {1, 1, 0}}), r);
  EXPECT_EQ(whole.curvature_extrema, 1U);
  EXPECT_FALSE(whole.valid());
  EXPECT_TRUE(check_validity(bezier({{0, 0, 0}, {0.5, 0, 0}, {1, 1, 0}}), r).valid());
}

// checks: the constraint values follow the requirements asked, in order; bad requirements name the member.
TEST(Validity, ConstraintsAndErrors) {
  const ValidityRequirements r{.no_self_intersection = true, .min_speed = 0.05, .monotone_curvature = true};
  EXPECT_EQ(r.count(), 3U);
  ValidityCheck c;
  c.self_intersections = 2;
  c.speed_ratio = 0.01;
  c.curvature_extrema = 1;
  std::vector<double> g(3);
  validity_constraints(c, r, g);
  EXPECT_EQ(g, (std::vector<double>{2.0, 0.04, 1.0}));
  HULA_EXPECT_ERROR(ValidityRequirements{.min_speed = 1.0}.validate(), Errc::InvalidArgument, "validity.min_speed");
  HULA_EXPECT_ERROR(ValidityRequirements{.penalty = -1.0}.validate(), Errc::InvalidArgument, "validity.penalty");
}

// The study: points 3 and 4 of a looped spline may move; the target is the loop's own profile.
io::MatchStudyFile loop_study(const std::string& validity) {
  const std::string text = R"({"format": "hula-study", "version": 1, "study": "match-curvature", "seed": 3,
    "points": [[0, 0], [10, 0], [10, 6], [4, 2], [8, -4]],
    "lower": [[0, 0], [0, 0], [0, 0], [4, 4], [0, 0]], "upper": [[0, 0], [0, 0], [0, 0], [8, 4], [8, 0]],
    "target": {"of_points": [[0, 0], [10, 0], [10, 6], [4, 2], [8, -4]]},
    "samples": 100, "method": "ga", "ga": {"population": 30, "generations": 30})" +
                           validity + "}";
  return io::match_study_from_json(io::parse_study_json(text, "match-curvature"), io::relative_to("."));
}

std::size_t result_loops(const CurvatureMatch& match, const MatchResult& r) {
  std::vector<Vec3> p(match.setup().points.size());
  match.points_from(r.best, p);
  return polyline_self_crossings(match.sampler().curve(p));
}

// checks: unconstrained, the GA matches the target exactly with the looped spline; with no_self_intersection
// (feasibility rules, and a penalty) it returns a valid curve — no polyline crossing — at a larger distance.
TEST(ValidityStudy, GaAvoidsTheLoop) {
  const io::MatchStudyFile free = loop_study("");
  const CurvatureMatch free_match(free.study.setup);
  const MatchResult unconstrained = run_curvature_match(free_match, free.study);
  EXPECT_LT(unconstrained.after.mean, 1e-9);
  EXPECT_EQ(result_loops(free_match, unconstrained), 1U);
  EXPECT_FALSE(unconstrained.validity.has_value());
  for (const std::string handling : {"feasibility", "penalty"}) {
    const io::MatchStudyFile file =
        loop_study(R"(, "validity": {"no_self_intersection": true, "handling": ")" + handling + "\"}");
    const CurvatureMatch match(file.study.setup);
    const MatchResult r = run_curvature_match(match, file.study);
    ASSERT_TRUE(r.validity.has_value()) << handling;
    EXPECT_TRUE(r.validity->valid()) << handling;
    EXPECT_EQ(result_loops(match, r), 0U) << handling;
    EXPECT_GT(r.after.mean, 1e-3) << handling;
    const io::Json out = io::match_result_to_json(match, file, r);
    EXPECT_EQ(out["validity"]["valid"], true);
    EXPECT_TRUE(out.contains("curve"));
    EXPECT_FALSE(out.contains("refused"));
    EXPECT_EQ(out["study"]["validity"]["handling"], handling);
  }
}

// checks: where every design in the box loops (only point 3 moves, x ≤ 8), the result is refused with the reason,
// without a curve, and with a warning.
TEST(ValidityStudy, RefusesWhenNoValidDesignExists) {
  io::MatchStudyFile file = loop_study(R"(, "validity": {"no_self_intersection": true})");
  file.study.setup.lower[4] = file.study.setup.upper[4] = Vec3{};
  file.study.setup.upper[3] = {4, 4, 0};
  const CurvatureMatch match(file.study.setup);
  const MatchResult r = run_curvature_match(match, file.study);
  ASSERT_TRUE(r.validity.has_value());
  EXPECT_FALSE(r.validity->valid());
  EXPECT_GE(result_loops(match, r), 1U);
  const io::Json out = io::match_result_to_json(match, file, r);
  EXPECT_FALSE(out.contains("curve"));
  ASSERT_TRUE(out.contains("refused"));
  EXPECT_NE(out["refused"][0].get<std::string>().find("meets itself"), std::string::npos);
  EXPECT_NE(out["warnings"].back().get<std::string>().find("refused"), std::string::npos);
}

// checks: the two-objective problem carries the requirements as constraints: a looped start violates by 1.
TEST(ValidityStudy, TorsionProblemCarriesTheConstraints) {
  CurvatureMatchSetup s;
  s.dimension = 3;
  s.points = {{0, 0, 0}, {10, 0, 1}, {10, 6, 2}, {4, 2, 2}, {8, -4, 4}};
  s.lower = s.upper = std::vector<Vec3>(5, Vec3{});
  s.upper[3] = {1, 1, 1};
  s.start_tangent = Vec3{1, 0, 0};
  s.end_tangent = Vec3{0, -1, 0};
  s.target = Profile::from_samples(std::vector<double>{0.0, 1.0}, std::vector<double>{0.1, 0.1});
  s.torsion_target = s.target;
  s.validity = {.no_self_intersection = true, .min_speed = 0.01};
  const CurvatureMatch match(s);
  const optim::Problem p = curvature_torsion_problem(match);
  ASSERT_EQ(p.inequality_constraints, 2U);
  std::vector<double> values(4);
  p.evaluate(match.start_variables(), values);
  EXPECT_EQ(values[2], static_cast<double>(match.validity(match.start_variables()).self_intersections));
  EXPECT_LT(values[3], 0.0);  // a spline through spread points runs well above 1 % of its mean speed
}

// checks: the "validity" member reads and writes back; unknown members, bad names and ranges are refused by name.
TEST(ValidityJson, ReadsWritesAndRefuses) {
  const io::json::JsonPath path = io::json::root_path("validity");
  const ValidityRequirements r = io::validity_from_json(
      io::Json::parse(R"({"no_self_intersection": true, "min_speed": 0.05, "handling": "penalty", "penalty": 50})"),
      path);
  EXPECT_TRUE(r.no_self_intersection);
  EXPECT_EQ(r.min_speed, 0.05);
  EXPECT_EQ(r.handling, optim::ConstraintHandling::Penalty);
  EXPECT_EQ(r.penalty, 50.0);
  EXPECT_EQ(io::validity_from_json(io::validity_to_json(r), path).penalty, 50.0);
  HULA_EXPECT_ERROR(io::validity_from_json(io::Json::parse(R"({"no_loops": true})"), path), Errc::ParseError,
                    "no_loops");
  HULA_EXPECT_ERROR(io::validity_from_json(io::Json::parse(R"({"handling": "repair"})"), path), Errc::ParseError,
                    "validity.handling");
  HULA_EXPECT_ERROR(io::validity_from_json(io::Json::parse(R"({"min_speed": 2})"), path), Errc::InvalidArgument,
                    "validity.min_speed");
  HULA_EXPECT_ERROR(io::validity_from_json(io::Json::parse(R"({"no_self_intersection": 1})"), path), Errc::ParseError,
                    "no_self_intersection");
}

}  // namespace
}  // namespace hula::studies
