// SPDX-License-Identifier: MIT
// Basis functions: The NURBS Book ex. 2.3 values, partition of unity,
// non-negativity and derivatives against central differences (property tests).
#include "hula/nurbs/basis.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>

namespace hula::nurbs {
namespace {

// checks: The NURBS Book ex. 2.3 (U = {0,0,0,1,2,3,4,4,5,5,5}, p = 2, t = 5/2).
TEST(Basis, NurbsBookExample) {
  const KnotVector kv({0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5}, 2);
  const std::size_t span = kv.find_span(2.5);
  ASSERT_EQ(span, 4u);
  double N[3];
  basis_functions(kv, span, 2.5, N);
  EXPECT_DOUBLE_EQ(N[0], 1.0 / 8.0);
  EXPECT_DOUBLE_EQ(N[1], 6.0 / 8.0);
  EXPECT_DOUBLE_EQ(N[2], 1.0 / 8.0);
  const auto d = basis_derivatives(kv, span, 2.5, 2);
  // N'_{2,2}(5/2) = -1/2, N'_{3,2} = 0, N'_{4,2} = 1/2; second derivatives 1, -2, 1 (ex. 2.4).
  EXPECT_DOUBLE_EQ(d[3], -0.5);
  EXPECT_DOUBLE_EQ(d[4], 0.0);
  EXPECT_DOUBLE_EQ(d[5], 0.5);
  EXPECT_DOUBLE_EQ(d[6], 1.0);
  EXPECT_DOUBLE_EQ(d[7], -2.0);
  EXPECT_DOUBLE_EQ(d[8], 1.0);
}

// checks: partition of unity and non-negativity on random knot vectors (property).
RC_GTEST_PROP(Basis, PartitionOfUnityAndNonNegativity, ()) {
  const int p = *rc::gen::inRange(1, 8);
  const int interior = *rc::gen::inRange(0, 12);
  std::vector<double> U(static_cast<std::size_t>(p + 1), 0.0);
  auto inner = *rc::gen::container<std::vector<int>>(static_cast<std::size_t>(interior), rc::gen::inRange(1, 1000));
  std::sort(inner.begin(), inner.end());
  // Cap multiplicities at p.
  std::vector<double> knots_inner;
  for (int v : inner) {
    const double u = v / 1000.0;
    if (std::count(knots_inner.begin(), knots_inner.end(), u) < p) knots_inner.push_back(u);
  }
  U.insert(U.end(), knots_inner.begin(), knots_inner.end());
  U.insert(U.end(), static_cast<std::size_t>(p + 1), 1.0);
  const KnotVector kv(U, p);
  const double t = *rc::gen::inRange(0, 1000001) / 1e6;
  const std::size_t span = kv.find_span(t);
  std::vector<double> N(static_cast<std::size_t>(p + 1));
  basis_functions(kv, span, t, N);
  double sum = 0;
  for (double v : N) {
    RC_ASSERT(v >= -1e-15);
    sum += v;
  }
  RC_ASSERT(std::fabs(sum - 1.0) < 1e-13);
  const auto d = basis_derivatives(kv, span, t, 1);
  double dsum = 0;
  for (int j = 0; j <= p; ++j) dsum += d[static_cast<std::size_t>(p + 1 + j)];
  RC_ASSERT(std::fabs(dsum) < 1e-8 * (1 + std::fabs(d[static_cast<std::size_t>(p + 1)])));
}

// checks: first derivatives equal central differences of the basis functions (property).
RC_GTEST_PROP(Basis, DerivativesMatchCentralDifferences, ()) {
  const int p = *rc::gen::inRange(1, 6);
  const KnotVector kv = KnotVector::uniform_clamped(static_cast<std::size_t>(p + 5), p);
  const double t = 0.05 + 0.9 * (*rc::gen::inRange(0, 100001) / 1e5);
  const std::size_t span = kv.find_span(t);
  const double h = 1e-6;
  if (kv.find_span(t - h) != span || kv.find_span(t + h) != span) return;
  std::vector<double> a(static_cast<std::size_t>(p + 1)), b(static_cast<std::size_t>(p + 1));
  basis_functions(kv, span, t + h, a);
  basis_functions(kv, span, t - h, b);
  const auto d = basis_derivatives(kv, span, t, 1);
  for (int j = 0; j <= p; ++j) {
    const auto J = static_cast<std::size_t>(j);
    const double fd = (a[J] - b[J]) / (2 * h);
    RC_ASSERT(std::fabs(fd - d[static_cast<std::size_t>(p + 1) + J]) < 1e-5 * (1 + std::fabs(fd)));
  }
}

// checks: Bernstein polynomials (closed form vs recursion) sum to one.
TEST(Basis, BernsteinFormsAgree) {
  for (int n : {1, 3, 7, 12}) {
    for (double t : {0.0, 0.25, 0.5, 0.9, 1.0}) {
      std::vector<double> B(static_cast<std::size_t>(n + 1));
      bernstein_all(n, t, B);
      double s = 0;
      for (int i = 0; i <= n; ++i) {
        EXPECT_NEAR(B[static_cast<std::size_t>(i)], bernstein(i, n, t), 1e-15);
        s += B[static_cast<std::size_t>(i)];
      }
      EXPECT_NEAR(s, 1.0, 1e-14);
    }
  }
}

}  // namespace
}  // namespace hula::nurbs
