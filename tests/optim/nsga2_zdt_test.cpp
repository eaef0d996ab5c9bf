// SPDX-License-Identifier: MIT
// Oracle tests: NSGA-II reaches the known Pareto fronts of ZDT1-3 and DTLZ2
// (closed forms, Zitzler-Deb-Thiele 2000, Deb et al. 2002) and their known
// hypervolume with reference (1.1, 1.1).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "hula/optim/nsga2.hpp"
#include "hula/optim/pareto.hpp"
#include "hula/optim/test_problems.hpp"

namespace hula::optim {
namespace {

double front_hv(const Nsga2Result& r) {
  std::vector<double> pts;
  for (const auto& s : r.front) pts.insert(pts.end(), s.objectives.begin(), s.objectives.end());
  return hypervolume(pts, 2, std::vector<double>{1.1, 1.1});
}

Nsga2Result run(const Problem& p, std::uint64_t seed) {
  Nsga2Options o;
  o.population = 100;
  o.run.stop.generations = 250;
  o.run.seed = seed;
  return solve_nsga2(p, o);
}

// checks: ZDT1 front within 0.03 of f2 = 1 - sqrt(f1) and hypervolume >= 0.865 (optimum 0.8722)
TEST(OptimNsga2Oracle, Zdt1FrontReached) {
  const auto r = run(zdt(1), 1);
  ASSERT_GE(r.front.size(), 90U);
  for (const auto& s : r.front) EXPECT_NEAR(s.objectives[1], 1.0 - std::sqrt(s.objectives[0]), 0.03);
  const double hv = front_hv(r);
  EXPECT_GT(hv, 0.865);
  EXPECT_LT(hv, 0.8722);
}

// checks: ZDT2 front within 0.03 of f2 = 1 - f1^2 and hypervolume >= 0.53 (optimum 0.5389)
TEST(OptimNsga2Oracle, Zdt2FrontReached) {
  const auto r = run(zdt(2), 1);
  for (const auto& s : r.front) EXPECT_NEAR(s.objectives[1], 1.0 - s.objectives[0] * s.objectives[0], 0.03);
  const double hv = front_hv(r);
  EXPECT_GT(hv, 0.53);
  EXPECT_LT(hv, 0.5389);
}

// checks: ZDT3 front within 0.03 of f2 = 1 - sqrt(f1) - f1 sin(10 pi f1) and hypervolume >= 1.32 (optimum 1.3277)
TEST(OptimNsga2Oracle, Zdt3FrontReached) {
  const auto r = run(zdt(3), 1);
  for (const auto& s : r.front) {
    const double f1 = s.objectives[0];
    EXPECT_NEAR(s.objectives[1], 1.0 - std::sqrt(f1) - f1 * std::sin(10 * std::numbers::pi * f1), 0.03);
  }
  EXPECT_GT(front_hv(r), 1.32);
}

// checks: DTLZ2 with 3 objectives: front on the unit sphere (|f| = 1 within 0.05), HV within 0.2 of the exact 1.331 -
// pi/6 (100 points cannot cover the sphere)
TEST(OptimNsga2Oracle, Dtlz2FrontOnSphere) {
  Nsga2Options o;
  o.population = 100;
  o.run.stop.generations = 250;
  const auto r = solve_nsga2(dtlz2(3), o);
  std::vector<double> pts;
  for (const auto& s : r.front) {
    double q = 0.0;
    for (const double f : s.objectives) q += f * f;
    EXPECT_NEAR(std::sqrt(q), 1.0, 0.05);
    pts.insert(pts.end(), s.objectives.begin(), s.objectives.end());
  }
  // Exact hypervolume of the whole front w.r.t. (1.1,1.1,1.1): 1.1^3 - pi/6.
  const double exact = 1.331 - std::numbers::pi / 6.0;
  const double hv = hypervolume(pts, 3, std::vector<double>{1.1, 1.1, 1.1});
  EXPECT_LT(hv, exact);
  EXPECT_GT(hv, exact - 0.2);
}

// checks: the ZDT definitions at Pareto-optimal points (x_i = 0, i >= 1) against the closed-form fronts
TEST(OptimNsga2Oracle, ZdtDefinitionsOnFront) {
  for (const unsigned which : {1U, 2U, 3U, 4U, 6U}) {
    const Problem p = zdt(which);
    std::vector<double> x(p.dimension(), 0.0), f(2);
    for (const double x0 : {0.0, 0.25, 0.5, 1.0}) {
      x[0] = x0;
      p.evaluate(x, f);
      double want = 0.0;
      const double f1 = f[0];
      if (which == 1 || which == 4) want = 1 - std::sqrt(f1);
      if (which == 2 || which == 6) want = 1 - f1 * f1;
      if (which == 3) want = 1 - std::sqrt(f1) - f1 * std::sin(10 * std::numbers::pi * f1);
      if (which != 6) {
        EXPECT_EQ(f1, x0);
      }
      EXPECT_NEAR(f[1], want, 1e-12) << "zdt" << which;
    }
  }
}

}  // namespace
}  // namespace hula::optim
