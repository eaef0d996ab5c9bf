// SPDX-License-Identifier: MIT
// Unit tests of knot_removal.hpp against closed forms: an inserted knot is
// removed exactly (the inverse of Boehm's insertion), the removal bound of a
// polyline's vertex is its distance from the chord, and bad input is refused
// by name.
#include "hula/nurbs/knot_removal.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/nurbs/refine.hpp"
#include "hula/testing/curve_generators.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::nurbs {
namespace {

// checks: the rational quadratic circle with u = 0.3 inserted twice comes back knot for knot, and its
// control points and weights to 1e-12, after removing u twice with tolerance 0 (closed form: insertion's inverse).
TEST(KnotRemoval, InsertedKnotsOfTheCircleAreRemovedExactly) {
  const NurbsCurve circle = testing::rational_circle(2.0);
  const NurbsCurve refined = insert_knot(circle, 0.3, 2);
  const KnotRemovalResult r = remove_knot(refined, 0.3, 2, 0.0);
  EXPECT_EQ(r.removed, 2u);
  EXPECT_LE(r.error_bound, 1e-12 * circle.model_size());
  ASSERT_EQ(r.curve.knots(), circle.knots());
  for (std::size_t i = 0; i < circle.control_points().size(); ++i) {
    EXPECT_LE(distance(r.curve.control_points()[i], circle.control_points()[i]), 1e-12) << i;
    EXPECT_NEAR(r.curve.weights()[i], circle.weights()[i], 1e-12) << i;
  }
}

// checks: the knots of the circle itself are not removable at 1e-3 (removing a double knot of a rational
// quadratic arc would change the circle by far more), and the curve is returned unchanged.
TEST(KnotRemoval, TheCirclesOwnKnotsStay) {
  const NurbsCurve circle = testing::rational_circle(2.0);
  const KnotRemovalResult r = remove_knots(circle, 1e-3);
  EXPECT_EQ(r.removed, 0u);
  EXPECT_EQ(r.curve.knots(), circle.knots());
  EXPECT_EQ(r.error_bound, 0.0);
}

// checks: the polyline (0,0)-(1,1)-(2,0) with knots {0,0,½,1,1}: removing ½ replaces the vertex by the chord
// point (1,0) at the same parameter, so the bound is exactly 1 (the vertex's distance) and the curve moves by
// exactly 1 at t = ½; tolerance 0.99 keeps the knot, tolerance 1 removes it.
TEST(KnotRemoval, PolylineVertexBoundIsItsDistanceFromTheChord) {
  const NurbsCurve polyline(1, {0, 0, 0.5, 1, 1}, {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}});
  EXPECT_EQ(remove_knot(polyline, 0.5, 1, 0.99).removed, 0u);
  const KnotRemovalResult r = remove_knot(polyline, 0.5, 1, 1.0);
  ASSERT_EQ(r.removed, 1u);
  EXPECT_DOUBLE_EQ(r.error_bound, 1.0);
  ASSERT_EQ(r.curve.control_points().size(), 2u);
  EXPECT_EQ(r.curve.control_points()[0], (Vec3{0, 0, 0}));
  EXPECT_EQ(r.curve.control_points()[1], (Vec3{2, 0, 0}));
  EXPECT_DOUBLE_EQ(distance(r.curve.evaluate(0.5), polyline.evaluate(0.5)), 1.0);
}

// checks: a seeded random cubic refined with 20 knots gets back exactly its own knot vector and control points
// (to 1e-12 of its size) from remove_knots at 1e-9: every inserted knot is removable at zero cost, none of the
// random curve's own knots is.
TEST(KnotRemoval, RemoveKnotsUndoesARefinement) {
  Rng rng(2026);
  for (int trial = 0; trial < 20; ++trial) {
    const NurbsCurve c = testing::random_curve(rng, {.degree = 3, .rational = trial % 2 == 1, .extra_points = 5});
    const Interval d = c.domain();
    std::vector<double> X;
    for (int j = 1; j <= 20; ++j) {
      const double u = d.start + d.length() * (j - 0.5) / 20.0;
      if (c.knots().multiplicity(u) == 0) X.push_back(u);
    }
    const NurbsCurve refined = refine_knots(c, X);
    const KnotRemovalResult r = remove_knots(refined, 1e-9 * c.model_size());
    ASSERT_EQ(r.removed, X.size()) << trial;
    ASSERT_EQ(r.curve.knots(), c.knots()) << trial;
    for (std::size_t i = 0; i < c.control_points().size(); ++i)
      EXPECT_LE(distance(r.curve.control_points()[i], c.control_points()[i]), 1e-10 * c.model_size()) << trial;
  }
}

// checks: 60 seeded random curves (degrees 1–5, half rational), refined with 16 knots and their control points
// then moved by up to 1e-5 of the size (so removals cost something; a removal amplifies the move by up
// to 1/α per sweep step): remove_knots at 1 % of the size removes
// knots from every one, and the sampled distance to the input at equal parameters (4001 samples) stays within
// the reported bound, itself within the tolerance.
TEST(KnotRemoval, BoundHoldsOnPerturbedRefinedCurves) {
  Rng rng(77);
  for (int trial = 0; trial < 60; ++trial) {
    const NurbsCurve base = testing::random_curve(rng, {.degree = 1 + trial % 5, .rational = trial % 2 == 1});
    const Interval d = base.domain();
    std::vector<double> X;
    for (int j = 1; j <= 16; ++j)
      if (base.knots().multiplicity(d.start + d.length() * j / 17.0) == 0) X.push_back(d.start + d.length() * j / 17.0);
    const NurbsCurve refined = refine_knots(base, X);
    std::vector<Vec3> points(refined.control_points().begin(), refined.control_points().end());
    const double size = base.model_size();
    for (Vec3& q : points) q = q + Vec3{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)} * (1e-5 * size);
    const NurbsCurve c(refined.knots(), points, {refined.weights().begin(), refined.weights().end()},
                       refined.dimension());
    const double tol = 0.01 * size;
    const KnotRemovalResult r = remove_knots(c, tol);
    EXPECT_GT(r.removed, 0u) << trial << " degree " << c.degree() << (c.is_rational() ? " rational" : "");
    EXPECT_GT(r.error_bound, 0.0) << trial;
    EXPECT_LE(r.error_bound, tol) << trial;
    EXPECT_LE(testing::max_deviation(c, r.curve, 4000), r.error_bound + 1e-12 * size) << trial;
  }
}

// checks: every documented refusal names its input.
TEST(KnotRemoval, RefusesBadInput) {
  const NurbsCurve c(3, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}, {{0, 0, 0}, {1, 2, 0}, {2, 2, 0}, {3, 0, 0}, {4, 1, 0}});
  HULA_EXPECT_ERROR(remove_knot(c, 0.25, 1, 0.1), Errc::InvalidArgument, "u = 0.25");
  HULA_EXPECT_ERROR(remove_knot(c, 0.0, 1, 0.1), Errc::InvalidArgument, "u = 0");
  HULA_EXPECT_ERROR(remove_knot(c, 0.5, 0, 0.1), Errc::InvalidArgument, "times");
  HULA_EXPECT_ERROR(remove_knot(c, std::nan(""), 1, 0.1), Errc::NonFiniteInput, "u");
  HULA_EXPECT_ERROR(remove_knot(c, 0.5, 1, -1.0), Errc::InvalidArgument, "tolerance");
  HULA_EXPECT_ERROR(remove_knots(c, std::numeric_limits<double>::infinity()), Errc::NonFiniteInput, "tolerance");
}

}  // namespace
}  // namespace hula::nurbs
