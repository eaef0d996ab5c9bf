// SPDX-License-Identifier: MIT
// Unit tests of the law DAG: hash-consing, value-preserving simplification,
// dimensions and their errors, term, composition.
#include "hula/law/expr.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "hula/testing/expect_error.hpp"
#include "law_test_util.hpp"

namespace hula::law {
namespace {

using test::eval;
using test::eval1;

// checks: structurally equal subexpressions are one node (ids equal) against building them twice.
TEST(LawExpr, HashConsingSharesEqualSubexpressions) {
  Context ctx;
  const Law t = ctx.parameter("t");
  const Law a = sin(t * 2.0) + cos(t);
  const std::size_t before = ctx.node_count();
  const Law b = sin(t * 2.0) + cos(t);
  EXPECT_EQ(a, b);
  EXPECT_EQ(ctx.node_count(), before);
  EXPECT_EQ(ctx.parameter("t"), t);
  EXPECT_FALSE(sin(t) == cos(t));
  // a DAG shares: size of a + a counts a's nodes once
  EXPECT_EQ(Context::size(a + a), Context::size(a) + 1);
}

// checks: identities x+0, x*1, x/1, x^1, -(-x), constant folding against the expected nodes.
TEST(LawExpr, SimplificationIdentities) {
  Context ctx;
  const Law t = ctx.parameter("t");
  EXPECT_EQ(t + 0.0, t);
  EXPECT_EQ(0.0 + t, t);
  EXPECT_EQ(t - 0.0, t);
  EXPECT_EQ(t * 1.0, t);
  EXPECT_EQ(1.0 * t, t);
  EXPECT_EQ(t / 1.0, t);
  EXPECT_EQ(pow(t, 1.0), t);
  EXPECT_EQ(-(-t), t);
  EXPECT_EQ(0.0 - t, -t);
  EXPECT_EQ(ctx.constant(2.0) * ctx.constant(3.0), ctx.constant(6.0));
  EXPECT_EQ(sin(ctx.constant(0.0)), ctx.constant(0.0));
  EXPECT_EQ(t * 0.0, ctx.constant(0.0));  // t is total
  EXPECT_EQ(t - t, ctx.constant(0.0));
  EXPECT_EQ(pow(sin(t), 0.0), ctx.constant(1.0));
}

// checks: x*0, x-x, x^0 are kept where x may be undefined (1/t at t = 0), so no value changes.
TEST(LawExpr, SimplificationKeepsUndefinedness) {
  Context ctx;
  const Law t = ctx.parameter("t");
  const Law r = 1.0 / t;
  EXPECT_NE(r * 0.0, ctx.constant(0.0));
  EXPECT_NE(r - r, ctx.constant(0.0));
  EXPECT_NE(pow(sqrt(t), 0.0), ctx.constant(1.0));
  EXPECT_TRUE(std::isnan(eval1(r * 0.0, 0.0)));
  EXPECT_EQ(eval1(r * 0.0, 2.0), 0.0);
  // 1/0 is not folded to inf: it stays symbolic and evaluates as undefined
  const Law bad = ctx.constant(1.0) / ctx.constant(0.0);
  EXPECT_EQ(bad.op(), Op::Div);
  EXPECT_TRUE(std::isnan(eval1(bad, 0.0)));
}

// checks: vector laws have the dimension of their construction; term is 1-based (thesis term_law).
TEST(LawExpr, VectorsAndTerm) {
  Context ctx;
  const Law t = ctx.parameter("t");
  const Law v = vec(cos(t), sin(t), t);
  EXPECT_EQ(v.dimension(), 3);
  EXPECT_EQ(term(v, 1), cos(t));
  EXPECT_EQ(term(v, 3), t);
  EXPECT_EQ(vec(t, t).dimension(), 2);
  EXPECT_EQ(dot(v, v).dimension(), 1);
  EXPECT_EQ(cross(v, v).dimension(), 3);
  EXPECT_EQ(norm(v).dimension(), 1);
  EXPECT_EQ((2.0 * v).dimension(), 3);
  EXPECT_EQ((v / t).dimension(), 3);
  const auto x = eval(cross(v, vec(ctx.constant(0.0), ctx.constant(0.0), ctx.constant(1.0))), 0.3);
  EXPECT_DOUBLE_EQ(x[0], std::sin(0.3));
  EXPECT_DOUBLE_EQ(x[1], -std::cos(0.3));
  EXPECT_DOUBLE_EQ(x[2], 0.0);
  const Law w = term(normalize(v), 2);  // a Term node over a non-vec argument
  EXPECT_EQ(w.op(), Op::Term);
  EXPECT_NEAR(eval1(w, 0.3), std::sin(0.3) / std::sqrt(1.0 + 0.09), 1e-15);
}

// checks: dimension errors are hula::Error(InvalidArgument) naming the operation.
TEST(LawExpr, DimensionErrorsNameTheOperation) {
  Context ctx;
  const Law t = ctx.parameter("t");
  const Law v = vec(t, t, t);
  HULA_EXPECT_ERROR(t + v, Errc::InvalidArgument, "'+': cannot add a scalar and a 3-vector");
  HULA_EXPECT_ERROR(v - t, Errc::InvalidArgument, "'-'");
  HULA_EXPECT_ERROR(v * v, Errc::InvalidArgument, "'*': cannot multiply a 3-vector by a 3-vector");
  HULA_EXPECT_ERROR(t / v, Errc::InvalidArgument, "'/': cannot divide by a 3-vector");
  HULA_EXPECT_ERROR(sin(v), Errc::InvalidArgument, "'sin': expects a scalar");
  HULA_EXPECT_ERROR(pow(v, t), Errc::InvalidArgument, "'^'");
  HULA_EXPECT_ERROR(dot(v, vec(t, t)), Errc::InvalidArgument, "'dot'");
  HULA_EXPECT_ERROR(cross(vec(t, t), vec(t, t)), Errc::InvalidArgument, "'cross': expects two 3-vectors");
  HULA_EXPECT_ERROR(term(v, 0), Errc::InvalidArgument, "'term': index 0");
  HULA_EXPECT_ERROR(term(v, 4), Errc::InvalidArgument, "'term': index 4");
  HULA_EXPECT_ERROR(piecewise(v, t, t), Errc::InvalidArgument, "'piecewise': the condition");
  HULA_EXPECT_ERROR(piecewise(t, t, v), Errc::InvalidArgument, "'piecewise': branches");
  HULA_EXPECT_ERROR(vec(v, t), Errc::InvalidArgument, "'vec'");
  Context other;
  HULA_EXPECT_ERROR(t + other.parameter("t"), Errc::InvalidArgument, "different law contexts");
  HULA_EXPECT_ERROR(ctx.constant(std::nan("")), Errc::NonFiniteInput, "finite");
  HULA_EXPECT_ERROR(ctx.parameter("sin"), Errc::InvalidArgument, "'sin' is reserved");
  HULA_EXPECT_ERROR(ctx.parameter("2x"), Errc::InvalidArgument, "'2x' is not an identifier");
}

// checks: substitution (composition) equals building the composed law directly.
TEST(LawExpr, SubstituteIsComposition) {
  Context ctx;
  const Law t = ctx.parameter("t");
  const Law u = ctx.parameter("u");
  const Law f = sin(u) * u + exp(u);
  const Law g = t * t + 1.0;
  EXPECT_EQ(substitute(f, "u", g), sin(g) * g + exp(g));
  EXPECT_EQ(substitute(f, "w", g), f);  // unknown name: unchanged
  HULA_EXPECT_ERROR(substitute(f, "u", vec(t, t)), Errc::InvalidArgument, "'substitute'");
}

// checks: piecewise takes only the selected branch; min/max/sign/abs values against std.
TEST(LawExpr, PiecewiseAndFriends) {
  Context ctx;
  const Law t = ctx.parameter("t");
  const Law f = piecewise(less(t, ctx.constant(0.0)), sqrt(-t), t * t);
  EXPECT_DOUBLE_EQ(eval1(f, -4.0), 2.0);
  EXPECT_DOUBLE_EQ(eval1(f, 3.0), 9.0);  // sqrt(-3) not selected: defined
  EXPECT_DOUBLE_EQ(eval1(min(t, 1.0 - t), 0.2), 0.2);
  EXPECT_DOUBLE_EQ(eval1(max(t, 1.0 - t), 0.2), 0.8);
  EXPECT_DOUBLE_EQ(eval1(sign(t), -0.5), -1.0);
  EXPECT_DOUBLE_EQ(eval1(sign(t), 0.0), 0.0);
  EXPECT_DOUBLE_EQ(eval1(abs(t), -0.5), 0.5);
  EXPECT_DOUBLE_EQ(eval1(less_equal(t, ctx.constant(1.0)), 1.0), 1.0);
}

}  // namespace
}  // namespace hula::law
