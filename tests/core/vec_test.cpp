// SPDX-License-Identifier: MIT
// Vec3 arithmetic and overflow/underflow-safe norms.
#include "hula/core/vec.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "hula/core/tolerance.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula {
namespace {

// checks: |(3,4,12)| = 13 at unit scale and at 1e±200, where naive squares overflow or underflow.
TEST(Vec3, NormIsScaleSafe) {
  for (double s : {1.0, 1e-200, 1e200, 1e-300, 1e300}) {
    const Vec3 v{3 * s, 4 * s, 12 * s};
    EXPECT_DOUBLE_EQ(norm(v) / s, 13.0) << s;
    const Vec3 u = normalized(v);
    EXPECT_DOUBLE_EQ(u.z, 12.0 / 13.0) << s;
  }
  EXPECT_EQ(norm(Vec3{}), 0.0);
  EXPECT_TRUE(std::isnan(normalized(Vec3{}).x));
}

// checks: cross product is right-handed and dot is bilinear (closed forms).
TEST(Vec3, CrossAndDot) {
  const Vec3 x{1, 0, 0}, y{0, 1, 0};
  EXPECT_EQ(cross(x, y), (Vec3{0, 0, 1}));
  EXPECT_EQ(dot(x + 2 * y, y), 2.0);
  EXPECT_EQ((Vec3{1, 2, 3} - Vec3{1, 2, 3}), Vec3{});
}

// checks: boxes grow to contain points and report their diagonal safely.
TEST(Box3, DiagonalAndExtent) {
  Box3 b;
  EXPECT_TRUE(b.empty());
  b.add({1e200, 0, 0});
  b.add({-1e200, 0, 0});
  EXPECT_DOUBLE_EQ(b.diagonal(), 2e200);
  EXPECT_DOUBLE_EQ(b.extent(), 1e200);
}

// checks: the resolution scales down with tiny models and never drops below rounding noise.
TEST(Tolerance, ResolutionForSize) {
  const Tolerance tol;
  EXPECT_DOUBLE_EQ(resolution_for_size(tol, 100.0), 1e-6);
  EXPECT_DOUBLE_EQ(resolution_for_size(tol, 1e-200), 1e-206);
  EXPECT_DOUBLE_EQ(resolution_for_size(tol, 1e200), 1e186);
  HULA_EXPECT_ERROR((Tolerance{.resabs = -1.0}.validate()), Errc::InvalidOption, "resabs = -1");
  HULA_EXPECT_ERROR((Tolerance{.angular = NAN}.validate()), Errc::InvalidOption, "angular = nan");
}

}  // namespace
}  // namespace hula
