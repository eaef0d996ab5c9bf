// SPDX-License-Identifier: MIT
// Curvature monotonicity: a curve's domain split into pieces
// over which the curvature is monotone, and the points that break it. Designers
// ask for "monotone curvature" of class-A transitions and the log-aesthetic curves
// of Yoshida–Saito have it by construction; this analysis checks it on any curve.
//
// Method: the pieces are bounded by the curvature extrema (features.hpp, sign
// changes of dκ/ds); each extremum inside the domain is a violation of
// monotonicity over the whole curve. For a planar curve the *signed* curvature
// is the designer's quantity: it passes monotonically through zero at an
// inflection, where |κ| has a minimum, so a minimum of |κ| within a sampling
// step of an inflection neither splits a piece nor counts as a violation.
#pragma once

#include <span>
#include <string_view>
#include <vector>

#include "hula/curve/curve.hpp"
#include "hula/diffgeom/features.hpp"

namespace hula::diffgeom {

/// How the curvature varies over a piece.
enum class CurvatureTrend {
  Increasing,  ///< κ (signed for planar curves) grows from the piece's start to its end
  Decreasing,  ///< κ falls
  Constant,    ///< equal at both ends within 1e-12 of the largest |κ| seen (arcs, lines)
};

/// "increasing", "decreasing" or "constant".
[[nodiscard]] std::string_view curvature_trend_name(CurvatureTrend trend) noexcept;

/// One piece of monotone curvature.
struct MonotonePiece {
  double t0 = 0.0;      ///< start parameter
  double t1 = 0.0;      ///< end parameter
  double kappa0 = 0.0;  ///< κ at t0 (signed for planar curves)
  double kappa1 = 0.0;  ///< κ at t1 (signed for planar curves)
  CurvatureTrend trend = CurvatureTrend::Constant;
};

/// Result of curvature_monotonicity().
struct CurvatureMonotonicity {
  /// The pieces, covering the domain in increasing t (one piece when the curvature is monotone).
  std::vector<MonotonePiece> pieces{};
  /// The curvature extrema that bound the pieces: the points where monotonicity fails.
  std::vector<Feature> violations{};
  /// True when there is no violation.
  [[nodiscard]] bool monotone() const noexcept { return violations.empty(); }
};

/// Splits a curve into pieces of monotone curvature.
/// @param curve any curve value (NURBS or law)
/// @param planar true to use the signed curvature about options.frenet.plane_normal (a planar curve);
///   false for |κ|
/// @param options sampling and Frenet options, as curvature_extrema()
/// @returns the pieces and the violations
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] CurvatureMonotonicity curvature_monotonicity(const curve::Curve& curve, bool planar,
                                                           const FeatureOptions& options = {});
/// The same from the curve's curvature extrema and (planar curves) inflections already found.
/// @throws hula::Error as frenet
[[nodiscard]] CurvatureMonotonicity curvature_monotonicity(const curve::Curve& curve, bool planar,
                                                           std::span<const Feature> extrema,
                                                           std::span<const Feature> inflections,
                                                           const FeatureOptions& options = {});

}  // namespace hula::diffgeom
