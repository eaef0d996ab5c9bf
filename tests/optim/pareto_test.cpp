// SPDX-License-Identifier: MIT
// Tests of the Pareto tools: non-dominated sort against a brute-force peeling
// by the definition of constrained domination, crowding distance by hand,
// hypervolume against inclusion-exclusion.
#include "hula/optim/pareto.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "hula/core/rng.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::optim {
namespace {

std::vector<std::size_t> brute_ranks(const std::vector<double>& f, std::size_t m, const std::vector<double>& v) {
  const std::size_t n = v.size();
  std::vector<std::size_t> rank(n, SIZE_MAX);
  std::size_t assigned = 0;
  std::size_t r = 0;
  // Failed points (NaN violation) are handled by the sorter as a last rank; peel the others.
  std::vector<bool> failed(n);
  for (std::size_t i = 0; i < n; ++i) failed[i] = std::isnan(v[i]);
  const std::size_t valid = static_cast<std::size_t>(std::count(failed.begin(), failed.end(), false));
  while (assigned < valid) {
    std::vector<std::size_t> front;
    for (std::size_t i = 0; i < n; ++i) {
      if (failed[i] || rank[i] != SIZE_MAX) continue;
      bool dominated = false;
      for (std::size_t j = 0; j < n && !dominated; ++j) {
        if (j == i || failed[j] || rank[j] != SIZE_MAX) continue;
        dominated = constrained_dominates({&f[j * m], m}, v[j], {&f[i * m], m}, v[i]);
      }
      if (!dominated) front.push_back(i);
    }
    for (const std::size_t i : front) rank[i] = r;
    assigned += front.size();
    ++r;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (failed[i]) rank[i] = r;
  }
  return rank;
}

// checks: NonDominatedSorter ranks against brute-force peeling for m = 1, 2, 3, 4 with ties, infeasible and failed
// points
TEST(OptimPareto, SortMatchesDefinition) {
  Rng rng(2024, 0);
  NonDominatedSorter sorter;
  for (std::size_t m = 1; m <= 4; ++m) {
    for (int trial = 0; trial < 30; ++trial) {
      const std::size_t n = 1 + rng.below(60);
      std::vector<double> f(n * m), v(n);
      for (auto& x : f) x = static_cast<double>(rng.below(6));  // many ties
      for (auto& x : v) {
        const auto c = rng.below(10);
        x = c < 6 ? 0.0 : (c < 9 ? static_cast<double>(rng.below(3) + 1) : std::numeric_limits<double>::quiet_NaN());
      }
      const auto got = sorter.sort(f, m, v);
      const auto want = brute_ranks(f, m, v);
      for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(got[i], want[i]) << "m " << m << " trial " << trial << " i " << i;
      // feasible(): exactly the points of violation 0, for m <= 2 in lexicographic objective order.
      const auto feasible = sorter.feasible();
      ASSERT_EQ(feasible.size(), static_cast<std::size_t>(std::count(v.begin(), v.end(), 0.0)));
      for (const std::size_t i : feasible) EXPECT_EQ(v[i], 0.0);
      if (m > 2) continue;
      for (std::size_t q = 1; q < feasible.size(); ++q) {
        const double* a = &f[feasible[q - 1] * m];
        const double* b = &f[feasible[q] * m];
        const bool before = std::lexicographical_compare(a, a + m, b, b + m) ||
                            (std::equal(a, a + m, b) && feasible[q - 1] < feasible[q]);
        EXPECT_TRUE(before) << "m " << m << " trial " << trial << " position " << q;
      }
    }
  }
}

// checks: crowding distance does not depend on the order the front's members are given in (NSGA-II
// passes 2-D fronts already sorted by f0; the distances must equal those of a shuffled front), on
// fronts with repeated points, compared bit for bit
TEST(OptimPareto, CrowdingDistanceIndependentOfMemberOrder) {
  Rng rng(77, 1);
  for (int trial = 0; trial < 40; ++trial) {
    const std::size_t k = 3 + rng.below(30);
    std::vector<double> f(2 * k);
    for (std::size_t i = 0; i < k; ++i) {
      const double x = static_cast<double>(rng.below(k));  // repeats: equal points share a front
      f[2 * i] = x;
      f[2 * i + 1] = 1.0 - std::sqrt(x / static_cast<double>(k));
    }
    std::vector<std::size_t> sorted(k);
    for (std::size_t i = 0; i < k; ++i) sorted[i] = i;
    std::sort(sorted.begin(), sorted.end(),
              [&](std::size_t a, std::size_t b) { return f[2 * a] < f[2 * b] || (f[2 * a] == f[2 * b] && a < b); });
    std::vector<std::size_t> shuffled = sorted;
    for (std::size_t i = k - 1; i > 0; --i) std::swap(shuffled[i], shuffled[rng.below(i + 1)]);
    std::vector<double> d_sorted(k), d_shuffled(k);
    std::vector<std::size_t> scratch(k);
    crowding_distance(f, 2, sorted, d_sorted, scratch);
    crowding_distance(f, 2, shuffled, d_shuffled, scratch);
    for (std::size_t i = 0; i < k; ++i) {
      EXPECT_EQ(std::memcmp(&d_sorted[i], &d_shuffled[i], sizeof(double)), 0) << "trial " << trial << " i " << i;
    }
  }
}

// checks: crowding distance of a 2-objective front against hand computation
TEST(OptimPareto, CrowdingDistanceByHand) {
  const std::vector<double> f = {0.0, 4.0, 1.0, 2.0, 3.0, 1.0, 4.0, 0.0};
  const std::vector<std::size_t> front = {0, 1, 2, 3};
  std::vector<double> d(4);
  std::vector<std::size_t> scratch(4);
  crowding_distance(f, 2, front, d, scratch);
  EXPECT_TRUE(std::isinf(d[0]));
  EXPECT_TRUE(std::isinf(d[3]));
  EXPECT_DOUBLE_EQ(d[1], 3.0 / 4.0 + 3.0 / 4.0);
  EXPECT_DOUBLE_EQ(d[2], 3.0 / 4.0 + 2.0 / 4.0);
}

// checks: iterative crowding thinning against hand computation on f1 + f2 = 1; one-shot truncation
// would drop two of the three tied inner points, the iterative one recomputes and keeps an even spread
TEST(OptimPareto, ThinByCrowdingByHand) {
  const std::vector<double> f1 = {0.0, 0.125, 0.25, 0.375, 0.5, 1.0};
  std::vector<double> f;
  for (const double x : f1) f.insert(f.end(), {x, 1.0 - x});
  // Distances 2 x (gap around): 0.5, 0.5, 0.5, 1.25 for the inner points: remove index 1 (tie, lowest);
  // then 0.75, 0.5, 1.25: remove index 3; left 0, 0.25, 0.5, 1.
  EXPECT_EQ(thin_by_crowding(f, 2, 4), (std::vector<std::size_t>{0, 2, 4, 5}));
  EXPECT_EQ(thin_by_crowding(f, 2, 2), (std::vector<std::size_t>{0, 5}));
  EXPECT_EQ(thin_by_crowding(f, 2, 6), (std::vector<std::size_t>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(thin_by_crowding(f, 2, 9), (std::vector<std::size_t>{0, 1, 2, 3, 4, 5}));
}

double inclusion_exclusion(const std::vector<double>& p, std::size_t m, const std::vector<double>& ref) {
  const std::size_t n = p.size() / m;
  double total = 0.0;
  for (std::size_t mask = 1; mask < (std::size_t{1} << n); ++mask) {
    double vol = 1.0;
    int bits = 0;
    for (std::size_t j = 0; j < m; ++j) {
      double worst = -std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < n; ++i) {
        if (mask & (std::size_t{1} << i)) worst = std::max(worst, p[i * m + j]);
      }
      vol *= std::max(0.0, ref[j] - worst);
    }
    for (std::size_t i = 0; i < n; ++i) bits += (mask >> i) & 1U;
    total += (bits % 2 ? 1.0 : -1.0) * vol;
  }
  return total;
}

// checks: hypervolume for m = 2..4 against inclusion-exclusion over all subsets (independent formula)
TEST(OptimPareto, HypervolumeMatchesInclusionExclusion) {
  Rng rng(77, 0);
  for (std::size_t m = 2; m <= 4; ++m) {
    for (int trial = 0; trial < 20; ++trial) {
      const std::size_t n = 1 + rng.below(9);
      std::vector<double> p(n * m);
      for (auto& x : p) x = rng.uniform(0.0, 1.2);
      const std::vector<double> ref(m, 1.1);
      EXPECT_NEAR(hypervolume(p, m, ref), inclusion_exclusion(p, m, ref), 1e-12) << "m " << m;
    }
  }
  const std::vector<double> one = {0.5, 0.5};
  EXPECT_DOUBLE_EQ(hypervolume(one, 2, std::vector<double>{1.0, 1.0}), 0.25);
}

// checks: hypervolume errors name the bad argument
TEST(OptimPareto, HypervolumeErrors) {
  const std::vector<double> p = {0.5, 0.5, 0.1};
  HULA_EXPECT_ERROR(hypervolume(p, 2, std::vector<double>{1.0, 1.0}), Errc::InvalidArgument,
                    "points has 3 values, not a multiple of m = 2");
  HULA_EXPECT_ERROR(hypervolume(p, 3, std::vector<double>{1.0, 1.0}), Errc::InvalidArgument,
                    "reference has 2 values, expected m = 3");
  const std::vector<double> nan_point = {0.5, std::numeric_limits<double>::quiet_NaN()};
  HULA_EXPECT_ERROR(hypervolume(nan_point, 2, std::vector<double>{1.0, 1.0}), Errc::NonFiniteInput,
                    "points[0][1] = nan");
}

}  // namespace
}  // namespace hula::optim
