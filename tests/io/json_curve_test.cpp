// SPDX-License-Identifier: MIT
// JSON curve files: every kind parses, 2-D files give 2-D curves and 2-D
// output, unknown members are ignored, and every documented error names the
// JSON path and value (ErrorWhere field / index / component set).
#include "hula/io/json_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "hula/core/error.hpp"
#include "hula/testing/expect_error.hpp"
#include "hula/testing/fpe.hpp"

namespace hula::io {
namespace {

// Returns the hula::Error thrown by parse_curve_json(text), or fails the test.
Error parse_error_of(const std::string& text) {
  try {
    (void)parse_curve_json(text);
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "no hula::Error for " << text;
  return Error(Errc::InvalidArgument, "none");
}

const char* const kCubic = R"({
  "kind": "nurbs", "degree": 3,
  "knots": [0, 0, 0, 0, 0.5, 1, 1, 1, 1],
  "control_points": [[0, 0, 0], [1, 2, 0], [2, 2, 1], [3, 0, 1], [4, 1, 0]],
  "weights": null
})";

// checks: the nurbs kind parses to the curve built directly from the same arrays.
TEST(JsonCurve, NurbsKindParses) {
  const curve::Curve f = parse_curve_json(kCubic);
  EXPECT_EQ(f.kind(), curve::Kind::Nurbs);
  EXPECT_FALSE(std::get_if<curve::InterpolatedData>(&f.data()));
  const nurbs::NurbsCurve expected(3, {0, 0, 0, 0, 0.5, 1, 1, 1, 1},
                                   {{0, 0, 0}, {1, 2, 0}, {2, 2, 1}, {3, 0, 1}, {4, 1, 0}});
  EXPECT_EQ(f.nurbs(), expected);
  EXPECT_EQ(f.nurbs().dimension(), 3);
  EXPECT_FALSE(f.nurbs().is_rational());
}

// checks: absent weights mean non-rational; given weights make the curve rational.
TEST(JsonCurve, WeightsAbsentOrGiven) {
  const curve::Curve a = parse_curve_json(R"({"kind": "nurbs", "degree": 1, "knots": [0, 0, 1, 1],
                                           "control_points": [[0, 0], [1, 1]]})");
  EXPECT_FALSE(a.nurbs().is_rational());
  const curve::Curve b = parse_curve_json(R"({"kind": "nurbs", "degree": 1, "knots": [0, 0, 1, 1],
                                           "control_points": [[0, 0], [1, 1]], "weights": [1, 2]})");
  ASSERT_TRUE(b.nurbs().is_rational());
  EXPECT_EQ(b.nurbs().weights()[1], 2.0);
}

// checks: 2-D control points give a 2-D curve, written back as [x, y].
TEST(JsonCurve, TwoDimensionalFilesGiveTwoDimensionalCurvesAndOutput) {
  const curve::Curve f = parse_curve_json(R"({"kind": "bezier", "control_points": [[0, 0], [1, 2], [2, 0]]})");
  EXPECT_EQ(f.nurbs().dimension(), 2);
  const Json out = curve_to_json(f.nurbs());
  ASSERT_EQ(out["control_points"].size(), 3u);
  for (const auto& p : out["control_points"]) EXPECT_EQ(p.size(), 2u);
  EXPECT_EQ(parse_curve_json(out.dump()).nurbs(), f.nurbs());
}

// checks: the bezier kind has degree n - 1 and knots 0..0 1..1; midpoint of the
// quadratic (0,0),(1,2),(2,0) is (1,1) (de Casteljau by hand).
TEST(JsonCurve, BezierKindParses) {
  const curve::Curve f = parse_curve_json(R"({"kind": "bezier", "control_points": [[0, 0], [1, 2], [2, 0]],
                                           "weights": null})");
  EXPECT_EQ(f.kind(), curve::Kind::Bezier);
  EXPECT_EQ(f.nurbs().degree(), 2);
  const std::vector<double> knots(f.nurbs().knots().values().begin(), f.nurbs().knots().values().end());
  EXPECT_EQ(knots, (std::vector<double>{0, 0, 0, 1, 1, 1}));
  const Vec3 mid = f.nurbs().evaluate(0.5);
  EXPECT_DOUBLE_EQ(mid.x, 1.0);
  EXPECT_DOUBLE_EQ(mid.y, 1.0);
}

// checks: the interpolated kind resolves through interpolate_cubic (the curve
// passes through its points) and keeps its inputs, which round-trip.
TEST(JsonCurve, InterpolatedKindParsesAndKeepsInputs) {
  const curve::Curve f = parse_curve_json(R"({"kind": "interpolated",
      "points": [[0, 0, 0], [40, 25, 0], [80, -25, 0], [120, 0, 0]],
      "parameterisation": "centripetal", "start": "bessel", "end": {"tangent": [1, 0, 0]}})");
  EXPECT_EQ(f.kind(), curve::Kind::Interpolated);
  ASSERT_TRUE(std::get_if<curve::InterpolatedData>(&f.data()));
  const auto& in = std::get<curve::InterpolatedData>(f.data());
  EXPECT_EQ(in.parameterisation, nurbs::Parameterisation::Centripetal);
  EXPECT_EQ(in.start.kind, nurbs::EndCondition::Kind::Bessel);
  EXPECT_EQ(in.end.kind, nurbs::EndCondition::Kind::Clamped);
  EXPECT_EQ(in.end.derivative, (Vec3{1, 0, 0}));
  EXPECT_EQ(f.nurbs(), nurbs::interpolate_cubic(in.points, in.options()));
  EXPECT_NEAR(distance(f.nurbs().evaluate(0.0), Vec3{0, 0, 0}), 0.0, 1e-12);
  EXPECT_NEAR(distance(f.nurbs().evaluate(1.0), Vec3{120, 0, 0}), 0.0, 1e-12);
  EXPECT_NEAR(distance(f.nurbs().derivatives(1.0, 1)[1], Vec3{1, 0, 0}), 0.0, 1e-9);

  const curve::Curve again = parse_curve_json(curve_to_json(f).dump());
  ASSERT_TRUE(std::get_if<curve::InterpolatedData>(&again.data()));
  EXPECT_EQ(std::get<curve::InterpolatedData>(again.data()).points, std::get<curve::InterpolatedData>(f.data()).points);
  EXPECT_EQ(again.nurbs(), f.nurbs());
}

// checks: every END name and both parameterisation spellings parse; "knots" means "parameters".
TEST(JsonCurve, InterpolatedEndNamesAndKnots) {
  for (const char* end : {"natural", "bessel", "not-a-knot", "occt"}) {
    const std::string text = std::string(R"({"kind": "interpolated", "points": [[0, 0], [1, 1], [2, 0], [3, 1]],
        "parameterisation": "uniform", "start": ")") +
                             end + R"(", "end": ")" + end + R"("})";
    const curve::Curve f = parse_curve_json(text);
    EXPECT_EQ(f.nurbs().dimension(), 2) << end;
    EXPECT_EQ(end_condition_to_json(std::get<curve::InterpolatedData>(f.data()).start), Json(end));
  }
  const curve::Curve k = parse_curve_json(R"({"kind": "interpolated", "points": [[0, 0], [1, 1], [2, 0]],
                                           "knots": [0, 1, 3]})");
  const curve::Curve p = parse_curve_json(R"({"kind": "interpolated", "points": [[0, 0], [1, 1], [2, 0]],
                                           "parameters": [0, 1, 3], "knots": [0, 1, 3]})");
  EXPECT_EQ(std::get<curve::InterpolatedData>(k.data()).parameters, (std::vector<double>{0, 1, 3}));
  EXPECT_EQ(k.nurbs(), p.nurbs());
}

// checks: unknown members are ignored (forward compatibility).
TEST(JsonCurve, UnknownMembersAreIgnored) {
  const curve::Curve f = parse_curve_json(R"({"kind": "bezier", "control_points": [[0, 0], [1, 1]],
                                           "colour": "red", "meta": {"author": "x"}})");
  EXPECT_EQ(f.nurbs().degree(), 1);
}

// checks: an unknown kind names the kind.
TEST(JsonCurveErrors, UnknownKindNamesTheKind) {
  HULA_EXPECT_ERROR(parse_curve_json(R"({"kind": "clothoid"})"), Errc::ParseError, "kind = \"clothoid\"");
  EXPECT_EQ(parse_error_of(R"({"kind": "clothoid"})").where().field, "kind");
  HULA_EXPECT_ERROR(parse_curve_json(R"({"kind": 7})"), Errc::ParseError, "kind = 7 must be a string");
  HULA_EXPECT_ERROR(parse_curve_json(R"([1, 2])"), Errc::ParseError,
                    "document = an array of 2 elements must be a JSON object");
}

// checks: a missing member is named.
TEST(JsonCurveErrors, MissingMemberIsNamed) {
  HULA_EXPECT_ERROR(parse_curve_json(R"({"degree": 3})"), Errc::ParseError, "missing member \"kind\"");
  HULA_EXPECT_ERROR(parse_curve_json(R"({"kind": "nurbs", "degree": 1, "knots": [0, 0, 1, 1]})"), Errc::ParseError,
                    "missing member \"control_points\"");
  EXPECT_EQ(parse_error_of(R"({"kind": "interpolated"})").where().field, "points");
  HULA_EXPECT_ERROR(parse_curve_json(R"({"kind": "interpolated", "points": [[0, 0], [1, 1]], "end": {"x": 1}})"),
                    Errc::ParseError, "missing member \"tangent\" in end");
}

// checks: a wrong type names the JSON path and the value, with index and component.
TEST(JsonCurveErrors, WrongTypeNamesPathAndValue) {
  const std::string text = R"({"kind": "nurbs", "degree": 1, "knots": [0, 0, 0.5, 1, 1],
      "control_points": [[0, 0, 0], [1, 1, 1], [2, 0, 0], [3, "abc", 0]]})";
  HULA_EXPECT_ERROR(parse_curve_json(text), Errc::ParseError, "control_points[3][1] = \"abc\" must be a number");
  const Error e = parse_error_of(text);
  EXPECT_EQ(e.where().field, "control_points");
  EXPECT_EQ(e.where().index, 3u);
  EXPECT_EQ(e.where().component, 1u);

  HULA_EXPECT_ERROR(parse_curve_json(R"({"kind": "bezier", "control_points": [[0, null], [1, 1]]})"), Errc::ParseError,
                    "control_points[0][1] = null must be a number");
  HULA_EXPECT_ERROR(parse_curve_json(R"({"kind": "nurbs", "degree": "3", "knots": [], "control_points": []})"),
                    Errc::ParseError, "degree = \"3\" must be an integer");
  HULA_EXPECT_ERROR(parse_curve_json(R"({"kind": "nurbs", "degree": 1.5, "knots": [], "control_points": []})"),
                    Errc::ParseError, "degree = 1.5 must be an integer");
  HULA_EXPECT_ERROR(parse_curve_json(R"({"kind": "nurbs", "degree": 1, "knots": [0, 0, "1", 1],
                                         "control_points": [[0, 0], [1, 1]]})"),
                    Errc::ParseError, "knots[2] = \"1\" must be a number");
  HULA_EXPECT_ERROR(parse_curve_json(R"({"kind": "bezier", "control_points": [[0, 0], [1, 1]], "weights": "yes"})"),
                    Errc::ParseError, "weights = \"yes\" must be an array");
  HULA_EXPECT_ERROR(parse_curve_json(R"({"kind": "bezier", "control_points": [[0, 0], [1, 1, 2, 3]]})"),
                    Errc::ParseError, "control_points[1] = an array of 4 elements must be an array of 2 or 3 numbers");
  {
    // Parsing 1e999 overflows inside strtod (FE_OVERFLOW): untrap it in Debug test builds.
    const testing::FpeGuard overflow_is_expected;
    HULA_EXPECT_ERROR(parse_curve_json(R"({"kind": "bezier", "control_points": [[0, 0], [1, 1e999]]})"),
                      Errc::NonFiniteInput, "1e999");
  }
}

// checks: mixing 2 and 3 components names the index.
TEST(JsonCurveErrors, MixedDimensionsNameTheIndex) {
  const std::string text = R"({"kind": "bezier", "control_points": [[0, 0], [1, 1], [2, 0, 0]]})";
  HULA_EXPECT_ERROR(parse_curve_json(text), Errc::ParseError, "control_points[2] has 3 components");
  EXPECT_EQ(parse_error_of(text).where().index, 2u);
}

// checks: decreasing knots pass the kernel's InvalidKnots through with field "knots" and the index.
TEST(JsonCurveErrors, DecreasingKnotsPassThroughFromTheKernel) {
  const std::string text = R"({"kind": "nurbs", "degree": 1, "knots": [0, 0, 0.7, 0.3, 1, 1],
      "control_points": [[0, 0], [1, 1], [2, 0], [3, 1]]})";
  HULA_EXPECT_ERROR(parse_curve_json(text), Errc::InvalidKnots, "knots[3] = 0.29999999999999999");
  const Error e = parse_error_of(text);
  EXPECT_EQ(e.where().field, "knots");
  EXPECT_EQ(e.where().index, 3u);
  HULA_EXPECT_ERROR(parse_curve_json(R"({"kind": "bezier", "control_points": [[0, 0], [1, 1]], "weights": [1, 0]})"),
                    Errc::InvalidWeight, "weights[1] = 0");
}

// checks: a bad END string or parameterisation is named with its value.
TEST(JsonCurveErrors, BadEndConditionAndParameterisation) {
  const std::string text = R"({"kind": "interpolated", "points": [[0, 0], [1, 1], [2, 0]], "start": "clamp"})";
  HULA_EXPECT_ERROR(parse_curve_json(text), Errc::ParseError, "start = \"clamp\" is not an end condition");
  EXPECT_EQ(parse_error_of(text).where().field, "start");
  HULA_EXPECT_ERROR(parse_curve_json(R"({"kind": "interpolated", "points": [[0, 0], [1, 1]], "end": 3})"),
                    Errc::ParseError, "end = 3 must be an end condition");
  HULA_EXPECT_ERROR(parse_curve_json(R"({"kind": "interpolated", "points": [[0, 0], [1, 1]],
                                         "end": {"tangent": [1, "x"]}})"),
                    Errc::ParseError, "end.tangent[1] = \"x\" must be a number");
  HULA_EXPECT_ERROR(
      parse_curve_json(R"({"kind": "interpolated", "points": [[0, 0], [1, 1]], "parameterisation": "arc"})"),
      Errc::ParseError, "parameterisation = \"arc\"");
}

// checks: "parameters" and "knots" both given and different is an error naming the first difference;
// kernel errors about given knots name "knots".
TEST(JsonCurveErrors, ParametersAndKnotsDisagree) {
  const std::string text = R"({"kind": "interpolated", "points": [[0, 0], [1, 1], [2, 0]],
                               "parameters": [0, 1, 2], "knots": [0, 1.5, 2]})";
  HULA_EXPECT_ERROR(parse_curve_json(text), Errc::ParseError, "knots[1] = 1.5 differs from parameters[1] = 1");
  EXPECT_EQ(parse_error_of(text).where().index, 1u);
  HULA_EXPECT_ERROR(parse_curve_json(R"({"kind": "interpolated", "points": [[0, 0], [1, 1], [2, 0]],
                                         "parameters": [0, 1], "knots": [0, 1, 2]})"),
                    Errc::ParseError, "knots has 3 values but parameters has 2");
  const std::string bad = R"({"kind": "interpolated", "points": [[0, 0], [1, 1], [2, 0]], "knots": [0, 2, 1]})";
  HULA_EXPECT_ERROR(parse_curve_json(bad), Errc::InvalidArgument, "knots[2] = 1");
  EXPECT_EQ(parse_error_of(bad).where().field, "knots");
}

// checks: invalid JSON reports line and column.
TEST(JsonCurveErrors, SyntaxErrorHasLineAndColumn) {
  const std::string text = "{\"kind\": \"nurbs\",\n  \"degree\": 3,,\n}";
  HULA_EXPECT_ERROR(parse_curve_json(text), Errc::ParseError, "line 2");
  const Error e = parse_error_of(text);
  EXPECT_EQ(e.where().line, 2u);
  EXPECT_TRUE(e.where().column.has_value());
}

// checks: too few Bezier points is named.
TEST(JsonCurveErrors, BezierNeedsTwoPoints) {
  HULA_EXPECT_ERROR(parse_curve_json(R"({"kind": "bezier", "control_points": [[0, 0]]})"), Errc::TooFewPoints,
                    "control_points has 1 point");
}

}  // namespace
}  // namespace hula::io

namespace hula::io {
namespace {

const char* const kHelixLaw =
    R"j({"kind": "law", "expression": "vec(2*cos(t), 2*sin(t), 0.5*t)", "parameter": "t",
        "domain": [0, 12.566370614359172]})j";

// checks: a "law" curve file reads to the law (exact values) plus a stand-in NURBS within
// curve::kApproximationTolerance, and writes back the same members.
TEST(JsonCurveLaw, ReadsLawKind) {
  const curve::Curve f = parse_curve_json(kHelixLaw);
  EXPECT_EQ(f.kind(), curve::Kind::Law);
  ASSERT_NE(f.law(), nullptr);
  EXPECT_EQ(f.law()->dimension(), 3);
  EXPECT_LE(f.approximation_deviation(), curve::kApproximationTolerance);
  EXPECT_NEAR(f.nurbs().evaluate(1.0).x, 2 * std::cos(1.0), 1e-6);
  const Json back = curve_to_json(f);
  EXPECT_EQ(back["kind"], "law");
  EXPECT_EQ(back["expression"], "vec(2*cos(t), 2*sin(t), 0.5*t)");
  EXPECT_EQ(back["domain"][1], 12.566370614359172);
  const curve::Curve g =
      parse_curve_json(R"j({"kind": "law", "expression": "vec(u, u^2)", "parameter": "u", "domain": [0, 1]})j");
  EXPECT_EQ(g.nurbs().dimension(), 2);
}

// checks: bad law files: expression errors keep line/column under field "expression"; scalar laws,
// bad domains and laws undefined inside the domain are rejected naming the member.
TEST(JsonCurveLaw, Errors) {
  HULA_EXPECT_ERROR(parse_curve_json(R"j({"kind": "law", "expression": "vec(t, sin(t)", "domain": [0, 1]})j"),
                    Errc::ParseError, "expression: line 1, column 14: expected ',' or ')'");
  HULA_EXPECT_ERROR(parse_curve_json(R"j({"kind": "law", "expression": "sin(t)", "domain": [0, 1]})j"),
                    Errc::ParseError, "a law curve must be a 2- or 3-vector");
  HULA_EXPECT_ERROR(parse_curve_json(R"j({"kind": "law", "expression": "vec(t, t)", "domain": [1, 0]})j"),
                    Errc::ParseError, "domain must be [start, end] with start < end");
  HULA_EXPECT_ERROR(parse_curve_json(R"j({"kind": "law", "expression": "vec(t, u)", "domain": [0, 1]})j"),
                    Errc::ParseError, "unknown identifier 'u'");
  HULA_EXPECT_ERROR(parse_curve_json(R"j({"kind": "law", "expression": "vec(t, log(t))", "domain": [-1, 1]})j"),
                    Errc::InvalidArgument, "undefined at t = -1");
  HULA_EXPECT_ERROR(parse_curve_json(R"j({"kind": "law", "domain": [0, 1]})j"), Errc::ParseError, "expression");
}

}  // namespace
}  // namespace hula::io
