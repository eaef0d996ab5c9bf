// SPDX-License-Identifier: MIT
#include "hula/oli/kernel/occt_convert.hpp"

#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <string>
#include <vector>

namespace hula::oli {

Handle(Geom_BSplineCurve) to_occt(const nurbs::NurbsCurve& curve) {
  if (curve.degree() > Geom_BSplineCurve::MaxDegree())
    throw Error(Errc::Unsupported,
                "degree " + std::to_string(curve.degree()) + ": not supported by the occt backend (Open CASCADE's " +
                    "B-spline degree limit is " + std::to_string(Geom_BSplineCurve::MaxDegree()) + ")",
                {.field = "degree"});
  const auto P = curve.control_points();
  const int n = static_cast<int>(P.size());
  TColgp_Array1OfPnt poles(1, n);
  for (int i = 0; i < n; ++i) {
    const Vec3& p = P[static_cast<std::size_t>(i)];
    poles.SetValue(i + 1, gp_Pnt(p.x, p.y, p.z));
  }
  // Run-length encode the full knot vector: OCCT stores distinct knots with multiplicities.
  std::vector<double> distinct;
  std::vector<int> mults;
  for (double u : curve.knots().values()) {
    if (!distinct.empty() && distinct.back() == u) {
      ++mults.back();
    } else {
      distinct.push_back(u);
      mults.push_back(1);
    }
  }
  const int k = static_cast<int>(distinct.size());
  TColStd_Array1OfReal knots(1, k);
  TColStd_Array1OfInteger m(1, k);
  for (int i = 0; i < k; ++i) {
    knots.SetValue(i + 1, distinct[static_cast<std::size_t>(i)]);
    m.SetValue(i + 1, mults[static_cast<std::size_t>(i)]);
  }
  try {
    if (curve.is_rational()) {
      TColStd_Array1OfReal w(1, n);
      for (int i = 0; i < n; ++i) w.SetValue(i + 1, curve.weights()[static_cast<std::size_t>(i)]);
      return new Geom_BSplineCurve(poles, w, knots, m, curve.degree());
    }
    return new Geom_BSplineCurve(poles, knots, m, curve.degree());
  } catch (const Standard_Failure& f) {
    throw Error(
        Errc::InvalidKnots,
        std::string("Open CASCADE refuses the curve's knots: ") + f.DynamicType()->Name() + ": " + f.GetMessageString(),
        {.field = "knots"});
  }
}

nurbs::NurbsCurve from_occt(const Handle(Geom_BSplineCurve) & curve, int dimension) {
  Handle(Geom_BSplineCurve) c = curve;
  if (c->IsPeriodic()) {
    c = Handle(Geom_BSplineCurve)::DownCast(curve->Copy());
    c->SetNotPeriodic();
  }
  const int n = c->NbPoles();
  std::vector<Vec3> points(static_cast<std::size_t>(n));
  bool planar = true;
  for (int i = 1; i <= n; ++i) {
    points[static_cast<std::size_t>(i - 1)] = to_vec3(c->Pole(i));
    planar = planar && c->Pole(i).Z() == 0.0;
  }
  std::vector<double> weights;
  if (c->IsRational()) {
    weights.resize(static_cast<std::size_t>(n));
    for (int i = 1; i <= n; ++i) weights[static_cast<std::size_t>(i - 1)] = c->Weight(i);
  }
  std::vector<double> knots;
  for (int i = 1; i <= c->NbKnots(); ++i)
    for (int j = 0; j < c->Multiplicity(i); ++j) knots.push_back(c->Knot(i));
  return {c->Degree(), std::move(knots), std::move(points), std::move(weights), dimension == 2 && planar ? 2 : 3};
}

Error occt_failure(std::string_view operation, const Standard_Failure& failure) {
  return Error(Errc::NumericalFailure,
               std::string(operation) + ": Open CASCADE raised " + failure.DynamicType()->Name() + ": " +
                   failure.GetMessageString(),
               {.field = std::string(operation)});
}

}  // namespace hula::oli
