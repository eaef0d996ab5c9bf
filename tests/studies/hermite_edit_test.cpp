// SPDX-License-Identifier: MIT
// Hermite editing (thesis 7.5.2): with no edit the rebuilt curve is the cubic
// spline (same positions and derivatives at the knots, dense samples equal to
// rounding); an edit gives exactly the edited derivatives at its knot (rotation
// by a known angle, scale) and leaves the other knots' values; the promised
// continuity holds at the knots (C2 for the quintic rebuild, C1 for the cubic);
// bad edits are refused naming the edit and field.
#include "hula/studies/hermite_edit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hula/testing/curve_generators.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::studies {
namespace {

const std::vector<Vec3> kPoints{{0, 0, 0}, {40, 25, 0}, {80, -25, 0}, {120, 0, 0}, {150, 30, 0}};

double vec_error(const Vec3& a, const Vec3& b) { return norm(a - b) / std::max(1.0, norm(b)); }

// checks that without edits both rebuilds reproduce the spline: max deviation over dense samples ~1e-12
// relative to the size, and the handles equal the spline's P', P'' at the knots.
TEST(HermiteEdit, NoEditReproducesSpline) {
  for (HermiteRebuild rebuild : {HermiteRebuild::Quintic, HermiteRebuild::Cubic}) {
    HermiteEditOptions o;
    o.interpolation.dimension = 2;
    o.rebuild = rebuild;
    const HermiteEditResult r = hermite_edit(kPoints, {}, o);
    EXPECT_LT(testing::max_deviation(r.curve, r.spline, 2000), 1e-12 * 150.0);
    for (std::size_t i = 0; i < kPoints.size(); ++i) {
      EXPECT_LT(distance(r.after.points[i], kPoints[i]), 1e-12 * 150.0);
      EXPECT_LT(vec_error(r.after.first[i], r.before.first[i]), 1e-12);
      EXPECT_LT(vec_error(r.after.second[i], r.before.second[i]), 1e-10);
    }
  }
}

// checks an edit at knot 2: P' rotated by 30° about +Z and scaled 1.5, P'' rotated by −20° and scaled 0.5
// (compared with the rotation written out in coordinates), the other knots unchanged, and C2 at the knots.
TEST(HermiteEdit, EditGivesEditedDerivativesOnly) {
  HermiteEditOptions o;
  o.interpolation.dimension = 2;
  const double a = std::numbers::pi / 6.0, b = -std::numbers::pi / 9.0;
  const HandleEdit e{.knot = 2, .tangent_angle = a, .tangent_scale = 1.5, .normal_angle = b, .normal_scale = 0.5};
  const HermiteEditResult r = hermite_edit(kPoints, std::span(&e, 1), o);
  const Vec3 d1 = r.before.first[2], d2 = r.before.second[2];
  const Vec3 e1{1.5 * (std::cos(a) * d1.x - std::sin(a) * d1.y), 1.5 * (std::sin(a) * d1.x + std::cos(a) * d1.y), 0};
  const Vec3 e2{0.5 * (std::cos(b) * d2.x - std::sin(b) * d2.y), 0.5 * (std::sin(b) * d2.x + std::cos(b) * d2.y), 0};
  EXPECT_LT(vec_error(r.after.first[2], e1), 1e-12);
  EXPECT_LT(vec_error(r.after.second[2], e2), 1e-11);
  for (std::size_t i = 0; i < kPoints.size(); ++i) {
    EXPECT_LT(distance(r.after.points[i], kPoints[i]), 1e-10);
    if (i == 2) continue;
    EXPECT_LT(vec_error(r.after.first[i], r.before.first[i]), 1e-12) << i;
    EXPECT_LT(vec_error(r.after.second[i], r.before.second[i]), 1e-10) << i;
  }
  // C2 at the interior knots: left and right derivatives agree.
  for (std::size_t i = 1; i + 1 < kPoints.size(); ++i) {
    const double t = r.after.parameters[i];
    const auto L = r.curve.derivatives(t, 2, {.side = nurbs::Side::Left});
    const auto R = r.curve.derivatives(t, 2, {.side = nurbs::Side::Right});
    EXPECT_LT(vec_error(L[1], R[1]), 1e-11) << i;
    EXPECT_LT(vec_error(L[2], R[2]), 1e-10) << i;
  }
}

// checks the cubic rebuild: a tangent edit is honoured, C1 at the knots, and P'' jumps at the edited knot.
TEST(HermiteEdit, CubicRebuildIsC1) {
  HermiteEditOptions o;
  o.rebuild = HermiteRebuild::Cubic;
  const HandleEdit e{.knot = 1, .tangent_scale = 2.0};
  const HermiteEditResult r = hermite_edit(kPoints, std::span(&e, 1), o);
  EXPECT_LT(vec_error(r.after.first[1], 2.0 * r.before.first[1]), 1e-12);
  const double t = r.after.parameters[1];
  const auto L = r.curve.derivatives(t, 2, {.side = nurbs::Side::Left});
  const auto R = r.curve.derivatives(t, 2, {.side = nurbs::Side::Right});
  EXPECT_LT(vec_error(L[1], R[1]), 1e-12);
  EXPECT_GT(vec_error(L[2], R[2]), 1e-3);
}

// checks a space curve: the default axis is the binormal (the rotated tangent stays in the osculating plane
// and keeps its length), and a given axis is used as given.
TEST(HermiteEdit, SpaceCurveRotatesAboutBinormal) {
  const std::vector<Vec3> pts{{0, 0, 0}, {1, 1, 0.5}, {2, 0, 1}, {3, 1, 0}, {4, 0, 0.3}};
  const HandleEdit e{.knot = 2, .tangent_angle = 0.4};
  const HermiteEditResult r = hermite_edit(pts, std::span(&e, 1));
  const Vec3 d1 = r.before.first[2], d2 = r.before.second[2];
  const Vec3 bn = normalized(cross(d1, d2));
  EXPECT_NEAR(dot(r.after.first[2], bn), 0.0, 1e-12 * norm(d1));
  EXPECT_NEAR(norm(r.after.first[2]), norm(d1), 1e-12 * norm(d1));
  EXPECT_NEAR(std::acos(dot(normalized(r.after.first[2]), normalized(d1))), 0.4, 1e-12);
  const HandleEdit ez{.knot = 2, .tangent_angle = 0.4, .axis = Vec3{0, 0, 2}};
  const HermiteEditResult rz = hermite_edit(pts, std::span(&ez, 1));
  EXPECT_LT(vec_error(rz.after.first[2], rotate_about(d1, {0, 0, 1}, 0.4)), 1e-12);
}

// checks the refusals name the edit and field.
TEST(HermiteEdit, RefusesBadEdits) {
  HermiteEditOptions o;
  const HandleEdit bad_knot{.knot = 9};
  HULA_EXPECT_ERROR(hermite_edit(kPoints, std::span(&bad_knot, 1), o), Errc::InvalidArgument, "edits[0].knot = 9");
  const HandleEdit twice[] = {{.knot = 1}, {.knot = 1}};
  HULA_EXPECT_ERROR(hermite_edit(kPoints, twice, o), Errc::InvalidArgument, "edits[1].knot = 1 is edited twice");
  const HandleEdit bad_scale{.knot = 1, .tangent_scale = 0.0};
  HULA_EXPECT_ERROR(hermite_edit(kPoints, std::span(&bad_scale, 1), o), Errc::InvalidArgument,
                    "edits[0].tangent_scale = 0");
  o.rebuild = HermiteRebuild::Cubic;
  const HandleEdit normal{.knot = 1, .normal_scale = 2.0};
  HULA_EXPECT_ERROR(hermite_edit(kPoints, std::span(&normal, 1), o), Errc::InvalidArgument, "edits[0].normal_angle");
  // A straight space curve has no binormal: a rotation needs an axis.
  const std::vector<Vec3> line{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  const HandleEdit turn{.knot = 1, .tangent_angle = 0.1};
  HULA_EXPECT_ERROR(hermite_edit(line, std::span(&turn, 1)), Errc::InvalidArgument, "edits[0].axis is needed");
}

}  // namespace
}  // namespace hula::studies
