// SPDX-License-Identifier: MIT
// The fairing preview of an entity (oli/fair_preview.hpp) on a real document:
// the ghost of a curve entity keeps the assistant's contract (energy never up,
// every data point within the tolerance), the document is unchanged, and an
// entity that is not a curve is refused naming its label.
#include "hula/oli/fair_preview.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "hula/testing/expect_error.hpp"

namespace hula::oli {
namespace {

// checks the ghost of a wavy interpolated curve against the contract of fair_within_tolerance: energy_after ≤
// energy_before, |faired − data| ≤ tolerance for every point (measured here), and the document's revision unchanged
TEST(FairPreview, GhostOfACurveEntityKeepsTheContract) {
  std::vector<Vec3> points;
  for (int i = 0; i < 12; ++i) points.push_back({static_cast<double>(i), std::sin(1.3 * i) + 0.2 * (i % 2), 0.1 * i});
  Document doc;
  Label label;
  curve::InterpolatedData data;
  data.points = points;
  doc.transact("add", [&](Edit& e) { label = e.add_curve(curve::Curve::interpolated(data)); }).throw_if_failed();
  const std::uint64_t revision = doc.revision();
  studies::AssistantOptions options;
  options.tolerance = 0.05;
  const studies::AssistantResult r = fair_preview(doc.get(label), options);
  EXPECT_LE(r.energy_after, r.energy_before);
  ASSERT_EQ(r.data_points.size(), points.size());
  ASSERT_EQ(r.faired_points.size(), points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    EXPECT_EQ(r.data_points[k], points[k]) << k;
    EXPECT_LE(distance(r.faired_points[k], points[k]), options.tolerance * (1 + 1e-12)) << k;
  }
  EXPECT_EQ(doc.revision(), revision);
}

// checks a point set entity is refused with InvalidArgument naming its label and kind (Entity::curve)
TEST(FairPreview, PointSetIsRefusedNamingTheLabel) {
  Document doc;
  Label label;
  PointSet set;
  set.points = {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}};
  doc.transact("add", [&](Edit& e) { label = e.add_point_set(set); }).throw_if_failed();
  HULA_EXPECT_ERROR(fair_preview(doc.get(label), {}), Errc::InvalidArgument,
                    "entity " + std::to_string(label.value) + " is a point-set, not a curve");
}

}  // namespace
}  // namespace hula::oli
