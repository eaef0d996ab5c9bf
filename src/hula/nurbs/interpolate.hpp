// SPDX-License-Identifier: MIT
// Curves through data points (thesis 5.3, 7.1.2, 7.5, 10.2.1, 10.2.5):
// parameterisation (uniform, chord length eq. 29, centripetal), the global C2
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
};

/// End condition of the global cubic spline at one end.
struct EndCondition {
  enum class Kind {
    Natural,   ///< C''(end) = 0
    Clamped,   ///< C'(end) = derivative, magnitude honoured (dC/dt with t ∈ [0, 1])
    Bessel,    ///< C'(end) from the quadratic through the 3 end points at their parameters
    NotAKnot,  ///< C''' continuous at the second (last but one) data parameter
    Occt,      ///< C'(end) from the cubic through the 4 end points (Open CASCADE GeomAPI_Interpolate)
  };
  Kind kind = Kind::Natural;
  /// dC/dt at the end for Kind::Clamped; ignored otherwise.
  Vec3 derivative{};

  [[nodiscard]] static EndCondition natural() { return {Kind::Natural, {}}; }
  [[nodiscard]] static EndCondition clamped(const Vec3& d) { return {Kind::Clamped, d}; }
  [[nodiscard]] static EndCondition bessel() { return {Kind::Bessel, {}}; }
  [[nodiscard]] static EndCondition not_a_knot() { return {Kind::NotAKnot, {}}; }
  [[nodiscard]] static EndCondition occt() { return {Kind::Occt, {}}; }
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

  /// @throws hula::Error(Errc::InvalidOption) naming the bad field
  /// (non-finite clamped derivative, dimension not 2/3, bad tolerance).
  void validate() const;
};

/// Cumulative chord lengths L_0 = 0, L_i = Σ_{j<i} |P_{j+1} - P_j| (overflow-safe).
/// The thesis's example (0,0,0), (40,25,0), (80,-25,0), (120,0,0) gives 0, 47.17, 111.20, 158.37.
/// @throws hula::Error(Errc::NonFiniteInput) naming the point and coordinate
[[nodiscard]] std::vector<double> cumulative_chord_lengths(std::span<const Vec3> points);

/// Data parameters in [0, 1] (first 0, last 1, strictly increasing).
/// @throws hula::Error(Errc::TooFewPoints) if fewer than 2 points
/// @throws hula::Error(Errc::NonFiniteInput) naming the point and coordinate
/// @throws hula::Error(Errc::CoincidentPoints) naming the index pair when consecutive
///   points coincide under ChordLength or Centripetal
[[nodiscard]] std::vector<double> parameterise(std::span<const Vec3> points, Parameterisation rule,
                                               const Tolerance& tolerance = {});

/// Global C2 cubic spline through N ≥ 2 points, O(N) (banded solve).
/// N = 2 gives the straight segment (or the cubic meeting clamped ends); N = 3
/// with not-a-knot gives the parabola. The result is a clamped cubic NURBS on
/// [0, 1] with simple interior knots at the data parameters.
/// @throws hula::Error(Errc::TooFewPoints) if N < 2
/// @throws hula::Error(Errc::NonFiniteInput) naming the point, parameter or end derivative
/// @throws hula::Error(Errc::CoincidentPoints) as parameterise
/// @throws hula::Error(Errc::InvalidArgument) if given parameters are not strictly
///   increasing (names the index) or their count differs from the points'
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
[[nodiscard]] NurbsCurve interpolate_cubic(std::span<const Vec3> points, const InterpolationOptions& options = {});

/// Lagrange interpolation (thesis 5.3.1): the polynomial of degree N - 1 through
/// N ≥ 2 points, as a Bézier curve on [0, 1]. `parameters` as in
/// InterpolationOptions (empty: uniform, the thesis's evenly spaced values).
/// Ill-conditioned for large N (thesis 5.3.1); accepted up to kMaxDegree + 1 points.
/// @throws as interpolate_cubic, and hula::Error(Errc::TooFewPoints / InvalidDegree)
[[nodiscard]] NurbsCurve interpolate_lagrange(std::span<const Vec3> points, std::span<const double> parameters = {},
                                              int dimension = 3);

/// Piecewise cubic Hermite (thesis 5.3.2, 7.5.2): C1 through points with the
/// given first derivatives dC/dt (t ∈ [0, 1]); double interior knots.
/// `parameters` empty: chord length.
/// @throws as interpolate_cubic, and InvalidArgument if tangent count ≠ point count
[[nodiscard]] NurbsCurve hermite_cubic(std::span<const Vec3> points, std::span<const Vec3> derivatives,
                                       std::span<const double> parameters = {}, int dimension = 3);

/// Piecewise quintic Hermite: C2 through points with given first and second
/// derivatives (dC/dt, d²C/dt², t ∈ [0, 1]); triple interior knots.
[[nodiscard]] NurbsCurve hermite_quintic(std::span<const Vec3> points, std::span<const Vec3> derivatives,
                                         std::span<const Vec3> second_derivatives,
                                         std::span<const double> parameters = {}, int dimension = 3);

}  // namespace hula::nurbs
