// SPDX-License-Identifier: MIT
// The Schubfach digits and the JSON number text (shortest_double.hpp) against libstdc++'s
// std::to_chars (Ryu, an independent shortest-digits algorithm) laid out by the rules written plainly
// here, and against std::from_chars reading every text back to the same bits.
#include "hula/io/shortest_double.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <random>
#include <string>
#include <system_error>
#include <vector>

namespace {

using hula::io::kJsonNumberRoom;
using hula::io::shortest_decimal;
using hula::io::write_json_number;

// std::to_chars's shortest scientific text of v > 0 split into its digits (no point) and the decimal
// exponent of its first digit.
struct RyuDigits {
  std::string digits;
  int exponent10 = 0;
};
RyuDigits ryu_digits(double v) {
  char text[64];
  const auto [end, ec] = std::to_chars(text, text + sizeof text, v, std::chars_format::scientific);
  EXPECT_EQ(ec, std::errc());
  RyuDigits out;
  const char* c = text;
  for (; *c != 'e'; ++c)
    if (*c != '.') out.digits += *c;
  const char* const last = end;
  out.exponent10 = std::atoi(std::string(c + 1, last).c_str());
  return out;
}

// The text the curve files have always had: nlohmann's layout of the shortest digits, written plainly.
std::string reference_text(double v) {
  if (v == 0.0) return "0.0";
  if (!std::isfinite(v)) return "null";
  std::string sign = std::signbit(v) ? "-" : "";
  const RyuDigits r = ryu_digits(std::fabs(v));
  const auto k = static_cast<int>(r.digits.size());
  const int n = r.exponent10 + 1;  // v = 0.d1…dk × 10^n
  if (k <= n && n <= 15) return sign + r.digits + std::string(static_cast<std::size_t>(n - k), '0') + ".0";
  if (0 < n && n <= 15) return sign + r.digits.substr(0, static_cast<std::size_t>(n)) + "." + r.digits.substr(n);
  if (-4 < n && n <= 0) return sign + "0." + std::string(static_cast<std::size_t>(-n), '0') + r.digits;
  std::string out = sign + r.digits.substr(0, 1);
  if (k > 1) out += "." + r.digits.substr(1);
  const int e = n - 1;
  std::string exponent = std::to_string(std::abs(e));
  if (exponent.size() < 2) exponent = "0" + exponent;
  return out + "e" + (e < 0 ? "-" : "+") + exponent;
}

// Counts the numbers whose digits, text or read-back differ (reporting the first few).
struct Checker {
  int failures = 0;
  long checked = 0;
  void check(double v) {
    ++checked;
    char text[kJsonNumberRoom];
    const std::string ours(text, write_json_number(text, v));
    const std::string expected = reference_text(v);
    bool ok = ours == expected;
    if (std::isfinite(v) && v != 0.0) {
      const RyuDigits r = ryu_digits(std::fabs(v));
      const hula::io::ShortestDecimal d = shortest_decimal(std::fabs(v));
      const std::string digits = std::to_string(d.digits);
      ok = ok && digits == r.digits && d.exponent + static_cast<int>(digits.size()) - 1 == r.exponent10;
      double back = 0.0;
      const auto [end, ec] = std::from_chars(ours.data(), ours.data() + ours.size(), back);
      ok = ok && ec == std::errc() && end == ours.data() + ours.size() &&
           std::bit_cast<std::uint64_t>(back) == std::bit_cast<std::uint64_t>(v);
    }
    if (!ok && ++failures <= 10)
      ADD_FAILURE() << "bits 0x" << std::hex << std::bit_cast<std::uint64_t>(v) << std::dec << ": ours " << ours
                    << ", to_chars laid out " << expected;
  }
};

double from_bits(std::uint64_t b) { return std::bit_cast<double>(b); }

// checks: 1,000,000 random bit patterns (every magnitude, subnormals, both signs) give std::to_chars's
// digits and exponent, the reference layout, and read back to the same bits
TEST(ShortestDouble, RandomBitPatternsMatchToChars) {
  std::mt19937_64 rng(27);
  Checker c;
  while (c.checked < 1000000) {
    const double v = from_bits(rng());
    if (std::isfinite(v) && v != 0.0) c.check(v);
  }
  EXPECT_EQ(c.failures, 0);
}

// checks: every binary exponent (each power of ten in the table is used by one of them) with the extreme
// significands (a power of two, whose lower neighbour is closer, and the largest) and random ones
TEST(ShortestDouble, EveryExponentMatchesToChars) {
  std::mt19937_64 rng(2027);
  constexpr std::uint64_t kFraction = (std::uint64_t{1} << 52) - 1;
  Checker c;
  for (std::uint64_t e = 0; e < 2047; ++e) {
    for (const std::uint64_t f : {std::uint64_t{0}, std::uint64_t{1}, std::uint64_t{2}, std::uint64_t{3}, kFraction,
                                  kFraction - 1, std::uint64_t{1} << 51})
      if (e != 0 || f != 0) c.check(from_bits(e << 52 | f));
    for (int i = 0; i < 100; ++i) {
      const std::uint64_t f = rng() & kFraction;
      if (e != 0 || f != 0) c.check(-from_bits(e << 52 | f));
    }
  }
  EXPECT_EQ(c.failures, 0);
  EXPECT_GT(c.checked, 2047 * 100);
}

// checks: powers of ten and their neighbours, integers (below and above 2^53), short decimals of a
// CSV file and their neighbours, and the limits, at both layout bounds (1e15/1e16, 1e-4/1e-5)
TEST(ShortestDouble, BoundaryCasesMatchToChars) {
  Checker c;
  for (int p = -324; p <= 308; ++p) {
    const double v = std::strtod(("1e" + std::to_string(p)).c_str(), nullptr);
    if (v == 0.0) continue;
    c.check(v);
    c.check(std::nextafter(v, 0.0));
    c.check(std::nextafter(v, 2 * v));
    c.check(-v);
  }
  for (std::int64_t i = 1; i <= 200000; ++i) c.check(static_cast<double>(i));
  for (int b = 0; b < 1024; ++b) {
    c.check(std::ldexp(1.0, b));
    c.check(std::ldexp(1.0, -b - 50));
    c.check(std::ldexp(3.0, b));
  }
  std::mt19937_64 rng(9);
  for (int i = 0; i < 200000; ++i) {
    // Up to 9 decimals, as bench/cli/startup.sh writes its helix.
    const double v = static_cast<double>(static_cast<std::int64_t>(rng() % 2000000001) - 1000000000) / 1e9;
    c.check(v);
    c.check(std::nextafter(v, 2.0));
    c.check(static_cast<double>(rng() % 100000) * std::pow(10.0, static_cast<double>(rng() % 44) - 22));
  }
  for (const double v : {std::numeric_limits<double>::max(), std::numeric_limits<double>::min(),
                         std::numeric_limits<double>::denorm_min(), 9007199254740991.0, 9007199254740992.0,
                         9007199254740993.0, 1e15, 999999999999999.9, 1e16, 1e-4, 9.9999999999999e-5, 1e-5, 0.1 + 0.2,
                         1.0 / 3.0, 5e-324, 1.7976931348623157e308, 2.2250738585072009e-308})
    c.check(v);
  EXPECT_EQ(c.failures, 0);
}

// checks: zero of either sign, infinities and NaN are written as format_json has always written them
TEST(ShortestDouble, ZeroAndNonFinite) {
  char text[kJsonNumberRoom];
  EXPECT_EQ(std::string(text, write_json_number(text, 0.0)), "0.0");
  EXPECT_EQ(std::string(text, write_json_number(text, -0.0)), "0.0");
  EXPECT_EQ(std::string(text, write_json_number(text, std::numeric_limits<double>::infinity())), "null");
  EXPECT_EQ(std::string(text, write_json_number(text, -std::numeric_limits<double>::infinity())), "null");
  EXPECT_EQ(std::string(text, write_json_number(text, std::numeric_limits<double>::quiet_NaN())), "null");
  // Hand-checked texts, independent of any library: 2^-1074, the largest double, 0.1 + 0.2.
  EXPECT_EQ(std::string(text, write_json_number(text, std::numeric_limits<double>::denorm_min())), "5e-324");
  EXPECT_EQ(std::string(text, write_json_number(text, std::numeric_limits<double>::max())), "1.7976931348623157e+308");
  EXPECT_EQ(std::string(text, write_json_number(text, 0.1 + 0.2)), "0.30000000000000004");
  EXPECT_EQ(std::string(text, write_json_number(text, 1e14)), "100000000000000.0");
  EXPECT_EQ(std::string(text, write_json_number(text, 1e15)), "1e+15");
  EXPECT_EQ(std::string(text, write_json_number(text, 1e16)), "1e+16");
  EXPECT_EQ(std::string(text, write_json_number(text, -1.5e-5)), "-1.5e-05");
  EXPECT_EQ(std::string(text, write_json_number(text, 0.0001)), "0.0001");
}

}  // namespace
