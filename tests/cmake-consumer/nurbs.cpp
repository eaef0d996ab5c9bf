// SPDX-License-Identifier: MIT
// HulaHoops::nurbs alone: a clamped cubic Bézier passes through its end control points exactly, and
// the version header is installed beside the module headers.
#include <cstdio>
#include <cstring>
#include <vector>

#include "hula/nurbs/nurbs_curve.hpp"
#include "hula/version.hpp"

int main() {
  using hula::Vec3;
  const std::vector<Vec3> P = {{0.1, 0.2, 0.3}, {1, 2, 0}, {2, -1, 0}, {3.3, 0.7, 0.9}};
  const hula::nurbs::NurbsCurve c(3, {0, 0, 0, 0, 1, 1, 1, 1}, P);
  const bool ends = c.evaluate(0.0) == P.front() && c.evaluate(1.0) == P.back();
  // B(1/2) = (P0 + 3 P1 + 3 P2 + P3) / 8.
  const Vec3 mid = (P[0] + 3.0 * P[1] + 3.0 * P[2] + P[3]) / 8.0;
  const double e = distance(c.evaluate(0.5), mid);
  std::printf("nurbs (hulahoops %s): ends %s, B(1/2) off by %g\n", hula::kVersionString, ends ? "exact" : "WRONG", e);
  return ends && e < 1e-14 && std::strlen(HULA_VERSION_STRING) > 0 ? 0 : 1;
}
