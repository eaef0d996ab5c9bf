// SPDX-License-Identifier: MIT
// Open CASCADE's fairing baselines beside a study run's curves (`hula
// fair-knots --occt`, `hula match-curvature --occt`): FairCurve_Batten fixed
// and sliding and FairCurve_MinimalVariation (oli/kernel/occt_fairing.hpp)
// between the data's end points with the end tangents and signed curvatures
// of the run's best curve, their energies and deviations from the data
// points, and a figure of the run's curves and the baselines, each with its
// curvature comb at the best curve's automatic scale.
#pragma once

#include "hula/io/svg.hpp"
#include "hula/oli/study_runner.hpp"

namespace hula::oli {

/// The baselines of a run.
struct FairingBaselines {
  /// {"ends": {"tangent_angles", "curvatures"}, "curves": [{"name", "status", "bending", "variation",
  /// "max_deviation", "mean_deviation", "tangent_error", "curve"}]} (non-finite values and missing curves
  /// null).
  io::Json json = io::Json::object();
  /// "baselines": the run's curves (fair-knots: chord length, GA, Nelder–Mead; match-curvature: start,
  /// best) and the baselines, with combs, and the data points.
  io::SvgFigure figure{900, 700};
};

/// The baselines of a "fair-knots" or planar "match-curvature" run: for fair-knots between the data
/// points' ends with the better optimum's end tangents and curvatures (the chord-length curve's when no
/// optimiser ran), measured from the data points; for match-curvature with the best curve's (the direct
/// method's NURBS, else the spline through the best points), measured from the best points.
/// @throws hula::Error(Errc::Unsupported) naming "occt" in a build without Open CASCADE
/// @throws hula::Error(Errc::InvalidArgument) naming "occt" for a 3-D match study or another kind
[[nodiscard]] FairingBaselines fairing_baselines(const StudyOutcome& outcome);

}  // namespace hula::oli
