// SPDX-License-Identifier: MIT
// The batch evaluator's fast paths (issue 27): the run kernels of every instruction set this CPU has
// (hula/core/simd.hpp, nurbs/detail/span_simd.hpp) give bit for bit what the point-by-point path gives, and the
// bucketed span search finds the span std::upper_bound finds (KnotVector::find_span), on knots of very different
// lengths, at knots, next to knots and outside the domain.
#include "hula/nurbs/detail/span_simd.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/core/simd.hpp"
#include "hula/nurbs/basis.hpp"
#include "hula/nurbs/nurbs_curve.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::nurbs {
namespace {

// Restores the instruction-set level when a test ends.
struct LevelGuard {
  SimdLevel saved = simd_level();
  ~LevelGuard() { set_simd_level(saved); }
};

bool bitwise_equal(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

// Parameters that exercise every path: sorted runs, shuffled points, every breakpoint, its neighbours
// one ulp away, and repeated values.
std::vector<double> parameters(const NurbsCurve& c, Rng& rng, bool sorted) {
  const Interval d = c.domain();
  std::vector<double> ts;
  for (int i = 0; i < 300; ++i) ts.push_back(rng.uniform(d.start, d.end));
  for (const double b : c.knots().breakpoints()) {
    ts.push_back(b);
    if (b > d.start) ts.push_back(std::nextafter(b, -HUGE_VAL));
    if (b < d.end) ts.push_back(std::nextafter(b, HUGE_VAL));
  }
  ts.push_back(ts[7]);
  ts.push_back(ts[7]);
  if (sorted) {
    std::sort(ts.begin(), ts.end());
  } else {
    for (std::size_t i = ts.size(); i > 1; --i) std::swap(ts[i - 1], ts[rng.below(i)]);
  }
  return ts;
}

// checks: every instruction set's batch derivatives (orders 0-5, degrees 1-10, rational or not, both
// sides, sorted and shuffled) are bit-identical to the scalar path's and to one call per point.
TEST(SpanSimd, EveryInstructionSetGivesTheScalarPathsDoubles) {
  LevelGuard guard;
  const SimdLevel widest = supported_simd_level();
  Rng rng(2701);
  int compared = 0;
  for (int i = 0; i < 40; ++i) {
    const int degree = 1 + i % 10;
    const NurbsCurve c = testing::random_curve(
        rng, {.degree = degree, .rational = (i % 3 == 0), .clamped = (i % 4 != 1), .extra_points = 12});
    for (const bool sorted : {true, false}) {
      const std::vector<double> ts = parameters(c, rng, sorted);
      for (int order = 0; order <= 5; ++order) {
        for (const Side side : {Side::Right, Side::Left}) {
          const EvalOptions options{.side = side};
          const std::size_t stride = static_cast<std::size_t>(order) + 1;
          set_simd_level(SimdLevel::Scalar);
          std::vector<Vec3> scalar(ts.size() * stride);
          c.derivatives(ts, order, scalar, options);
          std::vector<Vec3> one(ts.size() * stride);
          for (std::size_t k = 0; k < ts.size(); ++k)
            c.derivatives(ts[k], order, std::span<Vec3>(one).subspan(k * stride, stride), options);
          ASSERT_TRUE(bitwise_equal(scalar, one)) << "degree " << degree << " order " << order;
          for (auto level = static_cast<int>(SimdLevel::Baseline); level <= static_cast<int>(widest); ++level) {
            set_simd_level(static_cast<SimdLevel>(level));
            std::vector<Vec3> wide(ts.size() * stride);
            c.derivatives(ts, order, wide, options);
            ASSERT_TRUE(bitwise_equal(scalar, wide))
                << simd_level_name(static_cast<SimdLevel>(level)) << " degree " << degree << " order " << order
                << (c.is_rational() ? " rational" : "") << (sorted ? " sorted" : " shuffled");
            ++compared;
          }
        }
      }
    }
  }
  EXPECT_GT(compared, 0);
}

// The span a parameter belongs to, read off the evaluation: derivatives on a curve whose pieces differ
// (multiplicity-p interior knots: only C0) identify the piece. The reference evaluates the basis
// functions of KnotVector::find_span (std::upper_bound, A2.1) directly.
std::vector<Vec3> direct_derivatives(const NurbsCurve& c, double t, Side side) {
  const std::size_t span = c.knots().find_span(t, side);
  const int p = c.degree();
  const std::vector<double> N = basis_derivatives(c.knots(), span, t, 1);
  std::vector<Vec3> d(2);
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j <= p; ++j)
      d[static_cast<std::size_t>(k)] +=
          N[static_cast<std::size_t>(k * (p + 1) + j)] * c.control_points()[span - static_cast<std::size_t>(p - j)];
  return d;
}

// checks: the bucketed span search picks find_span's span (first derivatives agree to 1e-9 relative on
// C0 curves, where a neighbouring piece's derivative differs by O(1)) for knot spacings from 1e-9 to 1
// in one vector, clamped and Domain::Extrapolate parameters outside the domain, both sides.
TEST(SpanSimd, BucketedSpanSearchAgreesWithUpperBound) {
  Rng rng(27);
  for (int trial = 0; trial < 12; ++trial) {
    const int p = 2 + trial % 3;
    // Interior breakpoints with spacings spread over nine decades (clusters and long spans together),
    // each of multiplicity p (C0 joins).
    // The end spans have length 1, so extrapolating 0.5 beyond them stays well conditioned.
    std::vector<double> breaks = {0.0, 1.0};
    for (int i = 0; i < 40; ++i) breaks.push_back(breaks.back() + std::pow(10.0, -rng.uniform(0.0, 9.0)));
    breaks.push_back(breaks.back() + 1.0);
    std::vector<double> U(static_cast<std::size_t>(p) + 1, breaks.front());
    for (std::size_t i = 1; i + 1 < breaks.size(); ++i) U.insert(U.end(), static_cast<std::size_t>(p), breaks[i]);
    U.insert(U.end(), static_cast<std::size_t>(p) + 1, breaks.back());
    std::vector<Vec3> P(U.size() - static_cast<std::size_t>(p) - 1);
    for (auto& q : P) q = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    const NurbsCurve c(p, U, P);
    std::vector<double> ts;
    for (const double b : breaks) {
      ts.push_back(b);
      ts.push_back(std::nextafter(b, -HUGE_VAL));
      ts.push_back(std::nextafter(b, HUGE_VAL));
    }
    for (std::size_t i = 0; i + 1 < breaks.size(); ++i)
      for (int k = 0; k < 5; ++k) ts.push_back(rng.uniform(breaks[i], breaks[i + 1]));
    ts.push_back(-0.5);
    ts.push_back(breaks.back() + 0.5);
    for (std::size_t i = ts.size(); i > 1; --i) std::swap(ts[i - 1], ts[rng.below(i)]);
    for (const Side side : {Side::Right, Side::Left}) {
      std::vector<Vec3> out(2 * ts.size());
      c.derivatives(ts, 1, out, {.side = side, .domain = Domain::Extrapolate});
      for (std::size_t i = 0; i < ts.size(); ++i) {
        const std::vector<Vec3> ref = direct_derivatives(c, ts[i], side);
        const double scale = std::max(1.0, max_abs(ref[1]));
        ASSERT_LE(max_abs(out[2 * i + 1] - ref[1]), 1e-9 * scale)
            << "t = " << ts[i] << (side == Side::Left ? " (left)" : " (right)") << " trial " << trial;
      }
    }
  }
}

// checks: set_simd_level's cap at the supported level, the level names, and that the scalar level
// turns the run kernels off.
TEST(SpanSimd, LevelIsCappedAtTheSupportedOne) {
  LevelGuard guard;
  set_simd_level(SimdLevel::Avx512);
  EXPECT_LE(static_cast<int>(simd_level()), static_cast<int>(supported_simd_level()));
  EXPECT_EQ(set_simd_level(SimdLevel::Scalar), supported_simd_level());
  EXPECT_EQ(simd_level(), SimdLevel::Scalar);
  EXPECT_EQ(simd_level_name(SimdLevel::Avx2), "avx2");
  EXPECT_EQ(detail::run_kernel(3, false, 3), nullptr);  // scalar: point by point
}

}  // namespace
}  // namespace hula::nurbs
