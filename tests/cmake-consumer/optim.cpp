// SPDX-License-Identifier: MIT
// HulaHoops::optim alone: the hypervolume of {(1, 2), (2, 1)} from the reference (3, 3) is 3 (two 2 x 1
// boxes overlapping on a unit square).
#include <cstdio>
#include <vector>

#include "hula/optim/pareto.hpp"

int main() {
  const std::vector<double> points = {1, 2, 2, 1};
  const std::vector<double> reference = {3, 3};
  const double hv = hula::optim::hypervolume(points, 2, reference);
  std::printf("optim: hypervolume %.17g\n", hv);
  return hv == 3.0 ? 0 : 1;
}
