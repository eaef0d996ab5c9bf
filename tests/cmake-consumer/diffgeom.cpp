// SPDX-License-Identifier: MIT
// HulaHoops::diffgeom alone: the rational quadratic quarter circle of radius 2 has curvature 1/2 and
// zero torsion everywhere.
#include <cmath>
#include <cstdio>

#include "hula/diffgeom/frenet.hpp"

int main() {
  const double r = 2.0;
  const hula::nurbs::NurbsCurve arc(2, {0, 0, 0, 1, 1, 1}, {{r, 0, 0}, {r, r, 0}, {0, r, 0}},
                                    {1.0, std::sqrt(0.5), 1.0});
  double worst = 0.0;
  for (const double t : {0.0, 0.3, 0.5, 0.9, 1.0}) {
    const hula::diffgeom::FrenetPoint p = hula::diffgeom::frenet(arc, t);
    worst = std::fmax(worst, std::fabs(p.curvature - 1.0 / r));
  }
  std::printf("diffgeom: |kappa - 1/r| <= %g on a circle of radius %g\n", worst, r);
  return worst < 1e-12 ? 0 : 1;
}
