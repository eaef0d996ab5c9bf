// SPDX-License-Identifier: MIT
// Mapping techniques (thesis 6.3.2, after Moreton and Hoschek): curves that map
// a curve to another curve whose shape shows the first's quality.
//
// K-orthotomic with respect to a point P (Hoschek, "Detecting regions with
// undesirable curvature", CAGD 1, 1984): O_K(t) = P + K ((C − P) − ((C − P)·T) T),
// K times the vector from P to the foot of the perpendicular from P on the
// tangent line. K = 1 is the pedal curve, K = 2 the orthotomic (the
// reflections of P in the tangent lines; for a parabola and its focus, the
// directrix). Its speed is |O_K'| = K κ |C'| |(C − P)·T| for a plane curve, so
// it stops where κ = 0: inflections show as cusps.
//
// Polar mapping: the polar reciprocal of a plane curve with respect to the
// circle of centre P and radius ρ — the pole of each tangent line,
// Q(t) = P + ρ² n / ((C − P)·n), n the unit normal. Tangent lines and points
// swap roles, so an inflection of C (a stationary tangent) is a cusp of Q
// (a stationary point), and a circle of radius R about P maps to the circle
// of radius ρ²/R. Q is undefined where a tangent line passes through P.
//
// Both are laws of the curve's law, so the mapped curve of a law curve is an
// exact law curve.
#pragma once

#include "hula/core/vec.hpp"
#include "hula/curve/curve.hpp"
#include "hula/law/expr.hpp"

namespace hula::diffgeom {

/// O_K = P + K ((C − P) − ((C − P)·T) T) of a 3-vector law C (a 2-vector law gives a 2-vector law).
/// @throws hula::Error(Errc::InvalidArgument) naming "law" for a scalar law
[[nodiscard]] law::Law orthotomic_law(const law::Law& curve, std::string_view parameter, const Vec3& pole, double k);

/// Q = P + ρ² n / ((C − P)·n) of a plane curve law in x, y: a 2-vector law, or for a 3-vector law a 3-vector law
/// whose z is the curve's.
/// @throws hula::Error(Errc::InvalidArgument) naming "law" for a scalar law
[[nodiscard]] law::Law polar_law(const law::Law& curve, std::string_view parameter, const Vec3& centre, double radius);

/// Options of orthotomic() and polar_map().
struct MappingOptions {
  /// Largest distance between the mapped curve's NURBS and the mapped curve, model units. Default 1e-6; valid
  /// [1e-12, 1e-2].
  double tolerance = 1e-6;
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// A mapped curve.
struct MappedCurve {
  /// On the curve's domain and parameter: a law curve (exact) when the input is a law curve, else a NURBS within
  /// the tolerance. Dimension: the input's.
  curve::Curve curve;
  /// True when curve is a law curve.
  bool exact = false;
  /// The measured distance between curve.nurbs() and the mapped curve.
  double deviation = 0.0;
};

/// The K-orthotomic of a curve with respect to a pole.
/// @param pole P, model units (z ignored for a 2-D curve)
/// @param k K, finite and non-zero (1 pedal, 2 orthotomic)
/// @throws hula::Error(Errc::InvalidArgument) naming "pole" or "k" for non-finite values or K = 0
/// @throws hula::Error(Errc::NumericalFailure) naming "curve" where C' = 0
/// Example: the parabola y = x² with P its focus (0, 1/4) and K = 2 maps onto its directrix y = −1/4.
[[nodiscard]] MappedCurve orthotomic(const curve::Curve& curve, const Vec3& pole, double k,
                                     const MappingOptions& options = {});

/// The polar map of a plane curve with respect to the circle of centre P and radius ρ.
/// @param curve a plane curve in the XY plane (2-D, or 3-D at constant z: the map is then 3-D at that z)
/// @throws hula::Error(Errc::InvalidArgument) naming "curve" for a curve out of the XY plane, "centre" or "radius"
///   for bad values
/// @throws hula::Error(Errc::NumericalFailure) naming "centre" where a tangent line passes through P
/// Example: the circle of radius 2 about P maps onto the circle of radius ρ²/2 about P.
[[nodiscard]] MappedCurve polar_map(const curve::Curve& curve, const Vec3& centre, double radius,
                                    const MappingOptions& options = {});

}  // namespace hula::diffgeom
