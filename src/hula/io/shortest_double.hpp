// SPDX-License-Identifier: MIT
// The shortest decimal that reads back as a given double, and the JSON text the files are written
// with. The digits are the ones std::to_chars(double) gives (the shortest decimal in the double's
// rounding interval; of several, the closest to the double; of two equally close, the even one),
// computed by Giulietti's Schubfach algorithm ("The Schubfach way to render doubles", 2020) with a
// table of 128-bit powers of ten (detail/pow10_table.inc, written by scripts/gen_pow10_table.py),
// about three times faster than libstdc++'s to_chars for the curve files' numbers.
#pragma once

#include <cstddef>
#include <cstdint>

namespace hula::io {

/// v = digits × 10^exponent with the fewest digits (no trailing zero); digits < 10^17.
struct ShortestDecimal {
  std::uint64_t digits = 0;
  int exponent = 0;
};

/// The shortest decimal of a finite v > 0 (std::to_chars's digits, see above).
[[nodiscard]] ShortestDecimal shortest_decimal(double v);

/// The room write_json_number needs after `out`: it writes at most 24 characters
/// ("-1.2345678901234567e-308") but copies its digits in fixed-size pieces that may reach further.
inline constexpr std::size_t kJsonNumberRoom = 40;

/// Writes v as append_json_number (json_write.hpp) writes it at `out`, which has room for
/// kJsonNumberRoom characters; returns the end. "0.0" for ±0, "null" when not finite, else the
/// shortest digits laid out as nlohmann's dump() lays out its own: fixed with at least one decimal
/// ("12.0", "0.0001") for decimal exponents in (-4, 15], else scientific ("1e+16", "1.5e-05").
char* write_json_number(char* out, double v);

}  // namespace hula::io
