// SPDX-License-Identifier: MIT
// Tests of problem files: the problem they declare (variables, value layout,
// evaluation through the compiled tape) and the errors that name the member.
#include "hula/io/problem_file.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hula/testing/expect_error.hpp"

namespace hula::io {
namespace {

// checks: variables, counts and the value layout (objectives, inequalities, equalities)
// against hand-computed values at one point.
TEST(ProblemFile, DeclaresTheProblemAndEvaluatesIt) {
  const ProblemFile f = parse_problem_json(R"j({
    "name": "demo",
    "variables": [{"name": "x", "lower": -1, "upper": 2, "precision": 0.01},
                  {"name": "y_2", "lower": 0, "upper": 3}],
    "objectives": ["x^2 + y_2", "cos(pi * x)"],
    "constraints": [{"expression": "x - y_2", "type": "equality"},
                    {"expression": "x + y_2 - 1"}],
    "equality_tolerance": 1e-3,
    "reference": [5, 2]
  })j");
  const optim::Problem& p = f.problem;
  EXPECT_EQ(p.name, "demo");
  ASSERT_EQ(p.dimension(), 2u);
  EXPECT_EQ(p.variables[0].name, "x");
  EXPECT_EQ(p.variables[0].lower, -1.0);
  EXPECT_EQ(p.variables[0].upper, 2.0);
  EXPECT_EQ(p.variables[0].precision, 0.01);
  EXPECT_EQ(p.variables[1].precision, 0.0);
  EXPECT_EQ(p.objectives, 2u);
  EXPECT_EQ(p.inequality_constraints, 1u);
  EXPECT_EQ(p.equality_constraints, 1u);
  EXPECT_EQ(p.equality_tolerance, 1e-3);
  ASSERT_TRUE(f.reference);
  EXPECT_EQ(*f.reference, (std::vector<double>{5, 2}));
  const std::vector<double> x = {0.5, 2.0};
  std::vector<double> v(4);
  p.evaluate(x, v);
  EXPECT_DOUBLE_EQ(v[0], 2.25);
  EXPECT_NEAR(v[1], 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(v[2], 1.5);   // inequality x + y - 1
  EXPECT_DOUBLE_EQ(v[3], -1.5);  // equality x - y
  EXPECT_DOUBLE_EQ(p.violation(v), 1.5 + (1.5 - 1e-3));
}

// checks: an expression undefined at a point gives NaN (a failed evaluation), not an exception.
TEST(ProblemFile, UndefinedValuesAreNaN) {
  const ProblemFile f =
      parse_problem_json(R"j({"variables": [{"name": "x", "lower": -1, "upper": 1}], "objectives": ["sqrt(x)"]})j");
  EXPECT_EQ(f.problem.name, "problem-file");
  EXPECT_FALSE(f.reference);
  std::vector<double> v(1);
  f.problem.evaluate(std::vector<double>{-0.5}, v);
  EXPECT_TRUE(std::isnan(v[0]));
}

// checks: each kind of bad file is refused with the member named in the message and in `where`.
TEST(ProblemFile, ErrorsNameTheMember) {
  HULA_EXPECT_ERROR(parse_problem_json(R"j({"variables": [], "objectives": ["1"]})j"), Errc::ParseError,
                    "variables is empty");
  HULA_EXPECT_ERROR(parse_problem_json(R"j({"variables": [{"name": "x", "lower": 0}], "objectives": ["x"]})j"),
                    Errc::ParseError, "variables[0]");
  HULA_EXPECT_ERROR(
      parse_problem_json(R"j({"variables": [{"name": "sin", "lower": 0, "upper": 1}], "objectives": ["1"]})j"),
      Errc::ParseError, "variables[0].name = \"sin\"");
  HULA_EXPECT_ERROR(parse_problem_json(R"j({"variables": [{"name": "x", "lower": 0, "upper": 1},
                                                         {"name": "x", "lower": 0, "upper": 1}],
                                           "objectives": ["x"]})j"),
                    Errc::ParseError, "variables[1].name = \"x\" repeats");
  HULA_EXPECT_ERROR(
      parse_problem_json(R"j({"variables": [{"name": "x", "lower": 2, "upper": 1}], "objectives": ["x"]})j"),
      Errc::InvalidOption, "variables[0].lower = 2");
  HULA_EXPECT_ERROR(parse_problem_json(R"j({"variables": [{"name": "x", "lower": 0, "upper": 1}], "objectives": []})j"),
                    Errc::ParseError, "objectives is empty");
  HULA_EXPECT_ERROR(
      parse_problem_json(R"j({"variables": [{"name": "x", "lower": 0, "upper": 1}], "objectives": ["vec(x, x)"]
})j"),
      Errc::ParseError, "objectives[0]: \"vec(x, x)\" is a 2-vector");
  HULA_EXPECT_ERROR(parse_problem_json(R"j({"variables": [{"name": "x", "lower": 0, "upper": 1}], "objectives": ["x"],
                                           "constraints": [{"expression": "x", "type": "<="}]})j"),
                    Errc::ParseError, "constraints[0].type = \"<=\"");
  HULA_EXPECT_ERROR(parse_problem_json(R"j({"variables": [{"name": "x", "lower": 0, "upper": 1}], "objectives": ["x"],
                                           "constraints": [{"expression": "x + z"}]})j"),
                    Errc::ParseError, "constraints[0].expression: ");
  HULA_EXPECT_ERROR(
      parse_problem_json(
          R"j({"variables": [{"name": "x", "lower": 0, "upper": 1}], "objectives": ["x"], "reference": [1, 2]})j"),
      Errc::InvalidOption, "reference has 2 values");
  HULA_EXPECT_ERROR(parse_problem_json("{\"variables\": ["), Errc::ParseError, "");

  // The parser's position inside the expression string is kept.
  try {
    (void)parse_problem_json(
        R"j({"variables": [{"name": "x", "lower": 0, "upper": 1}], "objectives": ["x", "2 * (x + 1"]})j");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Errc::ParseError);
    EXPECT_EQ(e.where().field, "objectives");
    EXPECT_EQ(e.where().index, 1u);
    EXPECT_EQ(e.where().line, 1u);
    EXPECT_TRUE(e.where().column.has_value());
    EXPECT_EQ(std::string(e.message()).rfind("objectives[1]: ", 0), 0u) << e.message();
  }
}

}  // namespace
}  // namespace hula::io
