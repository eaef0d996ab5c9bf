// SPDX-License-Identifier: MIT
// Mutation operators: polynomial mutation for real coding (Deb & Goyal 1996,
// bounded form of Deb's NSGA-II reference code) and bit mutation for binary
// chromosomes with the thesis's probability and "level" (appendix 2
// "Individual::mutation", appendix 6.3.1).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

#include "hula/core/rng.hpp"

namespace hula::optim {

/// Polynomial mutation in place: each variable mutates with `probability`,
/// moving by delta_q (upper - lower) where delta_q follows the bounded
/// polynomial distribution of index `eta`; results stay inside the bounds.
/// Variables with lower == upper never move.
/// @param x d variables inside [lower, upper], modified in place.
/// @param probability per-variable mutation probability in [0, 1].
/// @param lower, upper d bounds each.
/// @param eta distribution index >= 0 (large = small steps).
/// @param rng the stream to draw from.
/// @returns the number of variables mutated.
std::size_t polynomial_mutation(std::span<double> x, std::span<const double> lower, std::span<const double> upper,
                                double probability, double eta, Rng& rng) noexcept;

/// Bit mutation in place: each bit flips with `probability`, resolved to
/// `level` decimal digits (see chance()).
/// @param bits n bits, one per byte (0 or 1).
/// @param probability per-bit probability in [0, 1].
/// @param level decimal digits of the probability, 0..9 (0 = full resolution).
/// @param rng the stream to draw from.
/// @returns the number of bits flipped.
std::size_t bit_mutation(std::span<std::uint8_t> bits, double probability, unsigned level, Rng& rng) noexcept;

}  // namespace hula::optim
