// SPDX-License-Identifier: MIT
// Basis function properties on random knot vectors: partition of unity,
// non-negativity, and derivatives against central differences.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>

#include "hula/nurbs/basis.hpp"

namespace hula::nurbs {
namespace {

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

}  // namespace
}  // namespace hula::nurbs
