// SPDX-License-Identifier: MIT
#include "hula/optim/mutation.hpp"

#include <algorithm>
#include <cmath>

#include "hula/optim/detail/fixed_power.hpp"
#include "hula/optim/detail/power.hpp"
#include "hula/optim/selection.hpp"

namespace hula::optim {

std::size_t polynomial_mutation(std::span<double> x, std::span<const double> lower, std::span<const double> upper,
                                double probability, double eta, Rng& rng) noexcept {
  std::size_t mutated = 0;
  const double e1 = eta + 1.0;
  const detail::FixedPower& root = detail::fixed_power(1.0 / e1);
  // Whether a variable mutates: 32 random bits each, two per draw.
  const std::uint64_t threshold = detail::threshold32(probability);
  std::uint64_t word = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (i % 2 == 0) word = rng();
    if (((i % 2 == 0 ? word : word >> 32) & 0xffff'ffffU) >= threshold) continue;
    const double yl = lower[i];
    const double yu = upper[i];
    if (!(yu > yl)) continue;
    ++mutated;
    const double y = x[i];
    const double width = yu - yl;
    const double r = rng.uniform();
    // Moving down (r < 1/2), the (1 - delta1)^(eta+1) term truncates the step at yl, with
    // delta1 = (y - yl) / width:  val = 2r + (1 - 2r) (1 - delta1)^(eta+1),  deltaq = val^(1/(eta+1)) - 1.
    // Moving up, with delta2 = (yu - y) / width:  val = 2(1 - r) + (2r - 1) (1 - delta2)^(eta+1),
    // deltaq = 1 - val^(1/(eta+1)). The side is a coin flip: chosen without a branch.
    const bool down = r < 0.5;
    const double room = (down ? y - yl : yu - y) / width;
    const double val = (down ? 2.0 * r : 2.0 * (1.0 - r)) + std::fabs(1.0 - 2.0 * r) * detail::power(1.0 - room, e1);
    const double q = root(val);
    const double deltaq = down ? q - 1.0 : 1.0 - q;
    x[i] = std::clamp(y + deltaq * width, yl, yu);
  }
  return mutated;
}

std::size_t bit_mutation(std::span<std::uint8_t> bits, double probability, unsigned level, Rng& rng) noexcept {
  // chance() per bit, with its threshold worked out once for the chromosome (llround per bit was a
  // third of the thesis GA's own time): the same draws from `rng`, the same decisions.
  const ChanceThreshold threshold(probability, level);
  std::size_t flipped = 0;
  for (auto& b : bits) {
    if (threshold(rng)) {
      b = static_cast<std::uint8_t>(b ^ 1U);
      ++flipped;
    }
  }
  return flipped;
}

}  // namespace hula::optim
