// SPDX-License-Identifier: MIT
// HulaHoops::studies alone (Ceres Solver reached through the package): the bounded least-squares
// refinement, on Ceres, takes Rosenbrock's residuals from (-1.2, 1) to their zero at (1, 1).
#include <cmath>
#include <cstdio>
#include <vector>

#include "hula/studies/hybrid_refine.hpp"

int main() {
  hula::studies::LeastSquaresProblem p;
  p.variables = {{"x", -5.0, 5.0, 0.0}, {"y", -5.0, 5.0, 0.0}};
  p.residual_count = 2;
  p.residuals = [](std::span<const double> x, std::span<double> r) {
    r[0] = 10.0 * (x[1] - x[0] * x[0]);
    r[1] = 1.0 - x[0];
    return true;
  };
  hula::studies::LmOptions o;
  o.solver = hula::studies::LsqSolver::Ceres;
  const hula::studies::LmResult r = hula::studies::refine_levenberg_marquardt(p, std::vector<double>{-1.2, 1.0}, o);
  const double e = std::fmax(std::fabs(r.variables[0] - 1.0), std::fabs(r.variables[1] - 1.0));
  std::printf("studies: Ceres took Rosenbrock to (%.12g, %.12g) in %zu steps (%s)\n", r.variables[0], r.variables[1],
              r.iterations, r.message.c_str());
  return e < 1e-6 ? 0 : 1;
}
