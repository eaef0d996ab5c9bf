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

// The draws are inline (the GA's selection, crossover and mutation draw once per bit or
// variable, and an out-of-line call cost more than the generator).

inline Rng::result_type Rng::operator()() noexcept {
  const auto rotl = [](std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); };
  const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
  const std::uint64_t t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = rotl(s_[3], 45);
  return result;
}

inline double Rng::uniform() noexcept { return static_cast<double>((*this)() >> 11) * 0x1.0p-53; }

inline std::uint64_t Rng::below(std::uint64_t n) noexcept {
  // Lemire (2019): multiply-shift with rejection of the biased low range.
  std::uint64_t x = (*this)();
  __uint128_t m = static_cast<__uint128_t>(x) * n;
  auto low = static_cast<std::uint64_t>(m);
  if (low < n) {
    const std::uint64_t threshold = (0 - n) % n;
    while (low < threshold) {
      x = (*this)();
      m = static_cast<__uint128_t>(x) * n;
      low = static_cast<std::uint64_t>(m);
    }
  }
  return static_cast<std::uint64_t>(m >> 64);
}

}  // namespace hula
