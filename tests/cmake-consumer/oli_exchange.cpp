// SPDX-License-Identifier: MIT
// HulaHoops::oli_exchange alone (built with Open CASCADE): a quadratic Bézier written to STEP by the
// installed hula-exchange helper (argv[1] is the install prefix) reads back as the same curve.
#include <cstdio>
#include <filesystem>
#include <vector>

#include "hula/oli/exchange/exchange.hpp"

int main(int argc, char** argv) {
  if (argc < 3) return 2;
  using hula::Vec3;
  const hula::oli::ExchangeOptions options{.helper = std::filesystem::path(argv[1]) / "bin" / "hula-exchange"};
  const std::vector<Vec3> P = {{0, 0, 0}, {2, 4, 1}, {4, 0, 2}};
  const hula::nurbs::NurbsCurve c(2, {0, 0, 0, 1, 1, 1}, P);
  const std::filesystem::path file = std::filesystem::path(argv[2]) / "consumer.step";
  const std::vector<hula::oli::ExportCurve> curves = {{.name = "spine", .curve = c, .deviation = 0.0}};
  const hula::oli::ExportReport written =
      hula::oli::export_curves(file, curves, hula::oli::ExchangeFormat::StepAp214, options);
  const hula::oli::ImportReport read = hula::oli::import_curves(file, options);
  if (read.curves.size() != 1) return 1;
  const Vec3 expect = (9.0 * P[0] + 6.0 * P[1] + P[2]) / 16.0;
  const double e = distance(read.curves[0].curve.evaluate(0.25), expect);
  std::printf("oli_exchange: %zu curve written, read back %s '%s', B(1/4) off by %g\n", written.curves,
              read.curves[0].type.c_str(), read.curves[0].name.c_str(), e);
  return e < 1e-12 ? 0 : 1;
}
