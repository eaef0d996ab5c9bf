// SPDX-License-Identifier: MIT
// Curves from their natural equations (thesis 8.2.2, eq. 34; Nutbourne):
// given the curvature κ(s) and torsion τ(s) as laws of arc length on [0, L],
// a start point and a start frame, the curve r(s) with its frame {T, N, B}.
//
// Notation: s arc length, κ curvature, τ torsion, θ turning angle, T/N/B the
// tangent, normal and binormal; h a step length.
//
// - Planar (τ ≡ 0): eq. 34 in the plane of the start frame, θ(s) = ∫κ from
//   law::antiderivative when a closed form exists on [0, L] (exact angle,
//   frame exactly orthonormal) and x + iy = ∫ e^{iθ} along T(0) and N(0) by
//   adaptive 10-point Gauss–Legendre; otherwise the Frenet–Serret system
//   below with τ = 0. κ may change sign: positive
//   turns towards N(0) (counter-clockwise seen from B(0) = T(0) × N(0)).
// - Space: the Frenet–Serret system r' = T, T' = κN, N' = −κT + τB,
//   B' = −τN, integrated by the embedded Runge–Kutta–Fehlberg 7(8) pair
//   (Boost.Odeint runge_kutta_fehlberg78 with its controlled stepper), with
//   the frame re-orthonormalised (Gram–Schmidt, B = T × N) after every accepted
//   step. Why RKF78 and not a Lie-group (Magnus) step: the 8th-order pair takes
//   few, long steps at tolerances 1e-9 … 1e-12, and the drift from
//   orthonormality per step is of the order of the local error, which the
//   projection removes; a Magnus integrator would keep the frame exactly on
//   SO(3) but needs matrix exponentials per stage for the same order.
//   N is the "signed" normal carried by the ODE: where κ < 0 it is minus the
//   Frenet normal, so κN (= r'') is continuous.
//
// Dense output: the accepted steps are stored; the value at any s is one RKF78
// step (or one Gauss–Legendre rule) of length s − s_k from the last node
// s_k ≤ s, so dense values have the local accuracy of the integration
// (shorter steps are more accurate).
// A NURBS is fitted by quintic Hermite interpolation with the exact r' = T and
// r'' = κN at breakpoints refined until the deviation is below a tolerance.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/law/expr.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::intrinsic {

/// Where the reconstructed curve starts and how it is oriented.
struct StartFrame {
  /// r(0), model units. Default the origin.
  Vec3 point{0.0, 0.0, 0.0};
  /// T(0): any non-zero finite vector, normalised. Default +X.
  Vec3 tangent{1.0, 0.0, 0.0};
  /// N(0): any finite vector not parallel to the tangent; its component along the tangent is
  /// removed and it is normalised. Default +Y. B(0) = T(0) × N(0).
  Vec3 normal{0.0, 1.0, 0.0};
};

/// How reconstruct() integrates.
enum class ReconstructionMethod {
  Auto,          ///< planar (eq. 34) when τ is the constant 0, else Frenet–Serret
  FrenetSerret,  ///< always integrate the Frenet–Serret system (also for τ ≡ 0)
};

/// How reconstruct() actually integrated (reported by IntrinsicCurve::method()).
enum class IntegrationKind {
  PlanarExactAngle,    ///< eq. 34, θ from the closed-form antiderivative of κ, x + iy by adaptive Gauss–Legendre
  PlanarNumericAngle,  ///< no closed-form angle: the Frenet–Serret system with τ = 0 (stays in the plane)
  FrenetSerret,        ///< the Frenet–Serret system
};

/// Options of reconstruct().
struct ReconstructionOptions {
  /// Requested absolute accuracy of the positions over [0, L], model units. The local error per
  /// step is held below tolerance / max(1, L) / 20 (frame errors grow into position errors times
  /// the remaining length). Default 1e-10; valid [1e-13, 1e-2]. Below ~1e-13 rounding dominates.
  double tolerance = 1e-10;
  /// Auto or force the Frenet–Serret integration. Default Auto.
  ReconstructionMethod method = ReconstructionMethod::Auto;
  /// Largest number of step attempts (accepted + rejected) before NumericalFailure. Default
  /// 1 000 000; valid 1 … 100 000 000.
  std::size_t max_steps = 1'000'000;
  /// The kinks and jumps of κ and τ inside (0, L) as reconstruction_breaks() returns them for these laws and this
  /// length: given, reconstruct() skips its singularity analysis of the laws (a root search per kink candidate,
  /// the dearest part of a reconstruction of a B-spline profile). For a caller that reconstructs laws of the same
  /// kinks many times, e.g. one profile plus a changing polynomial correction (studies::reconstruct_direct).
  /// Absent (default): analysed on every call.
  std::optional<std::vector<double>> breaks{};
  /// @throws hula::Error(Errc::InvalidOption) naming the field, its value and the valid range
  void validate() const;
};

/// What reconstruct(kappa, tau, parameter, length) finds in its singularity analysis: the kinks and jumps of κ and
/// τ inside (0, L) where they are finite (unsorted), for ReconstructionOptions::breaks. Pass tau = the constant 0
/// for reconstruct_planar.
/// @throws hula::Error(Errc::NumericalFailure) naming "kappa" or "tau" where a law has a pole on [0, L]
[[nodiscard]] std::vector<double> reconstruction_breaks(const law::Law& kappa, const law::Law& tau,
                                                        std::string_view parameter, double length);

/// Position and frame at one arc length.
struct FramePoint {
  /// Arc length from the start.
  double s = 0.0;
  /// r(s), model units.
  Vec3 position{};
  /// Unit tangent T = r'(s).
  Vec3 tangent{};
  /// Unit (signed) normal N, with r''(s) = κ(s) N(s); minus the Frenet normal where κ < 0.
  Vec3 normal{};
  /// Unit binormal B = T × N.
  Vec3 binormal{};
  /// κ(s) as given (signed).
  double curvature = 0.0;
  /// τ(s) as given (0 for planar reconstructions).
  double torsion = 0.0;
};

/// The reconstructed curve as a dense, law-like result: position and frame at any s in [0, L].
/// Immutable and thread-safe to evaluate (compiled laws with per-thread workspaces).
class IntrinsicCurve {
 public:
  /// Length L of the curve (the arc-length domain is [0, L]).
  [[nodiscard]] double length() const noexcept;
  /// How the curve was integrated.
  [[nodiscard]] IntegrationKind method() const noexcept;
  /// The requested position tolerance.
  [[nodiscard]] double tolerance() const noexcept;
  /// Arc lengths of the accepted integration steps, 0 = s_0 < … < s_n = L.
  [[nodiscard]] std::span<const double> nodes() const noexcept;
  /// Number of rejected step attempts (a measure of difficulty).
  [[nodiscard]] std::size_t rejected_steps() const noexcept;
  /// Interior arc lengths where κ or τ is not smooth (kinks and jumps of abs, min/max, sign,
  /// piecewise, NURBS knots, … found by law::singularities), increasing. Every integration step
  /// ends on them (they are among nodes()), so each step integrates a smooth piece; fit_nurbs()
  /// puts a knot on each.
  [[nodiscard]] std::span<const double> breakpoints() const noexcept;

  /// Position and frame at arc length s.
  /// @param s arc length in [0, L] (within 1e-12 L; clamped to the ends there)
  /// @returns the point with an orthonormal, right-handed frame
  /// @throws hula::Error(Errc::OutOfDomain) naming "s" if s is outside [0, L] or not finite
  [[nodiscard]] FramePoint evaluate(double s) const;
  /// Batch form of evaluate(); any order of arc lengths.
  /// @throws hula::Error(Errc::OutOfDomain) naming "s" and the index of the first bad value
  [[nodiscard]] std::vector<FramePoint> evaluate(std::span<const double> s) const;

  /// Opaque implementation (natural_equations.cpp).
  struct Impl;

 private:
  friend IntrinsicCurve reconstruct(const law::Law&, const law::Law&, std::string_view, double, const StartFrame&,
                                    const ReconstructionOptions&);
  friend IntrinsicCurve reconstruct_planar(const law::Law&, std::string_view, double, const StartFrame&,
                                           const ReconstructionOptions&);
  explicit IntrinsicCurve(std::shared_ptr<const Impl> impl);
  std::shared_ptr<const Impl> impl_;
};

/// The curve with curvature κ(s) and torsion τ(s), s ∈ [0, L], starting at `start`.
///
/// Example:
/// ```
/// law::Context ctx;
/// law::ParseOptions po; po.parameters = {"s"};
/// IntrinsicCurve c = reconstruct(law::parse("0.8", ctx, po), law::parse("0.4", ctx, po), "s", 20.0);
/// FramePoint p = c.evaluate(10.0);   // a point of the helix with κ = 0.8, τ = 0.4
/// ```
/// @param kappa scalar law of `parameter` only (signed for planar curves)
/// @param tau scalar law of `parameter` only, of the same context as kappa; the constant 0
///   selects the planar method (unless options.method = FrenetSerret)
/// @param parameter the arc-length parameter name, e.g. "s"
/// @param length L > 0, finite
/// @param start start point and frame (normalised here, see StartFrame)
/// @param options tolerance, method, step budget
/// @returns the dense curve
/// @throws hula::Error(Errc::InvalidArgument) naming "kappa" or "tau" if a law is empty, not
///   scalar, of another context or uses another parameter; naming "length" if L ≤ 0;
///   naming "start_frame.tangent" if T(0) = 0 and "start_frame.normal" if N(0) ∥ T(0)
/// @throws hula::Error(Errc::NonFiniteInput) naming "length", "start_frame.point",
///   "start_frame.tangent" or "start_frame.normal" for NaN/inf
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
/// @throws hula::Error(Errc::NumericalFailure) naming "kappa"/"tau" and s where a law is
///   undefined or infinite, or when the step budget is exhausted
/// Complexity: O(number of steps × cost of κ, τ); steps grow as tolerance^(−1/8), plus one step
/// end per kink of κ or τ (breakpoints()).
[[nodiscard]] IntrinsicCurve reconstruct(const law::Law& kappa, const law::Law& tau, std::string_view parameter,
                                         double length, const StartFrame& start = {},
                                         const ReconstructionOptions& options = {});

/// The planar curve with signed curvature κ(s) (eq. 34) in the plane of the start frame;
/// κ > 0 turns towards start.normal. Same as reconstruct() with τ ≡ 0 and method Auto.
/// @throws as reconstruct() (without the "tau" cases)
[[nodiscard]] IntrinsicCurve reconstruct_planar(const law::Law& kappa, std::string_view parameter, double length,
                                                const StartFrame& start = {},
                                                const ReconstructionOptions& options = {});

/// Options of fit_nurbs().
struct NurbsFitOptions {
  /// Largest allowed distance |C(s) − r(s)| between the NURBS and the dense curve at equal arc
  /// length, model units (an upper bound of the geometric deviation). Default 1e-9; valid
  /// [1e-13, 1]. It cannot be met below the curve's own integration tolerance.
  double tolerance = 1e-9;
  /// When true, `tolerance` is relative to the curve's size, the diagonal of the bounding box of
  /// the curve at its integration nodes (absolute = tolerance × diagonal; the length L when the
  /// curve is straight and the box degenerates). Default false (absolute).
  bool relative = false;
  /// Largest number of Hermite segments before giving up (converged = false). Default 100 000;
  /// valid 1 … 10 000 000.
  std::size_t max_segments = 100'000;
  /// Samples per segment in the final deviation check (besides the ends). Default 16; valid 1 … 1000.
  int check_samples = 16;
  /// @throws hula::Error(Errc::InvalidOption) naming the field, its value and the valid range
  void validate() const;
};

/// Result of fit_nurbs().
struct NurbsFitResult {
  /// Quintic, parameterised by arc length on [0, L]. The Hermite fit has knots of multiplicity 3 at
  /// the breakpoints (C2), 5 where κ jumps (C1: the curve itself is only C1 there); then every knot
  /// whose removal keeps the curve within the tolerance is removed (nurbs::remove_knots).
  nurbs::NurbsCurve curve;
  /// Largest |C(s) − r(s)| found by dense sampling (check_samples per segment).
  double max_deviation = 0.0;
  /// Number of Hermite segments (before knot removal the NURBS has 3 × (segments + 1) + 2 j control
  /// points, j the number of jumps of κ; after it, usually far fewer).
  std::size_t segments = 0;
  /// The absolute tolerance applied (options.tolerance, times the curve's size when relative).
  double tolerance = 0.0;
  /// True when max_deviation ≤ tolerance.
  bool converged = false;
};

/// Fits a quintic NURBS to a reconstructed curve: Hermite interpolation through breakpoints with
/// the exact first (T) and second (κN) arc-length derivatives, then re-measuring by dense sampling.
///
/// Knot placement: a knot at each of the curve's breakpoints() (kinks of κ or τ; where κ jumps
/// the segments on either side take its one-sided values and the knot has multiplicity 5), and
/// within each smooth piece between them greedy longest segments: from each breakpoint s_a the
/// next one is the farthest s_b for which the Hermite segment [s_a, s_b] stays within half the
/// tolerance at check_samples interior points — the whole rest of the piece if it does, else
/// found by halving the remaining length until a segment fits and then bisecting between the
/// longest fitting and the shortest failing end (8 steps, so within 1/256 of the longest). Where
/// the deviation grows with the segment length (the h⁶ error of quintic Hermite), greedy covering
/// gives the fewest segments, hence the fewest control points for the tolerance.
/// Past max_segments each remaining piece gets one segment (converged = false), so the work is
/// bounded by max_segments + breakpoints segments.
/// Then knot removal (The NURBS Book A5.8, nurbs::remove_knots) within what the fit left of the
/// tolerance (tolerance − max deviation): the cheapest knot first, its bound accumulated per span,
/// so the result stays within the tolerance; the deviation is measured again at the same samples
/// (and the Hermite fit kept if that measurement missed the tolerance).
/// Complexity: O(segments × 12 × check_samples) dense evaluations.
/// @param curve a reconstructed curve
/// @param options tolerance, segment budget, check density
/// @returns the curve and its measured deviation (converged = false when the budget ran out;
///   the curve is then the last refinement)
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
[[nodiscard]] NurbsFitResult fit_nurbs(const IntrinsicCurve& curve, const NurbsFitOptions& options = {});

/// fit_nurbs() that fails instead of returning a fit outside the tolerance (converged = false):
/// the form of the front ends, where a curve that misses the tolerance is of no use.
/// @throws hula::Error(Errc::NumericalFailure) naming "kappa" (the law whose roughness needs the
///   segments), with max_segments, the tolerance and the deviation reached
/// @throws as fit_nurbs()
[[nodiscard]] NurbsFitResult fit_nurbs_converged(const IntrinsicCurve& curve, const NurbsFitOptions& options = {});

/// Defaults and work limits of the front ends (`hula reconstruct`, POST /api/reconstruct). The fit
/// tolerance is relative to the curve's size (NurbsFitOptions::relative): 1e-6 of the diagonal
/// gives a compact curve (few control points) far below what a viewport or a CAD
/// exchange resolves. The budgets bound the work of one request: at most kFrontEndMaxSteps step
/// attempts of the integration (ReconstructionOptions::max_steps) and kFrontEndMaxSegments Hermite
/// segments of the fit (3 × 2,001 control points), past which the request fails with an error
/// naming kappa and the limit rather than running for minutes.
inline constexpr double kFrontEndFitTolerance = 1e-6;
inline constexpr std::size_t kFrontEndMaxSteps = 100'000;
inline constexpr std::size_t kFrontEndMaxSegments = 2'000;

}  // namespace hula::intrinsic
