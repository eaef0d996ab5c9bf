// SPDX-License-Identifier: MIT
// Unit tests of the law text form: grammar and precedence against hand-built
// DAGs, C number notation against the values C gives, constants, the printer's
// round trip on fixed cases, and every documented parse error with its code,
// position and a message naming the offending character, name or operation.
#include "hula/law/parser.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "hula/nurbs/interpolate.hpp"
#include "hula/testing/expect_error.hpp"
#include "law_test_util.hpp"

namespace hula::law {
namespace {

// checks: precedence and associativity against the DAG built with the C++ operators.
TEST(LawParser, PrecedenceAndAssociativity) {
  Context ctx;
  const Law t = ctx.parameter("t");
  const Law two = ctx.constant(2.0);
  EXPECT_EQ(parse("1 + 2*t", ctx), 1.0 + 2.0 * t);
  EXPECT_EQ(parse("t - 1 - t", ctx), (t - 1.0) - t);
  EXPECT_EQ(parse("t / 2 / t", ctx), (t / 2.0) / t);
  EXPECT_EQ(parse("-t^2", ctx), -pow(t, two));
  EXPECT_EQ(parse("t^2^t", ctx), pow(t, pow(two, t)));
  EXPECT_EQ(parse("t^-1", ctx), pow(t, ctx.constant(-1.0)));
  EXPECT_EQ(parse("2*-t", ctx), 2.0 * -t);
  EXPECT_EQ(parse("+t", ctx), t);
  EXPECT_EQ(parse("t > 1", ctx), less(ctx.constant(1.0), t));
  EXPECT_EQ(parse("t >= 1", ctx), less_equal(ctx.constant(1.0), t));
  EXPECT_EQ(parse("piecewise(t < 0, -t, t)", ctx), piecewise(less(t, ctx.constant(0.0)), -t, t));
  EXPECT_EQ(parse("vec(2*cos(t), 2*sin(t), 0.5*t)", ctx), vec(2.0 * cos(t), 2.0 * sin(t), 0.5 * t));
  EXPECT_EQ(parse("term(vec(t, 1), 2)", ctx), ctx.constant(1.0));
  EXPECT_EQ(parse("pow(t, 3)", ctx), pow(t, 3.0));
  EXPECT_EQ(parse("dot(vec(t,t), vec(1,t)) + norm(cross(vec(t,0,0), vec(0,t,0)))", ctx),
            dot(vec(t, t), vec(ctx.constant(1.0), t)) + norm(cross(vec(t, ctx.constant(0.0), ctx.constant(0.0)),
                                                                   vec(ctx.constant(0.0), t, ctx.constant(0.0)))));
  EXPECT_EQ(parse("\n  sin (t)\t*\r\n2", ctx), sin(t) * 2.0);
}

// checks: numbers in C notation (decimal, exponent, hex float, hex/octal integers, suffixes) against C's values.
TEST(LawParser, CNumberNotation) {
  Context ctx;
  auto v = [&ctx](const char* s) {
    const Law l = parse(s, ctx);
    EXPECT_TRUE(l.is_constant()) << s;
    return l.node().value;
  };
  EXPECT_EQ(v("42"), 42.0);
  EXPECT_EQ(v("0.1"), 0.1);
  EXPECT_EQ(v(".5"), 0.5);
  EXPECT_EQ(v("5."), 5.0);
  EXPECT_EQ(v("1e-3"), 1e-3);
  EXPECT_EQ(v("2.5E+2"), 250.0);
  EXPECT_EQ(v("0x1p-3"), 0.125);
  EXPECT_EQ(v("0x1.8p1"), 3.0);
  EXPECT_EQ(v("0X1F"), 31.0);
  EXPECT_EQ(v("017"), 15.0);  // octal, as in C
  EXPECT_EQ(v("0"), 0.0);
  EXPECT_EQ(v("10u"), 10.0);
  EXPECT_EQ(v("7UL"), 7.0);
  EXPECT_EQ(v("0.1f"), static_cast<double>(0.1f));
  EXPECT_EQ(v("0.25L"), 0.25);
  EXPECT_EQ(v("1.7976931348623157e308"), 1.7976931348623157e308);
  EXPECT_EQ(v("pi"), std::numbers::pi);
  EXPECT_EQ(v("e"), std::numbers::e);
  EXPECT_EQ(v("-2"), -2.0);
}

// checks: print then parse returns the same node on fixed tricky cases (negative constants,
// nested powers, comparisons, NURBS leaves, -0).
TEST(LawParser, PrintParseRoundTrip) {
  const nurbs::NurbsCurve curve =
      nurbs::interpolate_cubic(std::vector<Vec3>{{0, 0, 0}, {1, 1, 0}, {2, 0, 1}, {3, 1, 1}});
  Context ctx;
  const Law t = ctx.parameter("t");
  const Law spine = ctx.curve(curve, t, "spine");
  ParseOptions opts;
  const std::vector<Law> laws{
      pow(ctx.constant(-2.0), t),
      pow(pow(t, t), ctx.constant(0.5)),
      ctx.constant(-0.0) + t * ctx.constant(-3.0),
      -(t - 1.0) * (t + 2.0) / (t - (t / 3.0)),
      piecewise(less_equal(t, sin(t)), vec(t, t), vec(-t, cos(t))),
      less(less(t, ctx.constant(1.0)), ctx.constant(0.5)),
      derivative(spine, "t", 2) * sin(t),
      ctx.constant(0.1) + ctx.constant(1e-300) * t + ctx.constant(1.7976931348623157e308),
      term(normalize(vec(t, exp(t), log(t))), 2),
      atan2(t, ctx.constant(1.0)) - abs(sign(t)) + min(t, max(t, ctx.constant(2.0))),
      -pow(t, ctx.constant(2.0)),
      pow(-t, ctx.constant(2.0)),
      t - -t,
  };
  for (const Law& l : laws) {
    const std::string s = print(l);
    EXPECT_EQ(parse(s, ctx, opts), l) << s << "  reprinted: " << print(parse(s, ctx, opts));
  }
  EXPECT_EQ(print(spine), "spine(t)");
  EXPECT_EQ(print(derivative(spine, "t", 2)), "spine(t, 2)");
}

struct BadCase {
  const char* text;
  std::size_t column;
  const char* message;
};

// checks: every documented parse error: code ParseError, line/column, and the message names what was
// expected and the offending character, name or operation.
TEST(LawParser, ErrorsArePositionedAndNamed) {
  const BadCase cases[] = {
      {"", 1, "expected an expression, found end of input"},
      {"   ", 4, "empty expression"},
      {"sin(t", 6, "expected ',' or ')' in the arguments of 'sin', found end of input"},
      {"(t + 1", 7, "expected ')' to close the '(' at line 1, column 1"},
      {"t + ", 5, "expected a number, a name or '(', found end of input"},
      {"t $ 2", 3, "unexpected character '$'"},
      {"t 2", 3, "expected an operator or end of input, found a number '2'"},
      {"t)", 2, "expected an operator or end of input, found ')'"},
      {"foo + t", 1, "unknown identifier 'foo' (parameters: t)"},
      {"foo(t)", 1, "unknown function 'foo'"},
      {"t(2)", 1, "'t' is a parameter, not a function"},
      {"sin", 4, "expected '(' after the function 'sin'"},
      {"sin(t, t)", 1, "'sin' takes 1 argument, got 2"},
      {"atan2(t)", 1, "'atan2' takes 2 arguments, got 1"},
      {"vec(t)", 1, "'vec' takes 2 or 3 arguments, got 1"},
      {"t + vec(t, t, t)", 3, "'+': cannot add a scalar and a 3-vector"},
      {"sin(vec(t, t))", 1, "'sin': expects a scalar argument, got a 2-vector"},
      {"term(vec(t, t), 3)", 1, "'term': index 3 is outside [1, 2]"},
      {"term(vec(t, t), t)", 17, "'term': the component index must be an integer constant"},
      {"1e", 1, "malformed number '1e': missing exponent digits"},
      {"0x", 1, "malformed number '0x': no hexadecimal digits"},
      {"09", 1, "invalid digit '9' in octal constant"},
      {"1.5.2", 1, "malformed number '1.5.2'"},
      {"2t", 1, "malformed number '2t'"},
      {"1e999", 1, "out of the range of double"},
      {"t < 1 < 2", 7, "comparison operators do not chain"},
      {"t \xC3\xA9", 3, "unexpected byte 0xC3"},
  };
  Context ctx;
  for (const BadCase& c : cases) {
    SCOPED_TRACE(c.text);
    HULA_EXPECT_ERROR(parse(c.text, ctx), Errc::ParseError, c.message);
    try {
      (void)parse(c.text, ctx);
    } catch (const Error& e) {
      EXPECT_EQ(e.where().line.value_or(0), 1U);
      EXPECT_EQ(e.where().column.value_or(0), c.column) << e.what();
      EXPECT_EQ(e.where().field, "expression");
    }
  }
  // line counting across newlines
  try {
    (void)parse("t +\n  2 *\n   )", ctx);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().line.value_or(0), 3U);
    EXPECT_EQ(e.where().column.value_or(0), 4U);
  }
}

// checks: limits (depth, length, nodes, DAG height) give positioned errors instead of stack overflow.
TEST(LawParser, LimitsAreEnforced) {
  Context ctx;
  const std::string deep = std::string(10000, '(') + "t" + std::string(10000, ')');
  HULA_EXPECT_ERROR(parse(deep, ctx), Errc::ParseError, "nested deeper than the limit of 200 levels");
  std::string powers = "t";
  for (int i = 0; i < 10000; ++i) powers += "^t";
  HULA_EXPECT_ERROR(parse(powers, ctx), Errc::ParseError, "nested deeper than the limit of 200 levels");
  EXPECT_NO_THROW((void)parse(std::string(200, '(') + "t" + std::string(200, ')'), ctx));  // 200 is allowed
  const std::string minus(10000, '-');
  HULA_EXPECT_ERROR(parse(minus + "t", ctx), Errc::ParseError, "ParseOptions::max_depth");
  std::string big;
  while (big.size() < (1U << 20)) big += "t+";
  big += "t";
  HULA_EXPECT_ERROR(parse(big, ctx), Errc::ParseError, "exceeds the limit of 65536 bytes");
  ParseOptions wide;
  wide.max_length = 1U << 21;
  HULA_EXPECT_ERROR(parse(big, ctx, wide), Errc::ParseError, "nested deeper than the limit of 4000 levels");
  ParseOptions few;
  few.max_nodes = 5;
  HULA_EXPECT_ERROR(parse("sin(t)+cos(t)+exp(t)+log(t)+tan(t)", ctx, few), Errc::ParseError, "more than 5 nodes");
  ParseOptions bad;
  bad.max_depth = 0;
  HULA_EXPECT_ERROR(parse("t", ctx, bad), Errc::InvalidOption, "max_depth");
  bad = {};
  bad.parameters = {"pi"};
  HULA_EXPECT_ERROR(parse("t", ctx, bad), Errc::InvalidOption, "reserved name 'pi'");
}

// checks: several parameters and a NURBS leaf called by name with a derivative order.
TEST(LawParser, ParametersAndCurves) {
  const nurbs::NurbsCurve curve =
      nurbs::interpolate_cubic(std::vector<Vec3>{{0, 0, 0}, {1, 1, 0}, {2, 0, 1}, {3, 1, 1}});
  Context ctx;
  const Law u = ctx.parameter("u");
  const Law spine = ctx.curve(curve, u, "spine");
  ParseOptions o;
  o.parameters = {"u", "v"};
  EXPECT_EQ(parse("spine(u) * v", ctx, o), spine * ctx.parameter("v"));
  EXPECT_EQ(parse("spine(u, 1)", ctx, o), derivative(spine, "u"));
  HULA_EXPECT_ERROR(parse("spine(u, -1)", ctx, o), Errc::ParseError, "derivative order must be an integer constant");
  HULA_EXPECT_ERROR(parse("t", ctx, o), Errc::ParseError, "unknown identifier 't' (parameters: u, v)");
}

}  // namespace
}  // namespace hula::law
