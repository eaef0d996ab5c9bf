// SPDX-License-Identifier: MIT
// Conversion of a NurbsCurve to Open CASCADE's Geom_BSplineCurve for the
// oracle tests and the side-by-side benchmarks. Header-only so benchmarks can
// use it without linking the test-support library; link hula::occt.
#pragma once

#include <Geom2d_BSplineCurve.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <gp_Pnt.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec.hxx>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::testing {

namespace detail {

/// The full knot vector as OCCT's distinct knots and multiplicities.
struct OcctKnots {
  TColStd_Array1OfReal knots;
  TColStd_Array1OfInteger mults;
};

inline OcctKnots occt_knots(const nurbs::NurbsCurve& c) {
  std::vector<double> distinct;
  std::vector<int> mults;
  for (double u : c.knots().values()) {
    if (!distinct.empty() && distinct.back() == u) {
      ++mults.back();
    } else {
      distinct.push_back(u);
      mults.push_back(1);
    }
  }
  OcctKnots k{TColStd_Array1OfReal(1, static_cast<int>(distinct.size())),
              TColStd_Array1OfInteger(1, static_cast<int>(mults.size()))};
  for (std::size_t i = 0; i < distinct.size(); ++i) {
    k.knots.SetValue(static_cast<int>(i) + 1, distinct[i]);
    k.mults.SetValue(static_cast<int>(i) + 1, mults[i]);
  }
  return k;
}

}  // namespace detail

/// The same curve as an OCCT B-spline: poles, weights, and the full knot
/// vector as distinct knots with multiplicities (clamped or not).
inline Handle(Geom_BSplineCurve) to_occt(const nurbs::NurbsCurve& c) {
  const auto P = c.control_points();
  TColgp_Array1OfPnt poles(1, static_cast<int>(P.size()));
  for (std::size_t i = 0; i < P.size(); ++i) poles.SetValue(static_cast<int>(i) + 1, gp_Pnt(P[i].x, P[i].y, P[i].z));
  const detail::OcctKnots k = detail::occt_knots(c);
  if (c.is_rational()) {
    TColStd_Array1OfReal w(1, static_cast<int>(P.size()));
    for (std::size_t i = 0; i < P.size(); ++i) w.SetValue(static_cast<int>(i) + 1, c.weights()[i]);
    return new Geom_BSplineCurve(poles, w, k.knots, k.mults, c.degree());
  }
  return new Geom_BSplineCurve(poles, k.knots, k.mults, c.degree());
}

/// The (x, y) projection of the curve as an OCCT 2-D B-spline (for planar curves: the same curve).
inline Handle(Geom2d_BSplineCurve) to_occt_2d(const nurbs::NurbsCurve& c) {
  const auto P = c.control_points();
  TColgp_Array1OfPnt2d poles(1, static_cast<int>(P.size()));
  for (std::size_t i = 0; i < P.size(); ++i) poles.SetValue(static_cast<int>(i) + 1, gp_Pnt2d(P[i].x, P[i].y));
  const detail::OcctKnots k = detail::occt_knots(c);
  if (c.is_rational()) {
    TColStd_Array1OfReal w(1, static_cast<int>(P.size()));
    for (std::size_t i = 0; i < P.size(); ++i) w.SetValue(static_cast<int>(i) + 1, c.weights()[i]);
    return new Geom2d_BSplineCurve(poles, w, k.knots, k.mults, c.degree());
  }
  return new Geom2d_BSplineCurve(poles, k.knots, k.mults, c.degree());
}

/// OCCT point or vector as a Vec3.
inline Vec3 to_vec3(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
inline Vec3 to_vec3(const gp_Vec& v) { return {v.X(), v.Y(), v.Z()}; }
inline Vec3 to_vec3(const gp_Pnt2d& p) { return {p.X(), p.Y(), 0.0}; }

}  // namespace hula::testing
