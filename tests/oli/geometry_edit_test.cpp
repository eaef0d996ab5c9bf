// SPDX-License-Identifier: MIT
// Edit's geometric operations (insert knot, elevate degree, reverse, split) run
// through the document's kernel backend, on both backends: the shape is checked
// against the curve before the edit at sampled parameters, undo against the
// stored state bit for bit, failures against the untouched document.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "hula/curve/curve.hpp"
#include "hula/oli/document.hpp"
#include "hula/oli/kernel/kernel.hpp"
#include "oli_fixtures.hpp"

namespace hula::oli {
namespace {

using testing::cubic;
using testing::observable;

class GeometryEdit : public ::testing::TestWithParam<std::string> {
 protected:
  Document doc{DocumentOptions{.backend = GetParam()}};
  Label label{};

  void SetUp() override {
    doc.transact("add", [&](Edit& e) { label = e.add_curve(cubic(7), {.name = "spine"}); }).throw_if_failed();
  }
  [[nodiscard]] nurbs::NurbsCurve nurbs_of(Label l) const { return doc.get(l).curve().nurbs(); }
};

// Max |C_after(t) − C_before(t)| over 101 parameters of the domain.
double max_distance(const nurbs::NurbsCurve& a, const nurbs::NurbsCurve& b) {
  const auto [t0, t1] = a.domain();
  double worst = 0.0;
  for (int i = 0; i <= 100; ++i) {
    const double t = t0 + (t1 - t0) * i / 100.0;
    worst = std::max(worst, norm(a.evaluate(t) - b.evaluate(t)));
  }
  return worst;
}

// Checks knot insertion keeps the curve (1e-12 against the curve before at 101 parameters), adds one
// control point, and undo restores the stored state exactly (to_json and the raw knots/points equal).
TEST_P(GeometryEdit, InsertKnotKeepsShapeAndUndoRestoresBitForBit) {
  const nurbs::NurbsCurve before = nurbs_of(label);
  const Json stored = observable(doc);
  const Outcome o = doc.transact("insert knot", [&](Edit& e) { e.insert_knot(label, 0.37); });
  ASSERT_TRUE(o) << o.error_message;
  EXPECT_EQ(o.changes.changed, std::vector<Label>{label});
  const nurbs::NurbsCurve after = nurbs_of(label);
  EXPECT_EQ(after.control_points().size(), before.control_points().size() + 1);
  EXPECT_LE(max_distance(before, after), 1e-12);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(observable(doc), stored);
  const nurbs::NurbsCurve undone = nurbs_of(label);
  EXPECT_TRUE(std::equal(undone.knots().values().begin(), undone.knots().values().end(),
                         before.knots().values().begin(), before.knots().values().end()));
  ASSERT_EQ(undone.control_points().size(), before.control_points().size());
  for (std::size_t i = 0; i < before.control_points().size(); ++i)
    EXPECT_EQ(undone.control_points()[i], before.control_points()[i]) << i;
}

// Checks degree elevation by 2 keeps the curve (1e-12 at 101 parameters) and raises the degree by 2.
TEST_P(GeometryEdit, ElevateKeepsShape) {
  const nurbs::NurbsCurve before = nurbs_of(label);
  ASSERT_TRUE(doc.transact("elevate degree", [&](Edit& e) { e.elevate_degree(label, 2); }));
  const nurbs::NurbsCurve after = nurbs_of(label);
  EXPECT_EQ(after.degree(), before.degree() + 2);
  EXPECT_LE(max_distance(before, after), 1e-12);
}

// Checks reverse against the closed form R(t) = C(a + b − t) at 101 parameters.
TEST_P(GeometryEdit, ReverseTraversesBackwards) {
  const nurbs::NurbsCurve before = nurbs_of(label);
  ASSERT_TRUE(doc.transact("reverse", [&](Edit& e) { e.reverse(label); }));
  const nurbs::NurbsCurve after = nurbs_of(label);
  const auto [a, b] = before.domain();
  for (int i = 0; i <= 100; ++i) {
    const double t = a + (b - a) * i / 100.0;
    EXPECT_LE(norm(after.evaluate(t) - before.evaluate(a + b - t)), 1e-12) << t;
  }
}

// Checks split replaces the entity by two pieces equal to the curve on [a, t] and [t, b], named and
// with provenance naming the source, and undo brings the source back.
TEST_P(GeometryEdit, SplitMakesTwoPiecesWithProvenance) {
  const nurbs::NurbsCurve before = nurbs_of(label);
  const Json stored = observable(doc);
  std::pair<Label, Label> pieces;
  ASSERT_TRUE(doc.transact("split", [&](Edit& e) { pieces = e.split(label, 0.5); }));
  EXPECT_FALSE(doc.contains(label));
  for (const Label piece : {pieces.first, pieces.second}) {
    const Entity e = doc.get(piece);
    ASSERT_TRUE(e.provenance().has_value());
    EXPECT_EQ(e.provenance()->operation, "split");
    EXPECT_EQ(e.provenance()->inputs, std::vector<Label>{label});
    const nurbs::NurbsCurve n = e.curve().nurbs();
    const auto [a, b] = n.domain();
    for (int i = 0; i <= 20; ++i) {
      const double t = a + (b - a) * i / 20.0;
      EXPECT_LE(norm(n.evaluate(t) - before.evaluate(t)), 1e-12) << t;
    }
  }
  EXPECT_EQ(doc.get(pieces.first).attributes().name, "spine (1)");
  EXPECT_EQ(doc.get(pieces.first).curve().nurbs().domain().end, 0.5);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(observable(doc), stored);
}

// Checks kernel errors roll back, keep their code and field, and name the entity and operation.
TEST_P(GeometryEdit, KernelErrorsRollBackAndNameTheInput) {
  const Json stored = observable(doc);
  const Outcome outside = doc.transact("insert knot", [&](Edit& e) { e.insert_knot(label, 2.0); });
  EXPECT_FALSE(outside);
  EXPECT_EQ(outside.error_code, "OutOfDomain");
  EXPECT_NE(outside.error_message.find("entity " + std::to_string(label.value)), std::string::npos);
  EXPECT_NE(outside.error_message.find("knot insertion"), std::string::npos);
  const Outcome too_many = doc.transact("insert knot", [&](Edit& e) { e.insert_knot(label, 0.5, 4); });
  EXPECT_FALSE(too_many);
  EXPECT_EQ(too_many.error_code, "InvalidKnots");
  EXPECT_FALSE(doc.transact("elevate degree", [&](Edit& e) { e.elevate_degree(label, 0); }));
  EXPECT_EQ(observable(doc), stored);
}

INSTANTIATE_TEST_SUITE_P(Backends, GeometryEdit, ::testing::ValuesIn(kernel_names()));

// Checks a law curve (whose NURBS is an approximation) is refused, naming the entity, and the document stays.
TEST(GeometryEditKinds, LawCurveIsRefused) {
  Document doc;
  Label l;
  doc.transact("add",
               [&](Edit& e) {
                 l = e.add_curve(curve::Curve::from_law("vec(t, t^2)", "t", {0.0, 1.0}));
               })
      .throw_if_failed();
  const Outcome o = doc.transact("insert knot", [&](Edit& e) { e.insert_knot(l, 0.5); });
  EXPECT_FALSE(o);
  EXPECT_EQ(o.error_code, "InvalidArgument");
  EXPECT_NE(o.error_message.find("entity " + std::to_string(l.value)), std::string::npos);
  EXPECT_EQ(doc.get(l).curve().kind(), curve::Kind::Law);
}

}  // namespace
}  // namespace hula::oli
