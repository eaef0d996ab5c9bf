// SPDX-License-Identifier: MIT
// HulaHoops::optim_pagmo alone (pagmo2 reached through the package): pagmo's differential evolution,
// seeded, finds the minimum 0 of the 3-D sphere at the origin.
#include <cmath>
#include <cstdio>

#include "hula/optim/pagmo_adapter.hpp"
#include "hula/optim/test_problems.hpp"

int main() {
  hula::optim::PagmoOptions o;
  o.algorithm = hula::optim::pagmo_algorithm("de");
  o.population = 20;
  o.generations = 300;
  o.seed = 7;
  const hula::optim::PagmoResult r = hula::optim::solve_with_pagmo(hula::optim::sphere(3), o);
  double far = 0.0;
  for (const double x : r.best.variables) far = std::fmax(far, std::fabs(x));
  std::printf("optim_pagmo: de on sphere-3: f = %g at max |x| = %g after %zu evaluations\n", r.best.objectives[0], far,
              r.report.evaluations);
  return r.best.objectives[0] < 1e-6 && far < 1e-3 ? 0 : 1;
}
