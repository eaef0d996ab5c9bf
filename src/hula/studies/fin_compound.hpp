// SPDX-License-Identifier: MIT
// Prescribed compound fins (thesis 8.3): the projection technique and the
// inverse Combescure transform.
//
// Projection technique (eq. 36–37). A space curve's normal fin compound
// P − s N cannot be inverted (eq. 36: its tangent has a B component), but a
// planar curve's can. The curve is projected on a plane (diffgeom::project);
// the projection's normal fin compound is
//     Q(t) = P(t) − s n_P(t),   n_P = n × T_P,
// where n is plane_normal(plane) and n_P the signed in-plane normal: it is the
// Frenet normal N where the projection turns counter-clockwise about n (κ_s > 0),
// so Q is the project's normal fin P − s N (diffgeom::FinKind::Normal) there,
// and unlike N it stays continuous through inflections. With the Frenet–Serret
// formula dn_P/ds = −κ_s T_P, dQ/ds = (1 + s κ_s) T_P (eq. 37), so Q's normal
// is parallel to P's. If 1 + s κ_s > 0 (the fins do not cross), Q runs the
// same way as P, n_Q = n_P and κ_Q = κ_s / (1 + s κ_s), hence
//     P = Q + s n_Q,   with 1 − s κ_Q = 1 / (1 + s κ_s) > 0.
// So the planar curve whose compound is a prescribed Q is Q's offset by +s along
// its own signed normal, and the construction breaks down exactly where
// 1 − s κ_Q ≤ 0 (the prescribed compound bends with a radius of curvature ≤ s
// towards +n_Q): there the offset reverses (a cusp), its own compound is
// Q + 2 s n_Q ≠ Q, and curve_from_normal_compound refuses it, naming the
// parameter. Where Q's curvature vanishes nothing breaks (n_Q stays defined);
// where Q's speed vanishes the normal is undefined and it is refused too.
// The 3-D curve is then rebuilt from the new projection's two coordinates and
// the original's third one (projection_edit.hpp, matched by normalised parameter).
//
// Combescure transform (eq. 38–44): Q = P + C (τ/κ T + B) (diffgeom::combescure_law);
// since Q shares P's T, N, B and τ/κ, the parent of a prescribed Q is Q's
// transform with −C. It is undefined at zero curvature and on planar pieces
// (τ = 0, thesis 8.3), and the compound involves P''' so a curve whose third
// derivative jumps (a cubic spline at its knots) has a torn compound: these are
// refused before any fitting.
//
// The results are laws (exact) fitted to quintic NURBS within a tolerance,
// span by span between the input's knots.
#pragma once
#include <string_view>

#include "hula/diffgeom/projection.hpp"
#include "hula/law/convert.hpp"
#include "hula/law/expr.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::studies {

/// Options of the projection technique.
struct NormalCompoundOptions {
  /// Projection plane. Default XY.
  diffgeom::Plane plane = diffgeom::Plane::XY;
  /// The fin scale s (model units), finite and non-zero. Default 1.
  double scale = 1.0;
  /// Samples (equally spaced in the parameter, knots added) of the stretch test 1 − s κ_Q and of the
  /// measured deviations. Default 1001; valid 2 … 1000000.
  int samples = 1001;
  /// The inverse is refused where 1 − s κ_Q < min_stretch (the reconstructed curve's speed relative
  /// to the compound's). Default 1e-3; valid (0, 1).
  double min_stretch = 1e-3;
  /// Fit of the exact laws to NURBS. Default tolerance 1e-9 model units.
  law::ToNurbsOptions fit{.tolerance = 1e-9};
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// A compound or a reconstructed curve: the exact law of `t` and its NURBS fit.
struct LawCurveFit {
  law::Law law;                ///< exact law of the input's parameter ("t" for NURBS input) on its domain
  nurbs::NurbsCurve curve;     ///< quintic fit of `law`, same parameterisation
  double fit_deviation = 0.0;  ///< max |law − curve| measured by law::to_nurbs
};

/// The normal fin compound of the projection of `curve` on options.plane: Q = P − s (n × T).
/// @param curve a 2-D or 3-D curve (its projection must have a tangent everywhere)
/// @returns Q on the curve's domain
/// @throws hula::Error(Errc::InvalidOption) for bad options
/// @throws hula::Error(Errc::InvalidArgument) naming "curve" and the parameter where the projection has
///   zero speed or the fins cross (1 + s κ_s < min_stretch: Q folds back and cannot be inverted), or
///   the knot where its tangent turns (a corner: the compound would tear)
[[nodiscard]] LawCurveFit normal_compound(const nurbs::NurbsCurve& curve, const NormalCompoundOptions& options = {});

/// The signed curvature stretch 1 − s κ_Q of a prescribed compound at its lowest point.
struct StretchReport {
  double min_stretch = 0.0;  ///< min over the samples of 1 − s κ_Q (κ_Q signed about the plane normal)
  double at = 0.0;           ///< the parameter where it occurs
};

/// Measures 1 − s κ_Q along a planar compound.
/// @throws hula::Error(Errc::InvalidArgument) naming "compound" and the parameter where Q has zero speed
[[nodiscard]] StretchReport compound_stretch(const nurbs::NurbsCurve& compound, const NormalCompoundOptions& options);

/// The planar curve whose normal fin compound is the prescribed `compound`: P = Q + s n_Q.
/// @param compound a curve in a plane parallel to options.plane (e.g. an edited normal_compound)
/// @returns P on the compound's domain, in the compound's plane
/// @throws hula::Error(Errc::InvalidArgument) naming "compound" if it is not planar in the plane (the
///   control point), has a corner at a knot, has zero speed, or 1 − s κ_Q < min_stretch somewhere
///   (the parameter and value)
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] LawCurveFit curve_from_normal_compound(const nurbs::NurbsCurve& compound,
                                                     const NormalCompoundOptions& options = {});

/// Result of edit_normal_compound().
struct CompoundEditResult {
  nurbs::NurbsCurve projection;  ///< the original's projection (diffgeom::project)
  LawCurveFit compound;          ///< the original projection's compound
  LawCurveFit planar;            ///< the new projection, whose compound is the edited one
  nurbs::NurbsCurve curve;       ///< the rebuilt 3-D curve (on [0, 1] unless structures matched)
  StretchReport stretch;         ///< 1 − s κ of the edited compound at its lowest
  /// max over samples of |compound of planar.curve − edited|: the forward check of the inverse.
  double forward_deviation = 0.0;
  /// Deviation of the 3-D assembly from its definition (edit_projection).
  double assembly_deviation = 0.0;
};

/// The projection technique of 8.3: the edited compound → new projection → 3-D curve.
/// @param curve the original 3-D curve
/// @param edited_compound the prescribed compound, planar in options.plane
/// @throws as curve_from_normal_compound and edit_projection
[[nodiscard]] CompoundEditResult edit_normal_compound(const nurbs::NurbsCurve& curve,
                                                      const nurbs::NurbsCurve& edited_compound,
                                                      const NormalCompoundOptions& options = {});

/// Options of the Combescure studies.
struct CombescureOptions {
  /// The constant C of eq. 44 (model units), finite and non-zero. Default 1.
  double c = 1.0;
  /// Samples of the definedness check. Default 1001; valid 2 … 1000000.
  int samples = 1001;
  /// A sample is planar (undefined) when |τ| ≤ angular · κ. Default 1e-10.
  double angular = 1e-10;
  /// Fit of the exact law. Default tolerance 1e-9.
  law::ToNurbsOptions fit{.tolerance = 1e-9};
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// The Combescure compound Q = P + C (τ/κ T + B) of a 3-D law curve.
/// @param curve a 3-vector law of `parameter`
/// @param parameter its parameter name
/// @param domain the domain, start < end
/// @returns Q as a law of `parameter` and its NURBS fit on `domain`
/// @throws hula::Error(Errc::InvalidArgument) naming "curve" and the parameter where κ = 0, the
///   speed vanishes or the curve has a planar piece (τ = 0), or if it is planar everywhere
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] LawCurveFit combescure_compound(const law::Law& curve, std::string_view parameter, nurbs::Interval domain,
                                              const CombescureOptions& options = {});

/// The Combescure compound of a NURBS curve (as a law of "t" on its domain).
/// @throws as the law form, and hula::Error(Errc::InvalidArgument) naming "curve" and the knot if its
///   third derivative jumps there (degree − multiplicity < 3): the compound would tear
[[nodiscard]] LawCurveFit combescure_compound(const nurbs::NurbsCurve& curve, const CombescureOptions& options = {});

/// The inverse Combescure transform: the parent P = Q − C (τ_Q/κ_Q T_Q + B_Q) of a prescribed compound
/// given as a law (exact: the parent of combescure_compound(P).law is P to rounding).
/// @throws as combescure_compound, naming "compound"
[[nodiscard]] LawCurveFit combescure_parent(const law::Law& compound, std::string_view parameter,
                                            nurbs::Interval domain, const CombescureOptions& options = {});

/// The inverse Combescure transform of a prescribed NURBS compound (C3, as combescure_compound).
/// @throws as combescure_compound, naming "compound"
[[nodiscard]] LawCurveFit combescure_parent(const nurbs::NurbsCurve& compound, const CombescureOptions& options = {});

}  // namespace hula::studies
