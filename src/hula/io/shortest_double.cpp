// SPDX-License-Identifier: MIT
// Shortest round-trip digits by Schubfach (shortest_double.hpp). Written from the paper: R. Giulietti,
// "The Schubfach way to render doubles" (2020), sections 9-10 (the 128-bit powers g of 10, the
// round-to-odd product) and figure 6 (choosing among s, t and the one-digit-shorter s', t'), without
// the Java-only rule that keeps two digits for the smallest subnormals: std::to_chars gives 5e-324.
#include "hula/io/shortest_double.hpp"

#include <bit>
#include <cmath>
#include <cstring>

namespace hula::io {
namespace {

struct Pow10 {
  std::uint64_t high;
  std::uint64_t low;
};

// g(e) for e = -292..324 (see the .inc file's header): 10^e ≈ g · 2^(floor(log2 10^e) - 127).
constexpr int kMinPow10 = -292;
constexpr Pow10 kPow10[] = {
#include "hula/io/detail/pow10_table.inc"
};
static_assert(sizeof kPow10 / sizeof kPow10[0] == 324 - kMinPow10 + 1);

// floor(log10(2^q)), floor(log10(3/4 · 2^q)) and floor(log2(10^e)) by fixed-point multiplication; exact
// for every q in [-1076, 971] and e in [-297, 329] (checked against exact rationals when the constants
// were chosen; ShortestDouble tests cover every exponent of a double).
constexpr int floor_log10_pow2(int q) { return (q * 1262611) >> 22; }
constexpr int floor_log10_three_quarters_pow2(int q) { return (q * 1262611 - 524031) >> 22; }
constexpr int floor_log2_pow10(int e) { return (e * 1741647) >> 19; }

// floor(g · cp / 2^128), made odd when the bits below it (from 2^64 up, the lower ones being the
// error of g's rounding) are not all zero: the paper's round-to-odd product, exact for every cp used.
inline std::uint64_t round_to_odd(const Pow10& g, std::uint64_t cp) {
  __extension__ using u128 = unsigned __int128;
  const u128 low = static_cast<u128>(g.low) * cp;
  const u128 product = static_cast<u128>(g.high) * cp + static_cast<std::uint64_t>(low >> 64);
  const auto high = static_cast<std::uint64_t>(product >> 64);
  return high | static_cast<std::uint64_t>(static_cast<std::uint64_t>(product) != 0);
}

// Without its trailing zeros (digits < 10^17, so at most 16 of them).
ShortestDecimal strip_zeros(std::uint64_t digits, int exponent) {
  if (digits % 10 != 0) return {digits, exponent};  // the usual case: 16 or 17 digits
  if (digits % 100000000 == 0) {
    digits /= 100000000;
    exponent += 8;
  }
  if (digits % 100000000 == 0) {
    digits /= 100000000;
    exponent += 8;
  }
  if (digits % 10000 == 0) {
    digits /= 10000;
    exponent += 4;
  }
  if (digits % 100 == 0) {
    digits /= 100;
    exponent += 2;
  }
  if (digits % 10 == 0) {
    digits /= 10;
    exponent += 1;
  }
  return {digits, exponent};
}

constexpr char kTwoDigits[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

inline void put2(char* p, std::uint32_t v) { std::memcpy(p, kTwoDigits + 2 * v, 2); }

// The number of decimal digits of 1 <= v < 10^19.
inline int decimal_length(std::uint64_t v) {
  static constexpr std::uint64_t kPowers[] = {1u,
                                              10u,
                                              100u,
                                              1000u,
                                              10000u,
                                              100000u,
                                              1000000u,
                                              10000000u,
                                              100000000u,
                                              1000000000u,
                                              10000000000u,
                                              100000000000u,
                                              1000000000000u,
                                              10000000000000u,
                                              100000000000000u,
                                              1000000000000000u,
                                              10000000000000000u,
                                              100000000000000000u,
                                              1000000000000000000u,
                                              10000000000000000000u};
  const int t = (std::bit_width(v) * 1233) >> 12;  // floor(log10(2^bit_width)): the length or one less
  return t + static_cast<int>(v >= kPowers[t]);
}

// The eight digits of v < 10^8 at p (the four pairs computed independently of each other).
inline void put8(char* p, std::uint32_t v) {
  const std::uint32_t high = v / 10000u, low = v % 10000u;
  put2(p, high / 100u);
  put2(p + 2, high % 100u);
  put2(p + 4, low / 100u);
  put2(p + 6, low % 100u);
}

// The 17 digits of v < 10^17, with leading zeros, at p.
inline void put17(char* p, std::uint64_t v) {
  const std::uint64_t high = v / 100000000u;  // < 10^9
  const auto low = static_cast<std::uint32_t>(v - high * 100000000u);
  const auto first = static_cast<std::uint32_t>(high / 100000000u);
  p[0] = static_cast<char>('0' + first);
  put8(p + 1, static_cast<std::uint32_t>(high - std::uint64_t{first} * 100000000u));
  put8(p + 9, low);
}

}  // namespace

ShortestDecimal shortest_decimal(double v) {
  const auto bits = std::bit_cast<std::uint64_t>(v);
  const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
  const auto biased_exponent = static_cast<int>((bits >> 52) & 0x7FF);
  std::uint64_t c = 0;  // v = c · 2^q
  int q = 0;
  if (biased_exponent != 0) {
    c = fraction | (std::uint64_t{1} << 52);
    q = biased_exponent - 1075;
    // An integer below 2^53 is its own shortest decimal (its rounding interval is at most ±1/2).
    if (-52 <= q && q <= 0) {
      const std::uint64_t integer = c >> -q;
      if (integer << -q == c) return strip_zeros(integer, 0);
    }
  } else {
    c = fraction;
    q = -1074;
  }
  // The rounding interval [c - 1/2, c + 1/2] · 2^q (its ends included when c is even, as a reader
  // rounds ties to even), with the lower half-gap a quarter at a power of two; 4 · (v, ends).
  const bool closer_below = fraction == 0 && biased_exponent > 1;
  const std::uint64_t cb = 4 * c;
  const std::uint64_t cbl = cb - 2 + static_cast<std::uint64_t>(closer_below);
  const std::uint64_t cbr = cb + 2;
  const int k = closer_below ? floor_log10_three_quarters_pow2(q) : floor_log10_pow2(q);
  const int h = q + floor_log2_pow10(-k) + 1;  // 1..4
  const Pow10& g = kPow10[-k - kMinPow10];
  // 4 · (v, lower end, upper end) · 10^-k, rounded to odd: the interval holds 1 to 10 units of 10^k.
  const std::uint64_t vb = round_to_odd(g, cb << h);
  const std::uint64_t vbl = round_to_odd(g, cbl << h);
  const std::uint64_t vbr = round_to_odd(g, cbr << h);
  const bool even = c % 2 == 0;
  const std::uint64_t lower = vbl + static_cast<std::uint64_t>(!even);
  const std::uint64_t upper = vbr - static_cast<std::uint64_t>(!even);
  // Units of 10^k: s = floor(v), t = s + 1; one digit fewer, units of 10^(k+1): sp = floor(v / 10),
  // tp = sp + 1. The interval holds at most one of sp, tp: when it holds exactly one, that one has the
  // fewest digits; else s or t, whichever the interval holds, or the closer one (the even one on a tie).
  // Computed without branches (which of these holds is as good as random from one number to the next).
  const std::uint64_t s = vb / 4;
  const std::uint64_t sp = s / 10;
  const bool sp_in = lower <= 40 * sp;
  const bool tp_in = 40 * sp + 40 <= upper;
  const bool s_in = lower <= 4 * s;
  const bool t_in = 4 * s + 4 <= upper;
  const std::uint64_t mid = 4 * s + 2;
  const bool closer_up = vb > mid || (vb == mid && (s & 1) != 0);
  const bool up = s_in != t_in ? t_in : closer_up;
  const bool shorter = s >= 10 && sp_in != tp_in;
  const std::uint64_t digits = shorter ? sp + static_cast<std::uint64_t>(tp_in) : s + static_cast<std::uint64_t>(up);
  return strip_zeros(digits, shorter ? k + 1 : k);
}

char* write_json_number(char* out, double v) {
  if (v == 0.0) {  // -0.0 too
    std::memcpy(out, "0.0", 3);
    return out + 3;
  }
  if (!std::isfinite(v)) {
    std::memcpy(out, "null", 4);
    return out + 4;
  }
  if (std::signbit(v)) {
    *out++ = '-';
    v = -v;
  }
  const ShortestDecimal d = shortest_decimal(v);
  const int length = decimal_length(d.digits);
  const int n = length + d.exponent;  // v = 0.d1d2…d(length) × 10^n
  // The digits, then fixed-size copies of them (past the digits they copy what the layout overwrites
  // or leaves past the end: within kJsonNumberRoom).
  char padded[48] = {};
  put17(padded, d.digits);
  const char* digits = padded + 17 - length;
  constexpr int kMinExp = -4, kMaxExp = 15;  // nlohmann's bounds for fixed notation
  if (0 < n && n <= kMaxExp) {
    if (length <= n) {  // digits[000].0
      std::memcpy(out, digits, 17);
      out += length;
      std::memset(out, '0', 16);
      out += n - length;
      std::memcpy(out, ".0", 2);
      return out + 2;
    }
    // dig.its
    std::memcpy(out, digits, 16);
    out[n] = '.';
    std::memcpy(out + n + 1, digits + n, 16);
    return out + length + 1;
  }
  if (kMinExp < n && n <= 0) {  // 0.[000]digits
    std::memcpy(out, "0.000", 5);
    out += 2 - n;
    std::memcpy(out, digits, 17);
    return out + length;
  }
  // d[.igits]e±XX
  out[0] = digits[0];
  out[1] = '.';
  std::memcpy(out + 2, digits + 1, 16);
  out += length > 1 ? length + 1 : 1;
  int e = n - 1;
  *out++ = 'e';
  *out++ = e < 0 ? '-' : '+';
  if (e < 0) e = -e;
  if (e >= 100) {
    *out++ = static_cast<char>('0' + e / 100);
    e %= 100;
  }
  put2(out, static_cast<std::uint32_t>(e));
  return out + 2;
}

}  // namespace hula::io
