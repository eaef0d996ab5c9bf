// SPDX-License-Identifier: MIT
// The batch evaluators allocate nothing per point (DESIGN "no allocation in
// per-point loops"): a counting global operator new sees zero allocations
// while a warm curve evaluates thousands of parameters.
#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/core/rng.hpp"
#include "hula/nurbs/nurbs_curve.hpp"
#include "hula/testing/counting_allocator.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::nurbs {
namespace {

// checks: batch position and derivative evaluation allocate 0 times (counting allocator), any degree.
TEST(NurbsCurveAlloc, BatchEvaluationDoesNotAllocate) {
  Rng rng(9);
  for (int i = 0; i < 20; ++i) {
    const NurbsCurve c = testing::random_curve(
        rng, {.degree = i < 15 ? 1 + i % 7 : 10 + i % 4, .rational = (i % 2 == 0), .extra_points = 20});
    std::vector<double> ts(2000);
    for (auto& t : ts) t = rng.uniform(c.domain().start, c.domain().end);
    std::vector<Vec3> out(ts.size() * 4);
    c.derivatives(ts, 3, out);  // warm: builds the span cache
    const long before = testing::allocation_count();
    c.evaluate(ts, std::span<Vec3>(out.data(), ts.size()));
    c.derivatives(ts, 3, out);
    c.derivatives(ts, 3, out, {.side = Side::Left});
    const long after = testing::allocation_count();
    EXPECT_EQ(after - before, 0) << "degree " << c.degree();
    // Single-point calls into a caller's span allocate nothing either (the direct
    // path for degree > kCachedDegreeLimit keeps a per-thread workspace).
    std::array<Vec3, 4> one;
    const long before_single = testing::allocation_count();
    for (double t : ts) c.derivatives(t, 3, one);
    EXPECT_EQ(testing::allocation_count() - before_single, 0) << "degree " << c.degree();
  }
}

// checks: a derivative that overflows double precision is reported as NumericalFailure naming t, never inf.
TEST(NurbsCurveAlloc, OverflowingDerivativeIsReported) {
  const std::vector<Vec3> P = {{0, 0, 0}, {1e299, 0, 0}, {0, 1e299, 0}, {1e299, 1e299, 0}};
  const NurbsCurve c(3, {0, 0, 0, 0, 1e-9, 1e-9, 1e-9, 1e-9}, P);
  EXPECT_TRUE(is_finite(c.evaluate(5e-10)));
  try {
    (void)c.derivatives(5e-10, 3);
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Errc::NumericalFailure);
    EXPECT_NE(std::string(e.what()).find("t = 5.0000000000000003e-10"), std::string::npos) << e.what();
  }
  std::vector<double> ts = {1e-10, 5e-10};
  std::vector<Vec3> out(6);
  EXPECT_THROW(c.derivatives(ts, 2, out), Error);
}

}  // namespace
}  // namespace hula::nurbs
