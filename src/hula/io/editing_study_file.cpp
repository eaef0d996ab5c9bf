// SPDX-License-Identifier: MIT
// Study files of the editing studies; see editing_study.hpp and docs/formats.md.
#include "hula/io/editing_study_file.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "hula/core/error.hpp"
#include "hula/diffgeom/combescure.hpp"
#include "hula/io/json_read.hpp"
#include "hula/law/convert.hpp"
#include "hula/law/tape.hpp"

namespace hula::io {

using namespace studies;  // NOLINT(google-build-using-namespace): this file is the studies' codec

namespace {

const json::JsonPath kRoot = json::root_path("");

double number_member(const Json& body, std::string_view name, double fallback) {
  const Json* v = json::optional_member(body, name);
  return v ? json::get_number(*v, kRoot.member(name)) : fallback;
}

int samples_member(const Json& body, int fallback) {
  const Json* v = json::optional_member(body, "samples");
  return v ? static_cast<int>(json::get_integer(*v, kRoot.member("samples"), 2, 1000000)) : fallback;
}

diffgeom::Plane plane_member(const Json& body) {
  const std::string name = json::get_string(json::require_member(body, kRoot, "plane"), kRoot.member("plane"));
  return plane_from_name(name, "plane");
}

// The curve a file describes, as the studies take it (law files: the stand-in NURBS).
const nurbs::NurbsCurve& nurbs_of(const curve::Curve& c) { return c.nurbs(); }

// The largest change of each coordinate of `changed` against `original` at 1001 points of equal
// normalised parameter: [x, y, z].
Json max_change(const nurbs::NurbsCurve& changed, const nurbs::NurbsCurve& original) {
  Json out = Json::array();
  const nurbs::Interval dr = changed.domain(), dc = original.domain();
  for (std::size_t k = 0; k < 3; ++k) {
    double m = 0.0;
    for (int i = 0; i <= 1000; ++i) {
      const double u = i / 1000.0;
      m = std::max(m, std::abs(changed.evaluate(dr.start * (1 - u) + dr.end * u)[k] -
                               original.evaluate(dc.start * (1 - u) + dc.end * u)[k]));
    }
    out.push_back(m);
  }
  return out;
}

// max |a(t) − b(t)| of two laws of `parameter` at 1001 parameters of `domain`.
double law_deviation(const law::Law& a, const law::Law& b, const std::string& parameter, Interval domain) {
  law::CurveEvaluator ea(a, parameter, 0), eb(b, parameter, 0);
  double d = 0.0;
  for (int i = 0; i <= 1000; ++i) {
    const double u = i / 1000.0;
    Vec3 va[1], vb[1];
    const double t = domain.start * (1 - u) + domain.end * u;
    if (!ea.derivatives(t, va) || !eb.derivatives(t, vb))
      throw Error(Errc::NumericalFailure, "the transform is undefined at t = " + format_number(t), {.field = "curve"});
    d = std::max(d, distance(va[0], vb[0]));
  }
  return d;
}

Json fit_json(const LawCurveFit& f) {
  Json j = Json::object();
  j["curve"] = curve_to_json(f.curve);
  j["fit_deviation"] = f.fit_deviation;
  return j;
}

Json handles_json(const HermiteHandles& h, int dim) {
  Json arr = Json::array();
  for (std::size_t i = 0; i < h.points.size(); ++i) {
    Json k = Json::object();
    k["t"] = h.parameters[i];
    k["point"] = point_to_json(h.points[i], dim);
    k["first"] = point_to_json(h.first[i], dim);
    k["second"] = point_to_json(h.second[i], dim);
    k["tangent_handle"] = point_to_json(h.first[i], dim);
    k["normal_handle"] = point_to_json(h.normal_handle[i], dim);
    arr.push_back(std::move(k));
  }
  return arr;
}

}  // namespace

curve::Curve read_curve_member(const Json& body, std::string_view name) {
  const Json& value = json::require_member(body, kRoot, name);
  try {
    return curve_from_json(value);
  } catch (const Error& e) {
    ErrorWhere where = e.where();
    where.field = where.field.empty() ? std::string(name) : std::string(name) + "." + where.field;
    throw Error(e.code(), std::string(name) + ": " + e.message(), where);
  }
}

FinCompoundStudy read_fin_compound_study(const StudyDocument& doc) {
  const Json& b = doc.body;
  check_members(b, {"method", "curve", "compound", "plane", "scale", "c", "samples", "min_stretch", "tolerance"});
  FinCompoundStudy s;
  s.header = doc.header;
  const std::string method = json::get_string(json::require_member(b, kRoot, "method"), kRoot.member("method"));
  if (method == "projection") {
    s.method = FinCompoundMethod::Projection;
  } else if (method == "combescure") {
    s.method = FinCompoundMethod::Combescure;
  } else {
    throw Error(Errc::ParseError, "method = " + io::json::quote(method) + " must be \"projection\" or \"combescure\"",
                {.field = "method"});
  }
  auto refuse = [](const char* member, const char* method_name) {
    throw Error(Errc::ParseError,
                std::string(member) + ": not a member of a \"" + method_name + "\" fin-compound study",
                {.field = member});
  };
  const double tolerance = number_member(b, "tolerance", 1e-9);
  if (s.method == FinCompoundMethod::Projection) {
    if (json::optional_member(b, "c")) refuse("c", "projection");
    s.projection.plane = plane_member(b);
    s.projection.scale = number_member(b, "scale", 1.0);
    s.projection.samples = samples_member(b, s.projection.samples);
    s.projection.min_stretch = number_member(b, "min_stretch", s.projection.min_stretch);
    s.projection.fit.tolerance = tolerance;
    s.projection.validate();
    s.curve = read_curve_member(b, "curve");
    if (json::optional_member(b, "compound")) {
      s.compound = read_curve_member(b, "compound");
      require_planar(nurbs_of(*s.compound), s.projection.plane, "compound");
    }
  } else {
    for (const char* m : {"plane", "scale", "min_stretch"})
      if (json::optional_member(b, m)) refuse(m, "combescure");
    s.combescure.c = number_member(b, "c", 1.0);
    s.combescure.samples = samples_member(b, s.combescure.samples);
    s.combescure.fit.tolerance = tolerance;
    s.combescure.validate();
    const bool has_curve = json::optional_member(b, "curve") != nullptr;
    const bool has_compound = json::optional_member(b, "compound") != nullptr;
    if (has_curve == has_compound)
      throw Error(Errc::ParseError,
                  "a \"combescure\" fin-compound study needs exactly one of \"curve\" (the parent: forward "
                  "transform) and \"compound\" (prescribed: inverse transform)",
                  {.field = has_curve ? "compound" : "curve"});
    if (has_curve) s.curve = read_curve_member(b, "curve");
    if (has_compound) s.compound = read_curve_member(b, "compound");
  }
  return s;
}

EditProjectionStudy read_edit_projection_study(const StudyDocument& doc) {
  const Json& b = doc.body;
  check_members(b, {"curve", "edited", "plane"});
  const diffgeom::Plane plane = plane_member(b);
  EditProjectionStudy s{doc.header, read_curve_member(b, "curve"), read_curve_member(b, "edited"), plane};
  require_planar(s.edited.nurbs(), plane, "edited");
  return s;
}

HermiteStudy read_hermite_study(const StudyDocument& doc) {
  const Json& b = doc.body;
  check_members(b, {"spline", "rebuild", "edits"});
  HermiteStudy s;
  s.header = doc.header;
  const curve::Curve spline = read_curve_member(b, "spline");
  const auto* inputs = std::get_if<curve::InterpolatedData>(&spline.data());
  if (!inputs)
    throw Error(Errc::ParseError,
                "spline: must be an \"interpolated\" curve document (points to interpolate), got kind \"" +
                    std::string(spline.kind_name()) + "\"",
                {.field = "spline"});
  s.spline = *inputs;
  s.options.interpolation = s.spline.options();
  if (const Json* r = json::optional_member(b, "rebuild")) {
    const std::string name = json::get_string(*r, kRoot.member("rebuild"));
    if (name == "quintic")
      s.options.rebuild = HermiteRebuild::Quintic;
    else if (name == "cubic")
      s.options.rebuild = HermiteRebuild::Cubic;
    else
      throw Error(Errc::ParseError, "rebuild = " + io::json::quote(name) + " must be \"quintic\" or \"cubic\"",
                  {.field = "rebuild"});
  }
  if (const Json* e = json::optional_member(b, "edits")) {
    const json::JsonPath path = kRoot.member("edits");
    const Json& arr = json::get_array(*e, path);
    constexpr double kDeg = std::numbers::pi / 180.0;
    for (std::size_t i = 0; i < arr.size(); ++i) {
      const json::JsonPath p = path.element(i);
      const Json& item = arr[i];
      json::reject_unknown_members(item, p,
                                   {"knot", "tangent_angle", "tangent_scale", "normal_angle", "normal_scale", "axis"});
      HandleEdit h;
      h.knot = static_cast<std::size_t>(
          json::get_integer(json::require_member(item, p, "knot"), p.member("knot"), 0, 1000000000));
      auto num = [&](const char* name, double fallback) {
        const Json* v = json::optional_member(item, name);
        return v ? json::get_number(*v, p.member(name)) : fallback;
      };
      h.tangent_angle = num("tangent_angle", 0.0) * kDeg;
      h.tangent_scale = num("tangent_scale", 1.0);
      h.normal_angle = num("normal_angle", 0.0) * kDeg;
      h.normal_scale = num("normal_scale", 1.0);
      if (const Json* a = json::optional_member(item, "axis")) h.axis = json::get_point(*a, p.member("axis")).first;
      s.edits.push_back(h);
    }
  }
  s.options.validate();
  // Index and value checks of the edits, before any work (the spline itself is cheap; hermite_edit
  // repeats them and also checks what needs the spline, e.g. an undefined binormal).
  for (std::size_t i = 0; i < s.edits.size(); ++i)
    if (s.edits[i].knot >= s.spline.points.size())
      throw Error(Errc::InvalidArgument,
                  "edits[" + std::to_string(i) + "].knot = " + std::to_string(s.edits[i].knot) +
                      " is not a data point index (0 … " + std::to_string(s.spline.points.size() - 1) + ")",
                  {.field = "edits[" + std::to_string(i) + "].knot", .index = i});
  return s;
}

Json edit_projection_result_to_json(const EditProjectionStudy& study, const studies::ProjectionEditResult& r) {
  Json out = Json::object();
  out["study"] = "edit-projection";
  out["plane"] = std::string(diffgeom::plane_name(study.plane));
  out["parameter_match"] = "normalised";
  out["curve"] = curve_to_json(r.curve);
  out["max_deviation"] = r.max_deviation;
  out["max_change"] = max_change(r.curve, study.curve.nurbs());
  return out;
}

const nurbs::NurbsCurve& FinCompoundRun::result_curve() const {
  if (edit) return edit->curve;
  if (compound) return compound->curve;
  if (parent) return parent->curve;
  throw Error(Errc::InvalidArgument, "a fin-compound run without a result curve", {.field = "method"});
}

FinCompoundRun run_fin_compound_study(const FinCompoundStudy& s) {
  FinCompoundRun run;
  if (s.method == FinCompoundMethod::Projection) {
    const nurbs::NurbsCurve& curve = s.curve->nurbs();
    run.projection = diffgeom::project(curve, s.projection.plane);
    run.compound = normal_compound(curve, s.projection);
    if (s.compound) run.edit = edit_normal_compound(curve, s.compound->nurbs(), s.projection);
    return run;
  }
  const CombescureOptions& o = s.combescure;
  const bool forward = s.curve.has_value();
  const curve::Curve& input = forward ? *s.curve : *s.compound;
  // Law curves are transformed exactly; NURBS curves as laws of "t".
  const std::string parameter = input.law() ? input.law_parameter() : std::string("t");
  const Interval domain = input.domain();
  const law::Law input_law = input.law() ? *input.law() : law::from_nurbs(input.nurbs(), law::Context(), "t");
  LawCurveFit result = input.law()
                           ? (forward ? combescure_compound(input_law, parameter, domain, o)
                                      : combescure_parent(input_law, parameter, domain, o))
                           : (forward ? combescure_compound(input.nurbs(), o) : combescure_parent(input.nurbs(), o));
  // The check: transforming back (with −C, resp. +C) must give the input.
  const law::Law back = diffgeom::combescure_law(result.law, parameter, forward ? -o.c : o.c);
  run.round_trip_deviation = law_deviation(back, input_law, parameter, domain);
  (forward ? run.compound : run.parent) = std::move(result);
  return run;
}

Json fin_compound_result_to_json(const FinCompoundStudy& s, const FinCompoundRun& run) {
  Json out = Json::object();
  out["study"] = "fin-compound";
  out["method"] = s.method == FinCompoundMethod::Projection ? "projection" : "combescure";
  if (s.method == FinCompoundMethod::Projection) {
    out["plane"] = std::string(diffgeom::plane_name(s.projection.plane));
    out["scale"] = s.projection.scale;
    out["projection"] = curve_to_json(*run.projection);
    out["compound"] = fit_json(*run.compound);
    if (run.edit) {
      Json e = Json::object();
      e["planar"] = fit_json(run.edit->planar);
      e["curve"] = curve_to_json(run.edit->curve);
      e["min_stretch"] = run.edit->stretch.min_stretch;
      e["min_stretch_at"] = run.edit->stretch.at;
      e["forward_deviation"] = run.edit->forward_deviation;
      e["assembly_deviation"] = run.edit->assembly_deviation;
      // The dropped coordinate must not change.
      e["max_change"] = max_change(run.edit->curve, s.curve->nurbs());
      out["edit"] = std::move(e);
    }
    return out;
  }
  out["c"] = s.combescure.c;
  const bool forward = run.compound.has_value();
  Json r = fit_json(forward ? *run.compound : *run.parent);
  r["round_trip_deviation"] = run.round_trip_deviation;
  out[forward ? "compound" : "parent"] = std::move(r);
  return out;
}

Json hermite_result_to_json(const HermiteStudy& s, const HermiteEditResult& r) {
  const int dim = s.spline.dimension;
  Json out = Json::object();
  out["study"] = "hermite";
  out["rebuild"] = s.options.rebuild == HermiteRebuild::Quintic ? "quintic" : "cubic";
  out["spline"] = curve_to_json(r.spline);
  out["curve"] = curve_to_json(r.curve);
  out["before"] = handles_json(r.before, dim);
  out["after"] = handles_json(r.after, dim);
  // The largest distance from the spline at 1001 points of equal normalised parameter.
  double d = 0.0;
  const nurbs::Interval dc = r.curve.domain(), ds = r.spline.domain();
  for (int i = 0; i <= 1000; ++i) {
    const double u = i / 1000.0;
    d = std::max(d, distance(r.curve.evaluate(dc.start * (1.0 - u) + dc.end * u),
                             r.spline.evaluate(ds.start * (1.0 - u) + ds.end * u)));
  }
  out["max_distance_from_spline"] = d;
  return out;
}

}  // namespace hula::io
