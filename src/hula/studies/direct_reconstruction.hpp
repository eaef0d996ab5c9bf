// SPDX-License-Identifier: MIT
// Direct reconstruction of a curve from a prescribed curvature profile (and
// torsion profile for space curves): the "function representation driven"
// route of thesis 8.2.2 (eq. 34–35), which stalled there for want of symbolic
// integration, done with the natural-equation solver of hula::intrinsic, plus
// a boundary-value version that also honours a prescribed end point and/or end
// tangent.
//
// Notation: u = s / L the normalised arc length, κ*(u), τ*(u) the target
// profiles, δκ, δτ the corrections, B_k the Bernstein polynomials of degree n
// on [0, 1], c the correction coefficients, F(c) the end residuals, J = ∂F/∂c.
//
// Initial-value problem (no end constraint): the curve with κ(s) = κ*(s/L),
// τ(s) = τ*(s/L) from the start point and frame, by intrinsic::reconstruct
// (exact angle for planar profiles with a closed-form integral, RKF78
// Frenet–Serret otherwise).
//
// Boundary-value problem: a target profile generally cannot meet a prescribed
// end, so the curve closest to the target that does is sought. The profiles
// receive corrections δκ(u) = Σ_k c_k B_k(u) (and δτ(u) = Σ_k d_k B_k(u) for
// space curves unless disabled; optionally the length L is also free), and the
// method is the minimum-norm Gauss–Newton iteration for
//
//     minimise ‖L·δκ‖²_{L²(0,1)} + ‖L·δτ‖²_{L²(0,1)} + w (ΔL / L)²   subject to F(c) = 0,
//
// i.e. each step solves the linearised constraints F + J (c⁺ − c) = 0 for the
// c⁺ of least weighted norm (Gram matrix of the Bernstein basis, pseudo-inverse
// by Eigen's complete orthogonal decomposition, so rank-deficient constraint
// sets are handled), with step halving while the end residual grows. Its fixed
// points satisfy F = 0 and c ∈ range(Gᐨ¹Jᵀ), the first-order conditions of the
// problem above; with end constraints taken from the target's own curve the
// answer is c = 0.
//
// The Jacobian is exact to first order, without finite differences: a change
// δκ(s), δτ(s) of the profiles turns the frame at s by the Darboux increment
// δω(s) = δκ(s) B(s) + δτ(s) T(s) per unit length, so
//     δr(L) = ∫₀ᴸ δω(s) × (r(L) − r(s)) ds,   δT(L) = (∫₀ᴸ δω(s) ds) × T(L),
// evaluated by Gauss–Legendre quadrature on the dense intrinsic curve. For the
// length, with the profiles fixed in u, ∂r(L)/∂L = (r(L) − r(0)) / L plus the same
// integrals with δω = (κB + τT) / L (a longer curve turns faster per unit u), and
// ∂T(L)/∂L = (∫ (κB + τT) / L ds) × T(L).
//
// End residuals (dimensionless): (r(L) − p*) / L, and for the tangent the
// rotation from t* to T(L) (its angle for planar curves, its two components
// normal to t* in space); for a prescribed end normal of a space curve, the
// rotation about T(L) from n* to N(L), whose sensitivity is δΩ · T(L).
//
// Relative corrections and held end curvatures (design by curvature):
// with an envelope e(u) the curvature correction is δκ(u) = e(u) Σ_k c_k B_k(u)
// and the metric the L² norm of that product (Gauss–Legendre Gram matrix). With
// e = κ* the curve's curvature is κ*(u)(1 + Σ c_k B_k(u)): wherever the target
// is zero (an inflection, a straight end) the result is zero too, so a
// correction that holds the ends cannot add inflections. Prescribed end
// curvatures fix c_0 and c_n (B_k(0) = δ_k0, B_k(1) = δ_kn), and the
// iteration runs on the other unknowns: with y = y_fix + P w (P selects the
// free unknowns), the least M-norm y with J P w = b is
//     w = v − M_ff⁻¹ g,   v the least M_ff-norm solution of J P v = b + J P M_ff⁻¹ g,
// M_ff = Pᵀ M P, g = Pᵀ M y_fix.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/intrinsic/natural_equations.hpp"
#include "hula/law/expr.hpp"
#include "hula/studies/profile.hpp"

namespace hula::studies {

/// What direct reconstruction is asked to build.
struct DirectReconstructionProblem {
  /// Target signed curvature κ*(u), u = s / L ∈ [0, 1], in 1 / model units. For planar curves
  /// κ > 0 turns towards start.normal.
  Profile curvature;
  /// Target torsion τ*(u) (1 / model units) for a space curve; absent for a planar curve.
  std::optional<Profile> torsion{};
  /// Total length L > 0, model units (the initial guess when options.vary_length is set).
  double length = 1.0;
  /// Start point r(0), tangent T(0) and normal N(0) (planar: the plane and the turning side).
  intrinsic::StartFrame start{};
  /// Prescribed end point r(L), model units; absent: free.
  std::optional<Vec3> end_point{};
  /// Prescribed end tangent direction T(L) (any non-zero length, normalised); absent: free.
  std::optional<Vec3> end_tangent{};
  /// Space curves only: prescribed end normal N(L) (with end_tangent, the whole end frame: a G2 join's
  /// osculating plane); its component along T(L) is ignored. Absent: free.
  std::optional<Vec3> end_normal{};
  /// Prescribed curvature κ(0), signed as the target (a G2 start); absent: free.
  std::optional<double> start_curvature{};
  /// Prescribed curvature κ(L) (a G2 end); absent: free.
  std::optional<double> end_curvature{};
  /// Envelope e(u) of the curvature correction, δκ(u) = e(u) Σ_k c_k B_k(u) (file comment); the
  /// curvature profile itself makes the correction relative, so zeros of κ* stay zeros. Must share
  /// the curvature profile's law::Context. Absent: e ≡ 1 (an additive correction).
  std::optional<Profile> curvature_envelope{};
};

/// Options of reconstruct_direct().
struct DirectReconstructionOptions {
  /// Degree n of the Bernstein basis of each correction (n + 1 coefficients per corrected
  /// profile). Default 5; valid 1 … 20. Higher degrees allow a closer-to-target curve for hard
  /// constraints at the cost of wigglier corrections.
  int correction_degree = 5;
  /// Space curves: also correct the torsion (else only κ is corrected, which cannot always meet
  /// a 3-D end point and tangent). Default true. Ignored for planar curves.
  bool correct_torsion = true;
  /// Let the length vary too (one more unknown, penalised by length_weight·(ΔL / L)²).
  /// Default false.
  bool vary_length = false;
  /// Weight w of (ΔL / L)² against ‖L·δκ‖² in the minimum-norm objective. Default 1; valid
  /// (0, 1e6]. Larger values keep the length closer to the given one.
  double length_weight = 1.0;
  /// End tolerance: converged when |r(L) − p*| ≤ end_tolerance·L and the angle between T(L)
  /// and t* ≤ end_tolerance. Default 1e-9; valid [1e-13, 1e-2].
  double end_tolerance = 1e-9;
  /// Optimality tolerance: once the end holds, stop when a step changes the corrections by less
  /// than this times their norm, ‖Δ‖_M ≤ optimality_tolerance · ‖y‖_M (or ‖Δ‖_M ≤ end_tolerance),
  /// with ‖y‖²_M the objective of the file comment. The iteration converges linearly there (rate
  /// about 0.4 on the property-test Béziers), so the correction is then within a few times this
  /// relative distance of the minimum-norm one. Default 1e-6; valid [1e-12, 0.1].
  double optimality_tolerance = 1e-6;
  /// Largest number of Gauss–Newton iterations. Default 50; valid 1 … 10 000.
  int max_iterations = 50;
  /// Position tolerance of each reconstruction relative to L (absolute = this·L, clamped to
  /// [1e-13, 1e-2]). Default 1e-11: an order below end_tolerance so integration error does not
  /// mask the end residual. Valid [1e-13, 1e-3].
  double integration_tolerance = 1e-11;
  /// Largest number of integration step attempts per reconstruction (intrinsic::ReconstructionOptions::max_steps);
  /// front ends bound it with intrinsic::kFrontEndMaxSteps. Default 1 000 000; valid 1 … 100 000 000.
  std::size_t max_steps = 1'000'000;
  /// Samples N of the reported mean profile deviation (uniform in u, ends included). Default
  /// 200; valid 2 … 1 000 000.
  std::size_t deviation_samples = 200;
  /// Fit a NURBS to the final curve with intrinsic::fit_nurbs. Default true.
  bool fit = true;
  /// Options of the NURBS fit: by default tolerance 1e-6 relative to the curve's size (the diagonal
  /// of its bounding box), which with the greedy knot placement of intrinsic::fit_nurbs gives a
  /// few dozen control points for a simple planar curve; set fit_options.relative = false for an
  /// absolute tolerance.
  intrinsic::NurbsFitOptions fit_options{.tolerance = 1e-6, .relative = true};
  /// @throws hula::Error(Errc::InvalidOption) naming the field, its value and the valid range
  void validate() const;
};

/// Result of reconstruct_direct().
struct DirectReconstructionResult {
  /// The dense reconstructed curve (κ* + δκ, τ* + δτ integrated from the start frame).
  intrinsic::IntrinsicCurve curve;
  /// The NURBS fit (options.fit), its measured deviation from `curve` in NurbsFitResult.
  std::optional<intrinsic::NurbsFitResult> nurbs{};
  /// The curvature law of arc length "s" that was integrated (κ*(s/L) + δκ(s/L)).
  law::Law curvature_law{};
  /// The torsion law of "s" (the constant 0 for planar curves).
  law::Law torsion_law{};
  /// True for a planar reconstruction (no torsion profile).
  bool planar = true;
  /// Final length L (the given one unless options.vary_length).
  double length = 0.0;
  /// Bernstein coefficients of δκ (degree options.correction_degree); all zero without end constraints.
  std::vector<double> curvature_correction{};
  /// Bernstein coefficients of δτ; empty for planar curves or correct_torsion = false.
  std::vector<double> torsion_correction{};
  /// |r(L) − p*|, model units; 0 when no end point is prescribed.
  double end_point_error = 0.0;
  /// Angle between T(L) and t*, radians; 0 when no end tangent is prescribed.
  double end_tangent_error = 0.0;
  /// mean_i |κ(u_i) − κ*(u_i)| = mean |δκ| over options.deviation_samples uniform u_i.
  double mean_curvature_deviation = 0.0;
  /// max_i |κ(u_i) − κ*(u_i)|.
  double max_curvature_deviation = 0.0;
  /// mean_i |τ(u_i) − τ*(u_i)| (0 for planar curves).
  double mean_torsion_deviation = 0.0;
  /// max_i |τ(u_i) − τ*(u_i)|.
  double max_torsion_deviation = 0.0;
  /// Gauss–Newton iterations = linearisations, the last of which may only confirm convergence
  /// (0 without end constraints).
  int iterations = 0;
  /// Reconstructions performed (1 + trial steps).
  int reconstructions = 0;
  /// Wall time of reconstruct_direct(), seconds (NURBS fit included).
  double seconds = 0.0;
};

/// Reconstructs the curve of a prescribed curvature (and torsion) profile, as an initial-value
/// problem, or — with an end point and/or end tangent — as the boundary-value problem of the
/// file comment (the curve closest to the target that meets the end).
///
/// Example:
/// ```
/// law::Context ctx; law::ParseOptions po; po.parameters = {"u"};
/// DirectReconstructionProblem p{.curvature = Profile::from_law(law::parse("0.5 + 0.1*sin(6*u)", ctx, po)),
///                               .length = 4.0, .end_point = Vec3{2.5, 2.0, 0.0}};
/// DirectReconstructionResult r = reconstruct_direct(p);
/// // r.end_point_error <= 4e-9, r.mean_curvature_deviation: the price of the constraint
/// ```
/// @param problem target profile(s), length, start frame and the optional end constraints
/// @param options correction basis, tolerances, iteration budget, NURBS fit
/// @returns the curve, its NURBS, the corrections and the measured errors
/// @throws hula::Error(Errc::InvalidArgument) naming "length" if L ≤ 0; "end_point" if it is
///   farther than L from the start point (unreachable) or, for a planar curve, off the start
///   plane; "end_tangent" if it is zero or, planar, not in the start plane; "end_normal" for a
///   planar curve, without end_tangent, or parallel to it; "start_curvature" / "end_curvature"
///   where the envelope is zero but the value differs from the target's; "torsion" or
///   "curvature_envelope" if its profile belongs to another law::Context than the curvature's;
///   "start_frame.tangent" / "start_frame.normal" from intrinsic::reconstruct
/// @throws hula::Error(Errc::NonFiniteInput) naming "length", "end_point", "end_tangent", "end_normal",
///   "start_curvature" or "end_curvature" for NaN/inf
/// @throws hula::Error(Errc::InvalidOption) from options.validate(), or "correction_degree" when
///   the corrections have fewer unknowns than there are end conditions
/// @throws hula::Error(Errc::NumericalFailure) when the iteration does not meet the end within
///   max_iterations (the message gives the end errors reached), or a profile is undefined
/// Complexity: per iteration one reconstruction plus O(nodes × 8 × unknowns) for the Jacobian.
[[nodiscard]] DirectReconstructionResult reconstruct_direct(const DirectReconstructionProblem& problem,
                                                            const DirectReconstructionOptions& options = {});

}  // namespace hula::studies
