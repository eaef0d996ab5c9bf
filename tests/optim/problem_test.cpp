// SPDX-License-Identifier: MIT
// Tests of the Flexo problem: validation errors, bits per variable and batch
// evaluation (failures, lowest-index error, thread-count invariance).
#include "hula/optim/problem.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>

#include "hula/optim/test_problems.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::optim {
namespace {

Problem line(double lo, double hi) {
  Problem p;
  p.variables = {Variable{.name = "a", .lower = lo, .upper = hi}};
  p.evaluate = [](std::span<const double> x, std::span<double> f) { f[0] = x[0]; };
  return p;
}

// checks: every documented Problem::validate error against its code, field and value
TEST(OptimProblem, ValidateNamesFieldAndValue) {
  Problem empty = line(0, 1);
  empty.variables.clear();
  HULA_EXPECT_ERROR(empty.validate(), Errc::InvalidOption, "variables is empty");
  HULA_EXPECT_ERROR(line(2.0, 1.0).validate(), Errc::InvalidOption, "variables[0].lower = 2 > upper = 1");
  HULA_EXPECT_ERROR(line(std::numeric_limits<double>::quiet_NaN(), 1.0).validate(), Errc::InvalidOption,
                    "variables[0].lower = nan");
  HULA_EXPECT_ERROR(line(0.0, std::numeric_limits<double>::infinity()).validate(), Errc::InvalidOption,
                    "variables[0].upper = inf");
  Problem fine = line(0.0, 1.0);
  fine.variables[0].precision = 1e-17;
  HULA_EXPECT_ERROR(fine.validate(), Errc::InvalidOption, "variables[0].precision = 1.0000000000000001e-17");
  fine.variables[0].precision = -1.0;
  HULA_EXPECT_ERROR(fine.validate(), Errc::InvalidOption, "variables[0].precision = -1");
  Problem no_obj = line(0, 1);
  no_obj.objectives = 0;
  HULA_EXPECT_ERROR(no_obj.validate(), Errc::InvalidOption, "objectives = 0");
  Problem no_fn = line(0, 1);
  no_fn.evaluate = nullptr;
  HULA_EXPECT_ERROR(no_fn.validate(), Errc::InvalidOption, "evaluate is empty");
  Problem tol = line(0, 1);
  tol.equality_tolerance = -1.0;
  HULA_EXPECT_ERROR(tol.validate(), Errc::InvalidOption, "equality_tolerance = -1");
  EXPECT_NO_THROW(line(1.0, 1.0).validate());
}

// checks: bits_for against the defining inequality (u-l)/(2^b-1) <= precision < (u-l)/(2^(b-1)-1)
TEST(OptimProblem, BitsForMeetsPrecisionMinimally) {
  const double ranges[] = {1.0, 10.0, 0.04, 1000.0};
  const double precisions[] = {1e-3, 0.1, 1e-6, 1e-9, 0.3};
  for (const double r : ranges) {
    for (const double p : precisions) {
      const Variable v{.lower = -r / 3, .upper = 2 * r / 3, .precision = p};
      const std::size_t b = bits_for(v, 0);
      EXPECT_LE(r / (std::ldexp(1.0, static_cast<int>(b)) - 1.0), p * (1 + 1e-12)) << r << " " << p;
      if (b > 1) {
        EXPECT_GT(r / (std::ldexp(1.0, static_cast<int>(b - 1)) - 1.0), p) << r << " " << p;
      }
    }
  }
  HULA_EXPECT_ERROR((void)bits_for(Variable{.lower = 0, .upper = 1, .precision = 0}, 3), Errc::InvalidOption,
                    "variables[3].precision = 0");
  HULA_EXPECT_ERROR((void)bits_for(Variable{.lower = 0, .upper = 1e6, .precision = 1e-12}, 1), Errc::InvalidOption,
                    "finer than the 52 bits");
}

// checks: violation against its definition sum max(0,g) + sum max(0,|h|-tol)
TEST(OptimProblem, ViolationSumsInequalityAndEquality) {
  Problem p = line(0, 1);
  p.inequality_constraints = 2;
  p.equality_constraints = 1;
  p.equality_tolerance = 0.5;
  const double values[] = {7.0, -1.0, 2.0, -3.0};
  EXPECT_DOUBLE_EQ(p.violation(values), 2.0 + 2.5);
  const double ok[] = {7.0, -1.0, 0.0, 0.25};
  EXPECT_EQ(p.violation(ok), 0.0);
}

// checks: evaluate_batch marks throwing/NaN points failed and reports the lowest failing index on 1 and 4 threads
TEST(OptimProblem, BatchFailuresAreDeterministic) {
  Problem p = line(0, 100);
  p.evaluate = [](std::span<const double> x, std::span<double> f) {
    if (x[0] == 7.0 || x[0] == 3.0) throw std::runtime_error("boom at " + std::to_string(static_cast<int>(x[0])));
    f[0] = x[0] == 5.0 ? std::numeric_limits<double>::quiet_NaN() : x[0] * 2;
  };
  std::vector<double> pts(20);
  for (std::size_t i = 0; i < pts.size(); ++i) pts[i] = static_cast<double>(i);
  for (const std::size_t threads : {1U, 4U}) {
    std::vector<double> vals(20);
    std::vector<std::uint8_t> failed(20);
    const BatchReport r = evaluate_batch(p, pts, vals, failed, {.threads = threads});
    EXPECT_EQ(r.failed, 3U);
    EXPECT_EQ(r.first_failed, 3U);
    EXPECT_EQ(r.first_message, "boom at 3");
    EXPECT_EQ(failed[5], 1);
    EXPECT_TRUE(std::isnan(vals[7]));
    EXPECT_EQ(vals[8], 16.0);
    try {
      (void)evaluate_batch(p, pts, vals, failed, {.threads = threads, .rethrow = true});
      ADD_FAILURE() << "did not rethrow";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "boom at 3");
    }
  }
  std::vector<double> vals(3);
  std::vector<std::uint8_t> failed(20);
  HULA_EXPECT_ERROR(evaluate_batch(p, pts, vals, failed), Errc::InvalidArgument, "values has 3 numbers, expected 20");
}

// checks: parallel batch evaluation of Rastrigin against the serial one, bit for bit
TEST(OptimProblem, BatchIsThreadInvariant) {
  const Problem p = rastrigin(5);
  std::vector<double> pts(5 * 64);
  for (std::size_t i = 0; i < pts.size(); ++i) pts[i] = std::sin(static_cast<double>(i)) * 5;
  std::vector<double> a(64), b(64);
  std::vector<std::uint8_t> fa(64), fb(64);
  (void)evaluate_batch(p, pts, a, fa, {.threads = 1});
  (void)evaluate_batch(p, pts, b, fb, {.threads = 3});
  EXPECT_EQ(0, std::memcmp(a.data(), b.data(), a.size() * sizeof(double)));
}

// checks a whole-batch evaluation against the per-point one: same values, NaN rows failed, exceptions propagate
TEST(OptimProblem, EvaluateManyIsOneCallPerBatch) {
  Problem p = sphere(2);
  const EvaluateFn one = p.evaluate;
  int calls = 0;
  p.evaluate = {};
  p.evaluate_many = [&](std::span<const double> x, std::span<double> v) {
    ++calls;
    for (std::size_t i = 0; i < v.size(); ++i) one(x.subspan(2 * i, 2), v.subspan(i, 1));
    v[1] = std::numeric_limits<double>::quiet_NaN();
  };
  const std::vector<double> x{1, 2, 3, 4, 0.5, 0.5};
  std::vector<double> v(3);
  std::vector<std::uint8_t> failed(3);
  const BatchReport r = evaluate_batch(p, x, v, failed);
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(v[0], 5.0);
  EXPECT_EQ(v[2], 0.5);
  EXPECT_EQ(r.failed, 1U);
  EXPECT_EQ(r.first_failed, 1U);
  EXPECT_EQ(failed, (std::vector<std::uint8_t>{0, 1, 0}));
  p.evaluate_many = [](std::span<const double>, std::span<double>) { throw std::runtime_error("backend down"); };
  EXPECT_THROW((void)evaluate_batch(p, x, v, failed), std::runtime_error);
}

// checks: bound_hits flags exactly the values within 1e-6 of the box width of a bound (and not fixed variables),
// and bound_warnings names the variable, its value and the bound.
TEST(Problem, BoundHitsAndWarnings) {
  const std::vector<Variable> v = {{"a", 0.0, 10.0, 0.0}, {"b", -1.0, 1.0, 0.0}, {"c", 2.0, 2.0, 0.0}, {"", 0, 1, 0}};
  const std::vector<double> x = {10.0, -1.0 + 1e-7, 2.0, 0.5};
  const std::vector<BoundHit> h = bound_hits(v, x);
  ASSERT_EQ(h.size(), 2U);
  EXPECT_EQ(h[0].variable, 0U);
  EXPECT_TRUE(h[0].upper);
  EXPECT_EQ(h[1].variable, 1U);
  EXPECT_FALSE(h[1].upper);
  const std::vector<std::string> w = bound_warnings(v, h);
  ASSERT_EQ(w.size(), 2U);
  EXPECT_EQ(w[0].rfind("a = 10 is on its upper bound 10", 0), 0U) << w[0];
  EXPECT_TRUE(bound_hits(v, std::vector<double>{5.0, 0.0, 2.0, 0.5}).empty());
  HULA_EXPECT_ERROR((void)bound_hits(v, std::vector<double>{1.0}), Errc::InvalidArgument, "1 values for 4");
}

}  // namespace
}  // namespace hula::optim
