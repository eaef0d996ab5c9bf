// SPDX-License-Identifier: MIT
// HulaHoops::core alone: the banded solver gives the exact solution of a small tridiagonal system and
// parallel_for (oneTBB, reached through the package) visits every index once.
#include <atomic>
#include <cstdio>
#include <vector>

#include "hula/core/banded.hpp"
#include "hula/core/parallel.hpp"

int main() {
  // [2 -1 0; -1 2 -1; 0 -1 2] x = (0, 0, 4) has x = (1, 2, 3).
  hula::BandedMatrix a(3, 1, 1);
  for (std::size_t i = 0; i < 3; ++i) a.at(i, i) = 2.0;
  for (std::size_t i = 0; i + 1 < 3; ++i) a.at(i, i + 1) = a.at(i + 1, i) = -1.0;
  std::vector<double> b = {0.0, 0.0, 4.0};
  const bool solved = a.solve(b, 1);
  std::atomic<long> sum{0};
  hula::parallel_for(0, 1000, [&](std::size_t i) { sum += static_cast<long>(i); });
  std::printf("core: x = (%.17g, %.17g, %.17g), sum 0..999 = %ld\n", b[0], b[1], b[2], sum.load());
  const auto near = [](double u, double v) { return u - v < 1e-14 && v - u < 1e-14; };
  return solved && near(b[0], 1) && near(b[1], 2) && near(b[2], 3) && sum == 499500 ? 0 : 1;
}
