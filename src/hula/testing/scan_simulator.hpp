// SPDX-License-Identifier: MIT
// A second, independent generator of scanned clouds (a fit must not be tuned to
// one generator). It shares nothing with point_clouds.hpp: its own known curves (Bézier and
// polynomial graphs, a helix, closed loops; planar and space), given analytically with their
// first two derivatives; its own random engine (std::mt19937_64, not hula::Rng); sampling at
// uniform or varying arc length; noise models other than the truncated Gaussian there
// (uniform, heavy-tailed Student t, anisotropic along the curve, along a fixed viewing
// direction, none); orders other than a shuffle (in order, reversed, partly shuffled, in
// overlapping scanner passes); sizes from 1 to 1,000 units; strays at a chosen distance
// range from the curve. Distances to the known curve are measured on the analytic curve
// (dense seeding, then Newton on the foot point), not on any NURBS.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "hula/core/vec.hpp"

namespace hula::testing {

/// The known curves. Lengths are about 1 before scaling by ScanSpec::size.
enum class ScanShape {
  SCubic,        ///< planar cubic Bézier symmetric about its middle: exactly one inflection
  Convex,        ///< planar cubic Bézier bulging one way: no inflection
  Quartic,       ///< planar graph y = x⁴ − 1.2 x², x ∈ [−1.15, 1.15]: two inflections
  TwistedCubic,  ///< space curve (u, u², u³)-like: κ > 0 everywhere, torsion ≠ 0
  Helix,         ///< 1.25 turns of a circular helix
  Ellipse,       ///< closed planar ellipse, axes ratio 0.6: no inflection
  ClosedSpace,   ///< closed space loop (cos, 0.7 sin, 0.3 sin 2·): κ > 0
};

/// Name of a shape ("s-cubic", "convex", ...).
[[nodiscard]] std::string scan_shape_name(ScanShape shape);
/// True for Ellipse and ClosedSpace.
[[nodiscard]] bool scan_shape_closed(ScanShape shape);
/// True for the three planar open shapes and the ellipse.
[[nodiscard]] bool scan_shape_planar(ScanShape shape);
/// Inflections of the known curve (planar: sign changes of the signed curvature; space: zeros
/// of κ, none), by construction.
[[nodiscard]] std::size_t scan_shape_inflections(ScanShape shape);

/// How noise is drawn; `sigma` is the standard deviation of the offset across the curve
/// (along the normal, and along the binormal for space curves).
enum class ScanNoise {
  None,
  Uniform,      ///< uniform in [−√3 σ, √3 σ] per coordinate
  StudentT,     ///< Student t with 4 degrees of freedom per coordinate, scaled to σ: heavy tails
  Anisotropic,  ///< σ across the curve, 4 σ along it (a scanner's jitter along its path)
  Depth,        ///< all of it along one fixed viewing direction, σ (a laser's depth error): σ |d·N| across
};

/// The order the points are given in.
enum class ScanOrder {
  InOrder,         ///< along the curve
  Reversed,        ///< along the curve, backwards
  Shuffled,        ///< uniformly random
  PartlyShuffled,  ///< in order, but 15 % of the points moved to random places
  Passes,          ///< four overlapping passes, alternately forwards and backwards
};

/// What a simulated scan holds.
struct ScanSpec {
  ScanShape shape = ScanShape::SCubic;
  /// Length scale: the curve's chord (open) or its largest diameter (closed), model units. Default 100.
  double size = 100.0;
  /// Points on the curve (strays come on top). Default 1000.
  std::size_t points = 1000;
  /// Noise σ, model units. Default 0.
  double sigma = 0.0;
  ScanNoise noise = ScanNoise::Uniform;
  /// Arc-length spacing varies by ±60 % along the curve (else uniform). Default false.
  bool varying_density = false;
  ScanOrder order = ScanOrder::InOrder;
  /// Number of strays. Default 0.
  std::size_t strays = 0;
  /// Strays lie between these distances from the known curve, model units (min > 0). Default 1, 10.
  double stray_min = 1.0;
  double stray_max = 10.0;
  std::uint64_t seed = 1;
};

/// A simulated scan and the truth about it.
struct Scan {
  std::vector<Vec3> points;
  /// Indices of the strays in `points`, increasing.
  std::vector<std::size_t> strays;
  /// Per point: the curve parameter it was drawn at (strays: of their foot).
  std::vector<double> truth;
};

/// A seeded simulated scan.
[[nodiscard]] Scan simulate_scan(const ScanSpec& spec);

/// The known curve of `spec` at u ∈ [0, 1] (scaled to spec.size).
[[nodiscard]] Vec3 scan_curve_point(const ScanSpec& spec, double u);

/// Distance from `point` to the known curve of `spec`: dense seeding (4,000 samples) then Newton
/// iterations on the analytic foot-point equation; accurate to about 1e-12 × size.
[[nodiscard]] double distance_to_scan_curve(const ScanSpec& spec, const Vec3& point);

/// The foot of `point` on the known curve: its parameter u ∈ [0, 1] and the distance.
struct ScanFoot {
  double u = 0.0;
  double distance = 0.0;
};
[[nodiscard]] ScanFoot foot_on_scan_curve(const ScanSpec& spec, const Vec3& point);

}  // namespace hula::testing
