// SPDX-License-Identifier: MIT
// Match and Blend (what a CAD user reaches for first to join two curves):
//  - match_end moves the last k + 1 control points of one end of curve A so that
//    the end is Gk (k = 0 … 3) to curve B at one of its ends or at a parameter
//    on it. The end derivatives of A are set to those of B under the linear
//    reparameterisation that keeps A's end speed (A^(j) = λ^j B^(j), λ = |A'|/|B'|
//    times an optional scale), so position, unit tangent, curvature vector, dκ/ds
//    and torsion agree; the poles follow from the clamped-end derivative
//    formulas, solved from the end inwards (each derivative order involves one
//    more pole). A gets knots inserted first when it has fewer than k + 2 poles
//    (so its other end stays), and its degree raised when it is below k.
//  - blend builds the Hermite curve (cubic G1, quintic G2, septic G3) from A's end
//    to B's start (either end of each: a start is the end of the reversed curve) whose end derivatives are the curves'
//    own, scaled by one common factor m of the chord over the end speeds; m is chosen by golden-section search to
//    minimise ∫(dκ/ds)² ds (curvature_variation_energy).
// Both report the continuity reached, measured by compare_sides (continuity.hpp).
#pragma once
#include <vector>

#include "hula/diffgeom/continuity.hpp"
#include "hula/diffgeom/energy.hpp"

namespace hula::diffgeom {

/// Which end of a curve.
enum class CurveEnd { Start, End };

/// What Match moves and where to.
struct MatchOptions {
  int continuity = 2;                     ///< k of Gk: 0 … 3
  CurveEnd end = CurveEnd::End;           ///< the end of A that moves
  CurveEnd target_end = CurveEnd::Start;  ///< the end of B matched (when `at` is not used)
  bool use_parameter = false;             ///< match to B at `at` instead of an end
  double at = 0.0;                        ///< parameter on B (when use_parameter)
  /// Multiplies A's kept end speed (1: A's end tangent length is kept). Valid: (0, 1e3].
  double tangent_scale = 1.0;
  /// Throws hula::Error(Errc::InvalidOption) naming the bad field.
  void validate() const;
};

/// The matched curve and what was done.
struct MatchResult {
  nurbs::NurbsCurve curve;        ///< A after the match (same direction as A)
  std::vector<int> moved{};       ///< indices of the moved control points in `curve`
  int inserted_knots = 0;         ///< knots inserted before the match
  int degree_elevation = 0;       ///< degree raised by this much before the match
  double target_parameter = 0.0;  ///< the parameter on B matched to
  Continuity continuity{};        ///< A's end (as the left side) against B there (right side)
};

/// Makes A's end Gk to B (see the file comment).
/// @throws hula::Error(Errc::InvalidOption) for bad options; Errc::Unsupported naming "a" for a rational A
///   (its poles do not give the derivatives linearly); Errc::OutOfDomain naming "at" outside B's domain;
///   Errc::InvalidArgument naming "b" where B has zero speed at the target (no tangent to match)
[[nodiscard]] MatchResult match_end(const nurbs::NurbsCurve& a, const nurbs::NurbsCurve& b,
                                    const MatchOptions& options = {});

/// The blend options.
struct BlendOptions {
  int continuity = 2;                     ///< 1 … 3 (cubic, quintic, septic Hermite)
  CurveEnd end = CurveEnd::End;           ///< the end of A the blend leaves (Start: A is reversed first)
  CurveEnd target_end = CurveEnd::Start;  ///< the end of B the blend reaches (End: B is reversed first)
  double min_scale = 0.2;                 ///< golden-section bracket of the common scale m; valid 0 < min < max ≤ 10
  double max_scale = 3.0;
  int iterations = 30;  ///< golden-section steps; valid 1 … 200
  /// Throws hula::Error(Errc::InvalidOption) naming the bad field.
  void validate() const;
};

/// The blend curve and its fairness.
struct BlendResult {
  nurbs::NurbsCurve curve;             ///< from A's end to B's start, on [0, 1]
  double scale = 1.0;                  ///< the chosen m
  EnergyResult curvature_variation{};  ///< ∫(dκ/ds)² ds of the blend
  int curvature_extrema = 0;           ///< curvature_extrema(curve).size()
  Continuity start{};                  ///< A's chosen end against the blend's start
  Continuity end{};                    ///< the blend's end against B's chosen end
};

/// Blends A's chosen end with B's chosen end (see the file comment); A's start and B's end are blended as the
/// end of reverse(A) and the start of reverse(B), bit for bit.
/// @throws hula::Error(Errc::InvalidOption) for bad options; Errc::InvalidArgument naming "a" or "b" for zero
///   end speed, naming "b" when the ends coincide; as nurbs::hermite_cubic/quintic/septic
[[nodiscard]] BlendResult blend(const nurbs::NurbsCurve& a, const nurbs::NurbsCurve& b,
                                const BlendOptions& options = {});

}  // namespace hula::diffgeom
