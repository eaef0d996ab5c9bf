// SPDX-License-Identifier: MIT
// The consumer program: uses the installed headers and libraries the way a
// user would (a clamped cubic, a law and its derivative, the version header),
// and exits 0 only when the results are the closed-form ones.
#include <cstdio>
#include <cstring>
#include <vector>

#include "hula/law/derive.hpp"
#include "hula/law/parser.hpp"
#include "hula/law/tape.hpp"
#include "hula/nurbs/nurbs_curve.hpp"
#include "hula/version.hpp"

int main() {
  using hula::Vec3;
  // A clamped cubic Bézier: its ends are its first and last control points, exactly.
  const std::vector<Vec3> P = {{0.1, 0.2, 0.3}, {1, 2, 0}, {2, -1, 0}, {3.3, 0.7, 0.9}};
  const hula::nurbs::NurbsCurve c(3, {0, 0, 0, 0, 1, 1, 1, 1}, P);
  const bool ends = c.evaluate(0.0) == P.front() && c.evaluate(1.0) == P.back();
  // d/dt (t^3) at t = 2 is 12.
  hula::law::Context ctx;
  const hula::law::Law f = hula::law::derivative(hula::law::parse("t^3", ctx), "t");
  const hula::law::CurveEvaluator ev(f, "t", 0);
  const double d = ev.derivatives(2.0)[0].x;
  std::printf("hulahoops %s: ends %s, d/dt t^3 at 2 = %g\n", hula::kVersionString, ends ? "exact" : "WRONG", d);
  return ends && d == 12.0 && std::strlen(HULA_VERSION_STRING) > 0 ? 0 : 1;
}
