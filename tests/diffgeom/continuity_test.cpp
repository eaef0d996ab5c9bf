// SPDX-License-Identifier: MIT
// Knot and join continuity (thesis 7.1.2, Table 3) against constructions with
// known order: simple knots of a cubic (C2), a double knot (C1), a triple knot
// with collinear control points at unequal spacing (G1 not C1), the rational
// circle (G3, C1), and a join reparameterised to another speed (G3, C0).
#include "hula/diffgeom/continuity.hpp"

#include <gtest/gtest.h>

#include "hula/core/error.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::diffgeom {
namespace {

const std::vector<Vec3> kPoints = {{0, 0, 0}, {1, 2, 0}, {2, -1, 1}, {3, 1, 2}, {4, 0, 0}, {5, 2, 1}, {6, 0, 0}};

// checks C2 at simple interior knots of a cubic and the Table 3 sides equal up to C''.
TEST(Continuity, SimpleKnotsAreC2) {
  const nurbs::NurbsCurve c(3, {0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1}, kPoints);
  const std::vector<Continuity> k = knot_continuity(c);
  ASSERT_EQ(k.size(), 3U);
  for (const Continuity& x : k) {
    EXPECT_EQ(x.multiplicity, 1);
    EXPECT_EQ(x.parametric, 2);
    EXPECT_GE(x.geometric, 2);
    EXPECT_LT(distance(x.left[2], x.right[2]), 1e-9 * norm(x.left[2]));
    EXPECT_GT(distance(x.left[3], x.right[3]), 1e-3);  // C''' jumps at a simple cubic knot
  }
}

// checks a double knot gives C1, and a triple knot with collinear, unequally spaced neighbours G1 but C0.
TEST(Continuity, MultipleKnots) {
  const nurbs::NurbsCurve c1(3, {0, 0, 0, 0, 0.3, 0.6, 0.6, 1, 1, 1, 1}, kPoints);
  const std::vector<Continuity> k1 = knot_continuity(c1);
  ASSERT_EQ(k1.size(), 2U);
  EXPECT_EQ(k1[1].multiplicity, 2);
  EXPECT_EQ(k1[1].parametric, 1);
  // Triple knot at 0.5: P3 is on the curve; P2, P3, P4 collinear with |P4 − P3| = 2 |P3 − P2|.
  const std::vector<Vec3> P = {{0, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 1, 0}, {5, 1, 0}, {6, 0, 1}, {7, 0, 0}};
  const nurbs::NurbsCurve g1(3, {0, 0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1, 1}, P);
  const std::vector<Continuity> k = knot_continuity(g1);
  ASSERT_EQ(k.size(), 1U);
  EXPECT_EQ(k[0].multiplicity, 3);
  EXPECT_EQ(k[0].parametric, 0);
  EXPECT_EQ(k[0].geometric, 1);
  EXPECT_NEAR(k[0].tangent_angle, 0.0, 1e-15);
}

// checks the rational circle: constant κ and τ = 0 make it G3 at its doubled knots, and C1 by symmetry.
TEST(Continuity, RationalCircleIsG3) {
  const std::vector<Continuity> k = knot_continuity(testing::rational_circle(3.0));
  ASSERT_EQ(k.size(), 3U);
  for (const Continuity& x : k) {
    EXPECT_EQ(x.geometric, 3);
    EXPECT_GE(x.parametric, 1);
    EXPECT_NEAR(x.curvature_left, 1.0 / 3.0, 1e-12);
  }
}

// checks a join: a cubic Bézier split at its middle, the second half on [0, 2] (half the speed), is G3 but only C0;
// a tangent kink is C0 only; bad options name the field.
TEST(Continuity, Joins) {
  const nurbs::NurbsCurve a(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{0, 0, 0}, {0.5, 1, 0}, {1, 1.25, 0.25}, {1.5, 1.125, 0.5}});
  // The de Casteljau split of {(0,0,0), (1,2,0), (2,1,1), (3,0,1)} at 1/2: second half, knots on [0, 2].
  const nurbs::NurbsCurve b(3, {0, 0, 0, 0, 2, 2, 2, 2}, {{1.5, 1.125, 0.5}, {2, 1, 0.75}, {2.5, 0.5, 1}, {3, 0, 1}});
  const Continuity j = join_continuity(a, b);
  EXPECT_EQ(j.parametric, 0);
  EXPECT_EQ(j.geometric, 3);
  const nurbs::NurbsCurve kink(3, {0, 0, 0, 0, 1, 1, 1, 1}, {{1.5, 1.125, 0.5}, {2, 2, 0}, {3, 3, 0}, {4, 3, 0}});
  EXPECT_EQ(join_continuity(a, kink).geometric, 0);
  ContinuityOptions o;
  o.relative_tolerance = 2.0;
  try {
    (void)join_continuity(a, b, o);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().field, "relative_tolerance");
  }
}

}  // namespace
}  // namespace hula::diffgeom
