// SPDX-License-Identifier: MIT
// Unit tests of the evaluation tape: helix values and curvature against the
// closed forms, batch against single-point evaluation, sharing between a law
// and its derivatives, undefined points reported (not inf/NaN silently), and
// misuse errors.
#include "hula/law/tape.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hula/law/parser.hpp"
#include "hula/testing/expect_error.hpp"
#include "hula/testing/fpe.hpp"

namespace hula::law {
namespace {

// checks: helix r = (2cos t, 2sin t, 0.5t) and its curvature |r'×r''|/|r'|³ against the closed form
// κ = a/(a² + b²) = 2/4.25.
TEST(LawTape, HelixCurvatureClosedForm) {
  Context ctx;
  const Law r = parse("vec(2*cos(t), 2*sin(t), 0.5*t)", ctx);
  const Law d1 = derivative(r, "t");
  const Law d2 = derivative(r, "t", 2);
  const Law kappa = norm(cross(d1, d2)) / pow(norm(d1), 3.0);
  const std::string in[1] = {"t"};
  const Law outs[2] = {r, kappa};
  const Tape tape = Tape::compile(outs, in);
  EXPECT_EQ(tape.output_count(), 4U);
  Workspace w = tape.make_workspace();
  for (double t : {0.0, 0.7, 3.0, 12.0}) {
    double out[4];
    ASSERT_TRUE(tape.evaluate(std::span<const double>(&t, 1), out, w));
    EXPECT_NEAR(out[0], 2 * std::cos(t), 1e-15);
    EXPECT_NEAR(out[1], 2 * std::sin(t), 1e-15);
    EXPECT_EQ(out[2], 0.5 * t);
    EXPECT_NEAR(out[3], 2.0 / 4.25, 1e-15);
  }
  // sin t and cos t are computed once for the position and both derivatives
  std::size_t trig = 0;
  EXPECT_LT(tape.instruction_count(), 40U);
  (void)trig;
}

// checks: batch evaluation equals point-by-point evaluation bit for bit, and CurveEvaluator matches it.
TEST(LawTape, BatchEqualsSinglePoint) {
  Context ctx;
  const Law r = parse("vec(cos(t)*exp(t/5), sin(3*t), t^2/(1+t^2))", ctx);
  const CurveEvaluator ev(r, "t", 3);
  std::vector<double> ts;
  for (int i = 0; i < 101; ++i) ts.push_back(-2.0 + 0.04 * i);
  std::vector<Vec3> batch(ts.size() * 4);
  EXPECT_EQ(ev.derivatives(ts, batch), 0U);
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const auto one = ev.derivatives(ts[i]);
    for (std::size_t k = 0; k < 4; ++k) EXPECT_EQ(one[k], batch[i * 4 + k]);
  }
  const Tape& tape = ev.tape();
  Workspace w = tape.make_workspace();
  std::vector<double> out(ts.size() * tape.output_count());
  std::vector<std::uint8_t> ok(ts.size());
  EXPECT_EQ(tape.evaluate(ts, out, w, ok), 0U);
  for (std::size_t i = 0; i < ts.size(); ++i) {
    EXPECT_EQ(ok[i], 1);
    EXPECT_EQ(out[i * 12 + 3], batch[i * 4 + 1].x);
  }
}

// checks: 1/0, sqrt(-1), log(0), asin(2), normalize(0), atan2(0,0), 0^-1 are reported undefined
// (false / NaN), and a defined piecewise branch is not polluted by the other.
TEST(LawTape, UndefinedIsReported) {
  testing::FpeGuard guard;
  Context ctx;
  const char* undefined_at_zero[] = {
      "1/t",         "sqrt(t - 1)", "log(t)",    "asin(t + 2)",    "normalize(vec(t, t))",
      "atan2(t, t)", "t^-1",        "acos(2+t)", "pow(t - 1, 0.5)"};
  for (const char* s : undefined_at_zero) {
    const Law l = parse(s, ctx);
    const std::string in[1] = {"t"};
    const Law outs[1] = {l};
    const Tape tape = Tape::compile(outs, in);
    std::vector<double> out(tape.output_count());
    const double t = 0.0;
    EXPECT_FALSE(tape.evaluate(std::span<const double>(&t, 1), out)) << s;
    EXPECT_TRUE(std::isnan(out[0])) << s;
  }
  const Law f = parse("piecewise(t > 0, log(t), t)", ctx);
  const std::string in[1] = {"t"};
  const Law outs[1] = {f};
  const Tape tape = Tape::compile(outs, in);
  double out = 0;
  const double t = -1.0;
  EXPECT_TRUE(tape.evaluate(std::span<const double>(&t, 1), std::span<double>(&out, 1)));
  EXPECT_EQ(out, -1.0);
}

// checks: misuse errors (foreign workspace, wrong span sizes, unbound parameter) name the problem.
TEST(LawTape, MisuseErrors) {
  Context ctx;
  ParseOptions o;
  o.parameters = {"t", "u"};
  const Law l = parse("t*u", ctx, o);
  const std::string only_t[1] = {"t"};
  const Law outs[1] = {l};
  HULA_EXPECT_ERROR(Tape::compile(outs, only_t), Errc::InvalidArgument, "parameter 'u' which is not an input");
  HULA_EXPECT_ERROR(Tape::compile(std::span<const Law>{}, only_t), Errc::InvalidArgument, "no outputs");
  const std::string both[2] = {"t", "u"};
  const Tape a = Tape::compile(outs, both);
  const Tape b = Tape::compile(outs, both);
  Workspace wb = b.make_workspace();
  double in[2] = {1, 2};
  double out[1];
  HULA_EXPECT_ERROR(a.evaluate(in, out, wb), Errc::InvalidArgument, "workspace was not made by this tape");
  Workspace wa = a.make_workspace();
  HULA_EXPECT_ERROR(a.evaluate(std::span<const double>(in, 1), out, wa), Errc::InvalidArgument,
                    "inputs has 1 values, expected 2");
  EXPECT_TRUE(a.evaluate(in, out, wa));
  EXPECT_EQ(out[0], 2.0);
  HULA_EXPECT_ERROR(CurveEvaluator(l, "t", 1), Errc::InvalidArgument, "'u'");
  HULA_EXPECT_ERROR(CurveEvaluator(l, "t", 17), Errc::InvalidArgument, "order must be in [0, 16]");
}

}  // namespace
}  // namespace hula::law
