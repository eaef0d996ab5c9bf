// SPDX-License-Identifier: MIT
// HulaHoops::occt alone (built with Open CASCADE): its include directory and toolkits come from the
// package; Open CASCADE's own circle of radius 2 passes through (0, 2, 0) at a quarter turn.
#include <Geom_Circle.hxx>
#include <cstdio>
#include <gp_Ax2.hxx>
#include <gp_Pnt.hxx>
#include <numbers>

int main() {
  const Handle(Geom_Circle) circle = new Geom_Circle(gp_Ax2(), 2.0);
  const gp_Pnt p = circle->Value(std::numbers::pi / 2);
  const double e = p.Distance(gp_Pnt(0, 2, 0));
  std::printf("occt: Geom_Circle at pi/2 off by %g\n", e);
  return e < 1e-15 ? 0 : 1;
}
