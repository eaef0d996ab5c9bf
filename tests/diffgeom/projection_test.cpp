// SPDX-License-Identifier: MIT
// Bounding-box projections and reconstruction (thesis 8.1): the XY/YZ/ZX
// projections lie on the box faces and keep the in-plane coordinates; the curve
// rebuilt from an unedited projection is the original; an edit of the projection
// moves only in-plane coordinates; incompatible projections are refused.
#include "hula/diffgeom/projection.hpp"

#include <gtest/gtest.h>

#include "hula/core/error.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::diffgeom {
namespace {

// checks projections on all three planes and the exact round trip projection → reconstruction.
TEST(Projection, ProjectAndReconstruct) {
  Rng rng(21);
  const nurbs::NurbsCurve c = testing::random_curve(rng, {.degree = 3, .rational = true});
  for (Plane plane : {Plane::XY, Plane::YZ, Plane::ZX}) {
    const std::size_t k = plane == Plane::XY ? 2 : (plane == Plane::YZ ? 0 : 1);
    const nurbs::NurbsCurve p = project(c, plane);
    for (int i = 0; i <= 50; ++i) {
      const double t = c.domain().start + c.domain().length() * i / 50.0;
      const Vec3 a = c.evaluate(t), b = p.evaluate(t);
      EXPECT_NEAR(b[k], c.control_box().min[k], 1e-12);
      for (std::size_t j = 0; j < 3; ++j) {
        if (j != k) {
          EXPECT_NEAR(a[j], b[j], 1e-12);
        }
      }
    }
    EXPECT_EQ(reconstruct_from_projection(c, p, plane), c);
  }
}

// checks an edit of the XY projection: x, y follow the edit, z stays; a different knot vector is refused.
TEST(Projection, EditedProjection) {
  const nurbs::NurbsCurve c(3, {0, 0, 0, 0, 0.5, 1, 1, 1, 1}, {{0, 0, 1}, {1, 2, 3}, {2, 0, -1}, {3, 1, 2}, {4, 0, 0}});
  nurbs::NurbsCurve p = project(c, Plane::XY);
  std::vector<Vec3> P(p.control_points().begin(), p.control_points().end());
  P[2] = {2.5, 1.5, P[2].z};
  const nurbs::NurbsCurve edited(p.knots(), P);
  const nurbs::NurbsCurve r = reconstruct_from_projection(c, edited, Plane::XY);
  EXPECT_EQ(r.control_points()[2].x, 2.5);
  EXPECT_EQ(r.control_points()[2].y, 1.5);
  EXPECT_EQ(r.control_points()[2].z, -1.0);
  const nurbs::NurbsCurve other(3, {0, 0, 0, 0, 0.4, 1, 1, 1, 1}, P);
  try {
    (void)reconstruct_from_projection(c, other, Plane::XY);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.where().field, "knots");
  }
}

}  // namespace
}  // namespace hula::diffgeom
