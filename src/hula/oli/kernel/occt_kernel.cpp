// SPDX-License-Identifier: MIT
// Each operation converts the value to a Geom_BSplineCurve (exact, see
// occt_convert.hpp), lets Open CASCADE do the work and converts back. Input
// checks OCCT does not make (it extrapolates outside the domain, merges
// knots, accepts one end tangent) are made first, with the native backend's
// error codes, so a document sees the same refusals whichever backend it uses.
#include "hula/oli/kernel/occt_kernel.hpp"

#include <GCPnts_AbscissaPoint.hxx>
#include <GeomAPI_Interpolate.hxx>
#include <GeomAdaptor_Curve.hxx>
#include <GeomLProp_CLProps.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_HArray1OfPnt.hxx>
#include <cmath>
#include <limits>
#include <string>

#include "hula/core/nan.hpp"
#include "hula/nurbs/knot_vector.hpp"
#include "hula/oli/kernel/detail/checks.hpp"
#include "hula/oli/kernel/occt_convert.hpp"

namespace hula::oli {
namespace {

// Every OCCT call goes through here so an OCCT exception becomes a hula::Error naming the operation.
template <class F>
auto guarded(std::string_view operation, F&& f) {
  try {
    return f();
  } catch (const Standard_Failure& e) {
    throw occt_failure(operation, e);
  }
}

Handle(Geom_BSplineCurve) copy_of(const nurbs::NurbsCurve& curve) { return to_occt(curve); }

// A copy clamped at its domain ends. OCCT's IncreaseDegree and Reverse work on the whole knot
// vector: on an unclamped curve the first fails and the second moves the domain. Segment to the
// domain clamps it exactly (knot insertion) and keeps the domain ends.
Handle(Geom_BSplineCurve) clamped_copy_of(const nurbs::NurbsCurve& curve) {
  auto c = to_occt(curve);
  const int p = c->Degree();
  if (c->Multiplicity(1) != p + 1 || c->Multiplicity(c->NbKnots()) != p + 1) {
    const auto d = curve.domain();
    c->Segment(d.start, d.end);
  }
  return c;
}

}  // namespace

nurbs::NurbsCurve OcctKernel::construct(int degree, std::vector<double> knots, std::vector<Vec3> control_points,
                                        std::vector<double> weights, int dimension) const {
  // The NurbsCurve constructor names the input at fault; OCCT then builds the curve (and may
  // refuse it with its own limits), and the result is what OCCT holds.
  const nurbs::NurbsCurve checked(degree, std::move(knots), std::move(control_points), std::move(weights), dimension);
  return from_occt(to_occt(checked), dimension);
}

Vec3 OcctKernel::evaluate(const nurbs::NurbsCurve& curve, double t) const {
  detail::check_parameter(curve, t);
  return guarded("evaluate", [&] { return to_vec3(copy_of(curve)->Value(t)); });
}

std::vector<Vec3> OcctKernel::derivatives(const nurbs::NurbsCurve& curve, double t, int order) const {
  detail::check_derivative_order(order);
  detail::check_parameter(curve, t);
  return guarded("derivatives", [&] {
    const auto c = copy_of(curve);
    gp_Pnt p;
    gp_Vec d1, d2, d3;
    c->D3(t, p, d1, d2, d3);
    std::vector<Vec3> out{to_vec3(p), to_vec3(d1), to_vec3(d2), to_vec3(d3)};
    out.resize(static_cast<std::size_t>(order) + 1);
    return out;
  });
}

nurbs::NurbsCurve OcctKernel::insert_knot(const nurbs::NurbsCurve& curve, double u, int times) const {
  detail::check_times(times);
  detail::check_parameter(curve, u, "u");
  const int p = curve.degree();
  int multiplicity = 0;
  for (double k : curve.knots().values()) multiplicity += k == u ? 1 : 0;
  if (multiplicity + times > p)
    throw Error(Errc::InvalidKnots,
                "u = " + format_number(u) + " has multiplicity " + std::to_string(multiplicity) + "; inserting it " +
                    std::to_string(times) + " more time(s) would exceed the degree " + std::to_string(p),
                {.field = "u"});
  return guarded("insert_knot", [&] {
    auto c = copy_of(curve);
    // Add = true raises the multiplicity by `times`; tolerance 0: only an exactly equal knot is "the same".
    c->InsertKnot(u, times, 0.0, Standard_True);
    return from_occt(c, curve.dimension());
  });
}

nurbs::NurbsCurve OcctKernel::elevate_degree(const nurbs::NurbsCurve& curve, int times) const {
  detail::check_times(times);
  const int target = curve.degree() + times;
  if (target > nurbs::kMaxDegree)
    throw Error(Errc::InvalidDegree,
                "degree " + std::to_string(curve.degree()) + " + " + std::to_string(times) +
                    " exceeds kMaxDegree = " + std::to_string(nurbs::kMaxDegree),
                {.field = "times"});
  if (target > Geom_BSplineCurve::MaxDegree())
    throw Error(Errc::Unsupported,
                "elevate_degree to " + std::to_string(target) + ": not supported by the occt backend (degree limit " +
                    std::to_string(Geom_BSplineCurve::MaxDegree()) + ")",
                {.field = "elevate_degree"});
  return guarded("elevate_degree", [&] {
    auto c = clamped_copy_of(curve);
    c->IncreaseDegree(target);
    return from_occt(c, curve.dimension());
  });
}

nurbs::SplitResult OcctKernel::split(const nurbs::NurbsCurve& curve, double t) const {
  detail::check_parameter(curve, t);
  const auto d = curve.domain();
  if (t <= d.start || t >= d.end)
    throw Error(Errc::OutOfDomain,
                "t = " + format_number(t) + " is not strictly inside the domain (" + format_number(d.start) + ", " +
                    format_number(d.end) + ")",
                {.field = "t"});
  return guarded("split", [&] {
    auto before = copy_of(curve);
    auto after = copy_of(curve);
    before->Segment(d.start, t);
    after->Segment(t, d.end);
    return nurbs::SplitResult{from_occt(before, curve.dimension()), from_occt(after, curve.dimension())};
  });
}

nurbs::NurbsCurve OcctKernel::reverse(const nurbs::NurbsCurve& curve) const {
  return guarded("reverse", [&] {
    auto c = clamped_copy_of(curve);
    c->Reverse();
    return from_occt(c, curve.dimension());
  });
}

nurbs::NurbsCurve OcctKernel::interpolate(std::span<const Vec3> points, const KernelInterpolation& options) const {
  detail::check_interpolation(points, options);
  const std::size_t n = points.size();
  if (n < 2)
    throw Error(Errc::TooFewPoints, "interpolation needs at least 2 points, got " + std::to_string(n),
                {.field = "points"});
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t k = 0; k < 3; ++k)
      if (!std::isfinite(points[i][k]))
        throw Error(Errc::NonFiniteInput, "points[" + std::to_string(i) + "][" + std::to_string(k) + "] is not finite",
                    {.field = "points", .index = i, .component = k});
  // Data parameters on [0, 1]: given ones mapped affinely, else normalised chord length (eq. 29) —
  // GeomAPI_Interpolate's own default is the unnormalised chord length, so they are always passed.
  std::vector<double> t(n);
  if (!options.parameters.empty()) {
    if (options.parameters.size() != n)
      throw Error(Errc::InvalidArgument,
                  std::to_string(options.parameters.size()) + " parameters for " + std::to_string(n) + " points",
                  {.field = "parameters"});
    for (std::size_t i = 0; i < n; ++i) {
      if (!std::isfinite(options.parameters[i]))
        throw Error(Errc::NonFiniteInput, "parameters[" + std::to_string(i) + "] is not finite",
                    {.field = "parameters", .index = i});
      if (i > 0 && !(options.parameters[i] > options.parameters[i - 1]))
        throw Error(Errc::InvalidArgument,
                    "parameters[" + std::to_string(i) + "] = " + format_number(options.parameters[i]) +
                        " is not greater than parameters[" + std::to_string(i - 1) + "]",
                    {.field = "parameters", .index = i});
    }
    const double a = options.parameters.front(), L = options.parameters.back() - a;
    for (std::size_t i = 0; i < n; ++i) t[i] = (options.parameters[i] - a) / L;
  } else {
    Box3 box;
    for (const Vec3& p : points) box.add(p);
    const double coincident = 1e-12 * box.diagonal();
    t[0] = 0.0;
    for (std::size_t i = 1; i < n; ++i) {
      const double d = norm(points[i] - points[i - 1]);
      if (d <= coincident)
        throw Error(Errc::CoincidentPoints,
                    "points[" + std::to_string(i - 1) + "] and points[" + std::to_string(i) +
                        "] coincide (chord-length parameters need distinct consecutive points)",
                    {.field = "points", .index = i});
      t[i] = t[i - 1] + d;
    }
    for (std::size_t i = 1; i < n; ++i) t[i] /= t[n - 1];
  }
  t.back() = 1.0;
  return guarded("interpolate", [&] {
    Handle(TColgp_HArray1OfPnt) poles = new TColgp_HArray1OfPnt(1, static_cast<int>(n));
    Handle(TColStd_HArray1OfReal) params = new TColStd_HArray1OfReal(1, static_cast<int>(n));
    for (std::size_t i = 0; i < n; ++i) {
      poles->SetValue(static_cast<int>(i) + 1, gp_Pnt(points[i].x, points[i].y, points[i].z));
      params->SetValue(static_cast<int>(i) + 1, t[i]);
    }
    // Tolerance 0: the coincidence test above already ran with our scale-relative rule.
    GeomAPI_Interpolate interpolator(poles, params, Standard_False, 0.0);
    if (options.start_tangent) {
      const Vec3 &s = *options.start_tangent, &e = *options.end_tangent;
      // Scale = false: the tangents are dC/dt as given, magnitude honoured.
      interpolator.Load(gp_Vec(s.x, s.y, s.z), gp_Vec(e.x, e.y, e.z), Standard_False);
    }
    interpolator.Perform();
    if (!interpolator.IsDone())
      throw Error(Errc::NumericalFailure, "GeomAPI_Interpolate failed on " + std::to_string(n) + " points",
                  {.field = "points"});
    return from_occt(interpolator.Curve(), 3);
  });
}

double OcctKernel::curvature(const nurbs::NurbsCurve& curve, double t) const {
  detail::check_parameter(curve, t);
  return guarded("curvature", [&] {
    const auto c = copy_of(curve);
    // The resolution below which OCCT calls a derivative zero, relative to the model size and
    // domain length like the native zero-speed test.
    const double resolution = 1e-14 * curve.model_size() / curve.domain().length();
    GeomLProp_CLProps props(c, t, 2, resolution);
    if (!props.IsTangentDefined()) return kNaN;
    return props.Curvature();
  });
}

double OcctKernel::torsion(const nurbs::NurbsCurve& /*curve*/, double /*t*/) const {
  throw Error(Errc::Unsupported, "torsion: not supported by the occt backend (GeomLProp_CLProps has no torsion)",
              {.field = "torsion"});
}

double OcctKernel::arc_length(const nurbs::NurbsCurve& curve, double a, double b) const {
  detail::check_parameter(curve, a, "a");
  detail::check_parameter(curve, b, "b");
  if (a > b)
    throw Error(Errc::InvalidArgument, "a = " + format_number(a) + " is greater than b = " + format_number(b),
                {.field = "a"});
  return guarded("arc_length", [&] {
    GeomAdaptor_Curve adaptor(copy_of(curve));
    return GCPnts_AbscissaPoint::Length(adaptor, a, b, 1e-14);
  });
}

}  // namespace hula::oli
