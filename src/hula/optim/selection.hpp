// SPDX-License-Identifier: MIT
// Selection operators (thesis 2.3, appendix 2): roulette-wheel selection with
// sector sizes proportional to fitness, tournament selection, and the
// "probability with level" draw of appendix 2, where an operator's probability
// is resolved to `level` decimal digits ("accuracy of probability").
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "hula/core/rng.hpp"

namespace hula::optim {

/// Draws an event of probability `probability` resolved to `level` decimal
/// digits (appendix 2 "accuracy of crossover/mutation probability"): the event
/// happens when a uniform integer in [0, 10^level) is below
/// round(probability * 10^level). Level 0 uses the full 53-bit resolution.
/// @param rng the stream to draw from.
/// @param probability in [0, 1] (checked by the options' validate()).
/// @param level 0..9.
/// @returns true when the event happens.
[[nodiscard]] bool chance(Rng& rng, double probability, unsigned level) noexcept;

/// chance() with its threshold worked out once, for many draws of one probability and level:
/// `ChanceThreshold t(p, level); t(rng)` draws exactly as `chance(rng, p, level)`.
class ChanceThreshold {
 public:
  ChanceThreshold(double probability, unsigned level) noexcept;
  /// One draw (none at all for probability >= 1 or <= 0, as chance()).
  [[nodiscard]] bool operator()(Rng& rng) const noexcept {
    if (always_ || never_) return always_;
    if (scale_ == 0) return rng.uniform() < probability_;
    return rng.below(scale_) < threshold_;
  }

 private:
  double probability_;
  bool always_ = false, never_ = false;
  std::uint64_t scale_ = 0;  // 10^level, 0 for level 0 (full resolution)
  std::uint64_t threshold_ = 0;
};

/// Roulette wheel over non-negative fitness values (thesis 2.3 "Roulette
/// wheel selection"). Reuse one wheel per run: reset() does not allocate once
/// the capacity is reached.
class RouletteWheel {
 public:
  /// Rebuilds the wheel: individual i gets a sector proportional to fitness[i].
  /// Negative or NaN fitness counts as 0. If every fitness is 0, spin() picks
  /// uniformly.
  /// @param fitness one value per individual, at least one.
  void reset(std::span<const double> fitness);
  /// Spins the wheel once.
  /// @param rng the stream to draw from.
  /// @returns an index in [0, size) with probability fitness[i] / sum(fitness).
  /// Complexity: O(log n).
  [[nodiscard]] std::size_t spin(Rng& rng) const noexcept;
  /// Number of sectors.
  [[nodiscard]] std::size_t size() const noexcept { return cumulative_.size(); }

 private:
  std::vector<double> cumulative_;
};

/// Tournament selection: draws `size` individuals uniformly with replacement
/// and returns the best according to `better`.
/// @param population number of individuals, > 0.
/// @param size tournament size, >= 1.
/// @param rng the stream to draw from.
/// @param better better(a, b) is true when individual a beats b.
/// @returns the winner's index.
template <class Better>
[[nodiscard]] std::size_t tournament_select(std::size_t population, std::size_t size, Rng& rng, const Better& better) {
  std::size_t best = static_cast<std::size_t>(rng.below(population));
  for (std::size_t k = 1; k < size; ++k) {
    const auto c = static_cast<std::size_t>(rng.below(population));
    if (better(c, best)) best = c;
  }
  return best;
}

}  // namespace hula::optim
