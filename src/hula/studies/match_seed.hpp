// SPDX-License-Identifier: MIT
// Curvature-matching setups seeded from a curve (the workbench's "From
// selection"): the study starts from the curve the designer selected — its
// points as the design variables, its end tangents held, and its own curvature
// (and, for a space curve, torsion) profile as the targets to edit — instead of
// a generic template. The study's curve is the C2 cubic spline through the
// points (curvature_match.hpp) with the selected curve's end tangent directions;
// the profiles are taken by normalised arc length u = s / L, the abscissa the
// setup then uses (ProfileAbscissa::ArcLength), so a target sample and the
// spline's sample at the same u sit at the same place along the curve.
#pragma once

#include <cstddef>
#include <vector>

#include "hula/curve/curve.hpp"
#include "hula/studies/curvature_match.hpp"

namespace hula::studies {

/// Options of seed_match_setup().
struct MatchSeedOptions {
  /// Data points of the study's spline: 0 (default) takes an interpolated or Hermite curve's own points, and
  /// otherwise handle count + 2 points (at least 4) at uniform arc length on the curve. Valid 0 or 2 … 1000.
  std::size_t points = 0;
  /// Bounds of every free coordinate: ± bound × the curve's size (its control box diagonal); the first point is
  /// fixed (the setups' rule). Default 0.1; valid (0, 10].
  double bound = 0.1;
  /// Profile samples of the study (CurvatureMatchSetup::samples). Default 60; valid 2 … 100 000.
  std::size_t samples = 60;
  /// Samples of the target profiles (joined linearly). Default 101; valid 2 … 100 000.
  std::size_t profile_samples = 101;
  /// @throws hula::Error(Errc::InvalidOption) naming the field, its value and the valid range
  void validate() const;
};

/// A setup seeded from a curve, with the sampled targets it was built from (a study file writes them as
/// {"samples": [[u, v], ...]}).
struct MatchSeed {
  /// Points, bounds, end tangents, targets (κ, and τ for a space curve), samples, abscissa ArcLength.
  CurvatureMatchSetup setup{};
  /// The target abscissae u_i = i / (profile_samples − 1) and the curve's κ(u_i) (unsigned, as the study's
  /// profiles) and τ(u_i) (empty for a planar curve).
  std::vector<double> u{}, curvature{}, torsion{};
};

/// The matching setup of a curve (file comment).
/// @param curve any curve value with a tangent at both ends; planar curves (dimension 2, or every control point in
///   one plane) give a planar setup without a torsion target, others a 3-D one with it
/// @param options point count, bounds, samples
/// @returns the seed: its setup validates, and the spline through its points starts close to the curve
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
/// @throws hula::Error(Errc::InvalidArgument) naming "curve" for a curve with zero speed at an end, or a space
///   curve whose curvature vanishes at every sample (no torsion anywhere)
[[nodiscard]] MatchSeed seed_match_setup(const curve::Curve& curve, const MatchSeedOptions& options = {});

}  // namespace hula::studies
