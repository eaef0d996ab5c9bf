// SPDX-License-Identifier: MIT
#include "hula/optim/mutation.hpp"

#include <algorithm>
#include <cmath>

#include "hula/optim/detail/power.hpp"
#include "hula/optim/selection.hpp"

namespace hula::optim {

std::size_t polynomial_mutation(std::span<double> x, std::span<const double> lower, std::span<const double> upper,
                                double probability, double eta, Rng& rng) noexcept {
  std::size_t mutated = 0;
  const double power = 1.0 / (eta + 1.0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!(rng.uniform() < probability)) continue;
    const double yl = lower[i];
    const double yu = upper[i];
    if (!(yu > yl)) continue;
    ++mutated;
    const double y = x[i];
    const double delta1 = (y - yl) / (yu - yl);
    const double delta2 = (yu - y) / (yu - yl);
    const double r = rng.uniform();
    double deltaq = 0.0;
    if (r < 0.5) {
      // Move down; the (1 - delta1)^(eta+1) term truncates the step at yl.
      const double val = 2.0 * r + (1.0 - 2.0 * r) * detail::power(1.0 - delta1, eta + 1.0);
      deltaq = std::pow(val, power) - 1.0;
    } else {
      const double val = 2.0 * (1.0 - r) + 2.0 * (r - 0.5) * detail::power(1.0 - delta2, eta + 1.0);
      deltaq = 1.0 - std::pow(val, power);
    }
    x[i] = std::clamp(y + deltaq * (yu - yl), yl, yu);
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
