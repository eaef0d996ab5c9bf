// SPDX-License-Identifier: MIT
// Distance between two curves, sampled (thesis 10.2.2, "Position Distance":
// the distance of two curves at the same parameter value, averaged over the
// samples, with the averages of |Δx|, |Δy|, |Δz|, used to judge a solution
// curve against a reference curve). Two measures:
//   - Parameter: |A(s) − B(s)| at equal normalised parameters s (each curve's
//     domain mapped to [0, 1]) — the thesis's measure, which also sees a
//     difference of parameterisation;
//   - Closest: the distance from each sample of A to the nearest point of B
//     (closest_point) — the one-sided shape distance, blind to parameterisation.
#pragma once

#include <cstddef>

#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::nurbs {

/// How the two curves are paired.
enum class DeviationMode {
  Parameter,  ///< A(s) against B(s) at equal normalised parameters (thesis 10.2.2)
  Closest,    ///< A(s) against the point of B nearest to it
};

/// Options of deviation().
struct DeviationOptions {
  /// Number of samples, uniform in the normalised parameter, both ends included. Default 1001; valid ≥ 2.
  std::size_t samples = 1001;
  DeviationMode mode = DeviationMode::Parameter;
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// Result of deviation(): statistics of d_i = |A(s_i) − B_i| over the samples.
struct DeviationResult {
  double max = 0.0;   ///< max d_i (model units)
  double mean = 0.0;  ///< mean d_i (the thesis's average distance)
  double rms = 0.0;   ///< sqrt(mean d_i²)
  double at = 0.0;    ///< normalised parameter s ∈ [0, 1] of the maximum
  Vec3 mean_axis{};   ///< mean |Δx|, |Δy|, |Δz| (the thesis's per-axis averages)
  Vec3 max_axis{};    ///< max |Δx|, |Δy|, |Δz|
  std::size_t samples = 0;
};

/// Sampled distance between curves a and b (see the file comment).
/// @returns zero for a curve against itself: exactly in Parameter mode, to rounding (closest_point's
///   recognition of points on the curve) in Closest mode
/// @throws hula::Error(Errc::InvalidOption) if options are invalid
/// Complexity: samples evaluations of each curve (Parameter) or samples closest-point searches (Closest).
[[nodiscard]] DeviationResult deviation(const NurbsCurve& a, const NurbsCurve& b, const DeviationOptions& options = {});

}  // namespace hula::nurbs
