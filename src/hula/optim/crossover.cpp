// SPDX-License-Identifier: MIT
#include "hula/optim/crossover.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "hula/optim/detail/fixed_power.hpp"
#include "hula/optim/detail/power.hpp"

namespace hula::optim {
namespace {
// Variables handled per block, in three passes over stack arrays (no allocation): the decisions, the
// roots' arguments, the roots in one tight loop (independent of each other, so they overlap in the
// pipeline), the children.
constexpr std::size_t kBlock = 64;

// Inverse CDF of the spread factor truncated so the child stays inside the bound on its side:
// alpha = 2 - beta_bound^-(eta+1) is the mass allowed, with beta_bound = 1 + 2 room / dy >= 1, so
// 1 / beta_bound = x = dy / (dy + 2 room). Raising x cannot overflow (it may underflow to 0, the right
// limit far from the bound). Below `negligible` the power is below 2^-54, so 2 - power rounds to 2: the
// division and the power are skipped (the same alpha, and no subnormal products, which cost a microcode
// assist); x < negligible is tested as dy < negligible (dy + 2 room).
double alpha_of(double dy, double room, double e1, double negligible) noexcept {
  const double sum = dy + 2.0 * room;
  if (dy < negligible * sum) return 2.0;
  return 2.0 - detail::power(dy / sum, e1);
}
}  // namespace

void sbx_crossover(std::span<const double> parent1, std::span<const double> parent2, std::span<const double> lower,
                   std::span<const double> upper, std::span<double> child1, std::span<double> child2,
                   const SbxSettings& settings, Rng& rng) noexcept {
  const std::size_t d = parent1.size();
  const double e1 = settings.eta + 1.0;
  // beta_q = (u alpha)^(1/e1) for u alpha <= 1, else (2 - u alpha)^(-1/e1): the side is a coin flip's
  // worth of unpredictable, so the argument and the exponent's tables are chosen without a branch.
  const detail::FixedPower& root = detail::fixed_power(1.0 / e1);
  const detail::FixedPower& inverse_root = detail::fixed_power(-1.0 / e1);
  const std::array<const detail::FixedPower*, 2> roots{&root, &inverse_root};
  // 2^(-54 / e1), less a margin for the rounding of both powers.
  const double negligible = 0.999 * root(0x1p-54);
  const std::uint64_t threshold = detail::threshold32(settings.variable_probability);
  std::copy_n(parent1.begin(), d, child1.begin());
  std::copy_n(parent2.begin(), d, child2.begin());
  std::array<std::uint32_t, kBlock> picked;  // written before read: no zero fill per call
  std::array<std::uint8_t, kBlock> swapped;
  std::array<double, 2 * kBlock> beta;
  std::array<std::uint8_t, 2 * kBlock> side;
  for (std::size_t block = 0; block < d; block += kBlock) {
    const std::size_t end = std::min(d, block + kBlock);
    // Step 0: which variables recombine (32 random bits each, two per draw, in order); the others stay
    // copies. Compacted without a branch: with the default probability 0.5 a branch would be
    // mispredicted half the time.
    std::size_t count = 0;
    std::uint64_t word = 0;
    for (std::size_t i = block; i < end; ++i) {
      const std::size_t k = i - block;
      if (k % 2 == 0) word = rng();
      const bool draw = ((k % 2 == 0 ? word : word >> 32) & 0xffff'ffffU) < threshold;
      const bool apart = std::fabs(parent1[i] - parent2[i]) > 1e-14;
      picked[count] = static_cast<std::uint32_t>(k);
      count += static_cast<std::size_t>(draw & apart);
    }
    // Steps 1 and 2: the spread factors of the child towards the lower bound (limited by y1 - yl) and
    // of the one towards the upper bound (limited by yu - y2), from one u per variable. One draw: u
    // from its top 53 bits, step 3's coin from its lowest bit.
    for (std::size_t q = 0; q < count; ++q) {
      const std::size_t i = block + picked[q];
      const double y1 = std::min(parent1[i], parent2[i]);
      const double y2 = std::max(parent1[i], parent2[i]);
      const double dy = y2 - y1;
      const std::uint64_t bits = rng();
      const double u = static_cast<double>(bits >> 11) * 0x1.0p-53;
      swapped[q] = static_cast<std::uint8_t>(bits & 1U);
      const double t1 = u * alpha_of(dy, y1 - lower[i], e1, negligible);
      const double t2 = u * alpha_of(dy, upper[i] - y2, e1, negligible);
      beta[2 * q] = t1 <= 1.0 ? t1 : 2.0 - t1;
      beta[2 * q + 1] = t2 <= 1.0 ? t2 : 2.0 - t2;
      side[2 * q] = static_cast<std::uint8_t>(t1 > 1.0);
      side[2 * q + 1] = static_cast<std::uint8_t>(t2 > 1.0);
    }
    for (std::size_t q = 0; q < 2 * count; ++q) beta[q] = (*roots[side[q]])(beta[q]);
    // Step 3: the children, exchanged with probability 0.5 so neither parent systematically receives
    // the lower one.
    for (std::size_t q = 0; q < count; ++q) {
      const std::size_t i = block + picked[q];
      const double y1 = std::min(parent1[i], parent2[i]);
      const double y2 = std::max(parent1[i], parent2[i]);
      const double dy = y2 - y1;
      const double c1 = std::clamp(0.5 * ((y1 + y2) - beta[2 * q] * dy), lower[i], upper[i]);
      const double c2 = std::clamp(0.5 * ((y1 + y2) + beta[2 * q + 1] * dy), lower[i], upper[i]);
      const bool swap = swapped[q] != 0;
      child1[i] = swap ? c2 : c1;
      child2[i] = swap ? c1 : c2;
    }
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
