// SPDX-License-Identifier: MIT
// Exact conversion between nurbs::NurbsCurve and Open CASCADE's
// Geom_BSplineCurve (distinct knots with multiplicities ↔ the full
// Piegl–Tiller knot vector), shared by the OCCT kernel backend and the
// STEP/IGES exchange helper. Only built with Open CASCADE (HULA_WITH_OCCT).
#pragma once

#include <Geom_BSplineCurve.hxx>
#include <Standard_Failure.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>
#include <string_view>

#include "hula/core/error.hpp"
#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::oli {

/// The same curve as an OCCT B-spline: poles, weights (when rational), distinct knots with their
/// multiplicities, non-periodic. Bit-exact: no value is recomputed.
/// @throws hula::Error(Errc::Unsupported) if the degree exceeds Geom_BSplineCurve::MaxDegree() (25)
/// @throws hula::Error(Errc::InvalidKnots) if OCCT refuses the knots (two distinct knots closer than
///   its parametric resolution), naming OCCT's reason
[[nodiscard]] Handle(Geom_BSplineCurve) to_occt(const nurbs::NurbsCurve& curve);

/// The OCCT B-spline as a NurbsCurve (a periodic curve is first made non-periodic, which OCCT
/// does exactly by knot insertion).
/// @param dimension 2 to return a planar curve when every pole has z = 0 exactly; else 3
/// @throws hula::Error from the NurbsCurve constructor if OCCT's data are not a valid curve
[[nodiscard]] nurbs::NurbsCurve from_occt(const Handle(Geom_BSplineCurve) & curve, int dimension = 3);

/// OCCT point or vector as a Vec3.
[[nodiscard]] inline Vec3 to_vec3(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
[[nodiscard]] inline Vec3 to_vec3(const gp_Vec& v) { return {v.X(), v.Y(), v.Z()}; }

/// A Standard_Failure raised by OCCT during `operation` as hula::Error(Errc::NumericalFailure)
/// naming the operation and OCCT's exception type and message.
[[nodiscard]] Error occt_failure(std::string_view operation, const Standard_Failure& failure);

}  // namespace hula::oli
