// SPDX-License-Identifier: MIT
#include "hula/optim/crossover.hpp"

#include <algorithm>
#include <cmath>

#include "hula/optim/detail/power.hpp"

namespace hula::optim {
namespace {
// Inverse CDF of the spread factor truncated so the child stays inside the
// bound on its side: alpha = 2 - beta_bound^-(eta+1) is the mass allowed.
// beta_bound >= 1; raising its inverse cannot overflow (it may underflow to 0,
// which is the right limit far from the bound).
double alpha_of(double beta_bound, double e1) noexcept { return 2.0 - detail::power(1.0 / beta_bound, e1); }
// inv_e1 = 1 / e1, computed once per call of sbx_crossover (the same double for every variable).
double beta_q(double u, double alpha, double inv_e1) noexcept {
  if (u <= 1.0 / alpha) return std::pow(u * alpha, inv_e1);
  return std::pow(1.0 / (2.0 - u * alpha), inv_e1);
}
}  // namespace

void sbx_crossover(std::span<const double> parent1, std::span<const double> parent2, std::span<const double> lower,
                   std::span<const double> upper, std::span<double> child1, std::span<double> child2,
                   const SbxSettings& settings, Rng& rng) noexcept {
  const std::size_t d = parent1.size();
  const double e1 = settings.eta + 1.0;
  const double inv_e1 = 1.0 / e1;
  for (std::size_t i = 0; i < d; ++i) {
    const double p1 = parent1[i];
    const double p2 = parent2[i];
    if (rng.uniform() >= settings.variable_probability || std::fabs(p1 - p2) <= 1e-14) {
      child1[i] = p1;
      child2[i] = p2;
      continue;
    }
    const double y1 = std::min(p1, p2);
    const double y2 = std::max(p1, p2);
    const double yl = lower[i];
    const double yu = upper[i];
    const double dy = y2 - y1;
    const double u = rng.uniform();
    // Step 1: child towards the lower bound, spread limited by y1 - yl.
    const double alpha1 = alpha_of(1.0 + 2.0 * (y1 - yl) / dy, e1);
    const double bq1 = beta_q(u, alpha1, inv_e1);
    // Step 2: child towards the upper bound, spread limited by yu - y2. Far
    // from both bounds the two truncations agree (alpha = 2 to the last
    // bit), and the costly root is shared.
    const double alpha2 = alpha_of(1.0 + 2.0 * (yu - y2) / dy, e1);
    const double bq2 = alpha2 == alpha1 ? bq1 : beta_q(u, alpha2, inv_e1);
    double c1 = 0.5 * ((y1 + y2) - bq1 * dy);
    double c2 = 0.5 * ((y1 + y2) + bq2 * dy);
    c1 = std::clamp(c1, yl, yu);
    c2 = std::clamp(c2, yl, yu);
    // Step 3: children are exchanged with probability 0.5 so neither parent
    // systematically receives the lower child.
    if (rng.uniform() < 0.5) std::swap(c1, c2);
    child1[i] = c1;
    child2[i] = c2;
  }
}

std::size_t single_point_crossover(std::span<const std::uint8_t> parent1, std::span<const std::uint8_t> parent2,
                                   std::span<std::uint8_t> child1, std::span<std::uint8_t> child2, Rng& rng) noexcept {
  const std::size_t n = parent1.size();
  const std::size_t cut = n > 1 ? 1 + static_cast<std::size_t>(rng.below(n - 1)) : n;
  for (std::size_t i = 0; i < n; ++i) {
    child1[i] = i < cut ? parent1[i] : parent2[i];
    child2[i] = i < cut ? parent2[i] : parent1[i];
  }
  return cut;
}

std::size_t uniform_crossover(std::span<const std::uint8_t> parent1, std::span<const std::uint8_t> parent2,
                              std::span<std::uint8_t> child1, std::span<std::uint8_t> child2, Rng& rng) noexcept {
  const std::size_t n = parent1.size();
  std::size_t exchanged = 0;
  std::uint64_t word = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (i % 64 == 0) word = rng();  // one random bit per position
    const bool swap = ((word >> (i % 64)) & 1U) != 0;
    exchanged += swap ? 1 : 0;
    child1[i] = swap ? parent2[i] : parent1[i];
    child2[i] = swap ? parent1[i] : parent2[i];
  }
  return exchanged;
}

}  // namespace hula::optim
