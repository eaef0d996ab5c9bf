// SPDX-License-Identifier: MIT
// Curves made from curves and points (curve_edits.hpp).
#include "hula/io/curve_edits.hpp"

#include <algorithm>
#include <array>

#include "hula/core/error.hpp"
#include "hula/intrinsic/natural_curve.hpp"
#include "hula/io/frenet_handles_json.hpp"
#include "hula/law/convert.hpp"
#include "hula/law/parser.hpp"
#include "hula/law/tape.hpp"
#include "hula/nurbs/approximate.hpp"
#include "hula/nurbs/elevate.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/nurbs/knot_removal.hpp"
#include "hula/nurbs/refine.hpp"
#include "hula/nurbs/reparam.hpp"
#include "hula/studies/tolerance_fit.hpp"

namespace hula::io {

namespace {

// The NURBS of a curve file; edits need the NURBS itself, not the stand-in of a law or natural curve.
const nurbs::NurbsCurve& nurbs_of(const curve::Curve& c, const std::string& path) {
  if (c.has_exact_evaluation())
    throw Error(Errc::InvalidArgument,
                path + " is a " + std::string(c.kind_name()) + " curve: edit its NURBS form (hula edit to-nurbs " +
                    path + " --tolerance T -o FILE) instead",
                ErrorWhere{.field = "curve"});
  return c.nurbs();
}

}  // namespace

CurveEditAnswer edit_curve(const curve::Curve& c, const std::string& path, const CurveEditRequest& q) {
  CurveEditAnswer out;
  switch (q.edit) {
    case CurveEdit::InsertKnot:
      out.curves.push_back(nurbs::insert_knot(nurbs_of(c, path), q.at, q.times));
      break;
    case CurveEdit::Refine:
      out.curves.push_back(nurbs::refine_knots(nurbs_of(c, path), q.knots));
      break;
    case CurveEdit::RemoveKnot:
    case CurveEdit::RemoveKnots: {
      const nurbs::NurbsCurve& curve = nurbs_of(c, path);
      nurbs::KnotRemovalResult r = q.edit == CurveEdit::RemoveKnot
                                       ? nurbs::remove_knot(curve, q.at, q.times, q.tolerance)
                                       : nurbs::remove_knots(curve, q.tolerance);
      out.report["removed"] = r.removed;
      out.report["error_bound"] = r.error_bound;
      out.report["tolerance"] = q.tolerance;
      out.curves.push_back(std::move(r.curve));
      break;
    }
    case CurveEdit::Elevate:
      out.curves.push_back(nurbs::elevate_degree(nurbs_of(c, path), q.times));
      break;
    case CurveEdit::ReduceDegree: {
      nurbs::DegreeReductionResult r = nurbs::reduce_degree(nurbs_of(c, path), q.tolerance);
      out.report["error_bound"] = r.error_bound;
      out.report["bezier_bound"] = r.bezier_bound;
      out.report["tolerance"] = q.tolerance;
      out.curves.push_back(std::move(r.curve));
      break;
    }
    case CurveEdit::Rebuild: {
      nurbs::RebuildResult r = nurbs::rebuild(
          nurbs_of(c, path), {.degree = q.degree, .control_points = q.control_points, .samples = q.samples});
      out.report["degree"] = q.degree;
      out.report["control_points"] = q.control_points;
      out.report["samples"] = r.samples;
      out.report["max_deviation"] = r.max_deviation;
      out.report["mean_deviation"] = r.mean_deviation;
      out.report["at"] = r.at;
      out.curves.push_back(std::move(r.curve));
      break;
    }
    case CurveEdit::Split: {
      nurbs::SplitResult s = nurbs::split(nurbs_of(c, path), q.at);
      out.report["at"] = q.at;
      out.curves.push_back(std::move(s.before));
      out.curves.push_back(std::move(s.after));
      break;
    }
    case CurveEdit::Reverse:
      out.curves.push_back(nurbs::reverse(nurbs_of(c, path)));
      break;
    case CurveEdit::Reparam:
      out.curves.push_back(nurbs::reparameterise(nurbs_of(c, path), q.domain));
      break;
    case CurveEdit::ToNurbs: {
      intrinsic::CurveToNurbsResult r = intrinsic::to_nurbs(c, q.tolerance);
      out.report["from"] = std::string(c.kind_name());
      out.report["tolerance"] = q.tolerance;
      out.report["max_deviation"] = r.max_deviation;
      out.curves.push_back(std::move(r.curve));
      break;
    }
  }
  return out;
}

LawConversionAnswer law_from_nurbs(const curve::Curve& c, const std::string& path) {
  if (c.has_exact_evaluation())
    throw Error(Errc::InvalidArgument,
                path + " is a " + std::string(c.kind_name()) +
                    " curve, held by its laws already: only a NURBS "
                    "(or Bézier, interpolated, Hermite) curve is written out as a law",
                ErrorWhere{.field = "curve"});
  const nurbs::NurbsCurve& n = c.nurbs();
  const law::Context context;
  const law::Law l = law::explicit_from_nurbs(n, context, "t");
  LawConversionAnswer out{curve::Curve::from_law(law::print(l), "t", n.domain()), law::print(l)};
  // The difference is measured on the text as the law curve holds it (parsed back), not on the built law.
  const law::CurveEvaluator exact(law::parse(out.expression, context), "t", 0);
  const Interval d = n.domain();
  double worst = 0.0;
  for (int i = 0; i <= 1000; ++i) {
    const double t = i == 1000 ? d.end : d.start + (d.end - d.start) * i / 1000.0;
    std::array<Vec3, 1> v{};
    (void)exact.derivatives(t, v);
    worst = std::max(worst, norm(v[0] - n.evaluate(t)));
  }
  std::size_t spans = 0;
  const auto U = n.knots().values();
  for (std::size_t i = 0; i + 1 < U.size(); ++i)
    if (U[i] < U[i + 1]) ++spans;
  out.report["spans"] = spans;
  out.report["degree"] = n.degree();
  out.report["max_difference"] = worst;
  out.report["expression_length"] = out.expression.size();
  return out;
}

Json edited_curve_summary(const std::string& path, const nurbs::NurbsCurve& c) {
  Json j = Json::object();
  j["output"] = path;
  j["degree"] = c.degree();
  j["control_points"] = c.control_points().size();
  Json knots = Json::array();
  for (double u : c.knots().values()) knots.push_back(u);
  j["knots"] = std::move(knots);
  j["domain"] = Json::array({c.domain().start, c.domain().end});
  return j;
}

Json curve_shape_summary(const nurbs::NurbsCurve& c) {
  Json j = Json::object();
  j["dimension"] = c.dimension();
  j["degree"] = c.degree();
  j["control_points"] = c.control_points().size();
  j["domain"] = Json::array({c.domain().start, c.domain().end});
  return j;
}

nurbs::NurbsCurve lagrange_curve(const PointSet& set, std::span<const double> parameters,
                                 nurbs::Parameterisation rule) {
  const std::vector<double> ts = parameters.empty() ? nurbs::parameterise(set.points, rule)
                                                    : std::vector<double>(parameters.begin(), parameters.end());
  return nurbs::interpolate_lagrange(set.points, ts, set.dimension);
}

nurbs::NurbsCurve closed_cubic_curve(const PointSet& set, std::span<const double> parameters,
                                     nurbs::Parameterisation rule) {
  nurbs::InterpolationOptions o;
  o.dimension = set.dimension;
  o.parameterisation = rule;
  if (!parameters.empty()) o.parameters = std::vector<double>(parameters.begin(), parameters.end());
  return nurbs::interpolate_closed_cubic(set.points, o);
}

MadeCurveAnswer closed_interpolation_answer(const PointSet& set, std::span<const double> parameters,
                                            std::string_view parameterisation) {
  const nurbs::Parameterisation rule = parameterisation_from_name(parameterisation, "parameterisation");
  MadeCurveAnswer out{closed_cubic_curve(set, parameters, rule)};
  out.report["kind"] = "nurbs";
  out.report["method"] = "closed";
  out.report["points"] = set.points.size();
  out.report.update(curve_shape_summary(out.curve));
  out.report["parameterisation"] = parameters.empty() ? std::string(parameterisation) : std::string("given");
  return out;
}

MadeCurveAnswer hermite_frenet_answer(const Json& handles) {
  MadeCurveAnswer out{hermite_frenet_curve(handles)};
  out.report["degree"] = out.curve.degree();
  out.report["control_points"] = out.curve.control_points().size();
  out.report["domain"] = Json::array({out.curve.domain().start, out.curve.domain().end});
  return out;
}

ApproximationAnswer approximation_answer(const PointSet& set, const ApproximationRequest& q) {
  if (q.tolerance.has_value() == q.control_points.has_value())
    throw Error(Errc::InvalidArgument, "give exactly one of tolerance and control_points",
                ErrorWhere{.field = "tolerance"});
  Json report = Json::object();
  if (q.tolerance) {
    studies::ToleranceFitOptions t;
    t.tolerance = *q.tolerance;
    t.degree = q.degree;
    t.min_degree = q.degree;
    t.ends = studies::FitEnds::Interpolated;
    t.max_control_points = std::max<std::size_t>(set.points.size(), static_cast<std::size_t>(q.degree) + 1);
    const std::vector<double> start = nurbs::parameterise(set.points, q.parameterisation);
    studies::ToleranceFit fit = studies::fit_within_tolerance(set.points, start, {}, t);
    report["degree"] = fit.faired.degree();
    report["control_points"] = fit.faired.control_points().size();
    report["tolerance"] = *q.tolerance;
    report["max_deviation"] = fit.max_deviation;
    report["max_deviation_index"] = fit.max_deviation_index;
    report["fits"] = fit.fits;
    report["fit_max_deviation"] = fit.fit_max_deviation;
    report["smoothing"] = fit.smoothing;
    return {std::move(fit.faired), std::move(report)};
  }
  nurbs::ApproximationOptions o;
  o.degree = q.degree;
  o.dimension = set.dimension;
  o.parameterisation = q.parameterisation;
  o.control_points = *q.control_points;
  nurbs::ApproximationResult fit = nurbs::approximate(set.points, o);
  report["degree"] = fit.curve.degree();
  report["control_points"] = fit.curve.control_points().size();
  report["max_deviation"] = fit.max_deviation;
  report["max_deviation_index"] = fit.max_deviation_index;
  report["fits"] = 1;
  return {std::move(fit.curve), std::move(report)};
}

}  // namespace hula::io
