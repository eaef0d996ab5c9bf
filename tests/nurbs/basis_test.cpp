// SPDX-License-Identifier: MIT
// Basis functions: The NURBS Book ex. 2.3/2.4 values and Bernstein forms.
#include "hula/nurbs/basis.hpp"

#include <gtest/gtest.h>

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
