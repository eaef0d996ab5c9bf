// SPDX-License-Identifier: MIT
// format_json's numbers (json_write.hpp): shortest round-trip digits laid out as nlohmann::json's
// dump() lays out its own, checked against dump() itself (grisu2, an independent digit generator) and
// against strtod reading every number back.
#include "hula/io/json_write.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace {

using hula::io::format_json_line;
using hula::io::json::Json;

// The text format_json_line gives one number, without the newline.
std::string text_of(const Json& v) {
  std::string s = format_json_line(v);
  s.pop_back();
  return s;
}

// checks: hand-picked numbers on each side of nlohmann's fixed/scientific bounds print as dump() prints them
TEST(JsonWrite, NumbersLookAsNlohmannWritesThem) {
  const std::vector<double> values = {1.0,
                                      -1.0,
                                      0.5,
                                      12.0,
                                      123.456,
                                      1e15,
                                      1e16,
                                      123456789012345.0,
                                      1e-4,
                                      1e-5,
                                      1.5e-5,
                                      0.00012,
                                      0.1,
                                      1.0 / 3,
                                      2.0 / 3,
                                      -7.25e-300,
                                      1e300,
                                      1e21,
                                      5e-324,
                                      1e-7,
                                      9.999e14,
                                      1e100,
                                      -0.001,
                                      6.02214076e23,
                                      std::numeric_limits<double>::max(),
                                      std::numeric_limits<double>::min()};
  for (const double x : values) EXPECT_EQ(text_of(Json(x)), Json(x).dump()) << x;
  EXPECT_EQ(text_of(Json(0.0)), "0.0");
  EXPECT_EQ(text_of(Json(-0.0)), "0.0");
  EXPECT_EQ(text_of(Json(std::numeric_limits<double>::quiet_NaN())), "null");
  EXPECT_EQ(text_of(Json(-std::numeric_limits<double>::infinity())), "null");
  EXPECT_EQ(text_of(Json(std::int64_t{-9223372036854775807 - 1})), "-9223372036854775808");
  EXPECT_EQ(text_of(Json(std::uint64_t{18446744073709551615u})), "18446744073709551615");
  EXPECT_EQ(text_of(Json(0)), "0");
  EXPECT_EQ(text_of(Json::array({1.5, -2, "x", true, nullptr})), "[1.5,-2,\"x\",true,null]");
}

// checks: random doubles over the whole exponent range read back exactly (strtod) and print as dump()
// prints them, or, where grisu2 does not find the shortest or the nearest digits (about 1 in 1,000), with
// no more characters than dump()
TEST(JsonWrite, RandomNumbersRoundTripAndMatchDump) {
  std::mt19937_64 rng(20261207);
  std::uniform_int_distribution<std::uint64_t> bits;
  int different = 0;
  for (int i = 0; i < 200000; ++i) {
    // Half uniform in bit pattern (every magnitude), half model-sized coordinates.
    double x;
    if (i % 2 == 0) {
      const std::uint64_t b = bits(rng);
      std::memcpy(&x, &b, sizeof x);
      if (!std::isfinite(x) || x == 0.0) continue;
    } else {
      x = std::uniform_real_distribution<double>(-1000.0, 1000.0)(rng);
    }
    const std::string ours = text_of(Json(x));
    ASSERT_EQ(std::strtod(ours.c_str(), nullptr), x) << ours;
    const std::string theirs = Json(x).dump();
    if (ours != theirs) {
      ++different;
      EXPECT_LE(ours.size(), theirs.size()) << ours << " vs " << theirs;
    }
  }
  EXPECT_LT(different, 1000) << "grisu2 misses the shortest digits rarely; the layouts must agree otherwise";
}

}  // namespace
