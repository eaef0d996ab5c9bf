// SPDX-License-Identifier: MIT
// The natural kind of the curve value type against closed forms: the circle
// κ = 1 (planar, eq. 34) and the helix κ = 0.8, τ = 0.4 (radius 1, pitch 0.5)
// from their start frames; bad data refused by name.
#include "hula/intrinsic/natural_curve.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hula/core/error.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::intrinsic {
namespace {

// checks: κ = 1 from the origin along +X turning to +Y is (sin s, 1 − cos s) within the tolerance.
TEST(NaturalCurve, UnitCircleFromItsCurvature) {
  curve::NaturalData d;
  d.curvature = "1";
  d.length = std::numbers::pi;
  const curve::Curve c = natural_curve(d, 1e-7);
  EXPECT_EQ(c.kind(), curve::Kind::Natural);
  EXPECT_EQ(c.law(), nullptr);
  EXPECT_EQ(c.domain().end, std::numbers::pi);
  EXPECT_LE(c.approximation_deviation(), 1e-7);
  for (int i = 0; i <= 20; ++i) {
    const double s = std::numbers::pi * i / 20.0;
    EXPECT_LT(distance(c.point(s), Vec3{std::sin(s), 1.0 - std::cos(s), 0.0}), 1e-7) << "s = " << s;
  }
}

// checks: κ = 0.8, τ = 0.4 is the helix of radius κ/(κ²+τ²) = 1 and pitch τ/(κ²+τ²) = 0.5, seen in
// the start frame (T0, N0, B0) = (X, Y, Z): r(s) = (T·d, N·d, B·d) with d the standard helix minus
// its start point and T, N, B its frame at φ = 0.
TEST(NaturalCurve, HelixFromConstantCurvatureAndTorsion) {
  curve::NaturalData d;
  d.curvature = "0.8";
  d.torsion = "0.4";
  d.length = 10.0;
  d.start_point = {1, 2, 3};
  const curve::Curve c = natural_curve(d, 1e-6);
  const double a = 1.0, b = 0.5, k = std::sqrt(a * a + b * b);
  const Vec3 T{0, a / k, b / k}, N{-1, 0, 0}, B{0, -b / k, a / k};
  for (int i = 0; i <= 20; ++i) {
    const double s = 10.0 * i / 20.0, phi = s / k;
    const Vec3 dd = Vec3{a * std::cos(phi), a * std::sin(phi), b * phi} - Vec3{a, 0, 0};
    EXPECT_LT(distance(c.point(s), Vec3{1 + dot(T, dd), 2 + dot(N, dd), 3 + dot(B, dd)}), 1e-6) << "s = " << s;
  }
}

// checks: bad expressions, lengths, frames and tolerances are refused naming the member.
TEST(NaturalCurve, RefusesBadDataByName) {
  curve::NaturalData d;
  d.curvature = "1 +";
  HULA_EXPECT_ERROR(natural_curve(d, 1e-6), Errc::ParseError, "curvature");
  d.curvature = "vec(s, s)";
  HULA_EXPECT_ERROR(natural_curve(d, 1e-6), Errc::ParseError, "curvature");
  d.curvature = "1";
  d.torsion = "t";
  HULA_EXPECT_ERROR(natural_curve(d, 1e-6), Errc::ParseError, "torsion");
  d.torsion = "0";
  d.length = -1.0;
  HULA_EXPECT_ERROR(natural_curve(d, 1e-6), Errc::InvalidArgument, "length");
  d.length = 1.0;
  d.start_normal = {1, 0, 0};
  HULA_EXPECT_ERROR(natural_curve(d, 1e-6), Errc::InvalidArgument, "start_frame.normal");
  d.start_normal = {0, 1, 0};
  HULA_EXPECT_ERROR(natural_curve(d, 0.5), Errc::InvalidArgument, "tolerance");
}

}  // namespace
}  // namespace hula::intrinsic
