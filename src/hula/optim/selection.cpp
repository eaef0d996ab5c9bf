// SPDX-License-Identifier: MIT
#include "hula/optim/selection.hpp"

#include <algorithm>
#include <cmath>

namespace hula::optim {

bool chance(Rng& rng, double probability, unsigned level) noexcept {
  if (probability >= 1.0) return true;
  if (probability <= 0.0) return false;
  if (level == 0) return rng.uniform() < probability;
  std::uint64_t scale = 1;
  for (unsigned i = 0; i < level; ++i) scale *= 10;
  const auto threshold = static_cast<std::uint64_t>(std::llround(probability * static_cast<double>(scale)));
  return rng.below(scale) < threshold;
}

void RouletteWheel::reset(std::span<const double> fitness) {
  cumulative_.resize(fitness.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < fitness.size(); ++i) {
    const double f = fitness[i];
    if (std::isfinite(f) && f > 0.0) sum += f;
    cumulative_[i] = sum;
  }
}

std::size_t RouletteWheel::spin(Rng& rng) const noexcept {
  const std::size_t n = cumulative_.size();
  const double total = n ? cumulative_.back() : 0.0;
  if (!(total > 0.0)) return static_cast<std::size_t>(rng.below(n));
  const double r = rng.uniform() * total;
  // First sector whose cumulative sum exceeds r; zero-width sectors are skipped.
  const auto it = std::upper_bound(cumulative_.begin(), cumulative_.end(), r);
  return std::min(n - 1, static_cast<std::size_t>(it - cumulative_.begin()));
}

}  // namespace hula::optim
