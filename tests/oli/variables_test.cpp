// SPDX-License-Identifier: MIT
// Unit tests of design variables over a document (oli/variables.hpp): names, values and bounds read from known
// control points, weights and knots; values written back in one transaction (and undone); apply_variables leaving
// the document alone; a problem whose constraints are the curve's stored constraints, evaluated against closed
// forms; bad selections refused naming the selection.
#include "hula/oli/variables.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hula/core/error.hpp"
#include "oli_fixtures.hpp"

namespace hula::oli {
namespace {

using testing::cubic;

Label add(Document& doc, const curve::Curve& c) {
  Label l;
  doc.transact("add", [&](Edit& e) { l = e.add_curve(c); }).throw_if_failed();
  return l;
}

// checks the names, values and bounds of control point y and z coordinates of points 1 and 3 of the cubic
// (i, i % 3, 0.5 i), relative bounds around each value and absolute ones as given
TEST(Variables, ReadsNamesValuesAndBounds) {
  Document doc;
  const Label l = add(doc, cubic(6));
  const VariableSet set{"shape",
                        {{.label = l,
                          .kind = VariableKind::ControlPoints,
                          .indices = {1, 3},
                          .axes = "yz",
                          .bounds = {BoundMode::Relative, -0.5, 0.25}},
                         {.label = l,
                          .kind = VariableKind::InteriorKnots,
                          .indices = {},
                          .axes = "xyz",
                          .bounds = {BoundMode::Absolute, 0.1, 0.9}}}};
  const VariableValues v = read_variables(doc, set);
  ASSERT_EQ(v.values.size(), 4u + 2u);  // 2 points × 2 axes, then the 2 interior knots of 6 clamped cubic points
  EXPECT_EQ(v.names[0], std::to_string(l.value) + ".control-points[1].y");
  EXPECT_EQ(v.names[3], std::to_string(l.value) + ".control-points[3].z");
  EXPECT_EQ(v.values[0], 1.0);  // point 1: (1, 1, 0.5)
  EXPECT_EQ(v.values[1], 0.5);
  EXPECT_EQ(v.values[2], 0.0);  // point 3: (3, 0, 1.5)
  EXPECT_EQ(v.values[3], 1.5);
  EXPECT_EQ(v.lower[1], 0.0);
  EXPECT_EQ(v.upper[1], 0.75);
  EXPECT_NEAR(v.values[4], 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(v.values[5], 2.0 / 3.0, 1e-15);
  EXPECT_EQ(v.lower[4], 0.1);
  EXPECT_EQ(v.upper[5], 0.9);
  const std::vector<optim::Variable> x = v.to_optim(0.001);
  ASSERT_EQ(x.size(), 6u);
  EXPECT_EQ(x[0].name, v.names[0]);
  EXPECT_EQ(x[0].precision, 0.001);
}

// checks write_variables moves exactly the selected coordinates in one undoable step, and apply_variables gives
// the same curve without changing the document
TEST(Variables, WritesBackInOneStepAndAppliesWithoutChanging) {
  Document doc;
  const Label l = add(doc, cubic(5));
  const VariableSet set{"p2", {{.label = l, .kind = VariableKind::ControlPoints, .indices = {2}, .axes = "xyz"}}};
  const std::vector<double> to{7.0, -1.0, 3.0};
  const std::map<Label, curve::Curve> applied = apply_variables(doc, set, to);
  EXPECT_EQ(doc.get(l).curve().nurbs().control_points()[2], (Vec3{2, 2, 1}));  // unchanged
  doc.transact("move", [&](Edit& e) { write_variables(e, set, to); }).throw_if_failed();
  const nurbs::NurbsCurve& c = doc.get(l).curve().nurbs();
  EXPECT_EQ(c.control_points()[2], (Vec3{7, -1, 3}));
  EXPECT_EQ(c.control_points()[1], (Vec3{1, 1, 0.5}));
  EXPECT_TRUE(applied.at(l) == doc.get(l).curve());
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.get(l).curve().nurbs().control_points()[2], (Vec3{2, 2, 1}));
}

// checks make_problem: the variables' bounds, the objective from the candidate curve, and one inequality
// constraint per stored constraint, g = residual − tolerance (a pass-through point 1 off the curve gives 1 − 1e-6)
TEST(Variables, ProblemCarriesTheStoredConstraints) {
  Document doc;
  const Label l = add(doc, cubic(4));
  doc.transact("constrain",
               [&](Edit& e) {
                 e.set_constraints(l, {{.kind = ConstraintKind::PassThrough, .point = {0, 1, 0}}});
               })
      .throw_if_failed();
  const VariableSet set{"x0", {{.label = l, .kind = VariableKind::ControlPoints, .indices = {0}, .axes = "x"}}};
  const optim::Problem p =
      make_problem(doc, set, [l](const std::map<Label, curve::Curve>& curves, std::span<double> f) {
        f[0] = curves.at(l).nurbs().control_points()[0].x;
      });
  ASSERT_EQ(p.dimension(), 1u);
  EXPECT_EQ(p.inequality_constraints, 1u);
  EXPECT_EQ(p.variables[0].lower, -1.0);  // default relative bounds ±1 around 0
  std::vector<double> values(p.values_per_point());
  const std::vector<double> x{0.0};
  p.evaluate(x, values);
  EXPECT_EQ(values[0], 0.0);
  // The curve starts at (0, 0, 0) heading to (1, 1, 0.5): the point (0, 1, 0) is at distance ≥ 0.5 from it.
  EXPECT_GT(values[1], 0.5 - 1e-6);
  const std::vector<double> moved{-0.25};
  p.evaluate(moved, values);
  EXPECT_EQ(values[0], -0.25);
}

// checks bad selections are refused naming the selection: a missing label, weights of a non-rational curve, an
// index out of range, inverted relative bounds
TEST(Variables, RefusesBadSelectionsNamingThem) {
  Document doc;
  const Label l = add(doc, cubic(4));
  const auto field_of = [&](const VariableSelection& s) {
    try {
      (void)read_variables(doc, {"bad", {s}});
    } catch (const Error& e) {
      return e.where().field;
    }
    return std::string("accepted");
  };
  EXPECT_NE(field_of({.label = Label{99}}).find("selections"), std::string::npos);
  EXPECT_NE(field_of({.label = l, .kind = VariableKind::Weights}).find("selections"), std::string::npos);
  EXPECT_NE(field_of({.label = l, .indices = {4}}).find("selections"), std::string::npos);
  EXPECT_NE(field_of({.label = l, .bounds = {BoundMode::Relative, 0.5, 1.0}}).find("selections"), std::string::npos);
}

}  // namespace
}  // namespace hula::oli
