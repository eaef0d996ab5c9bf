// SPDX-License-Identifier: MIT
// Conversion of a NurbsCurve to Open CASCADE's Geom_BSplineCurve for the
// oracle tests and the side-by-side benchmarks. Header-only so benchmarks can
// use it without linking the test-support library; link hula::occt.
#pragma once

#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <gp_Pnt.hxx>
#include <gp_Vec.hxx>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::testing {

/// The same curve as an OCCT B-spline: poles, weights, and the full knot
/// vector as distinct knots with multiplicities (clamped or not).
inline Handle(Geom_BSplineCurve) to_occt(const nurbs::NurbsCurve& c) {
  const auto P = c.control_points();
  TColgp_Array1OfPnt poles(1, static_cast<int>(P.size()));
  for (std::size_t i = 0; i < P.size(); ++i) poles.SetValue(static_cast<int>(i) + 1, gp_Pnt(P[i].x, P[i].y, P[i].z));
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
  TColStd_Array1OfReal knots(1, static_cast<int>(distinct.size()));
  TColStd_Array1OfInteger m(1, static_cast<int>(mults.size()));
  for (std::size_t i = 0; i < distinct.size(); ++i) {
    knots.SetValue(static_cast<int>(i) + 1, distinct[i]);
    m.SetValue(static_cast<int>(i) + 1, mults[i]);
  }
  if (c.is_rational()) {
    TColStd_Array1OfReal w(1, static_cast<int>(P.size()));
    for (std::size_t i = 0; i < P.size(); ++i) w.SetValue(static_cast<int>(i) + 1, c.weights()[i]);
    return new Geom_BSplineCurve(poles, w, knots, m, c.degree());
  }
  return new Geom_BSplineCurve(poles, knots, m, c.degree());
}

/// OCCT point or vector as a Vec3.
inline Vec3 to_vec3(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }
inline Vec3 to_vec3(const gp_Vec& v) { return {v.X(), v.Y(), v.Z()}; }

}  // namespace hula::testing
