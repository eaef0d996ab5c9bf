// SPDX-License-Identifier: MIT
// Curve features (thesis 6.3.1, 7.1): inflection points of planar curves (sign
// changes of the signed curvature), curvature extrema (sign changes of
// dκ/ds) and torsion extrema (sign changes of dτ/ds), found by sampling every knot span and refining each bracket by
// bisection to the parameter resolution. A root is reported only where the
// quantity changes sign, so straight spans and tangential zeros are not noise.
//
// One rule decides which extrema are reported, whatever found them (sampling
// of a NURBS, of an exact law, or the roots of a law's derivative): an
// extremum must stand out of its neighbours by more than
// FeatureOptions::significance × the largest |value| seen (persistence
// simplification: the closest pair of a neighbouring maximum and minimum, or an extremum and
// an end of the domain, is removed while its difference is below that floor).
// So a constant-κ curve (a circle, a helix) has no extremum, whatever rounding
// does to dκ/ds, and a maximum and a minimum found at the same point cancel.
#pragma once
#include <string_view>
#include <vector>

#include "hula/diffgeom/frenet.hpp"
#include "hula/law/expr.hpp"
#include "hula/law/roots.hpp"

namespace hula::diffgeom {

/// Options of the feature searches.
struct FeatureOptions {
  /// Samples per knot span (law curves: per 1/64 of the domain) used to bracket sign changes.
  /// Default 32; two roots closer than a sample step may be missed. Valid: 2 … 100000.
  int samples_per_span = 32;
  /// Frenet options (tolerances, plane normal of the signed curvature). Default {}.
  FrenetOptions frenet{};
  /// Relative size below which an extremum is not one: an extremum whose value differs from its
  /// neighbouring extrema (or the domain ends) by at most significance × max |value| is dropped (see
  /// the file comment). Default 1e-9: far above rounding of κ and τ (~1e-15 relative), far below any
  /// designed variation. Valid [0, 1e-3]; 0 keeps every sign change of the derivative.
  double significance = 1e-9;
  /// Throws hula::Error(Errc::InvalidOption) naming the bad field.
  void validate() const;
};

/// What a feature is.
enum class FeatureKind {
  Inflection,        ///< the signed curvature changes sign
  CurvatureMaximum,  ///< dκ/ds changes from + to −
  CurvatureMinimum,  ///< dκ/ds changes from − to +
  TorsionMaximum,    ///< dτ/ds changes from + to −
  TorsionMinimum,    ///< dτ/ds changes from − to +
};

/// "inflection", "curvature-maximum", "curvature-minimum", "torsion-maximum" or "torsion-minimum".
[[nodiscard]] std::string_view feature_kind_name(FeatureKind kind) noexcept;

/// One feature point.
struct Feature {
  FeatureKind kind = FeatureKind::Inflection;  ///< what it is
  /// Parameter: to rounding where a sample hits the root; otherwise to where the quantity becomes
  /// negligible (for inflections |κ| · model size ≤ tolerance.angular, the zero-curvature test).
  double t = 0.0;
  Vec3 position{};         ///< r(t)
  double curvature = 0.0;  ///< κ at t (0 at an inflection)
  double torsion = 0.0;    ///< τ at t (NaN where the frame is undefined)
};

/// Inflections of a curve about FeatureOptions::frenet.plane_normal (meaningful for planar curves
/// in that plane; 2-D curves use +Z), in increasing t.
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] std::vector<Feature> inflections(const nurbs::NurbsCurve& curve, const FeatureOptions& options = {});
/// Curvature maxima and minima in the open domain, in increasing t.
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] std::vector<Feature> curvature_extrema(const nurbs::NurbsCurve& curve,
                                                     const FeatureOptions& options = {});
/// Torsion maxima and minima (sign changes of dτ/ds, from r' … r''''), in increasing t. Knots where
/// τ only jumps are not reported. Uses unscaled derivatives: meant for curves of ordinary scale.
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] std::vector<Feature> torsion_extrema(const nurbs::NurbsCurve& curve, const FeatureOptions& options = {});
/// Inflections of a curve value over its domain: sampled as the NURBS form (per knot span of
/// nurbs(); law curves: per 1/64 of the domain, evaluated exactly from the law).
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] std::vector<Feature> inflections(const curve::Curve& curve, const FeatureOptions& options = {});
/// Curvature extrema of a curve value in its open domain (sampled as inflections(Curve)).
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] std::vector<Feature> curvature_extrema(const curve::Curve& curve, const FeatureOptions& options = {});
/// Torsion extrema of a curve value: of its NURBS, or of its exact law (torsion_extrema(law, ...)).
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] std::vector<Feature> torsion_extrema(const curve::Curve& curve, const FeatureOptions& options = {});

/// Inflections of a law curve without sampling the curve: the roots (law::roots) of the exact law
/// g = (r' × r'') · n, n = FeatureOptions::frenet.plane_normal, kept where g changes sign. 2-vector
/// laws are embedded in z = 0. FeatureOptions::samples_per_span is ignored; `roots` steers the
/// search on the derivative laws.
/// @param curve a 2- or 3-vector law of `parameter`
/// @throws hula::Error(Errc::InvalidArgument) naming "law" for a scalar law, "domain" for a bad domain
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] std::vector<Feature> inflections(const law::Law& curve, std::string_view parameter,
                                               nurbs::Interval domain, const FeatureOptions& options = {},
                                               const law::RootOptions& roots = {});
/// Curvature extrema of a law curve in the open domain without sampling the curve: the interior
/// extrema (law::extrema) of the exact smooth law κ² = |r' × r''|² / |r'|⁶ (an inflection, κ = 0,
/// is a curvature minimum). Stationary points without a change of sign, and extrema that differ from
/// their neighbours by no more than roots.value_tolerance × max |κ²|, are not reported.
/// @throws as inflections(const law::Law&, ...)
[[nodiscard]] std::vector<Feature> curvature_extrema(const law::Law& curve, std::string_view parameter,
                                                     nurbs::Interval domain, const FeatureOptions& options = {},
                                                     const law::RootOptions& roots = {});
/// Torsion extrema of a law curve in the open domain without sampling the curve: the interior
/// extrema (law::extrema) of the exact law τ = (r' × r'') · r''' / |r' × r''|² (as frenet_laws).
/// @throws as inflections(const law::Law&, ...)
[[nodiscard]] std::vector<Feature> torsion_extrema(const law::Law& curve, std::string_view parameter,
                                                   nurbs::Interval domain, const FeatureOptions& options = {},
                                                   const law::RootOptions& roots = {});
}  // namespace hula::diffgeom
