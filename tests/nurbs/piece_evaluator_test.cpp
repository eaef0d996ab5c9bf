// SPDX-License-Identifier: MIT
// PieceEvaluator and the fixed-degree basis: the same doubles as the curve's span cache and as the
// general basis routine, and no cache built on the way.
#include "hula/nurbs/piece_evaluator.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/core/rng.hpp"
#include "hula/core/simd.hpp"
#include "hula/nurbs/arc_length.hpp"
#include "hula/nurbs/basis.hpp"
#include "hula/nurbs/detail/basis_fixed.hpp"
#include "hula/testing/counting_allocator.hpp"
#include "hula/testing/curve_generators.hpp"

namespace hula::nurbs {
namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
bool same_bits(const Vec3& a, const Vec3& b) {
  return same_bits(a.x, b.x) && same_bits(a.y, b.y) && same_bits(a.z, b.z);
}

template <int P>
void expect_fixed_basis_is_general(Rng& rng) {
  for (int trial = 0; trial < 200; ++trial) {
    const NurbsCurve c = testing::random_curve(rng, {.degree = P, .clamped = trial % 2 == 0, .extra_points = 6});
    const KnotVector& K = c.knots();
    const std::size_t n = c.control_points().size() - 1;
    for (std::size_t i = P; i <= n; ++i) {
      if (!(K.values()[i] < K.values()[i + 1])) continue;
      const double t = K.values()[i] + rng.uniform(0.0, 1.0) * (K.values()[i + 1] - K.values()[i]);
      const std::vector<double> general = basis_derivatives(K, i, t, P);
      double fixed[P + 1][P + 1];
      detail::basis_derivatives_fixed<P>(K.values().data(), i, t, fixed);
      for (int k = 0; k <= P; ++k)
        for (int j = 0; j <= P; ++j)
          ASSERT_TRUE(same_bits(fixed[k][j], general[static_cast<std::size_t>(k * (P + 1) + j)]))
              << "degree " << P << " span " << i << " t " << t << " k " << k << " j " << j;
    }
  }
}

// checks: the compile-time-degree basis gives the general A2.3 routine's doubles bit for bit, degrees 1–9,
// clamped and unclamped random knots with repeated interior knots.
TEST(PieceEvaluator, FixedDegreeBasisIsTheGeneralOneBitForBit) {
  Rng rng(2027);
  expect_fixed_basis_is_general<1>(rng);
  expect_fixed_basis_is_general<2>(rng);
  expect_fixed_basis_is_general<3>(rng);
  expect_fixed_basis_is_general<4>(rng);
  expect_fixed_basis_is_general<5>(rng);
  expect_fixed_basis_is_general<6>(rng);
  expect_fixed_basis_is_general<7>(rng);
  expect_fixed_basis_is_general<8>(rng);
  expect_fixed_basis_is_general<9>(rng);
}

// Two curves with the same data that share nothing (a copy would share the cache), poles scaled by `scale`.
std::array<NurbsCurve, 2> twins(Rng& rng, const testing::RandomCurveSpec& spec, double scale = 1.0) {
  const NurbsCurve c = testing::random_curve(rng, spec);
  const std::vector<double> U(c.knots().values().begin(), c.knots().values().end());
  std::vector<Vec3> P(c.control_points().begin(), c.control_points().end());
  for (Vec3& q : P) q *= scale;
  const std::vector<double> W(c.weights().begin(), c.weights().end());
  return {NurbsCurve(c.degree(), U, P, W), NurbsCurve(c.degree(), U, P, W)};
}

// checks: on curves of 5,000+ spans (degrees 1–9, rational or not, clamped or not, repeated knots),
// PieceEvaluator gives the cached evaluator's doubles bit for bit for orders 0–4 at random parameters,
// at every breakpoint (exact points) and at the domain ends, builds no cache (no allocation once warm:
// the cache is three allocations), and sends parameters of several spans, or outside the domain, to the
// curve with the curve's own error.
TEST(PieceEvaluator, SameDoublesAsTheCacheWithoutBuildingIt) {
  Rng rng(27);
  for (int trial = 0; trial < 18; ++trial) {
    const int degree = 1 + trial % 9;
    auto [fresh, cached] = twins(rng, {.degree = degree,
                                       .rational = trial % 2 == 1,
                                       .clamped = trial % 3 != 2,
                                       .extra_points = static_cast<int>(PieceEvaluator::kMinSpans) + 900});
    PieceEvaluator pieces(fresh);
    const Interval dom = fresh.domain();
    const std::vector<double> breaks = fresh.knots().breakpoints();
    std::array<Vec3, 5> a, b;
    const double warm = dom.start;
    pieces.derivatives(std::span<const double>(&warm, 1), 4, a);
    long allocations = 0;  // by the evaluator's calls alone
    const auto counted = [&](std::span<const double> ts, int order, std::span<Vec3> out) {
      const long before = testing::allocation_count();
      pieces.derivatives(ts, order, out);
      allocations += testing::allocation_count() - before;
    };
    for (int order = 0; order <= 4; ++order) {
      const auto size = static_cast<std::size_t>(order) + 1;
      std::vector<double> ts(breaks.begin(), breaks.end());
      for (int k = 0; k < 3000; ++k) ts.push_back(rng.uniform(dom.start, dom.end));
      for (const double t : ts) {
        counted(std::span<const double>(&t, 1), order, std::span<Vec3>(a.data(), size));
        cached.derivatives(std::span<const double>(&t, 1), order, std::span<Vec3>(b.data(), size));
        for (std::size_t k = 0; k < size; ++k)
          ASSERT_TRUE(same_bits(a[k], b[k])) << "degree " << degree << " order " << order << " t " << t << " k " << k;
      }
      // A batch inside one span: 15 points of span 7 (the arc length's rule).
      std::array<double, 15> in;
      for (std::size_t j = 0; j < in.size(); ++j)
        in[j] = breaks[7] + (breaks[8] - breaks[7]) * (static_cast<double>(j) + 0.5) / 15.0;
      std::vector<Vec3> pa(in.size() * size), pb(in.size() * size);
      counted(in, order, pa);
      cached.derivatives(in, order, pb);
      for (std::size_t j = 0; j < pa.size(); ++j) ASSERT_TRUE(same_bits(pa[j], pb[j])) << j;
    }
    EXPECT_EQ(allocations, 0) << "degree " << degree << ": the cache was built";
    // Across spans, and out of the domain: the curve's own answer and error.
    const std::array<double, 2> across{breaks[1] * 0.5 + breaks[2] * 0.5, breaks[5] * 0.5 + breaks[6] * 0.5};
    std::vector<Vec3> pa(4), pb(4);
    pieces.derivatives(across, 1, pa);
    cached.derivatives(across, 1, pb);
    for (std::size_t j = 0; j < pa.size(); ++j) EXPECT_TRUE(same_bits(pa[j], pb[j])) << j;
    const double outside = dom.end + 1.0;
    EXPECT_THROW(pieces.derivatives(std::span<const double>(&outside, 1), 1, pa), Error);
  }
}

// checks: the arc length of a 6,000-span curve through pieces equals, to the last bit, the one computed
// after the curve's cache was built (the cached evaluator), and the closed-form length of a straight line.
TEST(PieceEvaluator, ArcLengthUnchangedByThePieces) {
  // A cubic through 6,003 random poles on uniform clamped knots (C2 everywhere: the quadrature converges).
  Rng rng(5);
  const std::size_t poles = 6003;
  std::vector<double> knots(poles + 4);
  for (std::size_t i = 0; i < knots.size(); ++i)
    knots[i] = static_cast<double>(std::min(std::max<std::size_t>(i, 3), poles)) - 3.0;
  std::vector<Vec3> P(poles);
  for (Vec3& q : P) q = {rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0), rng.uniform(-1.0, 1.0)};
  const NurbsCurve fresh(3, knots, P), cached(3, knots, P);
  (void)cached.evaluate(cached.domain().start);  // builds its cache
  EXPECT_TRUE(same_bits(arc_length(fresh), arc_length(cached)));
  // Control points on a line at uniform knots: the cubic is the segment itself, length |P_n − P_0|.
  const std::size_t n = 6000;
  std::vector<double> U(n + 4);
  for (std::size_t i = 0; i < U.size(); ++i) U[i] = static_cast<double>(std::min(std::max<std::size_t>(i, 3), n)) - 3.0;
  std::vector<Vec3> L(n);
  for (std::size_t i = 0; i < n; ++i) L[i] = Vec3{1.0, 2.0, 2.0} * static_cast<double>(i);
  const NurbsCurve line(3, U, L);
  EXPECT_NEAR(arc_length(line), 3.0 * static_cast<double>(n - 1), 1e-12 * 3.0 * static_cast<double>(n));
}

// checks: a derivative that overflows double precision on a 5,000-span curve is the curve's own
// NumericalFailure naming t, through the pieces as through the cache (spans of 1e-9 under 1e299 poles).
TEST(PieceEvaluator, OverflowIsTheCurvesError) {
  const std::size_t n = 5000;
  std::vector<double> U(n + 4);
  for (std::size_t i = 0; i < U.size(); ++i)
    U[i] = 1e-9 * (static_cast<double>(std::min(std::max<std::size_t>(i, 3), n)) - 3.0);
  std::vector<Vec3> P(n);
  for (std::size_t i = 0; i < n; ++i) P[i] = {i % 2 == 0 ? 0.0 : 1e299, 0.0, 0.0};
  const NurbsCurve fresh(3, U, P), cached(3, U, P);
  PieceEvaluator pieces(fresh);
  const double t = 1e-9 * 2500.5;
  std::array<Vec3, 4> out;
  std::string from_pieces, from_cache;
  try {
    pieces.derivatives(std::span<const double>(&t, 1), 3, out);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Errc::NumericalFailure);
    from_pieces = e.what();
  }
  try {
    cached.derivatives(std::span<const double>(&t, 1), 3, out);
  } catch (const Error& e) {
    from_cache = e.what();
  }
  EXPECT_NE(from_pieces.find("overflows"), std::string::npos) << from_pieces;
  EXPECT_EQ(from_pieces, from_cache);
  // Positions do not overflow: the same doubles.
  Vec3 a, b;
  pieces.derivatives(std::span<const double>(&t, 1), 0, std::span<Vec3>(&a, 1));
  cached.derivatives(std::span<const double>(&t, 1), 0, std::span<Vec3>(&b, 1));
  EXPECT_TRUE(same_bits(a, b));
}

// The speeds of `pieces` at ts against norm() of `cached`'s first derivatives, bit for bit.
void expect_speeds_are_norms(PieceEvaluator& pieces, const NurbsCurve& cached, std::span<const double> ts,
                             const std::string& what) {
  std::vector<double> speed(ts.size());
  pieces.speeds(ts, speed);
  std::vector<Vec3> d(2 * ts.size());
  cached.derivatives(ts, 1, d);
  for (std::size_t i = 0; i < ts.size(); ++i)
    ASSERT_TRUE(same_bits(speed[i], norm(d[2 * i + 1]))) << what << " t " << ts[i] << " i " << i;
}

// checks: speeds() gives norm(C') of the cached evaluator bit for bit at every SIMD level (scalar,
// baseline, AVX2, AVX-512F where the CPU has them), degrees 1–9, rational or not, on curves of 5,000+
// spans (pieces) and of 20 (through the curve's cache): the 15 nodes of a Gauss–Kronrod rule inside a
// span, 1 to 64 random parameters of one span, the breakpoints, parameters of two spans; on a curve
// scaled by 1e-160 (|C'|² below 1e-290, where norm() scales) and by 1e150 (above 1e290) as well.
TEST(PieceEvaluator, SpeedsAreTheNormOfTheDerivativeBitForBit) {
  Rng rng(2712);
  const SimdLevel saved = simd_level();
  for (const SimdLevel level : {SimdLevel::Scalar, SimdLevel::Baseline, SimdLevel::Avx2, SimdLevel::Avx512}) {
    if (level > supported_simd_level()) continue;
    set_simd_level(level);
    for (int trial = 0; trial < 18; ++trial) {
      const int degree = 1 + trial % 9;
      const bool long_curve = trial % 2 == 0;
      const double scale = trial % 6 == 1 ? 1e-160 : trial % 6 == 3 ? 1e150 : 1.0;
      auto [fresh, cached] =
          twins(rng,
                {.degree = degree,
                 .rational = trial % 4 >= 2,
                 .clamped = trial % 3 != 2,
                 .extra_points = long_curve ? static_cast<int>(PieceEvaluator::kMinSpans) + 900 : 20},
                scale);
      const std::string what = std::string(simd_level_name(level)) + " degree " + std::to_string(degree) + " scale " +
                               std::to_string(scale) + (long_curve ? " pieces" : " cache");
      PieceEvaluator pieces(fresh);
      const std::vector<double> breaks = fresh.knots().breakpoints();
      for (int k = 0; k < 300; ++k) {
        const std::size_t s = rng.below(breaks.size() - 1);
        const double b0 = breaks[s], b1 = breaks[s + 1];
        std::array<double, 15> rule;
        for (std::size_t j = 0; j < rule.size(); ++j)
          rule[j] = b0 + (b1 - b0) * (0.5 + 0.49 * std::cos(3.14159 * static_cast<double>(j) / 14.0));
        expect_speeds_are_norms(pieces, cached, rule, what + " rule");
        std::vector<double> ts(1 + rng.below(64));
        for (double& t : ts) t = rng.uniform(b0, b1);
        expect_speeds_are_norms(pieces, cached, ts, what + " random");
      }
      expect_speeds_are_norms(pieces, cached,
                              std::span<const double>(breaks).first(std::min<std::size_t>(64, breaks.size())),
                              what + " breakpoints");
      const std::size_t last = breaks.size() - 1;
      const std::array<double, 2> across{0.5 * (breaks[0] + breaks[1]), 0.5 * (breaks[last - 1] + breaks[last])};
      expect_speeds_are_norms(pieces, cached, across, what + " across");
    }
  }
  set_simd_level(saved);
}

// checks: an overflowing first derivative (1e299 poles on spans of 1e-12) is the curve's NumericalFailure
// through speeds() too.
TEST(PieceEvaluator, SpeedsOverflowIsTheCurvesError) {
  const std::size_t n = 5000;
  std::vector<double> U(n + 4);
  for (std::size_t i = 0; i < U.size(); ++i)
    U[i] = 1e-12 * (static_cast<double>(std::min(std::max<std::size_t>(i, 3), n)) - 3.0);
  std::vector<Vec3> P(n);
  for (std::size_t i = 0; i < n; ++i) P[i] = {i % 2 == 0 ? 0.0 : 1e299, 0.0, 0.0};
  const NurbsCurve fresh(3, U, P), cached(3, U, P);
  PieceEvaluator pieces(fresh);
  const std::array<double, 3> ts{1e-12 * 2500.25, 1e-12 * 2500.5, 1e-12 * 2500.75};
  std::array<double, 3> speed;
  std::array<Vec3, 6> d;
  std::string from_speeds, from_cache;
  try {
    pieces.speeds(ts, speed);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), Errc::NumericalFailure);
    from_speeds = e.what();
  }
  try {
    cached.derivatives(ts, 1, d);
  } catch (const Error& e) {
    from_cache = e.what();
  }
  EXPECT_NE(from_speeds.find("overflows"), std::string::npos) << from_speeds;
  EXPECT_EQ(from_speeds, from_cache);
}

}  // namespace
}  // namespace hula::nurbs
