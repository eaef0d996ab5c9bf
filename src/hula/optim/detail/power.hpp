// SPDX-License-Identifier: MIT
// x^e for the distribution indices of SBX and polynomial mutation. Indices
// are usually whole numbers (eta + 1 = 16, 21...), for which binary
// exponentiation is several times faster than std::pow and exact to a few
// ulps; other exponents fall back to std::pow.
#pragma once

#include <cmath>
#include <cstdint>

namespace hula::optim::detail {

/// x^e, x >= 0.
[[nodiscard]] inline double power(double x, double e) noexcept {
  if (e >= 0.0 && e <= 64.0 && e == std::floor(e)) {
    auto n = static_cast<unsigned>(e);
    double result = 1.0;
    double base = x;
    while (n != 0) {
      if ((n & 1U) != 0) result *= base;
      n >>= 1U;
      if (n != 0) base *= base;  // the last square is never used
    }
    return result;
  }
  return std::pow(x, e);
}

/// The threshold t for which a 32-bit random value v gives v < t with probability `probability`
/// (resolved to 2^-32: ceil(probability 2^32) / 2^32), probability in [0, 1].
[[nodiscard]] inline std::uint64_t threshold32(double probability) noexcept {
  return static_cast<std::uint64_t>(std::ceil(probability * 0x1p32));
}

}  // namespace hula::optim::detail
