// SPDX-License-Identifier: MIT
// Curves designed by their curvature (issue 14 item 6): clothoid (Euler
// spiral) segments, whose curvature varies linearly with arc length, the
// Fresnel integrals behind them, and G1 Hermite interpolation by one clothoid
// (Bertolazzi & Frego, "G1 fitting with clothoids", Math. Meth. Appl. Sci.
// 2015, the reference algorithm: the three G1 equations reduced to one
// equation in one unknown, solved by Newton from their guess A = 3(φ0 + φ1)).
//
// Notation: a segment starts at (x0, y0) with tangent angle θ0 and curvature
// κ0, its curvature changes at the rate κ′ = dκ/ds, and it is L long:
//     θ(s) = θ0 + κ0 s + κ′ s² / 2,   (x, y)(s) = (x0, y0) + ∫₀ˢ (cos θ, sin θ) dt.
// The Fresnel integrals are C(x) = ∫₀ˣ cos(π t²/2) dt, S(x) = ∫₀ˣ sin(π t²/2) dt
// (the normalisation of Abramowitz & Stegun 7.3.1–2).
#pragma once

#include <string_view>

#include "hula/core/vec.hpp"
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
  /// Newton stops when the step in A is below this times max(1, |A|). Default 1e-14; valid
  /// [1e-16, 1e-6].
  double tolerance = 1e-14;
  /// Largest number of Newton iterations. Default 20; valid 1 … 1000.
  int max_iterations = 20;
  /// @throws hula::Error(Errc::InvalidOption) naming the field, its value and the valid range
  void validate() const;
};

/// Result of fit_clothoid_g1().
struct ClothoidG1Result {
  /// The clothoid from (p0, θ0) to (p1, θ1).
  ClothoidSegment segment{};
  /// Newton iterations used.
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
/// solved by Newton from A = 3(φ0 + φ1) with g′(A) = ∫₀¹ (τ² − τ) cos(…) dτ; then
/// L = r / ∫₀¹ cos(…) dτ, κ0 = (δ − A) / L, κ′ = 2A / L². The integrals are 10-point
/// Gauss–Legendre sums (on panels of at most 4 rad of turning), exact to rounding.
///
/// Example:
/// ```
/// ClothoidG1Result r = fit_clothoid_g1({0, 0, 0}, 0.0, {1, 1, 0}, std::numbers::pi / 2);
/// // r.segment: the quarter circle, kappa0 = 1, dkappa = 0, length = π/2
/// ```
/// @param p0 start point (z ignored); @param theta0 start tangent angle, radians
/// @param p1 end point (z ignored); @param theta1 end tangent angle, radians (any multiple of 2π
///   away from the intended one: only the direction counts)
/// @param options Newton tolerance and budget
/// @returns the segment (start = p0, theta0 as given) and the iteration count
/// @throws hula::Error(Errc::NonFiniteInput) naming "p0", "p1", "theta0" or "theta1"
/// @throws hula::Error(Errc::CoincidentPoints) naming "p1" when p1 = p0 (no direction)
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
/// @throws hula::Error(Errc::NumericalFailure) if Newton does not converge (never seen on the
///   seeded property sweep over all φ0, φ1 in (−π, π])
/// Complexity: O(iterations × panels × 10) sine/cosine pairs; typically 2–4 iterations, 1 panel.
[[nodiscard]] ClothoidG1Result fit_clothoid_g1(const Vec3& p0, double theta0, const Vec3& p1, double theta1,
                                               const ClothoidG1Options& options = {});

}  // namespace hula::intrinsic
