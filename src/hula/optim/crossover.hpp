// SPDX-License-Identifier: MIT
// Crossover operators: simulated binary crossover for real coding (Deb &
// Agrawal 1995, bounded form of Deb's NSGA-II reference code) and
// single-point / uniform crossover of binary chromosomes (appendix 2
// "Individual::crossover").
//
// Notation (SBX): parents y1 <= y2, spread factor beta = |c2 - c1| / |y2 - y1|,
// distribution index eta: density 0.5 (eta+1) beta^eta for beta <= 1 and
// 0.5 (eta+1) / beta^(eta+2) for beta > 1, truncated at the bounds.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "hula/core/rng.hpp"

namespace hula::optim {

/// Settings of simulated binary crossover.
struct SbxSettings {
  /// Distribution index eta_c >= 0: large values keep children near their parents. Default 15.
  double eta = 15.0;
  /// Probability that a given variable is recombined (otherwise copied). Default 0.5.
  double variable_probability = 0.5;
};

/// Bounded simulated binary crossover of two real-coded parents.
/// @param parent1, parent2 d variables each, inside [lower, upper].
/// @param lower, upper d bounds each.
/// @param child1, child2 outputs, d variables each, inside the bounds; may alias nothing.
/// @param settings distribution index and per-variable probability.
/// @param rng the stream to draw from.
void sbx_crossover(std::span<const double> parent1, std::span<const double> parent2, std::span<const double> lower,
                   std::span<const double> upper, std::span<double> child1, std::span<double> child2,
                   const SbxSettings& settings, Rng& rng) noexcept;

/// Single-point crossover of two bit strings: a cut in [1, n) is drawn and the
/// tails are exchanged. Bits are stored one per byte (0 or 1).
/// @param parent1, parent2, child1, child2 n bits each (n >= 1).
/// @param rng the stream to draw from.
/// @returns the cut position (n when n == 1: the children are copies).
std::size_t single_point_crossover(std::span<const std::uint8_t> parent1, std::span<const std::uint8_t> parent2,
                                   std::span<std::uint8_t> child1, std::span<std::uint8_t> child2, Rng& rng) noexcept;

/// Uniform crossover: every bit is exchanged with probability 0.5.
/// @param parent1, parent2, child1, child2 n bits each.
/// @param rng the stream to draw from (one 64-bit draw per 64 bits).
/// @returns the number of bits exchanged.
std::size_t uniform_crossover(std::span<const std::uint8_t> parent1, std::span<const std::uint8_t> parent2,
                              std::span<std::uint8_t> child1, std::span<std::uint8_t> child2, Rng& rng) noexcept;

}  // namespace hula::optim
