// SPDX-License-Identifier: MIT
// Curves derived from a curve by a law construction (offsets, orthotomics,
// polar maps): the parent as a law in a fresh context, and the derived law
// turned into a curve value — a law curve (exact) when the parent is a law
// curve and the derived law prints within the parser's limit, else a NURBS
// fitted within a tolerance (law::to_nurbs).
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hula/core/interval.hpp"
#include "hula/curve/curve.hpp"
#include "hula/law/expr.hpp"

namespace hula::diffgeom::detail {

/// The parent's position law in a fresh context: a law curve's own expression re-parsed (its private context is
/// not shared), any other kind its NURBS as a leaf (a 3-vector, z = 0 for plane curves).
struct ParentLaw {
  law::Context context;
  law::Law r;
  std::string parameter;
  /// True when r is the parent's exact law text (the derived law can be printed as a law curve).
  bool printable = false;
};

/// @throws as law::parse (never for a valid law curve)
[[nodiscard]] ParentLaw parent_law(const curve::Curve& c);

/// Refuses a curve that does not lie in a plane z = constant (2-D curves do), naming "curve" and `what`.
/// @throws hula::Error(Errc::InvalidArgument) naming "curve"
void require_xy_plane(const curve::Curve& c, const char* what);

/// The parent's law as a plane law for a 2-D curve (its NURBS leaf is a 3-vector with z = 0), else as it is.
[[nodiscard]] law::Law plane_law(const ParentLaw& p, const curve::Curve& c);

/// A scalar law of the parent's parameter from an option's text.
/// @throws hula::Error(Errc::ParseError) naming `field` for a bad or non-scalar law
[[nodiscard]] law::Law scalar_option(std::string_view text, const ParentLaw& p, const char* field);

/// A derived curve and how it is held.
struct DerivedCurve {
  curve::Curve curve;
  bool exact = false;      ///< a law curve
  double deviation = 0.0;  ///< of its NURBS from the law (to_nurbs' measured deviation)
};

/// The derived law `l` (of p.parameter) on `domain` as a curve value.
/// The NURBS fit is made span by span between `breaks` (increasing, inside the domain; e.g. the parent's knots
/// where the derived law is less than C2) and the pieces joined C0.
/// @param printable false when `l` holds a NURBS leaf not of the parent's law
/// @throws as curve::Curve::from_law and law::to_nurbs
[[nodiscard]] DerivedCurve derived_curve(const law::Law& l, const ParentLaw& p, bool printable, Interval domain,
                                         double tolerance, std::span<const double> breaks = {});

/// The interior knots of a NURBS curve where a law built from its derivatives up to `order` is below C2: those
/// of multiplicity m with p − m − order < 2 (the curve is C^(p−m) there).
[[nodiscard]] std::vector<double> low_continuity_knots(const nurbs::NurbsCurve& c, int order);

/// Rethrows an "undefined" failure of derived_curve as NumericalFailure naming `field` with `why` appended;
/// other errors unchanged.
[[noreturn]] void rethrow_undefined(const char* field, const std::string& what, const std::string& why);

}  // namespace hula::diffgeom::detail
