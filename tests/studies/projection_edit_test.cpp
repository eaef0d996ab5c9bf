// SPDX-License-Identifier: MIT
// Projection editing (thesis 8.1): the identity edit reproduces the curve, an
// edit with a different structure (degree, knots, domain) changes exactly the
// two in-plane components and keeps the third one at the normalised parameter,
// a non-planar edit is refused naming the control point, and the common
// structure leaves both curves unchanged.
#include "hula/studies/projection_edit.hpp"

#include <gtest/gtest.h>

#include "hula/core/rng.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/nurbs/reparam.hpp"
#include "hula/testing/curve_generators.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::studies {
namespace {

using diffgeom::Plane;

// checks that the identity edit (the unedited projection) reproduces the curve on every plane, exactly.
TEST(ProjectionEdit, IdentityEditReproducesCurve) {
  Rng rng(3);
  const nurbs::NurbsCurve c = testing::random_curve(rng, {.degree = 3});
  for (Plane plane : {Plane::XY, Plane::YZ, Plane::ZX}) {
    const ProjectionEditResult r = edit_projection(c, diffgeom::project(c, plane), plane);
    EXPECT_EQ(r.curve, c);
    EXPECT_EQ(r.max_deviation, 0.0);
  }
}

// checks that an edit given as a differently built curve (another degree, knots and domain) changes exactly
// the two in-plane components: x, z follow the edit and y is the original's at the same normalised parameter.
TEST(ProjectionEdit, EditChangesExactlyTwoComponents) {
  const std::vector<Vec3> pts{{0, 0, 0}, {1, 2, 1}, {2, 3, -1}, {3, 2, 0.5}, {4, 0, 0}};
  const nurbs::NurbsCurve original = nurbs::interpolate_cubic(pts);
  const std::vector<Vec3> edit_pts{{0, 7, 0}, {1.5, 7, 2}, {2.5, 7, -2}, {4, 7, 1}};
  nurbs::InterpolationOptions io;
  io.parameterisation = nurbs::Parameterisation::Uniform;
  const nurbs::NurbsCurve edited = nurbs::reparameterise(nurbs::interpolate_cubic(edit_pts, io), {2.0, 5.0});
  const ProjectionEditResult r = edit_projection(original, edited, Plane::ZX);
  EXPECT_LT(r.max_deviation, 1e-12);
  for (int i = 0; i <= 100; ++i) {
    const double u = i / 100.0;
    const Vec3 a = r.curve.evaluate(u), o = original.evaluate(u), e = edited.evaluate(2.0 + 3.0 * u);
    EXPECT_NEAR(a.x, e.x, 1e-12) << "u = " << u;
    EXPECT_NEAR(a.z, e.z, 1e-12) << "u = " << u;
    EXPECT_NEAR(a.y, o.y, 1e-12) << "u = " << u;
  }
}

// checks that common_structure leaves both curves unchanged and gives them one degree and knot vector.
TEST(ProjectionEdit, CommonStructureKeepsCurves) {
  Rng rng(5);
  const nurbs::NurbsCurve a = testing::random_curve(rng, {.degree = 2});
  const nurbs::NurbsCurve b = testing::random_curve(rng, {.degree = 4});
  const CommonStructure c = common_structure(a, b);
  EXPECT_EQ(c.first.degree(), 4);
  EXPECT_TRUE(c.first.knots() == c.second.knots());
  for (int i = 0; i <= 200; ++i) {
    const double u = i / 200.0;
    EXPECT_LT(distance(c.first.evaluate(u), a.evaluate(a.domain().start * (1 - u) + a.domain().end * u)), 1e-9);
    EXPECT_LT(distance(c.second.evaluate(u), b.evaluate(b.domain().start * (1 - u) + b.domain().end * u)), 1e-9);
  }
}

// checks that an edit that is not planar in the chosen plane is refused, naming the member and control point,
// and that plane names are parsed strictly.
TEST(ProjectionEdit, RefusesNonPlanarEditAndBadPlane) {
  const std::vector<Vec3> pts{{0, 0, 0}, {1, 2, 1}, {2, 3, -1}, {3, 2, 0.5}};
  const nurbs::NurbsCurve c = nurbs::interpolate_cubic(pts);
  HULA_EXPECT_ERROR(edit_projection(c, c, Plane::XY), Errc::InvalidArgument, "edited is not planar in xy");
  HULA_EXPECT_ERROR(edit_projection(c, c, Plane::XY), Errc::InvalidArgument, "control_points[1].z");
  HULA_EXPECT_ERROR(plane_from_name("xz"), Errc::InvalidArgument, "\"xz\" is not a plane");
  EXPECT_EQ(plane_from_name("yz"), Plane::YZ);
}

}  // namespace
}  // namespace hula::studies
