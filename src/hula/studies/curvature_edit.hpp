// SPDX-License-Identifier: MIT
// Design by curvature on an existing curve (thesis 8.2.2 and
// appendix 8's "edit the curvature graph"): the designer changes the curve's
// curvature profile — drags its κ graph, or types a κ(s) law — and gets back a
// curve of the same kind, with about as many handles, that keeps what joins it
// to its neighbours: its start point and tangent always, its end point and end
// tangent by default (G1), and the curvature at both ends when asked (G2; for a
// space curve also the osculating plane at the end).
//
// Method:
//  1. The target, sampled at uniform arc length: a typed law κ*(s), or the
//     original's signed curvature changed in magnitude by δ(s), κ* = σ(κ)
//     max(|κ| + δ, 0), σ a smoothed sign (the κ graph shows |κ|: dragging it up
//     makes the curve bend more on the side it bends to, and never past zero).
//  2. The start curve. A change (a drag: a small edit) starts from the original
//     itself; a drag with held ends is fitted to a consistent target, the
//     boundary-value reconstruction of κ* (and, in space, of the original's τ)
//     with the held ends whose relative κ correction fades out under the drag
//     (envelope κ* (1 − |δ| / max |δ|)), so the dragged spot keeps what was asked
//     and the rest of the profile takes back the turning the drag adds (κ* itself
//     when that reconstruction would add an inflection); a space curve's τ takes
//     the minimum-norm share of the held end frame. A typed law starts from
//     studies::reconstruct_direct's boundary-value solution — the curve closest to κ* from the original's
//     start frame that meets the held end conditions, with the relative
//     correction δκ = κ* Σ c_k B_k(u) so the target's zeros (inflections,
//     natural ends) stay zeros — fitted by least squares on the original's
//     knots, and its profile becomes the target.
//  3. The profile fit: Levenberg–Marquardt on the control points of the
//     original's knot vector (its degree, breakpoints and weights) minimising
//     Σ_j w_j² (κ(t_j) − κ*_j)² (+ the torsion misses of a space curve; w_j = 1,
//     up to 1.5 inside a planar drag's support, so less of the miss the held
//     ends force falls where the designer dragged; the unweighted fit is kept
//     instead when it is nearer at the drag's peak) where t_j is
//     the candidate's own parameter at the fraction u_j of its own length (the
//     κ(s) graph the designer drew, redrawn for the new length: the length is
//     free, re-measured on every candidate on a fixed quadrature grid so the
//     misses are smooth in the control points; a step through zero speed is
//     refused like a worse one), the end conditions held exactly as linear
//     rows: C(a) = start, C'(a) ∥ T (and at b); a natural end (κ = 0) keeps
//     C''·N = 0 so no inflection appears there; for G2 the end speeds σ are
//     frozen and C'(a) = σ T, C''(a)·N = κ σ², C''(a)·B = 0. While the fit misses
//     the target by more than the tolerance, a knot is inserted at the middle of
//     the span of the worst sample, up to the handle budget. A space drag's fit
//     trades κ at the dragged spot for τ and the held end frame (it moved the
//     spot 0.58–0.71 of the drag fitted to κ + δ as asked, 0.76–1.07 fitted to
//     the consistent target): the drag's height is then corrected by the secant
//     method on the κ the fit reaches there (at most 4 more fits) until the fit
//     moves the spot by the drag within 1 %.
//  4. The curve value: an interpolated original comes back as an interpolated
//     spline through points on the result (its data parameters are the knots)
//     with clamped end derivatives, a Bézier as a Bézier when no knot was
//     needed, anything else as a NURBS with the original's (refined) weights.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

#include "hula/curve/curve.hpp"
#include "hula/law/expr.hpp"
#include "hula/studies/direct_reconstruction.hpp"

namespace hula::studies {

/// What an edited curve keeps at its end (its start point and tangent are always kept).
enum class EndHold {
  Free,       ///< nothing more: the initial-value reconstruction from the start frame
  Tangent,    ///< the end point and end tangent (G1 to the neighbour); the default
  Curvature,  ///< also the curvature at both ends, and a space curve's end normal (G2)
};

/// "free" | "tangent" | "curvature".
[[nodiscard]] std::string_view end_hold_name(EndHold hold) noexcept;
/// @throws hula::Error(Errc::InvalidArgument) naming `field` for any other name
[[nodiscard]] EndHold end_hold_from_name(std::string_view name, std::string_view field);

/// How CurvatureEdit::curvature is read.
enum class CurvatureTarget {
  /// The target curvature κ*(s): signed for planar curves (positive turns counter-clockwise seen from the
  /// plane normal, +Z for curves in the X-Y plane), ≥ 0 for space curves.
  Curvature,
  /// A change δ(s) of the magnitude |κ| (what the κ graph shows): κ* = κ + σ(κ) δ, so a positive δ makes the
  /// curve bend more towards the side it bends to.
  Change,
};

/// "curvature" | "change".
[[nodiscard]] std::string_view curvature_target_name(CurvatureTarget target) noexcept;
/// @throws hula::Error(Errc::InvalidArgument) naming `field` for any other name
[[nodiscard]] CurvatureTarget curvature_target_from_name(std::string_view name, std::string_view field);

/// The edit: laws of the original curve's arc length on [0, L].
struct CurvatureEdit {
  /// A scalar law of `parameter` only (the target or the change, see `target`).
  law::Law curvature{};
  /// How `curvature` is read. Default Curvature.
  CurvatureTarget target = CurvatureTarget::Curvature;
  /// Space curves: the target torsion τ*(s), a law of `parameter` in the same law::Context; absent keeps the
  /// original's torsion. Refused for planar curves.
  std::optional<law::Law> torsion{};
  /// The arc-length parameter's name. Default "s".
  std::string parameter = "s";
};

/// Options of edit_curvature().
struct CurvatureEditOptions {
  /// What the end keeps. Default EndHold::Tangent.
  EndHold hold = EndHold::Tangent;
  /// Most handles of the result as a multiple of the original's (handle_count()), rounded down, at least the
  /// original's count. Default 2; valid [1, 10].
  double max_handles_factor = 2.0;
  /// Curvature tolerance relative to the target's max |κ*| (and at most a fifth of the largest change asked): the
  /// fit is refined while max_j |κ(s_j) − κ*_j| exceeds it and the budget allows, s_j = u_j times the fit's own
  /// length. Default 0.02; valid [1e-6, 1].
  double curvature_tolerance = 0.02;
  /// Arc-length samples of the profiles and of the fit. Default 400; valid [50, 100 000].
  std::size_t samples = 400;
  /// The boundary-value solver's options for typed targets (fit is ignored: steps 3–4 make the curve).
  /// Defaults: correction degree 7, otherwise DirectReconstructionOptions{}.
  DirectReconstructionOptions reconstruction = [] {
    DirectReconstructionOptions o;
    o.correction_degree = 7;
    o.fit = false;
    return o;
  }();
  /// @throws hula::Error(Errc::InvalidOption) naming the field, its value and the valid range
  void validate() const;
};

/// Result of edit_curvature().
struct CurvatureEditResult {
  /// The edited curve: interpolated for an interpolated original, a Bézier for a Bézier that needed no knot,
  /// else a non-rational NURBS of the original's degree.
  curve::Curve curve;
  /// handle_count() of the original and of the result.
  std::size_t handles_before = 0;
  std::size_t handles_after = 0;
  /// True for a planar edit (signed curvature about the curve's plane).
  bool planar = true;
  /// True when the start came from the boundary-value reconstruction (a typed target).
  bool reconstructed = false;
  /// Length of the original and of the result (model units).
  double length_before = 0.0;
  double length_after = 0.0;
  /// max_j and mean_j |κ(u_j L') − κ*_j| of the result (length L') against the target it was fitted to (the
  /// reconstruction's profile for a typed law) at the samples' fractions u_j of the length, 1 / model units.
  double max_curvature_deviation = 0.0;
  double mean_curvature_deviation = 0.0;
  /// A typed law: the reconstruction's mean and max |κ − κ*| (the price of the held ends); 0 for a change.
  double reconstruction_mean_deviation = 0.0;
  double reconstruction_max_deviation = 0.0;
  /// Gauss–Newton iterations of the reconstruction (0 for a change or EndHold::Free).
  int iterations = 0;
  /// Measured on `curve` against the original: |Δ start|, |Δ end| (model units), the angles between the start
  /// and end tangents (radians), and |Δκ| at both ends (1 / model units, signed κ for planar curves).
  double start_point_error = 0.0;
  double end_point_error = 0.0;
  double start_tangent_error = 0.0;
  double end_tangent_error = 0.0;
  double start_curvature_error = 0.0;
  double end_curvature_error = 0.0;
  /// Inflections of the original and of the result (planar curves; 0 for space curves).
  std::size_t inflections_before = 0;
  std::size_t inflections_after = 0;
  /// Wall time, seconds.
  double seconds = 0.0;
};

/// The handles a designer drags: an interpolated or Hermite curve's points, a Bézier's or NURBS's control
/// points, the stand-in NURBS's control points of a law or natural curve.
[[nodiscard]] std::size_t handle_count(const curve::Curve& curve);

/// Edits the curvature profile of a curve and keeps its ends (file comment).
///
/// Example:
/// ```
/// law::Context ctx; law::ParseOptions po; po.parameters = {"s"};
/// // raise |κ| by 0.004 around a third of the length of an S-curve, keeping its ends and end tangents
/// CurvatureEdit edit{.curvature = law::parse("0.004*exp(-((s - 60)/12)^2)", ctx, po),
///                    .target = CurvatureTarget::Change};
/// CurvatureEditResult r = edit_curvature(s_curve, edit);
/// // r.curve: an interpolated spline with at most twice the points; r.end_point_error ≈ 0
/// ```
/// @param original a curve of degree ≥ 2 with a defined tangent at both ends; a space curve also needs κ > 0
///   everywhere (its torsion is undefined where κ = 0)
/// @param edit the target or change (and torsion) as laws of the original's arc length s on [0, L]; the result
///   matches them at the same fractions s / L of its own length
/// @param options what the end keeps, the handle budget, tolerances
/// @throws hula::Error(Errc::InvalidArgument) naming "curvature" or "torsion" for a law of another parameter or
///   context, or a non-scalar law; "torsion" for a planar curve; "curve" for a straight or degree-1 curve, a
///   zero end tangent, an unclamped knot vector, or a space curve whose curvature vanishes (naming s)
/// @throws hula::Error(Errc::OutOfDomain) naming "curvature"/"torsion" and s where a law is undefined
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
/// @throws hula::Error from reconstruct_direct (an unreachable end, NumericalFailure when the held ends cannot be
///   met); Errc::NumericalFailure naming "curve" if the fit reverses an end tangent
[[nodiscard]] CurvatureEditResult edit_curvature(const curve::Curve& original, const CurvatureEdit& edit,
                                                 const CurvatureEditOptions& options = {});

}  // namespace hula::studies
