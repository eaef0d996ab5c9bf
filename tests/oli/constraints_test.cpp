// SPDX-License-Identifier: MIT
// Unit tests of the constraints stored with a curve (oli/constraints.hpp): each kind's residual against a closed
// form (distance to a line, the angle between directions, the curvature and length of a circle), the JSON form
// read back equal, and bad constraints refused naming the member.
#include "hula/oli/constraints.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/curve/curve.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::oli {
namespace {

// The segment from (0, 0, 0) to (2, 0, 0) as a cubic Bézier (evenly spaced control points: unit speed 2).
curve::Curve segment() {
  return curve::Curve::bezier(
      {.control_points = {{0, 0, 0}, {2.0 / 3, 0, 0}, {4.0 / 3, 0, 0}, {2, 0, 0}}, .weights = {}, .dimension = 3});
}

// checks the pass-through residual is the distance from the point to the segment (1 for (1, 1, 0), 0 on it)
TEST(Constraints, PassThroughIsTheDistanceToTheCurve) {
  const std::vector<Constraint> c{{.kind = ConstraintKind::PassThrough, .point = {1, 1, 0}},
                                  {.kind = ConstraintKind::PassThrough, .point = {0.5, 0, 0}}};
  const std::vector<ConstraintResidual> r = check_constraints(segment(), c);
  ASSERT_EQ(r.size(), 2u);
  EXPECT_NEAR(r[0].residual, 1.0, 1e-12);
  EXPECT_FALSE(r[0].satisfied);
  EXPECT_NEAR(r[1].residual, 0.0, 1e-12);
  EXPECT_TRUE(r[1].satisfied);
  EXPECT_EQ(r[1].index, 1u);
}

// checks the end-tangent residual is the angle between the tangent (+x) and the direction: π/4 for (1, 1, 0),
// π for (−1, 0, 0) at the end, 0 for (3, 0, 0) whatever its length
TEST(Constraints, EndTangentIsTheAngle) {
  const std::vector<Constraint> c{{.kind = ConstraintKind::EndTangent, .end = CurveEnd::Start, .direction = {1, 1, 0}},
                                  {.kind = ConstraintKind::EndTangent, .end = CurveEnd::End, .direction = {-1, 0, 0}},
                                  {.kind = ConstraintKind::EndTangent, .end = CurveEnd::End, .direction = {3, 0, 0}}};
  const std::vector<ConstraintResidual> r = check_constraints(segment(), c);
  EXPECT_NEAR(r[0].residual, std::numbers::pi / 4, 1e-12);
  EXPECT_NEAR(r[1].residual, std::numbers::pi, 1e-12);
  EXPECT_NEAR(r[2].residual, 0.0, 1e-12);
  EXPECT_TRUE(r[2].satisfied);
}

// checks the curvature and length residuals on the rational circle of radius 2 (κ = 1/2, L = 4π)
TEST(Constraints, EndCurvatureAndLengthOfACircle) {
  const curve::Curve circle = testing::rational_circle(2.0);
  const std::vector<Constraint> c{
      {.kind = ConstraintKind::EndCurvature, .end = CurveEnd::Start, .value = 0.5},
      {.kind = ConstraintKind::EndCurvature, .end = CurveEnd::End, .value = 0.3},
      {.kind = ConstraintKind::FixedLength, .value = 4 * std::numbers::pi, .tolerance = 1e-9},
      {.kind = ConstraintKind::FixedLength, .value = 12.0}};
  const std::vector<ConstraintResidual> r = check_constraints(circle, c);
  EXPECT_NEAR(r[0].residual, 0.0, 1e-12);
  EXPECT_TRUE(r[0].satisfied);
  EXPECT_NEAR(r[1].residual, 0.2, 1e-12);
  EXPECT_NEAR(r[2].residual, 0.0, 1e-9);
  EXPECT_TRUE(r[2].satisfied);
  EXPECT_NEAR(r[3].residual, 4 * std::numbers::pi - 12.0, 1e-9);
  EXPECT_FALSE(r[3].satisfied);
}

// checks constraints_from_json(constraints_to_json(x)) == x bit for bit, tolerance optional on reading
TEST(Constraints, JsonReadsBackEqual) {
  const std::vector<Constraint> c{
      {.kind = ConstraintKind::PassThrough, .point = {0.1, -2.5, 1e-7}, .tolerance = 1e-3},
      {.kind = ConstraintKind::EndTangent, .end = CurveEnd::End, .direction = {0, 0.6, 0.8}},
      {.kind = ConstraintKind::EndCurvature, .end = CurveEnd::Start, .value = 0.125},
      {.kind = ConstraintKind::FixedLength, .value = 3.0000000000000004}};
  EXPECT_EQ(constraints_from_json(constraints_to_json(c)), c);
  const std::vector<Constraint> d =
      constraints_from_json(io::json::Json::parse(R"([{"kind": "fixed-length", "value": 2}])"));
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].tolerance, 1e-6);
}

// checks bad constraints are refused naming the member: a zero direction, a negative curvature, a length ≤ 0, an
// unknown kind
TEST(Constraints, RefusesBadConstraintsNamingTheMember) {
  const auto field_of = [](const char* text) {
    try {
      (void)constraints_from_json(io::json::Json::parse(text));
    } catch (const Error& e) {
      return e.where().field + " | " + e.message();
    }
    return std::string("accepted");
  };
  EXPECT_NE(field_of(R"([{"kind": "end-tangent", "end": "start", "direction": [0, 0, 0]}])").find("direction"),
            std::string::npos);
  EXPECT_NE(field_of(R"([{"kind": "end-curvature", "end": "end", "value": -1}])").find("value"), std::string::npos);
  EXPECT_NE(field_of(R"([{"kind": "fixed-length", "value": 0}])").find("value"), std::string::npos);
  EXPECT_NE(field_of(R"([{"kind": "tangent"}])").find("kind"), std::string::npos);
}

}  // namespace
}  // namespace hula::oli
