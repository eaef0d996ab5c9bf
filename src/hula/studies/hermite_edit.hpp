// SPDX-License-Identifier: MIT
// Hermite editing (thesis 7.5.2): a C2 cubic spline is interpolated through
// the points; at each data point (knot) its first and second derivatives
// P', P'' give the tangent T and principal normal N, shown as the handles
// T |P'| (= P') and N |P''|; the designer rotates and scales handles, the same
// rotation and scale are applied to the derivatives P', P'' (a rotation about
// an axis rotates both the handle and the derivative it stands for), and the
// curve is rebuilt through the same points and parameters from the edited
// derivatives:
//   - Quintic (default): nurbs::hermite_quintic with P' and P'' at every knot,
//     C2 at the knots (curvature continuous), and with no edit exactly the spline
//     (a cubic meets the quintic Hermite conditions, which fix the quintic);
//   - Cubic: nurbs::hermite_cubic with P' only (the thesis's figures 69–71),
//     C1 at the knots; normal-handle edits are refused because a cubic Hermite
//     segment cannot honour second derivatives.
// Angles are in radians, counter-clockwise about the axis. The default axis is
// +Z for planar (dimension 2) curves and the binormal at the knot for space
// curves (rotation in the osculating plane); an explicit axis may be given.
#pragma once
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "hula/nurbs/interpolate.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::studies {

/// How the edited curve is rebuilt.
enum class HermiteRebuild {
  Quintic,  ///< hermite_quintic from P' and P'' (C2)
  Cubic,    ///< hermite_cubic from P' (C1); normal edits refused
};

/// The edit of the handles at one knot.
struct HandleEdit {
  /// Index of the data point (knot), 0 … N − 1.
  std::size_t knot = 0;
  /// Rotation of the tangent handle (and P'), radians. Default 0.
  double tangent_angle = 0.0;
  /// Scale of the tangent handle (and P'), > 0. Default 1.
  double tangent_scale = 1.0;
  /// Rotation of the normal handle (and P''), radians. Default 0.
  double normal_angle = 0.0;
  /// Scale of the normal handle (and P''), > 0. Default 1.
  double normal_scale = 1.0;
  /// Rotation axis (normalised); empty: +Z for planar curves, the binormal at the knot otherwise.
  std::optional<Vec3> axis{};
};

/// Options of hermite_edit().
struct HermiteEditOptions {
  /// The spline through the points (parameterisation or parameters, end conditions, dimension).
  /// Default chord length, natural ends, 3-D.
  nurbs::InterpolationOptions interpolation{};
  /// Rebuild. Default Quintic.
  HermiteRebuild rebuild = HermiteRebuild::Quintic;
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// The Hermite data and handles at the knots.
struct HermiteHandles {
  std::vector<double> parameters;  ///< t_i in [0, 1]
  std::vector<Vec3> points;        ///< C(t_i)
  std::vector<Vec3> first;         ///< P'(t_i) = dC/dt, which is also the tangent handle T |P'|
  std::vector<Vec3> second;        ///< P''(t_i)
  /// N |P''| with N the principal normal; the zero vector where N is undefined (κ = 0).
  std::vector<Vec3> normal_handle;
};

/// Result of hermite_edit().
struct HermiteEditResult {
  nurbs::NurbsCurve spline;  ///< the C2 cubic spline through the points
  HermiteHandles before;     ///< the spline's handles
  HermiteHandles after;      ///< the edited derivatives and handles (those of `curve`)
  nurbs::NurbsCurve curve;   ///< the rebuilt curve
};

/// The handles of a curve at given parameters.
/// @throws as NurbsCurve::derivatives
[[nodiscard]] HermiteHandles hermite_handles(const nurbs::NurbsCurve& curve, std::span<const double> parameters);

/// The procedure of 7.5.2.
/// @param points N ≥ 2 data points (z = 0 when interpolation.dimension = 2)
/// @param edits at most one edit per knot
/// @param options the spline and the rebuild
/// @throws hula::Error(Errc::InvalidArgument) naming "edits[i].<field>": a knot outside [0, N − 1] or
///   edited twice, a non-finite angle, a scale ≤ 0 or non-finite, a zero or non-finite axis, an axis
///   needed where the binormal is undefined (a straight piece of a space curve), a normal edit with
///   the Cubic rebuild, or a rotation that leaves the plane of a planar curve
/// @throws as nurbs::interpolate_cubic and nurbs::hermite_quintic / hermite_cubic
[[nodiscard]] HermiteEditResult hermite_edit(std::span<const Vec3> points, std::span<const HandleEdit> edits,
                                             const HermiteEditOptions& options = {});

/// Rotation of v by `angle` radians about the unit vector `axis` (Rodrigues).
[[nodiscard]] Vec3 rotate_about(const Vec3& v, const Vec3& axis, double angle);

}  // namespace hula::studies
