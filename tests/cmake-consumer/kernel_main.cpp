// SPDX-License-Identifier: MIT
// The consumer of the oli kernel (built when the package was built with Open
// CASCADE): links HulaHoops::oli_kernel alone, so its Open CASCADE toolkits and
// headers must come from the installed package (find_dependency). Exits 0 only
// when the occt backend and OCCT's own Geom_BSplineCurve (through occt_convert.hpp,
// which includes OCCT headers) give the closed-form point of a quadratic Bézier.
#include <cmath>
#include <cstdio>
#include <vector>

#include "hula/oli/kernel/kernel.hpp"
#include "hula/oli/kernel/occt_convert.hpp"

int main() {
  using hula::Vec3;
  // B(t) = (1-t)² P0 + 2t(1-t) P1 + t² P2; at t = 1/4: (9 P0 + 6 P1 + P2) / 16.
  const std::vector<Vec3> P = {{0, 0, 0}, {2, 4, 1}, {4, 0, 2}};
  const hula::nurbs::NurbsCurve c(2, {0, 0, 0, 1, 1, 1}, P);
  const Vec3 expect = (9.0 * P[0] + 6.0 * P[1] + P[2]) / 16.0;
  const Vec3 by_kernel = hula::oli::make_kernel("occt")->evaluate(c, 0.25);
  const Vec3 by_geom = hula::oli::to_vec3(hula::oli::to_occt(c)->Value(0.25));
  const double e1 = distance(by_kernel, expect), e2 = distance(by_geom, expect);
  std::printf("occt kernel: B(1/4) off by %g (backend), %g (Geom_BSplineCurve)\n", e1, e2);
  return e1 < 1e-12 && e2 < 1e-12 ? 0 : 1;
}
