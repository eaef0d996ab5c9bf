// SPDX-License-Identifier: MIT
#include "hula/optim/selection.hpp"

#include <algorithm>
#include <cmath>

namespace hula::optim {

ChanceThreshold::ChanceThreshold(double probability, unsigned level) noexcept : probability_(probability) {
  if (probability >= 1.0) {
    always_ = true;
    return;
  }
  if (probability <= 0.0) {
    never_ = true;
    return;
  }
  if (level == 0) return;
  scale_ = 1;
  for (unsigned i = 0; i < level; ++i) scale_ *= 10;
  threshold_ = static_cast<std::uint64_t>(std::llround(probability * static_cast<double>(scale_)));
}

bool chance(Rng& rng, double probability, unsigned level) noexcept { return ChanceThreshold(probability, level)(rng); }

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
