// SPDX-License-Identifier: MIT
// Rng: reproducible streams, statistics of the uniform and normal draws.
#include "hula/core/rng.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace hula {
namespace {

// checks: same (seed, stream) gives the same sequence; other streams and seeds differ.
TEST(Rng, StreamsAreReproducibleAndDistinct) {
  Rng a(42, 0), b(42, 0), c(42, 1), d(43, 0);
  std::set<std::uint64_t> firsts;
  for (int i = 0; i < 1000; ++i) {
    const auto x = a();
    EXPECT_EQ(x, b());
    if (i == 0) firsts.insert(x);
  }
  firsts.insert(c());
  firsts.insert(d());
  EXPECT_EQ(firsts.size(), 3u);
}

// checks: uniform() in [0,1) with mean 1/2 and variance 1/12; below(n) in range and unbiased-ish.
TEST(Rng, UniformMoments) {
  Rng r(7);
  const int n = 200000;
  double s = 0, s2 = 0;
  for (int i = 0; i < n; ++i) {
    const double u = r.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    s += u;
    s2 += u * u;
  }
  const double mean = s / n, var = s2 / n - mean * mean;
  EXPECT_NEAR(mean, 0.5, 0.005);
  EXPECT_NEAR(var, 1.0 / 12.0, 0.002);
  int counts[7] = {};
  for (int i = 0; i < 70000; ++i) {
    const auto k = r.below(7);
    ASSERT_LT(k, 7u);
    ++counts[k];
  }
  for (int c : counts) EXPECT_NEAR(c, 10000, 500);
}

// checks: normal() has mean 0 and variance 1.
TEST(Rng, NormalMoments) {
  Rng r(11, 3);
  const int n = 200000;
  double s = 0, s2 = 0;
  for (int i = 0; i < n; ++i) {
    const double z = r.normal();
    s += z;
    s2 += z * z;
  }
  EXPECT_NEAR(s / n, 0.0, 0.01);
  EXPECT_NEAR(s2 / n, 1.0, 0.02);
}

}  // namespace
}  // namespace hula
