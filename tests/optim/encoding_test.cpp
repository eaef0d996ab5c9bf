// SPDX-License-Identifier: MIT
// Tests of the binary coding of appendix 2: layout, decoding precision, round trip.
#include "hula/optim/encoding.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "hula/core/rng.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::optim {
namespace {

// checks: decoded values against l + (u-l) k/(2^b-1): ends exact, steps equal the resolution <= precision
TEST(OptimEncoding, DecodingPrecision) {
  const std::vector<Variable> vars = {{.lower = -1.0, .upper = 2.0, .precision = 1e-3},
                                      {.lower = 0.02, .upper = 10.0, .precision = 0.5},
                                      {.lower = 5.0, .upper = 5.0, .precision = 1.0}};
  const BinaryEncoding enc(vars);
  EXPECT_EQ(enc.bits(0), 12U);  // 3/(2^12-1) = 7.3e-4 <= 1e-3 < 3/(2^11-1)
  EXPECT_EQ(enc.bits(1), 5U);   // 9.98/31 = 0.32 <= 0.5 < 9.98/15
  EXPECT_EQ(enc.bits(2), 1U);
  EXPECT_EQ(enc.length(), 18U);
  std::vector<std::uint8_t> zeros(enc.length(), 0), ones(enc.length(), 1);
  std::vector<double> x(3);
  enc.decode(zeros, x);
  EXPECT_EQ(x[0], -1.0);
  EXPECT_EQ(x[1], 0.02);
  EXPECT_EQ(x[2], 5.0);
  enc.decode(ones, x);
  EXPECT_EQ(x[0], 2.0);
  EXPECT_EQ(x[1], 10.0);
  // Gene 0 = 000000000001 decodes one resolution step above the lower bound.
  std::vector<std::uint8_t> one = zeros;
  one[11] = 1;
  enc.decode(one, x);
  EXPECT_NEAR(x[0] - (-1.0), enc.resolution(0), 1e-15);
  EXPECT_LE(enc.resolution(0), 1e-3);
  // Any value is represented within half a resolution step.
  Rng rng(1, 0);
  for (int i = 0; i < 1000; ++i) {
    const std::vector<double> v = {rng.uniform(-1, 2), rng.uniform(0.02, 10), 5.0};
    enc.decode(enc.encode(v), x);
    EXPECT_LE(std::fabs(x[0] - v[0]), enc.resolution(0) / 2 + 1e-15);
    EXPECT_LE(std::fabs(x[1] - v[1]), enc.resolution(1) / 2 + 1e-15);
  }
}

// checks: a 52-bit gene decodes every level exactly and 53 bits are refused naming the precision
TEST(OptimEncoding, FiftyTwoBitLimit) {
  const Variable ok{.lower = 0.0, .upper = std::ldexp(1.0, 52) - 1.0, .precision = 1.0};
  const BinaryEncoding enc(std::span<const Variable>(&ok, 1));
  EXPECT_EQ(enc.bits(0), 52U);
  std::vector<std::uint8_t> c(52, 0);
  c[51] = 1;
  c[0] = 1;
  std::vector<double> x(1);
  enc.decode(c, x);
  EXPECT_EQ(x[0], std::ldexp(1.0, 51) + 1.0);
  const Variable bad{.lower = 0.0, .upper = 1.0, .precision = 1e-16};
  HULA_EXPECT_ERROR(BinaryEncoding(std::span<const Variable>(&bad, 1)), Errc::InvalidOption,
                    "variables[0].precision = 9.9999999999999998e-17");
  const Variable unset{.lower = 0.0, .upper = 1.0};
  HULA_EXPECT_ERROR(BinaryEncoding(std::span<const Variable>(&unset, 1)), Errc::InvalidOption,
                    "variables[0].precision = 0 must be > 0");
}

}  // namespace
}  // namespace hula::optim
