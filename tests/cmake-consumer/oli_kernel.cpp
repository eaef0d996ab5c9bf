// SPDX-License-Identifier: MIT
// HulaHoops::oli_kernel alone: the native backend (and, in a package built with Open CASCADE, the occt
// backend and OCCT's own Geom_BSplineCurve through occt_convert.hpp, whose headers and toolkits come
// from the package) give the closed-form point of a quadratic Bézier.
#include <cstdio>
#include <vector>

#include "hula/oli/kernel/kernel.hpp"
#ifdef HULA_WITH_OCCT
#include "hula/oli/kernel/occt_convert.hpp"
#endif

int main() {
  using hula::Vec3;
  // B(t) = (1-t)² P0 + 2t(1-t) P1 + t² P2; at t = 1/4: (9 P0 + 6 P1 + P2) / 16.
  const std::vector<Vec3> P = {{0, 0, 0}, {2, 4, 1}, {4, 0, 2}};
  const hula::nurbs::NurbsCurve c(2, {0, 0, 0, 1, 1, 1}, P);
  const Vec3 expect = (9.0 * P[0] + 6.0 * P[1] + P[2]) / 16.0;
  double worst = distance(hula::oli::make_kernel("native")->evaluate(c, 0.25), expect);
  std::printf("oli_kernel: native B(1/4) off by %g\n", worst);
#ifdef HULA_WITH_OCCT
  const double e1 = distance(hula::oli::make_kernel("occt")->evaluate(c, 0.25), expect);
  const double e2 = distance(hula::oli::to_vec3(hula::oli::to_occt(c)->Value(0.25)), expect);
  std::printf("oli_kernel: occt backend off by %g, Geom_BSplineCurve off by %g\n", e1, e2);
  worst = std::max({worst, e1, e2});
#endif
  return worst < 1e-12 ? 0 : 1;
}
