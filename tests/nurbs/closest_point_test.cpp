// SPDX-License-Identifier: MIT
// Closest point: points around a circle project radially (closed form), far
// and out-of-plane points, allocation-free Newton, errors. Random-curve
// properties: closest_point_property_test.cpp.
#include "hula/nurbs/closest_point.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <numbers>
#include <vector>

#include "hula/testing/curve_generators.hpp"
#include "hula/testing/expect_error.hpp"

// Counting allocator for the allocation-free checks (STYLE.md: hot loops are
// checked with a counting allocator, not with timing).
namespace {
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace hula::nurbs {
namespace {

NurbsCurve circle(double R) {
  const double w = std::sqrt(0.5);
  return NurbsCurve(
      2, {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1},
      {{R, 0, 0}, {R, R, 0}, {0, R, 0}, {-R, R, 0}, {-R, 0, 0}, {-R, -R, 0}, {0, -R, 0}, {R, -R, 0}, {R, 0, 0}},
      {1, w, 1, w, 1, w, 1, w, 1}, 2);
}

// checks: points off a circle project radially: foot R(cos θ, sin θ), distance |r - R| (closed form).
TEST(ClosestPoint, CircleProjectsRadially) {
  const double R = 4.0;
  const NurbsCurve c = circle(R);
  for (double r : {0.3 * R, 0.999 * R, 1.5 * R, 100 * R}) {
    for (int k = 0; k < 37; ++k) {
      const double theta = 2 * std::numbers::pi * (k + 0.3) / 37.0;
      const Vec3 dir{std::cos(theta), std::sin(theta), 0};
      const ClosestPointResult res = closest_point(c, r * dir);
      EXPECT_LT(distance(res.point, R * dir), 1e-9 * R) << "r = " << r << " theta = " << theta;
      EXPECT_NEAR(res.distance, std::fabs(r - R), 1e-12 * R) << "r = " << r << " theta = " << theta;
      EXPECT_EQ(res.point, c.evaluate(res.t));
    }
  }
}

// checks: a point far away (1e12 R) and one out of plane project onto the circle (closed form).
TEST(ClosestPoint, FarAndOutOfPlanePoints) {
  const NurbsCurve c = circle(1.0);
  const ClosestPointResult far = closest_point(c, {0, -1e12, 0});
  EXPECT_LT(distance(far.point, {0, -1, 0}), 1e-9);
  EXPECT_NEAR(far.distance, 1e12 - 1.0, 1e-3);
  const ClosestPointResult above = closest_point(c, {3, 4, 12});
  EXPECT_LT(distance(above.point, {0.6, 0.8, 0}), 1e-9);
  EXPECT_NEAR(above.distance, std::hypot(4.0, 12.0), 1e-12);
}

// checks: documented errors carry their code and name the offending field.
TEST(ClosestPoint, ErrorsNameTheInput) {
  const NurbsCurve c = circle(1.0);
  HULA_EXPECT_ERROR(closest_point(c, {0, NAN, 0}), Errc::NonFiniteInput, "point[1]");
  HULA_EXPECT_ERROR(closest_point(c, {0, 0, 0}, {.samples_per_span = 1}), Errc::InvalidOption,
                    "options.samples_per_span = 1");
  HULA_EXPECT_ERROR(closest_point(c, {0, 0, 0}, {.max_iterations = 0}), Errc::InvalidOption,
                    "options.max_iterations = 0");
  HULA_EXPECT_ERROR(closest_point(c, {0, 0, 0}, {.tolerance = {.resabs = -1.0}}), Errc::InvalidOption, "resabs");
}

// checks: Newton iterations do not allocate: 1 and 50 iterations per start make the same number
// of allocations (counting allocator).
TEST(ClosestPoint, NewtonLoopIsAllocationFree) {
  const NurbsCurve c = circle(2.0);
  (void)closest_point(c, {1, 1, 0});  // builds the evaluation cache
  const auto count = [&](int iterations) {
    const long before = g_allocations.load();
    (void)closest_point(c, {3, 1, 0.5}, {.max_iterations = iterations});
    return g_allocations.load() - before;
  };
  EXPECT_EQ(count(1), count(50));
}

}  // namespace
}  // namespace hula::nurbs
