// SPDX-License-Identifier: MIT
// The tape allocates nothing per point (DESIGN "no allocation in per-point
// loops"): a counting global operator new sees zero allocations while a warm
// tape evaluates thousands of parameters, single-point and batch, including a
// NURBS leaf.
#include <gtest/gtest.h>

#include <vector>

#include "hula/law/parser.hpp"
#include "hula/law/tape.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/testing/counting_allocator.hpp"

namespace hula::law {
namespace {

// checks: single-point, batch and CurveEvaluator evaluation allocate 0 times (counting allocator).
TEST(LawTapeAlloc, EvaluationDoesNotAllocate) {
  const nurbs::NurbsCurve curve =
      nurbs::interpolate_cubic(std::vector<Vec3>{{0, 0, 0}, {1, 1, 0}, {2, 0, 1}, {3, 1, 1}, {4, 2, 0}});
  Context ctx;
  const Law t = ctx.parameter("t");
  const Law law = parse("vec(2*cos(t), 2*sin(t), 0.5*t)", ctx) * 0.1 + ctx.curve(curve, t / 13.0, "spine");
  const CurveEvaluator ev(law, "t", 3);
  std::vector<double> ts(2000);
  for (std::size_t i = 0; i < ts.size(); ++i) ts[i] = 12.0 * static_cast<double>(i) / 1999.0;
  std::vector<Vec3> out(ts.size() * 4);
  (void)ev.derivatives(ts, out);  // warm: per-thread buffer and the curve's span cache
  Workspace w = ev.tape().make_workspace();
  std::vector<double> raw(ts.size() * ev.tape().output_count());
  std::vector<std::uint8_t> ok(ts.size());
  const long before = testing::allocation_count();
  EXPECT_EQ(ev.derivatives(ts, out), 0U);
  EXPECT_EQ(ev.tape().evaluate(ts, raw, w, ok), 0U);
  for (double x : ts) (void)ev.tape().evaluate(std::span<const double>(&x, 1), std::span<double>(raw.data(), 12), w);
  EXPECT_EQ(testing::allocation_count() - before, 0);
}

}  // namespace
}  // namespace hula::law
