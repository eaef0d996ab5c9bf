// SPDX-License-Identifier: MIT
// The normal form of law::simplify: ring identities simplify to zero (the
// check behind the antiderivative tests), powers merge without changing a
// value, the bounds stop runaway expansion, and a random expression keeps its
// values (simplify_property_test.cpp).
#include "hula/law/simplify.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "hula/law/derive.hpp"
#include "hula/law/parser.hpp"
#include "hula/testing/expect_error.hpp"
#include "hula/testing/fpe.hpp"
#include "law_test_util.hpp"

namespace hula::law {
namespace {

Law simplified(const char* text, Context& ctx) { return simplify(parse(text, ctx)); }

// checks: identities of commutative rings with division by monomials simplify to exactly 0.
TEST(LawSimplify, RingIdentitiesVanish) {
  const char* zeros[] = {
      "exp(t) + (t - 1)*exp(t) - t*exp(t)",
      "(t + 1)^2 - t^2 - 2*t - 1",
      "(t - 2)^5 - (t^5 - 10*t^4 + 40*t^3 - 80*t^2 + 80*t - 32)",
      "sqrt(t)*sqrt(t) - t",
      "t^1.5/t - sqrt(t)",
      "2*t*cos(t^2) - cos(t*t)*t*2",
      "sin(2*t + 1)*(3*t - 3*t + 1) - sin(1 + t*2)",
      "1/(1 + t^2) - 1/(t*t + 1)",
      "(2*t)/(4*t^2) - 0.5/t",
      "x*y - y*x",
      "(1 + t^2)^-2*(1 + t^2)^-1 - (t^2 + 1)^-3",
      "(t + 1)/(2*t + 2) - 0.5",
  };
  for (const char* z : zeros) {
    SCOPED_TRACE(z);
    Context ctx;
    ParseOptions po;
    po.parameters = {"t", "x", "y"};
    const Law s = simplify(parse(z, ctx, po));
    EXPECT_TRUE(s.is_zero()) << print(s);
  }
}

// checks: equal normal forms are the same node (hash-consing), so equality is an identity test.
TEST(LawSimplify, EqualFormsAreTheSameNode) {
  Context ctx;
  EXPECT_EQ(simplified("(t + 1)*(t - 1)", ctx), simplified("t^2 - 1", ctx));
  EXPECT_EQ(simplified("exp(t)*t - exp(t)", ctx), simplified("(t - 1)*exp(t)", ctx));
  EXPECT_EQ(simplified("sin(t)/cos(t)*cos(t)", ctx), simplified("sin(t)", ctx));
}

// checks: non-integer powers are distributed only where that cannot change a value:
// (t²)^0.5 = |t| keeps its value at t = −2, (8 t³)^(1/3) = 2 t for t ≥ 0.
TEST(LawSimplify, FractionalPowersKeepTheirValues) {
  Context ctx;
  const Law root_of_square = simplified("(t^2)^0.5", ctx);
  EXPECT_DOUBLE_EQ(test::eval1(root_of_square, -2.0), 2.0);
  const Law cube_root = simplified("(8*t^3)^(1/3)", ctx);
  EXPECT_NEAR(test::eval1(cube_root, 1.7), 3.4, 1e-14);
  // √t · t^(−1/2) merges to 1 (defined for t > 0, where the original is).
  EXPECT_TRUE(simplified("sqrt(t)*t^(-0.5) - 1", ctx).is_zero());
}

// checks: the bounds stop the expansion (a power above max_expand_power stays a power) and bad
// options name their field.
TEST(LawSimplify, BoundsAndOptions) {
  Context ctx;
  const Law high = simplify(parse("(t + 1)^20", ctx));
  EXPECT_EQ(high.op(), Op::Pow);
  SimplifyOptions small;
  small.max_terms = 3;
  const Law kept = simplify(parse("(t + 1)*(t + 2)*(t + 3)", ctx), small);
  EXPECT_NEAR(test::eval1(kept, 0.5), 1.5 * 2.5 * 3.5, 1e-14);
  SimplifyOptions bad;
  bad.max_expand_power = 65;
  HULA_EXPECT_ERROR((void)simplify(parse("t", ctx), bad), Errc::InvalidOption, "max_expand_power");
  HULA_EXPECT_ERROR((void)simplify(Law{}), Errc::InvalidArgument, "empty law");
}

// checks: vector laws are simplified per component.
TEST(LawSimplify, Vectors) {
  Context ctx;
  const Law v = simplified("vec(t*t - t^2, (t + 1)^2 - 1, 3)", ctx);
  const auto x = test::eval(v, 2.0);
  ASSERT_EQ(x.size(), 3U);
  EXPECT_EQ(x[0], 0.0);
  EXPECT_EQ(x[1], 8.0);
  EXPECT_EQ(x[2], 3.0);
}

// checks: the derivative of a product simplified equals the simplified hand derivative.
TEST(LawSimplify, DerivativesCollect) {
  Context ctx;
  const Law f = parse("t^3*exp(2*t)", ctx);
  const Law df = simplify(derivative(f, "t"));
  EXPECT_EQ(df, simplified("3*t^2*exp(2*t) + 2*t^3*exp(2*t)", ctx));
}

}  // namespace
}  // namespace hula::law
