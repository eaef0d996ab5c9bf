// SPDX-License-Identifier: MIT
// The fairing assistant of the workbench: a faired "ghost" of
// a curve that lowers its curvature-variation energy ∫(dκ/ds)² ds while every
// data point stays within a tolerance the user sets. Two methods:
//  - knot fairing (thesis 7.2–7.4): the interpolated spline keeps its data
//    points exactly and only their parameters move (fair_knots_deterministic
//    on the Variation energy, under a time budget);
//  - minimal curvature variation: the data points themselves move, each by at
//    most the tolerance, to minimise Σ r_q² over the residuals
//    r_q = sqrt(w_q |r'(t_q)|) κ'(t_q) at Gauss–Legendre nodes of every knot
//    span (a quadrature of ∫κ'² ds), by Ceres's Levenberg–Marquardt
//    (refine_levenberg_marquardt, the hybrid's solver); every point's move is
//    a smooth map onto its tolerance ball, so no step leaves it. OCCT's
//    FairCurve_MinimalVariation (oli/kernel/occt_fairing) minimises the same
//    energy but only between two ends; this one holds every data point.
// The "data points" are the curve's construction points: the points of an
// interpolated or Hermite curve (the curve passes through them), the control
// points of a NURBS or Bézier curve (then the whole curve moves by at most the
// tolerance: a NURBS point is a convex combination of its control points).
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/curve/curve.hpp"

namespace hula::studies {

/// How the assistant fairs.
enum class AssistantMethod {
  Knots,             ///< move the parameters of an interpolated curve's data points (points kept exactly)
  MinimalVariation,  ///< move the data points within the tolerance, minimising ∫κ'² ds
};

/// "knots" or "min-variation".
[[nodiscard]] std::string_view assistant_method_name(AssistantMethod method) noexcept;
/// The method named "knots" or "min-variation".
/// @throws hula::Error(Errc::InvalidOption) naming "method" and the text for any other name
[[nodiscard]] AssistantMethod assistant_method_from_name(std::string_view name);

/// What the fairing keeps at the curve's two ends.
enum class AssistantHold {
  Free,      ///< every data point may move (within the tolerance)
  Points,    ///< the end points stay exactly where they are
  Tangents,  ///< the end points and the end tangent directions stay exactly as they are
};

/// "free", "points" or "tangents".
[[nodiscard]] std::string_view assistant_hold_name(AssistantHold hold) noexcept;
/// The hold named "free", "points" or "tangents".
/// @throws hula::Error(Errc::InvalidOption) naming "hold" and the text for any other name
[[nodiscard]] AssistantHold assistant_hold_from_name(std::string_view name);

/// Options of fair_within_tolerance.
struct AssistantOptions {
  /// The method. Default MinimalVariation.
  AssistantMethod method = AssistantMethod::MinimalVariation;
  /// Largest distance a data point may move, model units, finite and > 0. Default 1.
  /// Test: |q_k − q0_k| ≤ tolerance for every data point k (knots: 0, the points are kept).
  double tolerance = 1.0;
  /// Wall-clock budget of the optimisation, seconds, in (0, 60]. Default 0.1 (the workbench's ghost
  /// must be drawn ≤ 150 ms after the pointer stops). The best curve so far is returned when it runs out;
  /// the first step that lowers the energy always runs.
  double time_budget_seconds = 0.1;
  /// Most Levenberg–Marquardt iterations (min-variation: accepted steps, each after at most 12 tries of the
  /// damping), 1 … 1000. Default 30.
  std::size_t max_iterations = 30;
  /// What stays at the ends. Default Free. Points: the first and last data points are not moved (an
  /// interpolated or Hermite curve passes through them; a NURBS or Bézier curve must be clamped, its end
  /// control points are its ends). Tangents: besides, a NURBS or Bézier curve's second and last but one
  /// control points are not moved (C'(a) ∝ P1 − P0 and C'(b) ∝ P_n − P_{n−1}); a Hermite curve's
  /// tangents never move; an interpolated curve's ends become direction end conditions along its own
  /// end tangents (nurbs::EndCondition::direction), so the ghost leaves and arrives in the same directions.
  AssistantHold hold = AssistantHold::Free;
  /// @throws hula::Error(Errc::InvalidOption) naming the field and its value
  void validate() const;
};

/// The ghost and how it compares with the curve it fairs.
struct AssistantResult {
  /// The faired curve, of the same kind and construction rules as the input (knots: an interpolated
  /// curve with explicit parameters on [0, 1]); the input itself when nothing lowered the energy.
  curve::Curve curve;
  /// ∫(dκ/ds)² ds of the input and of the ghost (diffgeom::curvature_variation_energy), 1 / model units³.
  double energy_before = 0.0;
  double energy_after = 0.0;
  /// The data points of the input (see the file comment), model units.
  std::vector<Vec3> data_points{};
  /// The ghost's data points, one per input data point.
  std::vector<Vec3> faired_points{};
  /// max_k |faired_points[k] − data_points[k]| ≤ tolerance, model units.
  double max_deviation = 0.0;
  /// Levenberg–Marquardt steps tried (min-variation) or energy evaluations (knots).
  std::size_t iterations = 0;
  /// True when the time budget ended the optimisation (the ghost is the best so far).
  bool stopped = false;
  /// Wall-clock seconds.
  double seconds = 0.0;
};

/// Fairs `curve` within `options.tolerance` (see the file comment).
/// @param curve an interpolated, Hermite, NURBS or Bézier curve (knots: interpolated with ≥ 3 points)
/// @param options method, tolerance, budget
/// @returns the ghost; energy_after ≤ energy_before always (the input is returned when no step helps)
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
/// @throws hula::Error(Errc::InvalidArgument) naming "curve" for a law or natural curve, or for the
///   knot method on a curve that is not interpolated through ≥ 3 points
/// @throws hula::Error(Errc::InvalidArgument) naming "hold" for held ends of an unclamped NURBS curve
///   (its end points are not control points)
/// @throws as fair_knots_deterministic (knots)
/// Complexity per iteration (min-variation): 2n + 1 curve constructions and residual evaluations for
/// n free coordinates (central differences), plus a dense QR solve of the m × n Jacobian.
[[nodiscard]] AssistantResult fair_within_tolerance(const curve::Curve& curve, const AssistantOptions& options = {});

}  // namespace hula::studies
