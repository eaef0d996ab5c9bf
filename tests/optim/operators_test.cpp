// SPDX-License-Identifier: MIT
// Statistical tests of the GA operators: roulette frequencies, the level-resolved
// probability, tournament pressure, SBX spread distribution, polynomial and bit
// mutation rates, crossover bit conservation. Fixed seeds: deterministic.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/optim/crossover.hpp"
#include "hula/optim/detail/fixed_power.hpp"
#include "hula/optim/detail/power.hpp"
#include "hula/optim/mutation.hpp"
#include "hula/optim/selection.hpp"

namespace hula::optim {
namespace {

// checks: roulette frequencies against fitness proportions with a chi-square bound (3 dof, p = 0.001 -> 16.27)
TEST(OptimOperators, RouletteFrequenciesProportionalToFitness) {
  const std::vector<double> fitness = {1.0, 2.0, 0.0, 3.0, 4.0};
  RouletteWheel wheel;
  wheel.reset(fitness);
  Rng rng(42, 0);
  const int spins = 50000;
  std::vector<int> hits(fitness.size(), 0);
  for (int s = 0; s < spins; ++s) ++hits[wheel.spin(rng)];
  EXPECT_EQ(hits[2], 0) << "zero fitness must never be selected";
  double chi2 = 0.0;
  for (std::size_t i = 0; i < fitness.size(); ++i) {
    if (fitness[i] == 0.0) continue;
    const double expected = spins * fitness[i] / 10.0;
    chi2 += (hits[i] - expected) * (hits[i] - expected) / expected;
  }
  EXPECT_LT(chi2, 16.27);
  // All-zero fitness falls back to uniform choice.
  const std::vector<double> zeros(4, 0.0);
  wheel.reset(zeros);
  std::vector<int> uniform_hits(4, 0);
  for (int s = 0; s < 4000; ++s) ++uniform_hits[wheel.spin(rng)];
  for (const int h : uniform_hits) EXPECT_NEAR(h, 1000, 150);
}

// checks: chance(p, level) rate against round(p 10^level) / 10^level within 5 binomial sigma
TEST(OptimOperators, ChanceResolvesProbabilityToLevel) {
  Rng rng(7, 1);
  const int n = 200000;
  const auto rate = [&](double p, unsigned level) {
    int k = 0;
    for (int i = 0; i < n; ++i) k += chance(rng, p, level) ? 1 : 0;
    return static_cast<double>(k) / n;
  };
  const auto tol = [&](double p) { return 5.0 * std::sqrt(p * (1 - p) / n) + 1e-9; };
  EXPECT_NEAR(rate(0.013, 2), 0.01, tol(0.01));
  EXPECT_NEAR(rate(0.013, 3), 0.013, tol(0.013));
  EXPECT_NEAR(rate(0.3, 0), 0.3, tol(0.3));
  EXPECT_NEAR(rate(0.004, 2), 0.0, 1e-12);
  EXPECT_EQ(rate(1.0, 1), 1.0);
  EXPECT_EQ(rate(0.0, 0), 0.0);
}

// checks: binary tournament selection probabilities against the closed form (2(n-r)-1)/n^2 for rank r
TEST(OptimOperators, TournamentPressureMatchesClosedForm) {
  const std::size_t n = 5;
  Rng rng(3, 3);
  std::vector<int> hits(n, 0);
  const int draws = 100000;
  for (int s = 0; s < draws; ++s)
    ++hits[tournament_select(n, 2, rng, [](std::size_t a, std::size_t b) { return a < b; })];
  for (std::size_t r = 0; r < n; ++r) {
    const double p = (2.0 * static_cast<double>(n - r) - 1.0) / static_cast<double>(n * n);
    EXPECT_NEAR(hits[r] / static_cast<double>(draws), p, 5 * std::sqrt(p * (1 - p) / draws));
  }
}

// checks: SBX spread factor CDF against 0.5 b^(eta+1) (b <= 1) and 1 - 0.5 b^-(eta+1) (b > 1), for eta 2 and 15
TEST(OptimOperators, SbxSpreadFollowsDistributionIndex) {
  for (const double eta : {2.0, 15.0}) {
    Rng rng(11, static_cast<std::uint64_t>(eta));
    const std::vector<double> lo{-1e6}, hi{1e6}, p1{0.4}, p2{0.6};
    std::vector<double> c1(1), c2(1);
    const int n = 100000;
    std::vector<double> beta(n);
    for (int i = 0; i < n; ++i) {
      sbx_crossover(p1, p2, lo, hi, c1, c2, {.eta = eta, .variable_probability = 1.0}, rng);
      EXPECT_NEAR(c1[0] + c2[0], 1.0, 1e-9);  // children symmetric about the parents' mean
      beta[static_cast<std::size_t>(i)] = std::fabs(c2[0] - c1[0]) / 0.2;
    }
    for (const double b : {0.25, 0.5, 0.8, 1.0, 1.2, 2.0}) {
      const double expected = b <= 1.0 ? 0.5 * std::pow(b, eta + 1) : 1.0 - 0.5 * std::pow(b, -(eta + 1));
      const double got =
          static_cast<double>(std::count_if(beta.begin(), beta.end(), [b](double v) { return v <= b; })) / n;
      EXPECT_NEAR(got, expected, 0.006) << "eta " << eta << " b " << b;
    }
  }
}

// Distance in units in the last place between two finite doubles of the same sign.
std::uint64_t ulp_distance(double a, double b) {
  const auto ia = std::bit_cast<std::int64_t>(a);
  const auto ib = std::bit_cast<std::int64_t>(b);
  return ia > ib ? static_cast<std::uint64_t>(ia - ib) : static_cast<std::uint64_t>(ib - ia);
}

// checks: the tabled x^p of SBX and polynomial mutation against std::pow within 3 ulp, over 200,000
// seeded arguments per exponent (uniform in [0, 1), log-uniform over 2^-140..2^140) and the edges
TEST(OptimOperators, FixedPowerMatchesStdPow) {
  for (const double p : {1.0 / 21.0, 1.0 / 16.0, 1.0 / 3.5, 0.7, 1.0, -1.0 / 21.0, -1.0 / 16.0, -0.3, -1.0}) {
    const detail::FixedPower power(p);
    Rng rng(31, static_cast<std::uint64_t>(std::fabs(p) * 1000.0) + (p < 0.0 ? 7 : 0));
    std::uint64_t worst = 0;
    double worst_x = 0.0;
    for (int i = 0; i < 200000; ++i) {
      const double x = i % 2 == 0 ? rng.uniform() : std::exp2(rng.uniform(-140.0, 140.0));
      const double expected = std::pow(x, p);
      const std::uint64_t e = ulp_distance(power(x), expected);
      if (e > worst) {
        worst = e;
        worst_x = x;
      }
    }
    EXPECT_LE(worst, 3U) << "p " << p << " x " << worst_x;
    // Edges: outside the tables (0, subnormal, beyond 2^+-128, inf) the result is std::pow's.
    for (const double x : {0.0, 5e-324, 0x1p-127, 0x1p-126, 0x1.fffffffffffffp+127, 0x1p128, 1.0, 0.5, 2.0,
                           std::numeric_limits<double>::infinity()}) {
      EXPECT_LE(ulp_distance(power(x), std::pow(x, p)), 3U) << "p " << p << " x " << x;
    }
  }
  // p = 1: the tables and the series give x itself.
  const detail::FixedPower identity(1.0);
  Rng rng(32, 0);
  for (int i = 0; i < 1000; ++i) {
    const double x = rng.uniform(1e-30, 1e30);
    EXPECT_EQ(identity(x), x);
  }
}

// checks: the 32-bit decision thresholds against their exact values, and the SBX per-variable rate
// (probability 0.3, 5 binomial sigma)
TEST(OptimOperators, DecisionThresholdAndSbxVariableRate) {
  EXPECT_EQ(detail::threshold32(0.0), 0U);
  EXPECT_EQ(detail::threshold32(0.5), std::uint64_t{1} << 31);
  EXPECT_EQ(detail::threshold32(1.0), std::uint64_t{1} << 32);
  EXPECT_EQ(detail::threshold32(0.25), std::uint64_t{1} << 30);
  Rng rng(17, 0);
  const std::size_t d = 37;  // odd: the last variable of a draw's pair stands alone
  std::vector<double> lo(d, 0.0), hi(d, 1.0), p1(d, 0.25), p2(d, 0.75), c1(d), c2(d);
  std::size_t changed = 0;
  const int rounds = 5000;
  for (int r = 0; r < rounds; ++r) {
    sbx_crossover(p1, p2, lo, hi, c1, c2, {.eta = 15.0, .variable_probability = 0.3}, rng);
    for (std::size_t j = 0; j < d; ++j) changed += (c1[j] != p1[j] || c2[j] != p2[j]) ? 1 : 0;
  }
  const double n = static_cast<double>(d) * rounds;
  // A recombined variable keeps both parents' values only when beta = 1 exactly and the children are not
  // swapped: negligible.
  EXPECT_NEAR(static_cast<double>(changed) / n, 0.3, 5 * std::sqrt(0.3 * 0.7 / n));
}

// checks: the lower child's spread factor near a bound against the truncated CDF
// (2 - b^-(eta+1))... : b^(eta+1) / alpha for b <= 1, (2 - b^-(eta+1)) / alpha for 1 < b <= beta_bound,
// alpha = 2 - beta_bound^-(eta+1); parents 0.1 and 0.3 over [0, 1e6]: beta_bound = 2, eta = 2 (alpha = 15/8)
TEST(OptimOperators, SbxTruncatedSpreadNearBound) {
  Rng rng(23, 0);
  const std::vector<double> lo{0.0}, hi{1e6}, p1{0.1}, p2{0.3};
  std::vector<double> c1(1), c2(1);
  const int n = 100000;
  std::vector<double> beta(n);
  for (int i = 0; i < n; ++i) {
    sbx_crossover(p1, p2, lo, hi, c1, c2, {.eta = 2.0, .variable_probability = 1.0}, rng);
    const double lower_child = std::min(c1[0], c2[0]);
    EXPECT_GE(lower_child, 0.0);
    beta[static_cast<std::size_t>(i)] = (0.4 - 2.0 * lower_child) / 0.2;
  }
  const double alpha = 2.0 - 1.0 / 8.0;
  for (const double b : {0.3, 0.7, 1.0, 1.2, 1.5, 1.9}) {
    const double expected = b <= 1.0 ? b * b * b / alpha : (2.0 - 1.0 / (b * b * b)) / alpha;
    const double got =
        static_cast<double>(std::count_if(beta.begin(), beta.end(), [b](double v) { return v <= b; })) / n;
    EXPECT_NEAR(got, expected, 0.006) << "b " << b;
  }
}

// checks: SBX children stay inside tight bounds and identical parents are copied
TEST(OptimOperators, SbxRespectsBounds) {
  Rng rng(5, 5);
  const std::vector<double> lo{0.0, -1.0}, hi{1.0, 1.0}, p1{0.01, 0.5}, p2{0.99, 0.5};
  std::vector<double> c1(2), c2(2);
  for (int i = 0; i < 10000; ++i) {
    sbx_crossover(p1, p2, lo, hi, c1, c2, {.eta = 0.5, .variable_probability = 1.0}, rng);
    for (std::size_t j = 0; j < 2; ++j) {
      EXPECT_GE(c1[j], lo[j]);
      EXPECT_LE(c1[j], hi[j]);
      EXPECT_GE(c2[j], lo[j]);
      EXPECT_LE(c2[j], hi[j]);
    }
    EXPECT_EQ(c1[1], 0.5);
  }
}

// checks: polynomial mutation rate against the per-variable probability (5 sigma) and bounds
TEST(OptimOperators, PolynomialMutationRateAndBounds) {
  Rng rng(9, 0);
  const std::size_t d = 50;
  std::vector<double> lo(d, -2.0), hi(d, 3.0), x(d, 2.9);
  std::size_t mutated = 0;
  const int rounds = 4000;
  for (int r = 0; r < rounds; ++r) {
    std::fill(x.begin(), x.end(), 2.9);
    mutated += polynomial_mutation(x, lo, hi, 0.1, 20.0, rng);
    for (const double v : x) {
      EXPECT_GE(v, -2.0);
      EXPECT_LE(v, 3.0);
    }
  }
  const double n = static_cast<double>(d) * rounds;
  EXPECT_NEAR(static_cast<double>(mutated) / n, 0.1, 5 * std::sqrt(0.09 / n));
  // Fixed variables never move.
  std::vector<double> fixed{1.0}, flo{1.0}, fhi{1.0};
  EXPECT_EQ(polynomial_mutation(fixed, flo, fhi, 1.0, 20.0, rng), 0U);
}

// checks: bit mutation flip rate against probability at level 0 and level 2 (5 sigma)
TEST(OptimOperators, BitMutationRate) {
  Rng rng(13, 0);
  std::vector<std::uint8_t> bits(1000, 0);
  std::size_t flips = 0;
  for (int r = 0; r < 200; ++r) flips += bit_mutation(bits, 0.05, 0, rng);
  EXPECT_NEAR(flips / 200000.0, 0.05, 5 * std::sqrt(0.05 * 0.95 / 200000));
  EXPECT_EQ(static_cast<std::size_t>(std::count(bits.begin(), bits.end(), std::uint8_t{1})) % 2, flips % 2);
  flips = 0;
  for (int r = 0; r < 200; ++r) flips += bit_mutation(bits, 0.019, 2, rng);
  EXPECT_NEAR(flips / 200000.0, 0.02, 5 * std::sqrt(0.02 * 0.98 / 200000));
}

// checks: single-point and uniform crossover conserve every bit position's multiset; uniform exchanges half
TEST(OptimOperators, BinaryCrossoverConservesBits) {
  Rng rng(17, 0);
  const std::size_t n = 200;
  std::vector<std::uint8_t> a(n), b(n), c(n), d(n);
  for (std::size_t i = 0; i < n; ++i) {
    a[i] = static_cast<std::uint8_t>(rng() & 1U);
    b[i] = static_cast<std::uint8_t>(rng() & 1U);
  }
  const std::size_t cut = single_point_crossover(a, b, c, d, rng);
  ASSERT_GE(cut, 1U);
  ASSERT_LT(cut, n);
  for (std::size_t i = 0; i < n; ++i) {
    EXPECT_EQ(c[i], i < cut ? a[i] : b[i]);
    EXPECT_EQ(c[i] + d[i], a[i] + b[i]);
  }
  std::size_t exchanged = 0;
  for (int r = 0; r < 100; ++r) {
    exchanged += uniform_crossover(a, b, c, d, rng);
    for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(c[i] + d[i], a[i] + b[i]);
  }
  EXPECT_NEAR(exchanged / 20000.0, 0.5, 5 * std::sqrt(0.25 / 20000));
}

}  // namespace
}  // namespace hula::optim
