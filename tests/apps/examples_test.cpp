// SPDX-License-Identifier: MIT
// The shipped example files are what examples/cli/README.md says they are: the
// scanned cloud of the docs/cli.md `approximate` example is regenerated from its
// documented spec by hula::testing::scanned_cloud and compared byte for byte.
#include <gtest/gtest.h>

#include <sstream>
#include <string>

#include "hula/io/atomic_file.hpp"
#include "hula/testing/point_clouds.hpp"

namespace hula {
namespace {

// checks examples/cli/scan.csv against the S-curve cloud of its README (200 points, σ = 0.01, no strays,
// scanner order, seed 3), written as `x,y` lines with 17 significant digits
TEST(Examples, ScanIsTheDocumentedCloud) {
  const testing::Cloud cloud = testing::scanned_cloud({.curve = testing::KnownCurve::SCurve,
                                                       .points = 200,
                                                       .noise = 0.01,
                                                       .stray_fraction = 0.0,
                                                       .shuffle = false,
                                                       .seed = 3});
  std::ostringstream csv;
  csv.precision(17);
  for (const Vec3& p : cloud.points) csv << p.x << ',' << p.y << '\n';
  EXPECT_EQ(io::read_text_file(std::string(HULA_SOURCE_DIR) + "/examples/cli/scan.csv"), csv.str());
}

}  // namespace
}  // namespace hula
