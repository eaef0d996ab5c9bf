// SPDX-License-Identifier: MIT
// Open CASCADE fairing baselines (see the header).
#include "hula/oli/kernel/occt_fairing.hpp"

#include <FairCurve_AnalysisCode.hxx>
#include <FairCurve_Batten.hxx>
#include <FairCurve_MinimalVariation.hxx>
#include <Geom2d_BSplineCurve.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt2d.hxx>
#include <algorithm>
#include <cmath>
#include <limits>

#include "hula/core/error.hpp"
#include "hula/diffgeom/energy.hpp"
#include "hula/nurbs/closest_point.hpp"

namespace hula::oli {
namespace {

std::string code_name(FairCurve_AnalysisCode code) {
  switch (code) {
    case FairCurve_OK:
      return "OK";
    case FairCurve_NotConverged:
      return "NotConverged";
    case FairCurve_InfiniteSliding:
      return "InfiniteSliding";
    case FairCurve_NullHeight:
      return "NullHeight";
  }
  return "unknown";
}

// The planar OCCT B-spline as a 2-D NurbsCurve (flat knot sequence, poles, weights when rational).
nurbs::NurbsCurve from_occt_2d(const Handle(Geom2d_BSplineCurve) & c) {
  TColStd_Array1OfReal flat(1, c->NbPoles() + c->Degree() + 1);
  c->KnotSequence(flat);
  std::vector<double> knots(flat.begin(), flat.end());
  std::vector<Vec3> poles;
  std::vector<double> weights;
  for (int i = 1; i <= c->NbPoles(); ++i) {
    poles.push_back({c->Pole(i).X(), c->Pole(i).Y(), 0.0});
    if (c->IsRational()) weights.push_back(c->Weight(i));
  }
  return nurbs::NurbsCurve(c->Degree(), std::move(knots), std::move(poles), std::move(weights), 2);
}

double angle_of(const Vec3& v) { return std::atan2(v.y, v.x); }

// The angles OCCT's batten takes: Angle1 is the turn from the chord P1P2 to the tangent at P1 (counter-clockwise
// positive) and Angle2 the turn from the tangent at P2 to the chord (so a symmetric arch has Angle1 = Angle2).
// FairCurve's documentation gives no sign; these were measured — with them the computed curves' end tangents
// match the requested ones (tangent_error in tests/oli/occt_fairing_test.cpp).
double turn(const Vec3& from, const Vec3& to) {
  return std::remainder(angle_of(to) - angle_of(from), 2.0 * std::acos(-1.0));
}

double tangent_angle_error(const nurbs::NurbsCurve& c, double t, const Vec3& want) {
  const Vec3 d = c.derivatives(t, 1)[1];
  return std::abs(std::remainder(angle_of(d) - angle_of(want), 2.0 * std::acos(-1.0)));
}

void measure(FairingBaseline& b, const FairingEnds& ends, std::span<const Vec3> points) {
  const nurbs::NurbsCurve& c = *b.curve;
  b.bending = diffgeom::bending_energy(c).value;
  b.variation = diffgeom::curvature_variation_energy(c).value;
  double worst = 0.0, sum = 0.0;
  for (const Vec3& p : points) {
    const double d = nurbs::closest_point(c, Vec3{p.x, p.y, 0.0}).distance;
    worst = std::max(worst, d);
    sum += d;
  }
  b.max_deviation = worst;
  b.mean_deviation = points.empty() ? 0.0 : sum / static_cast<double>(points.size());
  b.tangent_error =
      std::max(tangent_angle_error(c, c.domain().start, ends.t1), tangent_angle_error(c, c.domain().end, ends.t2));
}

template <typename Algo>
FairingBaseline run(const char* name, Algo& algo, const FairingEnds& ends, std::span<const Vec3> points) {
  FairingBaseline b{.name = name};
  try {
    FairCurve_AnalysisCode code = FairCurve_OK;
    (void)algo.Compute(code, 50, 1e-3);
    b.status = code_name(code);
    const Handle(Geom2d_BSplineCurve) c = algo.Curve();
    if (!c.IsNull()) {
      b.curve = from_occt_2d(c);
      measure(b, ends, points);
    }
  } catch (const Standard_Failure& f) {
    b.status = std::string("exception: ") + f.DynamicType()->Name() + ": " +
               (f.GetMessageString() ? f.GetMessageString() : "");
    b.curve.reset();
  }
  if (!b.curve) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    b.bending = b.variation = b.max_deviation = b.mean_deviation = b.tangent_error = nan;
  }
  return b;
}

}  // namespace

std::vector<FairingBaseline> occt_fairing_baselines(const FairingEnds& ends, std::span<const Vec3> points) {
  const Vec3 chord{ends.p2.x - ends.p1.x, ends.p2.y - ends.p1.y, 0.0};
  const double length = std::hypot(chord.x, chord.y);
  if (!(length > 0.0))
    throw Error(Errc::CoincidentPoints, "p2 coincides with p1 in the xy-plane: a batten needs two distinct ends",
                ErrorWhere{.field = "p2"});
  if (std::hypot(ends.t1.x, ends.t1.y) == 0.0)
    throw Error(Errc::InvalidArgument, "t1 has no xy component", ErrorWhere{.field = "t1"});
  if (std::hypot(ends.t2.x, ends.t2.y) == 0.0)
    throw Error(Errc::InvalidArgument, "t2 has no xy component", ErrorWhere{.field = "t2"});
  const gp_Pnt2d p1(ends.p1.x, ends.p1.y), p2(ends.p2.x, ends.p2.y);
  // The section height only scales the batten's energy; 1 % of the chord keeps OCCT's tolerances relative.
  const double height = 0.01 * length;
  const double a1 = turn(chord, ends.t1), a2 = turn(ends.t2, chord);
  std::vector<FairingBaseline> out;
  for (const bool sliding : {false, true}) {
    try {
      FairCurve_Batten batten(p1, p2, height);
      batten.SetConstraintOrder1(1);
      batten.SetConstraintOrder2(1);
      batten.SetAngle1(a1);
      batten.SetAngle2(a2);
      batten.SetFreeSliding(sliding);
      out.push_back(run(sliding ? "batten-sliding" : "batten", batten, ends, points));
    } catch (const Standard_Failure& f) {
      out.push_back(FairingBaseline{.name = sliding ? "batten-sliding" : "batten",
                                    .status = std::string("exception: ") + f.DynamicType()->Name()});
    }
  }
  try {
    FairCurve_MinimalVariation mv(p1, p2, height, 0.0, 0.0);
    mv.SetConstraintOrder1(2);
    mv.SetConstraintOrder2(2);
    mv.SetAngle1(a1);
    mv.SetAngle2(a2);
    mv.SetCurvature1(ends.k1);
    mv.SetCurvature2(ends.k2);
    out.push_back(run("minimal-variation", mv, ends, points));
  } catch (const Standard_Failure& f) {
    out.push_back(
        FairingBaseline{.name = "minimal-variation", .status = std::string("exception: ") + f.DynamicType()->Name()});
  }
  return out;
}

}  // namespace hula::oli
