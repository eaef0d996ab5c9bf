// SPDX-License-Identifier: MIT
// Seeded random streams. A run is reproducible from (seed, stream): streams
// are independent sequences (xoshiro256** seeded through SplitMix64 from the
// pair), so parallel workers draw from their own stream and the results do not
// depend on how work is scheduled (DESIGN.md "Reproducibility").
#pragma once

#include <array>
#include <cstdint>
#include <limits>

namespace hula {

/// xoshiro256** generator (Blackman & Vigna 2018) seeded from (seed, stream).
/// Satisfies std::uniform_random_bit_generator, but prefer the members below:
/// they give the same numbers on every platform, unlike std distributions.
class Rng {
 public:
  using result_type = std::uint64_t;

  /// Stream `stream` of the run seeded with `seed`.
  explicit Rng(std::uint64_t seed, std::uint64_t stream = 0) noexcept;

  static constexpr result_type min() noexcept { return 0; }
  static constexpr result_type max() noexcept { return std::numeric_limits<result_type>::max(); }
  result_type operator()() noexcept;

  /// Uniform double in [0, 1) with 53 random bits.
  double uniform() noexcept;
  /// Uniform double in [lo, hi).
  double uniform(double lo, double hi) noexcept { return lo + (hi - lo) * uniform(); }
  /// Uniform integer in [0, n), n > 0, without modulo bias (Lemire's method).
  std::uint64_t below(std::uint64_t n) noexcept;
  /// Standard normal deviate (Marsaglia polar method; deterministic).
  double normal() noexcept;

 private:
  std::array<std::uint64_t, 4> s_{};
};

}  // namespace hula
