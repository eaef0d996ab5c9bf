// SPDX-License-Identifier: MIT
// Seeded scanned-point clouds for the scan-fit tests and benchmarks (thesis
// chapter 3: digitised points with noise and strays): points on a known planar
// curve, isotropic Gaussian noise whose offset is redrawn while longer than 2.5 σ (a
// scanner's accuracy is bounded; an untruncated σ = 0.1 puts 0.27 % of the points
// beyond the A-class 0.3, which no curve in the class band may keep, so they
// would be strays rather than inliers), a share of strays thrown uniformly over the
// enlarged bounding box but never within `stray_min_distance` of the curve (a
// stray nearer than the tolerance is indistinguishable from noise), and the
// order shuffled as a scanner's passes leave it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "hula/core/vec.hpp"

namespace hula::testing {

/// The known curves, planar (z = 0), about 130 model units long (a car body line in mm).
enum class KnownCurve {
  Arc,     ///< circular arc, radius 60, 110°: no inflection, constant curvature
  SCurve,  ///< y = 12 sin(2π x / 150), x ∈ [−60, 60]: one inflection (x = 0)
  Wave,    ///< y = 8 sin(2π x / 90), x ∈ [−30, 80]: two inflections (x = 0, 45)
};

/// "arc", "s-curve" or "wave".
[[nodiscard]] std::string_view known_curve_name(KnownCurve curve) noexcept;

/// Number of inflections of the known curve in its open domain (by construction).
[[nodiscard]] std::size_t known_curve_inflections(KnownCurve curve) noexcept;

/// The known curve at u ∈ [0, 1].
[[nodiscard]] Vec3 known_curve_point(KnownCurve curve, double u) noexcept;

/// What a cloud holds.
struct CloudSpec {
  KnownCurve curve = KnownCurve::Arc;
  /// Points in the cloud, strays included. Default 1000.
  std::size_t points = 1000;
  /// Standard deviation σ of the Gaussian noise per coordinate (offsets ≤ 2.5 σ), model units. Default 0.05.
  double noise = 0.05;
  /// Share of strays. Default 0.01 (1 %).
  double stray_fraction = 0.01;
  /// Strays lie at least this far from the curve, model units. Default 2.
  double stray_min_distance = 2.0;
  /// Shuffle the order of the points; false keeps the inliers in curve order with the strays at
  /// random places among them (a single scanner pass). Default true.
  bool shuffle = true;
  /// Seed of the cloud. Default 1.
  std::uint64_t seed = 1;
};

/// A cloud and the truth about it.
struct Cloud {
  std::vector<Vec3> points;
  /// Indices of the strays in `points`, increasing.
  std::vector<std::size_t> strays;
};

/// A seeded cloud: inliers at uniformly spaced curve parameters (u = i / (n_in − 1)) plus noise.
[[nodiscard]] Cloud scanned_cloud(const CloudSpec& spec);

/// Distance from `point` to the known curve (dense polyline of 20,000 segments; error < 1e-4).
[[nodiscard]] double distance_to_known_curve(KnownCurve curve, const Vec3& point);

}  // namespace hula::testing
