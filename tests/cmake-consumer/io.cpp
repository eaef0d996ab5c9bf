// SPDX-License-Identifier: MIT
// HulaHoops::io alone (no studies, no Ceres in its link interface): a JSON curve file and a CSV point
// file are read; the Bézier evaluates to its closed-form point and the points come back as written.
#include <cstdio>

#include "hula/io/json_curve.hpp"
#include "hula/io/points_file.hpp"

int main() {
  const hula::curve::Curve c =
      hula::io::parse_curve_json(R"({"kind": "bezier", "control_points": [[0, 0], [2, 4], [4, 0]]})");
  const double e = distance(c.point(0.25), hula::Vec3{1.0, 1.5, 0});
  const hula::io::PointSet pts = hula::io::parse_points_csv("x,y\n0,0\n1.5,2\n3,-1\n");
  const bool points = pts.points.size() == 3 && pts.points[1].x == 1.5 && pts.points[2].y == -1.0;
  std::printf("io: curve file C(1/4) off by %g; %zu points read\n", e, pts.points.size());
  return e < 1e-15 && points ? 0 : 1;
}
