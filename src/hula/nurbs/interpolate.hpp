// SPDX-License-Identifier: MIT
// Curves through data points (thesis 5.3, 7.1.2, 7.5, 10.2.1, 10.2.5):
// parameterisation (uniform, chord length eq. 29, centripetal, Foley), the global C2
// cubic spline with natural / clamped / Bessel / not-a-knot / Open CASCADE
// end conditions in O(N), Lagrange interpolation, and piecewise Hermite
// (cubic with tangents, quintic with tangents and second derivatives).
//
// Every interpolant is parameterised on [0, 1] (the thesis's
// reparameterisation), with its breakpoints at the data parameters.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "hula/core/tolerance.hpp"
#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::nurbs {

/// How data parameters are derived from the points.
enum class Parameterisation {
  Uniform,      ///< t_i = i / (N - 1)
  ChordLength,  ///< t_i proportional to the cumulative chord length (thesis eq. 29)
  Centripetal,  ///< t_i proportional to the cumulative square root of chord lengths (Lee 1989)
  Foley,        ///< chord lengths enlarged by the turning angles at their ends (Foley & Nielson 1989)
};

/// End condition of the global cubic spline at one end.
struct EndCondition {
  enum class Kind {
    Natural,   ///< C''(end) = 0
    Clamped,   ///< C'(end) = derivative, magnitude honoured (dC/dt with t ∈ [0, 1])
    Bessel,    ///< C'(end) from the quadratic through the 3 end points at their parameters
    NotAKnot,  ///< C''' continuous at the second (last but one) data parameter
    Occt,      ///< C'(end) from the cubic through the 4 end points (Open CASCADE GeomAPI_Interpolate)
    /// C'(end) along `derivative` (a direction: only its sense counts) with the magnitude the
    /// Bessel end would have, |B| for B = the derivative of the quadratic through the 3 end points
    /// at their parameters (thesis 10.2.1's "tangent direction" end; the study files' use). When
    /// B vanishes (the end points fold back on themselves) the magnitude is the end chord's
    /// speed |Q1 − Q0| / (t1 − t0) (|Q_{N−1} − Q_{N−2}| / (t_{N−1} − t_{N−2}) at the end).
    Direction,
  };
  // Small N (documented fallbacks, never an error): Bessel uses the Lagrange
  // polynomial of degree min(2, N - 1) through the end points and Occt of
  // degree min(3, N - 1), so with N = 2 both give the chord (the straight
  // segment C(t) = Q0 + t (Q1 - Q0)) and Occt with N = 3 gives the parabola —
  // exactly the degree-1 and degree-2 curves GeomAPI_Interpolate returns
  // without tangents. NotAKnot with N = 2 (no interior knot) falls back to
  // Bessel; with N = 3 at both ends (one interior knot for two conditions)
  // both ends fall back to Bessel, which gives the parabola.
  Kind kind = Kind::Natural;
  /// dC/dt at the end for Kind::Clamped; the direction (any non-zero length) for Kind::Direction;
  /// ignored otherwise.
  Vec3 derivative{};

  [[nodiscard]] static EndCondition natural() { return {Kind::Natural, {}}; }
  [[nodiscard]] static EndCondition clamped(const Vec3& d) { return {Kind::Clamped, d}; }
  [[nodiscard]] static EndCondition bessel() { return {Kind::Bessel, {}}; }
  [[nodiscard]] static EndCondition not_a_knot() { return {Kind::NotAKnot, {}}; }
  [[nodiscard]] static EndCondition occt() { return {Kind::Occt, {}}; }
  [[nodiscard]] static EndCondition direction(const Vec3& d) { return {Kind::Direction, d}; }
};

/// Options of interpolate_cubic.
struct InterpolationOptions {
  /// Parameter rule when `parameters` is empty. Default ChordLength.
  Parameterisation parameterisation = Parameterisation::ChordLength;
  /// Given data parameters (one per point, strictly increasing, finite). They
  /// are mapped affinely to [0, 1]. This is also the thesis's "interpolate
  /// knots" (10.2.1): the knots at the data points. Empty: use `parameterisation`.
  std::vector<double> parameters{};
  /// Start and end conditions. Default natural at both ends.
  EndCondition start = EndCondition::natural();
  EndCondition end = EndCondition::natural();
  /// 2 to produce a planar curve (points must have z = 0), else 3. Default 3.
  int dimension = 3;
  /// Coincident-point test for chord/centripetal parameters (scaled to the
  /// model size, see resolution_for_size).
  Tolerance tolerance{};

  /// Checks the options before any work.
  /// @throws hula::Error(Errc::InvalidOption) naming the bad field
  /// (non-finite clamped derivative, e.g. "start.derivative[1] = nan"; a clamped
  /// derivative with z ≠ 0 when dimension = 2; a zero direction; dimension not 2/3;
  /// an unknown enum value; bad tolerance).
  void validate() const;
};

/// Cumulative chord lengths L_0 = 0, L_i = Σ_{j<i} |P_{j+1} - P_j| (overflow-safe).
/// The thesis's example (0,0,0), (40,25,0), (80,-25,0), (120,0,0) gives 0, 47.17, 111.20, 158.37.
/// @param points any number of points (none gives an empty result)
/// @returns one length per point, in model units
/// @throws hula::Error(Errc::NonFiniteInput) naming the point and coordinate
[[nodiscard]] std::vector<double> cumulative_chord_lengths(std::span<const Vec3> points);

/// Data parameters in [0, 1] (first 0, last 1, strictly increasing).
/// @param points N ≥ 2 finite points
/// @param rule Uniform (i / (N - 1)), ChordLength (eq. 29), Centripetal or Foley
/// @param tolerance consecutive points whose distance is ≤
///   resolution_for_size(tolerance, diagonal of the points' box) coincide
/// @returns N parameters
/// @throws hula::Error(Errc::TooFewPoints) if fewer than 2 points
/// @throws hula::Error(Errc::NonFiniteInput) naming the point and coordinate
/// @throws hula::Error(Errc::CoincidentPoints) naming the index pair when consecutive
///   points coincide under ChordLength, Centripetal or Foley
[[nodiscard]] std::vector<double> parameterise(std::span<const Vec3> points, Parameterisation rule,
                                               const Tolerance& tolerance = {});

/// Global C2 cubic spline through N ≥ 2 points, O(N) (banded solve).
/// N = 2 gives the straight segment (or the cubic meeting clamped ends); N = 3
/// with not-a-knot gives the parabola. The result is a clamped cubic NURBS on
/// [0, 1] with simple interior knots at the data parameters.
/// Method: knots {0,0,0,0, t_1 … t_{N-2}, 1,1,1,1}, N + 2 control points,
/// P_1 … P_N from one banded system (start row, C(t_i) = Q_i rows, end row);
/// not-a-knot is imposed as a C''' jump row, so t_1 and t_{N-2} stay knots.
/// The Occt end reproduces GeomAPI_Interpolate without tangents (see EndCondition).
/// @param points N ≥ 2 data points
/// @param options parameters or rule, end conditions, dimension, tolerance
/// @returns the interpolant, C(t_i) = Q_i
/// @throws hula::Error(Errc::NumericalFailure) if the system is singular to working precision
/// @throws hula::Error(Errc::TooFewPoints) if N < 2
/// @throws hula::Error(Errc::NonFiniteInput) naming the point, parameter or end derivative
/// @throws hula::Error(Errc::CoincidentPoints) as parameterise
/// @throws hula::Error(Errc::InvalidArgument) if given parameters are not strictly
///   increasing (names the index) or their count differs from the points'
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
[[nodiscard]] NurbsCurve interpolate_cubic(std::span<const Vec3> points, const InterpolationOptions& options = {});

/// Piecewise septic Hermite: C3 through points with given first, second and third derivatives (dC/dt, d²C/dt²,
/// d³C/dt³, t ∈ [0, 1]). Each segment is the degree-7 Bézier curve of its end data
/// (ΔB0 = h D/7, Δ²B0 = h² S/42, Δ³B0 = h³ W/210 at the start, mirrored at the end); the segments are joined and
/// the knots reduced to multiplicity 4 (C3) exactly.
/// @param points, derivatives, second_derivatives, third_derivatives N ≥ 2 each
/// @param parameters as hermite_cubic; @param dimension 2 or 3
/// @throws as hermite_quintic, naming "third_derivatives" for the third array
[[nodiscard]] NurbsCurve hermite_septic(std::span<const Vec3> points, std::span<const Vec3> derivatives,
                                        std::span<const Vec3> second_derivatives,
                                        std::span<const Vec3> third_derivatives,
                                        std::span<const double> parameters = {}, int dimension = 3);

/// A Hermite handle given by its Frenet data (thesis 7.5 and its further work: "higher degree differential
/// constraints input like normal and bi-normal"): the point, the tangent with its speed, the curvature vector κN
/// and the torsion τ (the turning of the binormal B = T × N).
struct FrenetHandle {
  Vec3 point{};    ///< model units
  Vec3 tangent{};  ///< dC/dt, t ∈ [0, 1]: non-zero (direction and speed)
  /// Principal normal direction (its tangential part is removed); zero for no curvature at the handle (κ = 0).
  Vec3 normal{};
  double curvature = 0.0;  ///< κ ≥ 0, 1/model units, along `normal`
  double torsion = 0.0;    ///< τ, 1/model units (used where κ > 0)
};

/// The C3 septic Hermite curve through handles that fixes, at every handle, the point, the tangent (and speed),
/// the curvature κ with its normal N, and the torsion τ (so the binormal B = T × N): with v = |C'|, the data
/// C'' = v² κ N and C''' = v³ (−κ² T + κ τ B) (arc-length speed held: v' = v'' = 0; κ' = 0 at the handle) give
/// κ, N and τ of the curve there exactly.
/// @param handles N ≥ 2
/// @param parameters as hermite_cubic (chord length by default); @param dimension 2 (normals in z = 0, τ = 0) or 3
/// @throws hula::Error(Errc::InvalidArgument) naming "tangent" (zero), "normal" (parallel to the tangent with
///   κ > 0) or "curvature" (negative) with the handle's index; NonFiniteInput naming the field
/// Example: handles sampled from a circular helix (its T, N, κ, τ) give a curve with the helix's κ and τ at them.
[[nodiscard]] NurbsCurve hermite_frenet(std::span<const FrenetHandle> handles, std::span<const double> parameters = {},
                                        int dimension = 3);

/// Closed (periodic) C2 cubic spline through N ≥ 3 points: the curve runs through the points in order and back
/// to the first, C2 everywhere including the closure, on [0, 1] in clamped form (its ends equal, first and second
/// derivatives equal at both ends), with simple interior knots at the data parameters t_1 … t_{N−1}.
/// Parameters: `options.parameters` (N + 1 values, the last one the closure's, strictly increasing) or
/// options.parameterisation over the N + 1 points with the first repeated at the end. A last point equal to the
/// first (within the coincidence tolerance) is dropped, so a closed point list gives the same curve.
/// Method: the derivatives D_i of the C2 cubic Hermite spline from the cyclic tridiagonal system
///   h_i D_{i−1} + 2 (h_{i−1} + h_i) D_i + h_{i−1} D_{i+1} = 3 (h_i Δ_{i−1} / h_{i−1} + h_{i−1} Δ_i / h_i),
/// indices mod N, h_i = t_{i+1} − t_i, Δ_i = Q_{i+1} − Q_i (diagonally dominant; Sherman–Morrison on the Thomas
/// algorithm, O(N)), then hermite_cubic and removal of the redundant second copy of each knot (A5.8).
/// The start and end conditions of `options` are not used.
/// @throws hula::Error(Errc::TooFewPoints) if fewer than 3 distinct points
/// @throws as interpolate_cubic (InvalidArgument naming "parameters" for a count other than N + 1)
/// Example: the square (1, 0), (0, 1), (−1, 0), (0, −1) at uniform parameters gives D_i = 6 × (Q_i turned by 90°)
///   and C(1/8) = (11/16, 11/16).
[[nodiscard]] NurbsCurve interpolate_closed_cubic(std::span<const Vec3> points,
                                                  const InterpolationOptions& options = {});

/// Lagrange interpolation (thesis 5.3.1): the polynomial of degree N - 1 through
/// N ≥ 2 points, as a Bézier curve on [0, 1]. `parameters` as in
/// InterpolationOptions (empty: uniform, the thesis's evenly spaced values).
/// Ill-conditioned for large N (thesis 5.3.1); accepted up to kMaxDegree + 1 points.
/// Control points by solving the Bernstein collocation system (dense, partial pivoting).
/// @param points N finite points (z = 0 when dimension = 2)
/// @param parameters empty or N strictly increasing finite values
/// @param dimension 2 or 3 (else InvalidArgument)
/// @returns a Bézier curve of degree N - 1 with C(t_i) = Q_i
/// @throws as interpolate_cubic, and hula::Error(Errc::TooFewPoints / InvalidDegree)
[[nodiscard]] NurbsCurve interpolate_lagrange(std::span<const Vec3> points, std::span<const double> parameters = {},
                                              int dimension = 3);

/// Piecewise cubic Hermite (thesis 5.3.2, 7.5.2): C1 through points with the
/// given first derivatives dC/dt (t ∈ [0, 1]); double interior knots.
/// `parameters` empty: chord length.
/// Segment i has Bézier points Q_i, Q_i + h/3 D_i, Q_{i+1} - h/3 D_{i+1}, Q_{i+1}
/// (h = t_{i+1} - t_i); the B-spline keeps the inner ones as control points.
/// @param points N ≥ 2 points; @param derivatives N vectors dC/dt
/// @param parameters empty or N strictly increasing values (mapped to [0, 1];
///   the derivatives are with respect to the mapped t)
/// @param dimension 2 or 3
/// @returns a cubic with knots {0^4, t_1^2 … t_{N-2}^2, 1^4} (2N control points)
/// @throws as interpolate_cubic, and InvalidArgument if tangent count ≠ point count
///   (NonFiniteInput / InvalidArgument name "derivatives[i]" for bad vectors)
[[nodiscard]] NurbsCurve hermite_cubic(std::span<const Vec3> points, std::span<const Vec3> derivatives,
                                       std::span<const double> parameters = {}, int dimension = 3);

/// Piecewise quintic Hermite: C2 through points with given first and second
/// derivatives (dC/dt, d²C/dt², t ∈ [0, 1]); triple interior knots.
/// Built from each segment's quintic Bézier points by blossoming.
/// @param points N ≥ 2 points; @param derivatives, second_derivatives N vectors each
/// @param parameters as hermite_cubic; @param dimension 2 or 3
/// @returns a quintic with knots {0^6, t_1^3 … t_{N-2}^3, 1^6} (3N control points)
/// @throws as hermite_cubic, naming "second_derivatives" for the second-derivative array
[[nodiscard]] NurbsCurve hermite_quintic(std::span<const Vec3> points, std::span<const Vec3> derivatives,
                                         std::span<const Vec3> second_derivatives,
                                         std::span<const double> parameters = {}, int dimension = 3);

}  // namespace hula::nurbs
