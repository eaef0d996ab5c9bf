// SPDX-License-Identifier: MIT
// HulaHoops::law alone: the parsed law t^3 has the exact derivative 12 at t = 2.
#include <cstdio>

#include "hula/law/derive.hpp"
#include "hula/law/parser.hpp"
#include "hula/law/tape.hpp"

int main() {
  hula::law::Context ctx;
  const hula::law::Law f = hula::law::derivative(hula::law::parse("t^3", ctx), "t");
  const hula::law::CurveEvaluator ev(f, "t", 0);
  const double d = ev.derivatives(2.0)[0].x;
  std::printf("law: d/dt t^3 at 2 = %.17g\n", d);
  return d == 12.0 ? 0 : 1;
}
