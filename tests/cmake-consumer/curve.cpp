// SPDX-License-Identifier: MIT
// HulaHoops::curve alone: a curve value of kind "bezier" evaluates to the closed-form point of its
// quadratic at t = 1/4.
#include "hula/curve/curve.hpp"

#include <cstdio>

int main() {
  using hula::Vec3;
  const hula::curve::Curve c =
      hula::curve::Curve::bezier({.control_points = {{0, 0, 0}, {2, 4, 0}, {4, 0, 0}}, .weights = {}, .dimension = 2});
  // (9 P0 + 6 P1 + P2) / 16 = (1.0, 1.5, 0).
  const double e = distance(c.point(0.25), Vec3{1.0, 1.5, 0});
  std::printf("curve: kind %s, dimension %d, C(1/4) off by %g\n", std::string(c.kind_name()).c_str(), c.dimension(), e);
  return c.kind_name() == "bezier" && c.dimension() == 2 && e < 1e-15 ? 0 : 1;
}
