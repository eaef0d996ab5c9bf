// SPDX-License-Identifier: MIT
// Curves designed by their curvature: clothoid (Euler
// spiral) segments, whose curvature varies linearly with arc length, the
// Fresnel integrals behind them, and G1 Hermite interpolation by one clothoid
// (Bertolazzi & Frego, "G1 fitting with clothoids", Math. Meth. Appl. Sci.
// 2015, the reference algorithm: the three G1 equations reduced to one
// equation in one unknown, solved from their guess A = 3(φ0 + φ1) by Newton-type iteration),
// and G2 Hermite interpolation by three clothoids (Bertolazzi & Frego, "On the
// G2 Hermite interpolation problem with clothoids", J. Comput. Appl. Math. 341
// (2018) 99–116: outer arcs of fixed length, the reduced 2×2 system in the
// middle arc's length and mid angle solved by Newton from the G1 solution).
//
// Notation: a segment starts at (x0, y0) with tangent angle θ0 and curvature
// κ0, its curvature changes at the rate κ′ = dκ/ds, and it is L long:
//     θ(s) = θ0 + κ0 s + κ′ s² / 2,   (x, y)(s) = (x0, y0) + ∫₀ˢ (cos θ, sin θ) dt.
// The Fresnel integrals are C(x) = ∫₀ˣ cos(π t²/2) dt, S(x) = ∫₀ˣ sin(π t²/2) dt
// (the normalisation of Abramowitz & Stegun 7.3.1–2).
#pragma once

#include <array>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/curve/curve.hpp"
#include "hula/intrinsic/natural_equations.hpp"
#include "hula/law/expr.hpp"

namespace hula::intrinsic {

/// Values of the Fresnel integrals at one abscissa.
struct FresnelValues {
  /// C(x) = ∫₀ˣ cos(π t²/2) dt.
  double c = 0.0;
  /// S(x) = ∫₀ˣ sin(π t²/2) dt.
  double s = 0.0;
};

/// The Fresnel integrals C(x) and S(x), absolute error below 1e-14 for every finite x.
///
/// Method: for |x| ≤ 6 composite 10-point Gauss–Legendre quadrature on panels over which the
/// phase π t²/2 changes by at most 2 rad (the rule is then exact to rounding); beyond, the
/// asymptotic expansions C = 1/2 + f sin(πx²/2) − g cos(πx²/2), S = 1/2 − f cos(πx²/2) − g sin(πx²/2)
/// with f ~ (1/πx) Σ (−1)^m (4m−1)!!/(πx²)^{2m}, g ~ (1/π²x³) Σ (−1)^m (4m+1)!!/(πx²)^{2m}, summed
/// while the terms decrease (at x = 6 the smallest term is below 1e-19). Odd: C(−x) = −C(x).
/// @param x any finite abscissa
/// @returns C(x), S(x); C(±∞) = S(±∞) = ±1/2
/// @throws hula::Error(Errc::NonFiniteInput) naming "x" for NaN
[[nodiscard]] FresnelValues fresnel(double x);

/// A clothoid segment in the xy-plane (see the file comment for the notation).
struct ClothoidSegment {
  /// Start point (z ignored), model units.
  Vec3 start{};
  /// Tangent angle θ0 at the start, radians from +x, counter-clockwise.
  double theta0 = 0.0;
  /// Signed curvature κ0 at the start (> 0 turns left), 1 / model units.
  double kappa0 = 0.0;
  /// Curvature rate κ′ = dκ/ds, 1 / model units².
  double dkappa = 0.0;
  /// Length L ≥ 0, model units.
  double length = 0.0;

  /// θ(s) = θ0 + κ0 s + κ′ s²/2.
  [[nodiscard]] double angle(double s) const noexcept { return theta0 + s * (kappa0 + 0.5 * dkappa * s); }
  /// κ(s) = κ0 + κ′ s.
  [[nodiscard]] double curvature(double s) const noexcept { return kappa0 + dkappa * s; }
  /// The point at arc length s (any finite s, also outside [0, L]), z = start.z, to within
  /// about 1e-15 of the segment's size: composite Gauss–Legendre quadrature of (cos θ, sin θ)
  /// on panels over which θ turns by at most 4 rad.
  [[nodiscard]] Vec3 point(double s) const;
  /// The curvature κ(s) = κ0 + κ′ s as a law of `parameter` in `context`, for the law engine and
  /// the natural-equation solver.
  [[nodiscard]] law::Law curvature_law(const law::Context& context, std::string_view parameter = "s") const;
  /// The segment as an intrinsic curve (reconstruct_planar of curvature_law: the exact-angle
  /// integrator), to sample frames or fit a NURBS with fit_nurbs().
  /// @throws as reconstruct_planar (e.g. L ≤ 0)
  [[nodiscard]] IntrinsicCurve to_intrinsic(const ReconstructionOptions& options = {}) const;
};

/// Options of fit_clothoid_g1().
struct ClothoidG1Options {
  /// The iteration stops when the cube of the last step in A (the order of the error Halley's method
  /// leaves) is below this times max(1, |A|). Default 1e-14; valid [1e-16, 1e-6].
  double tolerance = 1e-14;
  /// Largest number of iterations. Default 20; valid 1 … 1000.
  int max_iterations = 20;
  /// @throws hula::Error(Errc::InvalidOption) naming the field, its value and the valid range
  void validate() const;
};

/// Result of fit_clothoid_g1().
struct ClothoidG1Result {
  /// The clothoid from (p0, θ0) to (p1, θ1).
  ClothoidSegment segment{};
  /// Iterations (evaluations of the integrals) used.
  int iterations = 0;
};

/// G1 Hermite interpolation by one clothoid (Bertolazzi–Frego): the clothoid from p0 with tangent
/// angle θ0 to p1 with tangent angle θ1 whose tangent turns by less than 2π — the solution they
/// prove unique.
///
/// Method (their section 3): with r = |p1 − p0|, φ the direction of p1 − p0, φ0 = θ0 − φ and
/// φ1 = θ1 − φ reduced to (−π, π] and δ = φ1 − φ0, the angle on τ = s/L ∈ [0, 1] is
/// φ0 + (δ − A) τ + A τ², and the end point condition reduces to
///     g(A) = ∫₀¹ sin(A τ² + (δ − A) τ + φ0) dτ = 0,
/// solved from their guess A = 3(φ0 + φ1) by Halley's method (g′(A) = ∫₀¹ (τ² − τ) cos(…) dτ,
/// g″(A) = −∫₀¹ (τ² − τ)² sin(…) dτ; the Newton step where Halley's correction is large), stopping
/// once the last step cubed is below the tolerance; then L = r / ∫₀¹ cos(…) dτ (its value at the
/// final A by a second-order Taylor step from the last evaluation), κ0 = (δ − A) / L, κ′ = 2A / L².
/// The integrals are 10-point Gauss–Legendre sums (on panels of at most 4 rad of turning), exact to
/// rounding; each iteration evaluates them once, with the derivatives from the same cosines and sines.
///
/// Example:
/// ```
/// ClothoidG1Result r = fit_clothoid_g1({0, 0, 0}, 0.0, {1, 1, 0}, std::numbers::pi / 2);
/// // r.segment: the quarter circle, kappa0 = 1, dkappa = 0, length = π/2
/// ```
/// @param p0 start point (z ignored); @param theta0 start tangent angle, radians
/// @param p1 end point (z ignored); @param theta1 end tangent angle, radians (any multiple of 2π
///   away from the intended one: only the direction counts)
/// @param options iteration tolerance and budget
/// @returns the segment (start = p0, theta0 as given) and the iteration count
/// @throws hula::Error(Errc::NonFiniteInput) naming "p0", "p1", "theta0" or "theta1"
/// @throws hula::Error(Errc::CoincidentPoints) naming "p1" when p1 = p0 (no direction)
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
/// @throws hula::Error(Errc::NumericalFailure) if the iteration does not converge (never seen on the
///   seeded property sweep over all φ0, φ1 in (−π, π])
/// Complexity: O(iterations × panels × 10) sine/cosine pairs; typically 2–3 iterations, 1 panel.
[[nodiscard]] ClothoidG1Result fit_clothoid_g1(const Vec3& p0, double theta0, const Vec3& p1, double theta1,
                                               const ClothoidG1Options& options = {});

/// Options of fit_clothoid_g2().
struct ClothoidG2Options {
  /// Newton stops when the end-point residual, relative to the chord |p1 − p0|, is at most this:
  /// |end of the third arc − p1| ≤ tolerance · |p1 − p0|. Default 1e-13; valid [1e-15, 1e-6].
  double tolerance = 1e-13;
  /// Largest number of Newton iterations (each with its own line search). Default 50; valid 1 … 1000.
  int max_iterations = 50;
  /// @throws hula::Error(Errc::InvalidOption) naming the field, its value and the valid range
  void validate() const;
};

/// Result of fit_clothoid_g2(): three clothoid arcs joined with G2 continuity.
struct ClothoidG2Result {
  /// The arcs in order: segments[0] starts at p0 with (θ0, κ0), segments[2] ends at p1 with (θ1, κ1);
  /// each starts where the one before ends, with its angle and curvature.
  std::array<ClothoidSegment, 3> segments{};
  /// Newton iterations used (summed over the restarts with shorter outer arcs, if any).
  int iterations = 0;
  /// Total length, the sum of the three arcs' lengths.
  [[nodiscard]] double length() const noexcept { return segments[0].length + segments[1].length + segments[2].length; }
};

/// G2 Hermite interpolation by three clothoids (Bertolazzi–Frego 2018): from p0 with tangent angle θ0
/// and curvature κ0 to p1 with θ1 and κ1, a G2 spline of three clothoid arcs (position, tangent angle
/// and curvature continuous at the two joins).
///
/// Method. In the frame where p0 = (0, 0), p1 = (1, 0) (lengths divided by r = |p1 − p0|, curvatures
/// multiplied by it, angles φ0, φ1 relative to the chord as in fit_clothoid_g1()), the outer arcs get
/// fixed lengths s0, s1 and the middle arc, of length sM, is written about its midpoint,
/// θ(t) = θM + KM t + aM t²/2 for t ∈ [−sM/2, sM/2]. The outer arcs are then determined by their end
/// data and the middle arc's: arc 0 runs from (φ0, K0) to the middle arc's start curvature KA, so its
/// angle gain is s0 (K0 + KA)/2, and arc 1 likewise ends at (φ1, K1). Given (sM, θM) the two angle
/// conditions are linear in (KM, aM) (a 2×2 system, solved in closed form), and the remaining
/// unknowns solve the end-point condition
///     F(sM, θM) = ∫arc 0 + ∫middle + ∫arc 1 of (cos θ, sin θ) ds − (1, 0) = 0,
/// by Newton with the exact Jacobian (moments ∫ tᵏ (cos θ, sin θ), k ≤ 2, by the same Gauss–Legendre
/// panels as fit_clothoid_g1()) and a backtracking line search on |F| that keeps sM > 0. The start is
/// the G1 clothoid through (p0, θ0), (p1, θ1) (length L, curvature κG(s)): sM = L − s0 − s1 and θM its
/// angle at the middle of the middle arc. Outer lengths (our heuristic, after their idea of keeping the
/// outer arcs close to the G1 guess): s_i = min(L/3, 2 d / |K_i − κG(end i)|) with d = π/8, so that an
/// outer arc turns at most about d away from the G1 clothoid; when Newton fails, s0 and s1 are halved
/// (up to 6 times). Data that lie on one clothoid (or one circle) give back that clothoid, split into
/// thirds: the start is then already the solution.
///
/// Example:
/// ```
/// ClothoidG2Result r = fit_clothoid_g2({0, 0, 0}, 0.0, 1.0, {1, 1, 0}, std::numbers::pi / 2, 1.0);
/// // the quarter circle of radius 1 in three arcs of length π/6, κ = 1 and κ′ = 0 on each
/// ```
/// @param p0 start point (z ignored, copied to the segments); @param theta0 start tangent angle,
///   radians; @param kappa0 start curvature (> 0 turns left), 1 / model units
/// @param p1 end point (z ignored); @param theta1 end tangent angle (only its direction counts, as in
///   fit_clothoid_g1()); @param kappa1 end curvature
/// @param options Newton tolerance and budget
/// @returns the three arcs (segments[0] starts with theta0 and kappa0 as given) and the iterations
/// @throws hula::Error(Errc::NonFiniteInput) naming "p0", "p1", "theta0", "theta1", "kappa0" or "kappa1"
/// @throws hula::Error(Errc::CoincidentPoints) naming "p1" when p1 = p0 (no chord, no G1 start)
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
/// @throws hula::Error(Errc::NumericalFailure) naming the end curvature ("kappa0" or "kappa1") that is
///   furthest from the G1 clothoid's when Newton fails after every restart (none seen on the seeded
///   sweep over |φ0|, |φ1| < π and |κ0|·r, |κ1|·r ≤ 10 of the tests)
/// Complexity: O(iterations × 3 arcs × panels × 10) sine/cosine pairs, plus one fit_clothoid_g1().
[[nodiscard]] ClothoidG2Result fit_clothoid_g2(const Vec3& p0, double theta0, double kappa0, const Vec3& p1,
                                               double theta1, double kappa1, const ClothoidG2Options& options = {});

/// Options of fit_clothoid_spline().
struct ClothoidSplineOptions {
  /// Continuity at the interior points: 1 (G1: tangent angles from the three-point circles, one G1 clothoid
  /// per interval), 2 (G2: angles solved so that the curvature is continuous too). Default 2; valid 1 or 2.
  int continuity = 2;
  /// A closed spline: one more segment from the last point back to the first, with the same continuity
  /// there. A last point equal to the first is dropped (the list may be given closed).
  bool closed = false;
  /// Tangent angles at the first and last point (radians from +x), open splines only, each optional.
  /// A free end angle: G1 takes it from the circle through the three end points (two points: the circular
  /// arc through them with the other angle), G2 solves for it with the end's curvature condition below.
  std::optional<double> start_angle{}, end_angle{};
  /// Curvatures at the first and last point (1 / model units, > 0 turns left), open G2 splines only, each
  /// optional, at an end without a given angle: the condition there is κ = this value. An end with neither an
  /// angle nor a curvature has a circular end segment (κ′ = 0 on it). Two points with both angles and both
  /// curvatures are the G2 Hermite problem: fit_clothoid_g2()'s three arcs.
  std::optional<double> start_curvature{}, end_curvature{};
  /// G2 Newton stops when every joint's curvature jump times the mean chord, and every end condition
  /// (angle in radians, or end-segment curvature change times the mean chord), is at most this.
  /// Default 1e-12; valid [1e-15, 1e-6].
  double tolerance = 1e-12;
  /// Largest number of G2 Newton iterations (each with its own line search). Default 100; valid 1 … 1000.
  int max_iterations = 100;
  /// @throws hula::Error(Errc::InvalidOption) naming the field, its value and the valid range
  void validate() const;
};

/// Result of fit_clothoid_spline() and fit_biarc_spline(): the segments in order, each starting where the
/// one before ends with its tangent angle (unwrapped: a segment's theta0 is the previous one's end angle).
struct ClothoidSplineResult {
  std::vector<ClothoidSegment> segments;
  /// G2 Newton iterations (0 for G1 and biarcs).
  int iterations = 0;
  /// Total length.
  [[nodiscard]] double length() const noexcept;
};

/// A clothoid spline through N planar points (the Clothoids library's ClothoidList / ClothoidSplineG2
/// problems, Bertolazzi–Frego, "Interpolating clothoid splines with curvature continuity", Math. Meth. Appl.
/// Sci. 41 (2018)): one clothoid per interval, G1 Hermite (fit_clothoid_g1) between consecutive points with
/// tangent angles θ_i at the points.
///
/// Method. The start angles are the tangents of the circles through each point and its two neighbours
/// (at an open end, the circle through the three end points; two points give the chord). G1 stops there.
/// G2 solves for the angles θ_i the equations "curvature at the end of segment i−1 = curvature at the start
/// of segment i" at every interior point (at every point when closed), plus at an open end the given angle, the
/// given curvature, or κ′ = 0 on the end segment, by Newton with a backtracking line search on the sum of the
/// squared scaled residuals. The Jacobian is tridiagonal (cyclic when closed: two corner entries, by the Woodbury
/// formula on the banded solve); its entries are the exact derivatives of a G1 clothoid's end curvatures with respect
/// to its end angles (implicit function theorem on the G1 equation, moments ∫ τᵏ (cos φ, sin φ)). Points on one circle
/// give that circle (every segment κ′ = 0, κ = 1/R) when the ends are free.
/// @param points ≥ 2 points (≥ 3 distinct when closed), z ignored (copied from the first point)
/// @param options continuity, closure, end angles, Newton tolerance and budget
/// @throws hula::Error(Errc::TooFewPoints) naming "points" for too few; hula::Error(Errc::InvalidArgument)
///   naming "start_angle", "end_angle", "start_curvature" or "end_curvature" given with a closed spline, a
///   curvature given with a G1 spline or with the angle at the same end (but for the two-point Hermite case);
///   hula::Error(Errc::NonFiniteInput) naming
///   "points" (with the index) or the angle; hula::Error(Errc::CoincidentPoints) naming "points" and the index of a
///   point equal to the one before; hula::Error(Errc::InvalidOption) from options.validate();
///   hula::Error(Errc::NumericalFailure) naming "points" when the G2 Newton fails (the residual left): none on
///   the tests' seeded walks and loops, but data that zigzag at the scale of their spacing (a 1024-point loop
///   with radial noise 50 times the spacing) can stall it
/// Complexity: G1 O(N) fits; G2 O(iterations × N) fits plus a banded solve.
[[nodiscard]] ClothoidSplineResult fit_clothoid_spline(std::span<const Vec3> points,
                                                       const ClothoidSplineOptions& options = {});

/// The biarc from p0 with tangent angle θ0 to p1 with θ1: two circular arcs (clothoid segments with
/// κ′ = 0) joined with G1 continuity. Of the one-parameter family, the equal-chord biarc: in the frame of the
/// chord (length d, angles φ0, φ1 relative to it in (−π, π]) the joint J lies on the chord's perpendicular
/// bisector, the joint tangent angle is ω = −(φ0 + φ1)/2, both arcs have chord a = d / (2 cos((φ1 − φ0)/4))
/// (never singular: |φ1 − φ0| < 2π), arc i turns by Δ_i (Δ0 = ω − φ0, Δ1 = φ1 − ω), has curvature
/// 2 sin(Δ_i/2) / a and length a Δ_i / (2 sin(Δ_i/2)) (a for Δ_i = 0). Data on one circle (φ1 = −φ0) give
/// that circle's arc in two halves; φ0 = φ1 = 0 gives the straight chord.
/// @throws hula::Error(Errc::NonFiniteInput) naming "p0", "p1", "theta0" or "theta1";
///   hula::Error(Errc::CoincidentPoints) naming "p1" when p1 = p0
[[nodiscard]] std::array<ClothoidSegment, 2> fit_biarc(const Vec3& p0, double theta0, const Vec3& p1, double theta1);

/// A G1 spline of biarcs through N points (Bertolazzi, Frego, Biral, "Interpolating splines of biarcs from
/// a sequence of planar points", CAD&A 2020, the problem; here with the three-point-circle tangent angles of
/// fit_clothoid_spline()'s G1 start and one fit_biarc() per interval). `options.continuity` is ignored;
/// `closed`, `start_angle` and `end_angle` are as for fit_clothoid_spline().
/// @throws as fit_clothoid_spline() for the points and the angles
[[nodiscard]] ClothoidSplineResult fit_biarc_spline(std::span<const Vec3> points,
                                                    const ClothoidSplineOptions& options = {});

/// Consecutive clothoid segments (one G1 segment, or the three arcs of a G2 spline) as natural-equation data:
/// κ(s) = κ0,i + κ′i (s − s_i) on the i-th arc as one piecewise law (printed exactly), τ = 0, the start frame
/// T = (cos θ0, sin θ0, 0), N = (−sin θ0, cos θ0, 0) at the first segment's start, the total length. The
/// exact curve value (intrinsic::natural_curve) evaluates θ(s) in closed form and the position by quadrature
/// of (cos θ, sin θ), the Fresnel integrals of each arc, to `tolerance`.
/// @param segments ≥ 1 segments, each starting where the one before ends (not checked: the data describe
///   the curvature and the start only)
/// @param tolerance position tolerance of the integration, model units (NaturalData::tolerance)
/// @throws hula::Error(Errc::InvalidArgument) naming "segments" when empty or when the total length is not
///   positive; hula::Error(Errc::NonFiniteInput) naming "segments" for a non-finite value
[[nodiscard]] curve::NaturalData clothoid_natural_data(std::span<const ClothoidSegment> segments,
                                                       double tolerance = curve::kNaturalTolerance);

}  // namespace hula::intrinsic
