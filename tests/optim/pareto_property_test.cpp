// SPDX-License-Identifier: MIT
// Properties of the Pareto tools on random point sets: ranks and hypervolume
// do not depend on the order of the points, hypervolume is monotone under
// adding a point and unchanged by adding a dominated one, every rank-k point
// (k > 0) is dominated by a rank-(k-1) point, and an encoded value decodes
// within half a resolution step.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "hula/optim/encoding.hpp"
#include "hula/optim/pareto.hpp"

namespace hula::optim {
namespace {

std::vector<double> random_points(std::size_t n, std::size_t m) {
  // Coarse grid values so that ties and duplicates occur.
  const auto ints = *rc::gen::container<std::vector<int>>(n * m, rc::gen::inRange(0, 40));
  std::vector<double> f(ints.size());
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = ints[i] / 40.0;
  return f;
}

// checks: ranks are permutation-invariant and each rank-k point is dominated by some rank-(k-1) point (property)
RC_GTEST_PROP(OptimParetoProperty, RanksInvariantAndLayered, ()) {
  const auto m = static_cast<std::size_t>(*rc::gen::inRange(1, 5));
  const auto n = static_cast<std::size_t>(*rc::gen::inRange(1, 80));
  const auto f = random_points(n, m);
  const ParetoRanking r = non_dominated_sort(f, m);
  std::vector<std::size_t> perm(n);
  std::iota(perm.begin(), perm.end(), std::size_t{0});
  std::reverse(perm.begin(), perm.end());
  std::rotate(perm.begin(), perm.begin() + static_cast<std::ptrdiff_t>(n / 3), perm.end());
  std::vector<double> g(n * m);
  for (std::size_t i = 0; i < n; ++i) std::copy_n(&f[perm[i] * m], m, &g[i * m]);
  const ParetoRanking s = non_dominated_sort(g, m);
  for (std::size_t i = 0; i < n; ++i) RC_ASSERT(s.rank[i] == r.rank[perm[i]]);
  for (std::size_t i = 0; i < n; ++i) {
    if (r.rank[i] == 0) continue;
    bool covered = false;
    for (std::size_t j = 0; j < n && !covered; ++j) {
      covered = r.rank[j] + 1 == r.rank[i] && constrained_dominates({&f[j * m], m}, 0.0, {&f[i * m], m}, 0.0);
    }
    RC_ASSERT(covered);
  }
}

// checks: hypervolume is permutation-invariant, monotone under adding a point, unchanged by a dominated one (property)
RC_GTEST_PROP(OptimParetoProperty, HypervolumeMonotone, ()) {
  const auto m = static_cast<std::size_t>(*rc::gen::inRange(2, 5));
  const auto n = static_cast<std::size_t>(*rc::gen::inRange(1, m == 4 ? 12 : 30));
  auto f = random_points(n, m);
  const std::vector<double> ref(m, 1.1);
  const double hv = hypervolume(f, m, ref);
  std::vector<double> reversed;
  for (std::size_t i = n; i-- > 0;) reversed.insert(reversed.end(), &f[i * m], &f[i * m] + m);
  RC_ASSERT(std::fabs(hypervolume(reversed, m, ref) - hv) <= 1e-12);
  auto more = f;
  const auto extra = random_points(1, m);
  more.insert(more.end(), extra.begin(), extra.end());
  RC_ASSERT(hypervolume(more, m, ref) >= hv - 1e-12);
  auto dominated = f;
  for (std::size_t j = 0; j < m; ++j) dominated.push_back(std::min(1.09, f[j] + 0.01));
  RC_ASSERT(std::fabs(hypervolume(dominated, m, ref) - hv) <= 1e-12);
}

// checks: encode/decode round trip within half a resolution step for random bounds and precisions (property)
RC_GTEST_PROP(OptimEncodingProperty, RoundTripWithinHalfStep, ()) {
  const double lower = *rc::gen::inRange(-1000, 1000) / 10.0;
  const double width = *rc::gen::inRange(1, 100000) / 100.0;
  const double precision = std::pow(10.0, -*rc::gen::inRange(0, 9));
  const Variable v{.lower = lower, .upper = lower + width, .precision = precision};
  const BinaryEncoding enc(std::span<const Variable>(&v, 1));
  RC_ASSERT(enc.resolution(0) <= precision * (1 + 1e-12));
  const double x = lower + width * (*rc::gen::inRange(0, 1000001) / 1e6);
  std::vector<double> back(1);
  enc.decode(enc.encode(std::span<const double>(&x, 1)), back);
  RC_ASSERT(std::fabs(back[0] - x) <= enc.resolution(0) / 2 + 1e-12 * std::max(1.0, std::fabs(x)));
  RC_ASSERT(back[0] >= v.lower && back[0] <= v.upper);
}

}  // namespace
}  // namespace hula::optim
