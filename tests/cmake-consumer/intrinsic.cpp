// SPDX-License-Identifier: MIT
// HulaHoops::intrinsic alone: the planar curve of constant curvature 1 and length pi from the origin
// along +X is the half circle that ends at (0, 2).
#include <cmath>
#include <cstdio>
#include <numbers>

#include "hula/intrinsic/natural_equations.hpp"
#include "hula/law/parser.hpp"

int main() {
  hula::law::Context ctx;
  hula::law::ParseOptions po;
  po.parameters = {"s"};
  const hula::intrinsic::IntrinsicCurve c =
      hula::intrinsic::reconstruct_planar(hula::law::parse("1", ctx, po), "s", std::numbers::pi);
  const hula::Vec3 end = c.evaluate(std::numbers::pi).position;
  const double e = distance(end, hula::Vec3{0, 2, 0});
  std::printf("intrinsic: half circle ends at (%.12g, %.12g), off by %g\n", end.x, end.y, e);
  return e < 1e-8 ? 0 : 1;
}
