// SPDX-License-Identifier: MIT
// Deterministic fairing baselines from Open CASCADE: the
// curves a CAD system's own fairing gives between the same two end points with
// the same end tangents (and curvatures), to set beside the knot-fairing and
// matching studies' GA and Nelder–Mead results. FairCurve_Batten simulates an
// elastic batten of constant section (minimum ∫κ² ds), with fixed length or
// free sliding; FairCurve_MinimalVariation minimises the jerk energy (∫κ′² ds,
// physical ratio 0) and can also hold end curvatures. Both are planar (gp_Pnt2d):
// the data are taken in their xy-plane. Only built with Open CASCADE; above the
// pure studies library in the layers (oli_kernel), so studies stay OCCT-free.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::oli {

/// The end conditions shared by every baseline.
struct FairingEnds {
  /// End points (xy used; z ignored), distinct.
  Vec3 p1{}, p2{};
  /// Tangent directions at p1 and p2 (xy used; any non-zero length).
  Vec3 t1{1.0, 0.0, 0.0}, t2{1.0, 0.0, 0.0};
  /// Signed curvatures at p1 and p2 (1 / model units; > 0 turns left), for MinimalVariation.
  double k1 = 0.0, k2 = 0.0;
};

/// One baseline curve and how it relates to the data.
struct FairingBaseline {
  /// "batten" (fixed length), "batten-sliding" (free sliding) or "minimal-variation".
  std::string name{};
  /// OCCT's FairCurve_AnalysisCode ("OK", "NotConverged", "InfiniteSliding", "NullHeight") or, when it
  /// threw, "exception: <type>: <message>". The curve is reported whenever OCCT returned one.
  std::string status{};
  /// The curve as a planar NURBS (absent when OCCT gave none).
  std::optional<nurbs::NurbsCurve> curve{};
  /// ∫κ² ds and ∫κ′² ds of the curve (diffgeom energies); NaN without a curve.
  double bending = 0.0, variation = 0.0;
  /// Largest and mean distance of the data points from the curve (closest points); NaN without a curve.
  double max_deviation = 0.0, mean_deviation = 0.0;
  /// Angle between the curve's end tangents and the requested ones, radians (how well OCCT held them).
  double tangent_error = 0.0;
};

/// Runs FairCurve_Batten (fixed length, then free sliding) and FairCurve_MinimalVariation (tangents and
/// curvatures held, jerk energy) between ends.p1 and ends.p2, and measures each against `points`.
/// @param ends the shared end conditions
/// @param points the data points the studies interpolate (deviations are their distances to each curve)
/// @returns the three baselines, in that order; a failed one carries its status and no curve
/// @throws hula::Error(Errc::CoincidentPoints) naming "p2" if the end points coincide
/// @throws hula::Error(Errc::InvalidArgument) naming "t1" / "t2" for a zero tangent
[[nodiscard]] std::vector<FairingBaseline> occt_fairing_baselines(const FairingEnds& ends,
                                                                  std::span<const Vec3> points);

/// occt_fairing_baselines computed by the Open CASCADE plugin (libhula_occt.so, loaded on first use),
/// for callers that must not link Open CASCADE themselves (the document, hence every `hula` command).
/// @throws as occt_fairing_baselines; hula::Error(Errc::IoError) with field "plugin" if the plugin is
///   not installed
[[nodiscard]] std::vector<FairingBaseline> occt_fairing_baselines_in_plugin(const FairingEnds& ends,
                                                                            std::span<const Vec3> points);

}  // namespace hula::oli
