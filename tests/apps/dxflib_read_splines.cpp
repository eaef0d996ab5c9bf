// SPDX-License-Identifier: MIT
// dxflib-read-splines FILE.dxf: the independent reader of the `hula convert`
// DXF round-trip test (convert_cli_test.cpp). dxflib's DL_Dxf::in with a
// creation adapter, as dxflib's documentation shows it, and nothing of
// HulaHoops: every SPLINE's degree, flags, knots, control points, weights,
// layer and colours (62 and 420), as one JSON object on standard output.
#include <dl_creationadapter.h>
#include <dl_dxf.h>

#include <cstdio>
#include <string>
#include <vector>

namespace {

struct Spline {
  unsigned degree = 0;
  int flags = 0;
  std::string layer;
  int colour = 0;
  int colour24 = -1;
  std::vector<double> knots;
  std::vector<DL_ControlPointData> points;
};

class Collector : public DL_CreationAdapter {
 public:
  void addSpline(const DL_SplineData& d) override {
    splines.push_back({d.degree,
                       d.flags,
                       getAttributes().getLayer(),
                       getAttributes().getColor(),
                       getAttributes().getColor24(),
                       {},
                       {}});
  }
  void addKnot(const DL_KnotData& k) override { splines.back().knots.push_back(k.k); }
  void addControlPoint(const DL_ControlPointData& p) override { splines.back().points.push_back(p); }
  std::vector<Spline> splines;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: dxflib-read-splines FILE.dxf\n");
    return 2;
  }
  Collector collector;
  DL_Dxf dxf;
  if (!dxf.in(argv[1], &collector)) return 3;
  std::printf("{\"splines\": [");
  for (std::size_t i = 0; i < collector.splines.size(); ++i) {
    const Spline& s = collector.splines[i];
    std::printf("%s{\"degree\": %u, \"flags\": %d, \"layer\": \"%s\", \"colour\": %d, \"colour24\": %d, \"knots\": [",
                i ? ", " : "", s.degree, s.flags, s.layer.c_str(), s.colour, s.colour24);
    for (std::size_t k = 0; k < s.knots.size(); ++k) std::printf("%s%.17g", k ? ", " : "", s.knots[k]);
    std::printf("], \"points\": [");
    for (std::size_t k = 0; k < s.points.size(); ++k)
      std::printf("%s[%.17g, %.17g, %.17g]", k ? ", " : "", s.points[k].x, s.points[k].y, s.points[k].z);
    std::printf("], \"weights\": [");
    for (std::size_t k = 0; k < s.points.size(); ++k) std::printf("%s%.17g", k ? ", " : "", s.points[k].w);
    std::printf("]}");
  }
  std::printf("]}\n");
  return 0;
}
