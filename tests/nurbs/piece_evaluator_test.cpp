// SPDX-License-Identifier: MIT
// PieceEvaluator and the fixed-degree basis: the same doubles as the curve's span cache and as the
// general basis routine, and no cache built on the way.
#include "hula/nurbs/piece_evaluator.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <string>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/core/rng.hpp"
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

// Two curves with the same data that share nothing (a copy would share the cache).
std::array<NurbsCurve, 2> twins(Rng& rng, const testing::RandomCurveSpec& spec) {
  const NurbsCurve c = testing::random_curve(rng, spec);
  const std::vector<double> U(c.knots().values().begin(), c.knots().values().end());
  const std::vector<Vec3> P(c.control_points().begin(), c.control_points().end());
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

}  // namespace
}  // namespace hula::nurbs
