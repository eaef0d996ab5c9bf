// SPDX-License-Identifier: MIT
// NurbsCurve, interpolate, analyse and reconstruct for Python: the nurbs,
// diffgeom and intrinsic modules behind NumPy arrays (analyse is
// diffgeom::analyse_curve, the one analysis of every door). Evaluation writes
// straight into the output array through the C++ batch APIs with the GIL
// released; t keeps its shape and gains a trailing axis of the curve's
// dimension (2 for planar curves, a view of the x, y columns).
#include <pybind11/numpy.h>
#include <pybind11/operators.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "hula/core/error.hpp"
#include "hula/diffgeom/analysis.hpp"
#include "hula/intrinsic/clothoid.hpp"
#include "hula/intrinsic/natural_equations.hpp"
#include "hula/io/curve_analysis_json.hpp"
#include "hula/io/curve_edits.hpp"
#include "hula/io/exact_curves.hpp"
#include "hula/io/intersection_json.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/points_file.hpp"
#include "hula/nurbs/arc_length.hpp"
#include "hula/nurbs/closest_point.hpp"
#include "hula/nurbs/elevate.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/nurbs/nurbs_curve.hpp"
#include "hula/nurbs/refine.hpp"
#include "hula/nurbs/reparam.hpp"
#include "laws.hpp"

namespace hula::python {

namespace py = pybind11;
using nurbs::NurbsCurve;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

nurbs::EvalOptions eval_options(const std::string& domain, const std::string& side) {
  nurbs::EvalOptions o;
  if (domain == "strict")
    o.domain = nurbs::Domain::Strict;
  else if (domain == "clamp")
    o.domain = nurbs::Domain::Clamp;
  else if (domain == "extrapolate")
    o.domain = nurbs::Domain::Extrapolate;
  else
    throw Error(
        Errc::InvalidArgument,
        "domain = \"" + domain + "\" is not a domain policy (expected \"strict\", \"clamp\" or \"extrapolate\")",
        {.field = "domain"});
  if (side == "right")
    o.side = nurbs::Side::Right;
  else if (side == "left")
    o.side = nurbs::Side::Left;
  else
    throw Error(Errc::InvalidArgument, "side = \"" + side + "\" is not a side (expected \"right\" or \"left\")",
                {.field = "side"});
  return o;
}

// The output array: t's shape followed by `extra` trailing axes, float64, C order. When `out` is given
// it must be exactly that (the allocation-free path of hot loops).
Doubles output(const Doubles& ts, std::vector<py::ssize_t> extra, const py::object& out) {
  std::vector<py::ssize_t> shape(ts.shape(), ts.shape() + ts.ndim());
  shape.insert(shape.end(), extra.begin(), extra.end());
  if (out.is_none()) return Doubles(shape);
  if (!py::isinstance<py::array>(out)) {
    throw Error(Errc::InvalidArgument, "out must be a float64 numpy array", {.field = "out"});
  }
  const auto a = out.cast<py::array>();
  bool ok = a.dtype().is(py::dtype::of<double>()) && (a.flags() & py::array::c_style) != 0 && a.writeable() &&
            a.ndim() == static_cast<py::ssize_t>(shape.size());
  for (std::size_t i = 0; ok && i < shape.size(); ++i) ok = a.shape(static_cast<py::ssize_t>(i)) == shape[i];
  if (!ok) {
    py::array expect(py::dtype::of<double>(), shape);
    throw Error(Errc::InvalidArgument,
                "out has shape " + shape_text(a) + " and dtype " + py::str(a.dtype()).cast<std::string>() +
                    ": expected a writeable C-contiguous float64 array of shape " + shape_text(expect),
                {.field = "out"});
  }
  return py::reinterpret_borrow<Doubles>(a);
}

py::object evaluate(const NurbsCurve& c, py::handle t, const std::string& domain, const std::string& side,
                    const py::object& out) {
  const nurbs::EvalOptions o = eval_options(domain, side);
  const Doubles ts = as_doubles(t, "t");
  const auto n = static_cast<std::size_t>(ts.size());
  // Always 3 doubles per point (Vec3); planar curves return a view of x, y, so `out` must be (..., 3).
  Doubles result = output(ts, {3}, out);
  {
    const py::gil_scoped_release release;
    c.evaluate(std::span<const double>(ts.data(), n),
               std::span<Vec3>(reinterpret_cast<Vec3*>(result.mutable_data()), n), o);
  }
  if (!out.is_none()) return out;
  return vec3_rows(result, c.dimension());
}

py::array derivatives(const NurbsCurve& c, py::handle t, int order, const std::string& domain,
                      const std::string& side) {
  if (order < 0 || order > 64) {
    throw Error(Errc::InvalidArgument, "order = " + std::to_string(order) + " must be in [0, 64]", {.field = "order"});
  }
  const nurbs::EvalOptions o = eval_options(domain, side);
  const Doubles ts = as_doubles(t, "t");
  const auto n = static_cast<std::size_t>(ts.size());
  const auto per = static_cast<std::size_t>(order) + 1;
  Doubles result = output(ts, {static_cast<py::ssize_t>(per), 3}, py::none());
  {
    const py::gil_scoped_release release;
    c.derivatives(std::span<const double>(ts.data(), n), order,
                  std::span<Vec3>(reinterpret_cast<Vec3*>(result.mutable_data()), n * per), o);
  }
  return vec3_rows(result, c.dimension());
}

NurbsCurve make_curve(int degree, py::handle knots, py::handle control_points, py::handle weights) {
  const Points p = as_points(control_points, "control_points");
  std::vector<double> w;
  if (!weights.is_none()) w = as_vector(weights, "weights");
  return NurbsCurve(degree, as_vector(knots, "knots"), p.points, std::move(w), p.dimension);
}

std::string to_json_text(const NurbsCurve& c) { return io::to_file_text(io::curve_to_json(c)); }

NurbsCurve from_json(py::handle value) {
  if (py::isinstance<py::str>(value)) return io::parse_curve_json(value.cast<std::string>()).nurbs();
  if (py::isinstance<py::dict>(value)) return io::curve_from_json(from_python(value, "document")).nurbs();
  throw Error(Errc::InvalidArgument, "document must be a JSON string or a dict", {.field = "document"});
}

nurbs::EndCondition end_condition(py::handle value, const std::string& name) {
  io::Json j;
  if (py::isinstance<py::str>(value)) {
    j = value.cast<std::string>();
  } else {
    const Vec3 d = as_point(value, name);
    j = io::Json{{"tangent", {d.x, d.y, d.z}}};
  }
  return io::end_condition_from_json(j, name);
}

// n rows of 3 doubles (NaN where `defined` is false or a coordinate is not).
template <class Get, class Defined>
Doubles rows3(std::size_t n, Get&& get, Defined&& defined) {
  Doubles a({static_cast<py::ssize_t>(n), py::ssize_t{3}});
  double* r = a.mutable_data();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 v = defined(i) ? get(i) : Vec3{kNaN, kNaN, kNaN};
    r[3 * i] = v.x, r[3 * i + 1] = v.y, r[3 * i + 2] = v.z;
  }
  return a;
}
template <class Get>
Doubles column(std::size_t n, Get&& get) {
  Doubles a(static_cast<py::ssize_t>(n));
  for (std::size_t i = 0; i < n; ++i) a.mutable_data()[i] = get(i);
  return a;
}

py::object vec_or_none(const Vec3& v, bool defined) {
  if (!defined || !is_finite(v)) return py::none();
  return py::make_tuple(v.x, v.y, v.z);
}

py::list feature_list(const std::vector<diffgeom::Feature>& list, const char* value_name, bool curvature) {
  py::list out;
  for (const diffgeom::Feature& f : list) {
    py::dict d;
    if (value_name != nullptr) d["kind"] = std::string(io::extremum_kind_name(f.kind));
    d["t"] = f.t;
    d["point"] = vec_or_none(f.position, true);
    if (value_name != nullptr) d[value_name] = curvature ? f.curvature : f.torsion;
    out.append(d);
  }
  return out;
}

// The analysis as Python objects with the members of io::curve_analysis_json (docs/formats.md, "Curve
// analysis"): columns as NumPy arrays (NaN where the JSON has null), features as lists of dicts.
py::dict analysis_to_python(const diffgeom::CurveAnalysis& a) {
  const std::vector<diffgeom::FrenetPoint>& f = a.samples;
  const std::size_t n = f.size();
  py::dict d;
  d["t"] = column(n, [&](std::size_t i) { return f[i].t; });
  if (!a.s.empty()) d["s"] = column(n, [&](std::size_t i) { return a.s[i]; });
  d["points"] = rows3(
      n, [&](std::size_t i) { return f[i].position; }, [](std::size_t) { return true; });
  py::dict frames;
  frames["T"] = rows3(
      n, [&](std::size_t i) { return f[i].tangent; }, [&](std::size_t i) { return f[i].tangent_defined; });
  frames["N"] = rows3(
      n, [&](std::size_t i) { return f[i].normal; }, [&](std::size_t i) { return f[i].frame_defined; });
  frames["B"] = rows3(
      n, [&](std::size_t i) { return f[i].binormal; }, [&](std::size_t i) { return f[i].frame_defined; });
  d["frames"] = frames;
  d["curvature"] = column(n, [&](std::size_t i) { return f[i].tangent_defined ? f[i].curvature : kNaN; });
  d["torsion"] = column(n, [&](std::size_t i) { return f[i].torsion_defined ? f[i].torsion : kNaN; });
  d["curvature_derivative"] =
      column(n, [&](std::size_t i) { return f[i].frame_defined ? f[i].curvature_derivative : kNaN; });
  d["speed"] =
      column(n, [&](std::size_t i) { return f[i].reason == diffgeom::Undefined::NonFinite ? kNaN : f[i].speed; });
  if (!a.bishop.empty()) {
    py::dict b;
    b["U"] = rows3(
        n, [&](std::size_t i) { return a.bishop[i].u; }, [&](std::size_t i) { return a.bishop[i].defined; });
    b["V"] = rows3(
        n, [&](std::size_t i) { return a.bishop[i].v; }, [&](std::size_t i) { return a.bishop[i].defined; });
    d["bishop"] = b;
  }
  py::list fins;
  for (const diffgeom::AnalysedFins& comb : a.fins) {
    const diffgeom::Fins& c = comb.fins;
    py::dict x;
    x["kind"] = std::string(diffgeom::fin_kind_name(comb.kind));
    x["scale"] = comb.scale;
    x["t"] = to_array(c.t);
    x["base"] = rows3(
        c.t.size(), [&](std::size_t i) { return c.base[i]; }, [](std::size_t) { return true; });
    x["tip"] = rows3(
        c.t.size(), [&](std::size_t i) { return c.tip[i]; }, [&](std::size_t i) { return c.defined[i] != 0; });
    fins.append(x);
  }
  d["fins"] = fins;
  d["planarity"] = to_python(io::planarity_to_json(a.planarity));
  if (a.features) {
    const diffgeom::CurveFeatures& ft = *a.features;
    py::dict x;
    x["inflections"] = feature_list(ft.inflections, nullptr, true);
    x["curvature_extrema"] = feature_list(ft.curvature_extrema, "curvature", true);
    x["torsion_extrema"] = feature_list(ft.torsion_extrema, "torsion", false);
    py::list knots;
    for (const diffgeom::Continuity& k : ft.knots) {
      py::dict kd;
      kd["t"] = k.t;
      kd["multiplicity"] = k.multiplicity;
      kd["parametric"] = k.parametric >= 0 ? py::object(py::int_(k.parametric)) : py::none();
      kd["geometric"] = k.geometric >= 0 ? py::object(py::int_(k.geometric)) : py::none();
      kd["tangent_angle"] = k.tangent_angle;
      kd["curvature_left"] = k.curvature_left;
      kd["curvature_right"] = k.curvature_right;
      py::list left, right;
      for (const Vec3& v : k.left) left.append(vec_or_none(v, true));
      for (const Vec3& v : k.right) right.append(vec_or_none(v, true));
      kd["left"] = left;
      kd["right"] = right;
      knots.append(kd);
    }
    x["knots"] = knots;
    const diffgeom::CurvatureMonotonicity& m = ft.monotonicity;
    py::dict mono;
    mono["monotone"] = m.monotone();
    py::list pieces, violations;
    for (const diffgeom::MonotonePiece& p : m.pieces) {
      py::dict pd;
      pd["t0"] = p.t0;
      pd["t1"] = p.t1;
      pd["curvature0"] = p.kappa0;
      pd["curvature1"] = p.kappa1;
      pd["trend"] = std::string(diffgeom::curvature_trend_name(p.trend));
      pieces.append(pd);
    }
    for (const diffgeom::Feature& v : m.violations) {
      py::dict vd;
      vd["kind"] = std::string(io::extremum_kind_name(v.kind));
      vd["t"] = v.t;
      vd["curvature"] = v.curvature;
      violations.append(vd);
    }
    mono["pieces"] = pieces;
    mono["violations"] = violations;
    x["curvature_monotonicity"] = mono;
    x["maximum_curvature"] = to_python(io::maximum_curvature_to_json(ft.maximum_curvature));
    x["self_intersections"] = to_python(io::intersection_to_json(ft.self_intersections, 3));
    d["features"] = x;
  }
  return d;
}

py::dict analyse(py::handle curve, int samples, py::handle at, const std::string& by, bool arc_lengths, bool bishop,
                 const std::vector<std::string>& fins, std::optional<double> fin_scale, int fin_density,
                 bool features) {
  const curve::Curve c = curve_value(curve);
  diffgeom::AnalysisOptions o;
  o.samples = samples;
  if (!at.is_none()) o.at = as_vector(at, "at");
  const std::optional<diffgeom::SampleBy> b = diffgeom::sample_by_from_name(by);
  if (!b)
    throw Error(Errc::InvalidOption, "by = \"" + by + "\" is not \"parameter\" or \"arclength\"", {.field = "by"});
  o.by = *b;
  o.arc_lengths = arc_lengths;
  o.bishop = bishop;
  for (std::size_t i = 0; i < fins.size(); ++i) {
    const std::optional<diffgeom::FinKind> k = diffgeom::fin_kind_from_name(fins[i]);
    if (!k)
      throw Error(Errc::InvalidOption, "fins[" + std::to_string(i) + "] = \"" + fins[i] + "\" is not a fin kind",
                  {.field = "fins", .index = i});
    o.fins.push_back(*k);
  }
  o.fin_scale = fin_scale;
  o.fin_density = fin_density;
  o.features = features;
  diffgeom::CurveAnalysis a;
  {
    const py::gil_scoped_release release;
    a = diffgeom::analyse_curve(c, o);
  }
  return analysis_to_python(a);
}

py::dict frames(const intrinsic::IntrinsicCurve& c, py::handle s_value) {
  const Doubles s = as_doubles(s_value, "s");
  const auto n = static_cast<std::size_t>(s.size());
  std::vector<intrinsic::FramePoint> pts;
  {
    const py::gil_scoped_release release;
    pts = c.evaluate(std::span<const double>(s.data(), n));
  }
  std::vector<py::ssize_t> shape(s.shape(), s.shape() + s.ndim());
  std::vector<py::ssize_t> shape3 = shape;
  shape3.push_back(3);
  Doubles position(shape3), tangent(shape3), normal(shape3), binormal(shape3), kappa(shape), tau(shape);
  for (std::size_t i = 0; i < n; ++i) {
    const intrinsic::FramePoint& p = pts[i];
    for (int k = 0; k < 3; ++k) {
      position.mutable_data()[3 * i + static_cast<std::size_t>(k)] = p.position[k];
      tangent.mutable_data()[3 * i + static_cast<std::size_t>(k)] = p.tangent[k];
      normal.mutable_data()[3 * i + static_cast<std::size_t>(k)] = p.normal[k];
      binormal.mutable_data()[3 * i + static_cast<std::size_t>(k)] = p.binormal[k];
    }
    kappa.mutable_data()[i] = p.curvature;
    tau.mutable_data()[i] = p.torsion;
  }
  py::dict d;
  d["s"] = s;
  d["position"] = position;
  d["T"] = tangent;
  d["N"] = normal;
  d["B"] = binormal;
  d["kappa"] = kappa;
  d["tau"] = tau;
  return d;
}

std::string method_name(intrinsic::IntegrationKind k) {
  switch (k) {
    case intrinsic::IntegrationKind::PlanarExactAngle:
      return "planar-exact-angle";
    case intrinsic::IntegrationKind::PlanarNumericAngle:
      return "planar-numeric-angle";
    case intrinsic::IntegrationKind::FrenetSerret:
      return "frenet-serret";
  }
  return "frenet-serret";
}

}  // namespace

void register_geometry(py::module_& m) {
  py::class_<nurbs::ClosestPointResult>(m, "ClosestPoint", "The closest point of a curve to a query point.")
      .def_readonly("t", &nurbs::ClosestPointResult::t, "Parameter of the closest point, in the domain.")
      .def_property_readonly(
          "point",
          [](const nurbs::ClosestPointResult& r) {
            const double xyz[3] = {r.point.x, r.point.y, r.point.z};
            return to_array(xyz);
          },
          "C(t), model units, shape (3,).")
      .def_readonly("distance", &nurbs::ClosestPointResult::distance, "|C(t) - P| in model units.")
      .def("__repr__", [](const nurbs::ClosestPointResult& r) {
        return "ClosestPoint(t=" + format_number(r.t) + ", distance=" + format_number(r.distance) + ")";
      });

  py::class_<NurbsCurve>(m, "NurbsCurve",
                         "An immutable, validated NURBS curve of any degree >= 1, planar (dimension 2) or spatial "
                         "(3).\n\nnurbs.NurbsCurve; curve(t) and curve.derivatives(t, n) are vectorised over NumPy "
                         "arrays (docs/python.md).")
      .def(py::init(&make_curve), py::arg("degree"), py::arg("knots"), py::arg("control_points"),
           py::arg("weights") = py::none(),
           "knots: the full (clamped or not) non-decreasing knot vector, n + degree + 1 values.\n"
           "control_points: (n, 2) or (n, 3) in model units. weights: n positive finite numbers, or None.\n"
           "Raises InvalidKnotsError, InvalidDegreeError, InvalidWeightError, NonFiniteInputError naming the entry.")
      .def_property_readonly("degree", &NurbsCurve::degree, "The polynomial degree p >= 1.")
      .def_property_readonly("dimension", &NurbsCurve::dimension, "2 (planar, z = 0) or 3.")
      .def_property_readonly("is_rational", &NurbsCurve::is_rational, "True when the weights are not all equal.")
      .def_property_readonly(
          "knots", [](const NurbsCurve& c) { return to_array(c.knots().values()); },
          "The full knot vector, n + degree + 1 values (a copy).")
      .def_property_readonly(
          "control_points", [](const NurbsCurve& c) { return to_rows(c.control_points(), c.dimension()); },
          "(n, dimension), model units (a copy).")
      .def_property_readonly(
          "weights",
          [](const NurbsCurve& c) -> py::object {
            if (!c.is_rational()) return py::none();
            return to_array(c.weights());
          },
          "The n weights of a rational curve, else None.")
      .def_property_readonly(
          "domain", [](const NurbsCurve& c) { return py::make_tuple(c.domain().start, c.domain().end); },
          "(start, end) of the parameter t.")
      .def("__call__", &evaluate, py::arg("t"), py::kw_only(), py::arg("domain") = "strict", py::arg("side") = "right",
           py::arg("out") = py::none(),
           "Points C(t), shape t.shape + (dimension,), model units. Vectorised in C++, GIL released.\n"
           "domain: \"strict\" raises OutOfDomainError naming the index of the first t outside the domain;\n"
           "\"clamp\" evaluates at the nearest end; \"extrapolate\" continues the end pieces.\n"
           "side: one-sided limit (\"right\" or \"left\") at knots of reduced continuity.\n"
           "out: a C-contiguous float64 array of shape t.shape + (3,) to write into (always 3 columns, no "
           "allocation).")
      .def("derivatives", &derivatives, py::arg("t"), py::arg("order"), py::kw_only(), py::arg("domain") = "strict",
           py::arg("side") = "right",
           "C, C', ..., C^(order) with respect to t, shape t.shape + (order + 1, dimension); domain and side as "
           "for curve(t).")
      .def(
          "insert_knot", [](const NurbsCurve& c, double u, int times) { return nurbs::insert_knot(c, u, times); },
          py::arg("u"), py::arg("times") = 1,
          "The same curve with u inserted `times` times (Boehm; The NURBS Book A5.1).")
      .def(
          "refine", [](const NurbsCurve& c, py::handle k) { return nurbs::refine_knots(c, as_vector(k, "knots")); },
          py::arg("knots"), "The same curve with every knot of `knots` (non-decreasing) inserted (A5.4).")
      .def(
          "elevate", [](const NurbsCurve& c, int times) { return nurbs::elevate_degree(c, times); },
          py::arg("times") = 1, "The same curve with degree + times (The NURBS Book A5.9).")
      .def(
          "reduce_degree",
          [](const NurbsCurve& c, double tolerance) {
            // `hula edit reduce-degree`'s edit and report (io::edit_curve), so both give the same bytes.
            io::CurveEditAnswer answer =
                io::edit_curve(curve::Curve(c), "curve", {.edit = io::CurveEdit::ReduceDegree, .tolerance = tolerance});
            py::dict d = to_python(answer.report);
            d["curve"] = std::move(answer.curves.front());
            return d;
          },
          py::arg("tolerance"),
          "The curve one degree lower while it moves by at most `tolerance` (model units, >= 0): a dict\n"
          "{\"curve\", \"error_bound\" (a guaranteed bound of the change), \"bezier_bound\", \"tolerance\"}\n"
          "(`hula edit reduce-degree`'s report). A rational curve is reduced on its homogeneous points, its bound\n"
          "taken in Euclidean space; raises when no such curve is within the tolerance or a reduced weight is not\n"
          "positive.")
      .def(
          "rebuild",
          [](const NurbsCurve& c, std::size_t control_points, int degree, std::size_t samples) {
            // `hula edit rebuild`'s edit and report (io::edit_curve), so both give the same bytes.
            io::CurveEditAnswer answer = io::edit_curve(curve::Curve(c), "curve",
                                                        {.edit = io::CurveEdit::Rebuild,
                                                         .degree = degree,
                                                         .control_points = control_points,
                                                         .samples = samples});
            py::dict d = to_python(answer.report);
            d["curve"] = std::move(answer.curves.front());
            return d;
          },
          py::arg("control_points"), py::kw_only(), py::arg("degree") = 3, py::arg("samples") = 0,
          "The curve refitted with `degree` and `control_points` (same ends and domain, least squares at the\n"
          "curve's own parameters on uniform knots; samples=0: max(201, 10 x control_points)): a dict {\"curve\",\n"
          "\"degree\", \"control_points\", \"samples\", \"max_deviation\" (largest distance of 1,001 samples of the\n"
          "new curve to the original, measured by closest points), \"mean_deviation\", \"at\"} (`hula edit rebuild`).")
      .def(
          "to_law",
          [](const NurbsCurve& c) {
            const io::LawConversionAnswer a = io::law_from_nurbs(curve::Curve(c), "curve");
            py::dict d = to_python(a.report);
            d["law"] = parse_law(a.expression, {"t"}, law::Context());
            d["expression"] = a.expression;
            return d;
          },
          "The curve written out as an exact law of t (a rational polynomial per knot span, `hula edit to-law`):\n"
          "a dict {\"law\" (a Law), \"expression\", \"spans\", \"degree\", \"max_difference\" (max |law(t) - C(t)|\n"
          "over 1,001 samples), \"expression_length\"}.")
      .def(
          "split",
          [](const NurbsCurve& c, double t) {
            nurbs::SplitResult r = nurbs::split(c, t);
            return py::make_tuple(std::move(r.before), std::move(r.after));
          },
          py::arg("t"), "The pieces on [a, t] and [t, b], each clamped at t.")
      .def(
          "reverse", [](const NurbsCurve& c) { return nurbs::reverse(c); },
          "The same curve traversed backwards: C_r(t) = C(a + b - t).")
      .def(
          "reparameterise",
          [](const NurbsCurve& c, double a, double b) {
            return nurbs::reparameterise(c, {a, b});
          },
          py::arg("start"), py::arg("end"), "The same curve on the domain [start, end] (a linear change of t).")
      .def(
          "arc_length",
          [](const NurbsCurve& c, std::optional<double> a, std::optional<double> b, double tolerance) {
            const py::gil_scoped_release release;
            return nurbs::arc_length(c, a.value_or(c.domain().start), b.value_or(c.domain().end),
                                     {.tolerance = tolerance});
          },
          py::arg("start") = py::none(), py::arg("end") = py::none(), py::kw_only(), py::arg("tolerance") = 1e-12,
          "Length between parameters (default the whole domain), model units, to a relative tolerance.")
      .def(
          "parameter_at_length",
          [](const NurbsCurve& c, double s, double tolerance) {
            const py::gil_scoped_release release;
            return nurbs::parameter_at_length(c, s, {.tolerance = tolerance});
          },
          py::arg("s"), py::kw_only(), py::arg("tolerance") = 1e-12,
          "The parameter t at arc length s (model units) from the domain start.")
      .def(
          "closest_point",
          [](const NurbsCurve& c, py::handle point) {
            const Vec3 p = as_point(point, "point");
            const py::gil_scoped_release release;
            return nurbs::closest_point(c, p);
          },
          py::arg("point"), "The ClosestPoint of the curve to a point (2 or 3 coordinates).")
      .def("to_json", &to_json_text, "The curve file text (docs/formats.md \"Curve files\").")
      .def_static("from_json", &from_json, py::arg("document"),
                  "A curve file's text or dict; interpolated and law kinds are resolved to NURBS.")
      .def_static(
          "load", [](const std::string& path) { return io::read_curve_file(path).nurbs(); }, py::arg("path"),
          "Reads a curve file (docs/formats.md \"Curve files\").")
      .def(
          "save", [](const NurbsCurve& c, const std::string& path) { io::write_curve_file(path, c); }, py::arg("path"),
          "Writes the curve file atomically.")
      .def(py::self == py::self)  // NOLINT(misc-redundant-expression)
      .def(py::pickle([](const NurbsCurve& c) { return to_json_text(c); },
                      [](const std::string& text) { return io::parse_curve_json(text).nurbs(); }))
      .def("__repr__", [](const NurbsCurve& c) {
        return "NurbsCurve(degree=" + std::to_string(c.degree()) +
               ", control_points=" + std::to_string(c.control_points().size()) +
               ", dimension=" + std::to_string(c.dimension()) + (c.is_rational() ? ", rational" : "") + ", domain=[" +
               format_number(c.domain().start) + ", " + format_number(c.domain().end) + "])";
      });

  // Benchmark support (python/bench/bench_python.py, docs/benchmarks.md): the best of `repeats`
  // timings of the C++ batch evaluation alone, to set the binding's per-call overhead against.
  m.def(
      "_time_batch_evaluate",
      [](const NurbsCurve& c, const Doubles& ts, Doubles out, int repeats) {
        const auto n = static_cast<std::size_t>(ts.size());
        if (out.size() != ts.size() * 3)
          throw Error(Errc::InvalidArgument, "out must hold 3 doubles per t", {.field = "out"});
        const std::span<const double> t(ts.data(), n);
        const std::span<Vec3> o(reinterpret_cast<Vec3*>(out.mutable_data()), n);
        const py::gil_scoped_release release;
        double best = std::numeric_limits<double>::infinity();
        for (int r = 0; r < repeats; ++r) {
          const auto start = std::chrono::steady_clock::now();
          c.evaluate(t, o);
          best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        }
        return best;
      },
      py::arg("curve"), py::arg("t"), py::arg("out"), py::arg("repeats"));

  m.def(
      "read_points",
      [](const std::string& path) {
        const io::PointSet set = io::read_points_file(path);
        return to_rows(set.points, set.dimension);
      },
      py::arg("path"),
      "The points of a point file as an (n, 2) or (n, 3) array: JSON, or lines of 2 or 3 numbers separated by\n"
      "whitespace, commas or semicolons, with header lines (an airfoil's name) and # comments; Selig and Lednicer\n"
      "airfoil files (docs/formats.md \"Point files\"). Errors name the file, the line and the separator.");

  m.def(
      "interpolate",
      [](py::handle points, py::handle start, py::handle end, const std::string& parameterisation,
         py::handle parameters, bool closed) {
        const Points p = as_points(points, "points", 2);
        nurbs::InterpolationOptions o;
        o.dimension = p.dimension;
        o.parameterisation = io::parameterisation_from_name(parameterisation);
        if (!parameters.is_none()) o.parameters = as_vector(parameters, "parameters");
        // `hula interpolate --closed`'s curve (io::closed_cubic_curve), so both give the same bytes.
        if (closed)
          return io::closed_cubic_curve({.points = p.points, .dimension = p.dimension}, o.parameters,
                                        o.parameterisation);
        o.start = end_condition(start, "start");
        o.end = end_condition(end, "end");
        return nurbs::interpolate_cubic(p.points, o);
      },
      py::arg("points"), py::kw_only(), py::arg("start") = "natural", py::arg("end") = "natural",
      py::arg("parameterisation") = "chord", py::arg("parameters") = py::none(), py::arg("closed") = false,
      "The C2 cubic spline through (n, 2) or (n, 3) points (thesis 5.5, 7.1); closed=True: the periodic C2\n"
      "cubic back to the first point (no end conditions).\n"
      "start/end: \"natural\", \"bessel\", \"not-a-knot\", \"occt\", or a tangent vector dC/dt (t in [0, 1]).\n"
      "parameterisation: \"chord\", \"uniform\", \"centripetal\" or \"foley\".\n"
      "parameters: explicit data parameters (increasing, from 0 to 1) instead of the parameterisation.");

  m.def(
      "approximate",
      [](py::handle points, std::optional<double> tolerance, std::optional<std::size_t> control_points, int degree,
         const std::string& parameterisation) {
        const Points p = as_points(points, "points", 2);
        const nurbs::Parameterisation rule = io::parameterisation_from_name(parameterisation, "parameterisation");
        const io::ApproximationAnswer a = [&] {
          const py::gil_scoped_release release;
          return io::approximation_answer(
              io::PointSet{p.points, p.dimension},
              {.tolerance = tolerance, .control_points = control_points, .degree = degree, .parameterisation = rule});
        }();
        return py::make_tuple(a.curve, to_python(a.report));
      },
      py::arg("points"), py::kw_only(), py::arg("tolerance") = py::none(), py::arg("control_points") = py::none(),
      py::arg("degree") = 3, py::arg("parameterisation") = "chord",
      "A B-spline approximating (n, 2) or (n, 3) points, as `hula approximate` makes it: with `tolerance`\n"
      "(model units) the compact fair curve with the fewest control points through the first and last point\n"
      "keeping every point within it; with `control_points` the plain least-squares fit (The NURBS Book 9.4.1).\n"
      "Give exactly one. Returns (curve, report), report = {degree, control_points, max_deviation,\n"
      "max_deviation_index, fits} (+ tolerance, fit_max_deviation, smoothing with a tolerance).\n"
      "parameterisation: \"chord\", \"uniform\", \"centripetal\" or \"foley\".");

  m.def(
      "clothoid_g1",
      [](py::handle p0, double theta0, py::handle p1, double theta1) {
        io::ClothoidRequest q;
        q.start_point = as_point(p0, "p0");
        q.start_angle = theta0;
        q.end_point = as_point(p1, "p1");
        q.end_angle = theta1;
        return to_python(io::clothoid_answer(q).json);
      },
      py::arg("p0"), py::arg("theta0"), py::arg("p1"), py::arg("theta1"),
      "The clothoid from p0 with tangent angle theta0 to p1 with theta1 (radians from +x, counter-clockwise),\n"
      "turning by less than 2 pi (Bertolazzi-Frego G1 Hermite), as `hula clothoid` gives it (io::clothoid_answer):\n"
      "{\"kind\": \"g1\", \"segments\": [one dict with start, theta0, kappa0, dkappa (dkappa/ds), length and end\n"
      "values (docs/formats.md \"Clothoid result\")], \"length\", \"iterations\"}. Points (x, y) or (x, y, z), z "
      "ignored.");
  m.def(
      "clothoid_g2",
      [](py::handle p0, double theta0, double kappa0, py::handle p1, double theta1, double kappa1) {
        io::ClothoidRequest q;
        q.start_point = as_point(p0, "p0");
        q.start_angle = theta0;
        q.start_curvature = kappa0;
        q.end_point = as_point(p1, "p1");
        q.end_angle = theta1;
        q.end_curvature = kappa1;
        return to_python(io::clothoid_answer(q).json);
      },
      py::arg("p0"), py::arg("theta0"), py::arg("kappa0"), py::arg("p1"), py::arg("theta1"), py::arg("kappa1"),
      "Three clothoid arcs joined with G2 continuity from (p0, theta0, kappa0) to (p1, theta1, kappa1)\n"
      "(Bertolazzi-Frego 2018), as `hula clothoid` gives them (io::clothoid_answer): {\"kind\": \"g2\", \"segments\":\n"
      "[3 segment dicts as clothoid_g1's], \"length\", \"iterations\"}. Curvatures in 1/model units (> 0 turns left).");

  m.def(
      "clothoid_spline",
      [](py::handle points, bool closed, int continuity, std::optional<double> start_angle,
         std::optional<double> end_angle, bool biarc, std::optional<double> start_curvature,
         std::optional<double> end_curvature) {
        io::ClothoidRequest q;
        q.points = as_points(points, "points", 2).points;
        q.closed = closed;
        q.biarc = biarc;
        if (!biarc) q.continuity = continuity;
        q.spline_start_angle = start_angle.has_value();
        q.spline_end_angle = end_angle.has_value();
        q.start_angle = start_angle.value_or(0.0);
        q.end_angle = end_angle.value_or(0.0);
        q.start_curvature = start_curvature;
        q.end_curvature = end_curvature;
        io::ClothoidAnswer a = io::clothoid_answer(q);
        a.json["curve"] = io::curve_to_json(io::clothoid_curve(a.segments, curve::kNaturalTolerance));
        return to_python(a.json);
      },
      py::arg("points"), py::kw_only(), py::arg("closed") = false, py::arg("continuity") = 2,
      py::arg("start_angle") = py::none(), py::arg("end_angle") = py::none(), py::arg("biarc") = false,
      py::arg("start_curvature") = py::none(), py::arg("end_curvature") = py::none(),
      "A clothoid spline through (n, 2) points, as `hula clothoid --points` makes it: G2 (curvature continuous,\n"
      "continuity=2) or G1 (continuity=1), open or closed; with biarc=True a G1 spline of biarcs (two arcs per\n"
      "interval). Open splines take at each end an optional tangent angle or (G2) curvature, 1/model units; an end\n"
      "with neither is a circular end segment for G2. Returns {\"kind\", \"segments\", \"length\", \"iterations\", "
      "\"through\", \"closed\",\n"
      "\"curve\"}: \"curve\" is the curve file (a natural curve held by its curvature law, docs/formats.md).");
  m.def(
      "biarc",
      [](py::handle p0, double theta0, py::handle p1, double theta1) {
        io::ClothoidRequest q;
        q.biarc = true;
        q.start_point = as_point(p0, "p0");
        q.start_angle = theta0;
        q.end_point = as_point(p1, "p1");
        q.end_angle = theta1;
        return to_python(io::clothoid_answer(q).json);
      },
      py::arg("p0"), py::arg("theta0"), py::arg("p1"), py::arg("theta1"),
      "The equal-chord biarc from p0 with tangent angle theta0 to p1 with theta1 (radians): two circular arcs\n"
      "joined with G1 continuity, as `hula clothoid --biarc` gives it (io::clothoid_answer): {\"kind\": \"biarc\",\n"
      "\"segments\": [2 segment dicts as clothoid_g1's, dkappa 0], \"length\", \"iterations\"}.");

  m.def("analyse", &analyse, py::arg("curve"), py::arg("samples") = 100, py::kw_only(), py::arg("at") = py::none(),
        py::arg("by") = "parameter", py::arg("arc_lengths") = false, py::arg("bishop") = false,
        py::arg("fins") = std::vector<std::string>{}, py::arg("fin_scale") = py::none(), py::arg("fin_density") = 0,
        py::arg("features") = false,
        "The curve's analysis (as `hula analyse` and POST .../analysis give it; docs/formats.md \"Curve analysis\"):\n"
        "t, s (arc lengths, by arc length or with arc_lengths), points (n, 3), frames {T, N, B} (n, 3), curvature,\n"
        "torsion, curvature_derivative, speed (n,), bishop {U, V} (with bishop), fins [{kind, scale, t, base, tip}],\n"
        "planarity {planar, normal, max_deviation, tolerance} and, with features, {inflections, curvature_extrema,\n"
        "torsion_extrema, knots, curvature_monotonicity, maximum_curvature}. Undefined values are NaN.\n"
        "curve: a NurbsCurve or a curve file as a dict.");

  py::class_<intrinsic::NurbsFitResult>(m, "NurbsFit", "A NURBS fitted to an IntrinsicCurve (IntrinsicCurve.to_nurbs).")
      .def_readonly("curve", &intrinsic::NurbsFitResult::curve, "The quintic NurbsCurve.")
      .def_readonly("max_deviation", &intrinsic::NurbsFitResult::max_deviation,
                    "The largest distance measured between the NURBS and the curve, model units.")
      .def_readonly("segments", &intrinsic::NurbsFitResult::segments, "Number of Hermite segments.")
      .def_readonly("converged", &intrinsic::NurbsFitResult::converged,
                    "False when the segment budget ran out before the tolerance was met.");

  py::class_<intrinsic::IntrinsicCurve>(
      m, "IntrinsicCurve",
      "A curve integrated from its natural equations, parameterised by arc length s in [0, length].")
      .def_property_readonly("length", &intrinsic::IntrinsicCurve::length, "The arc length L, model units.")
      .def_property_readonly(
          "method", [](const intrinsic::IntrinsicCurve& c) { return method_name(c.method()); },
          "How the curve was integrated.")
      .def_property_readonly("tolerance", &intrinsic::IntrinsicCurve::tolerance,
                             "The integration tolerance, model units.")
      .def(
          "__call__",
          [](const intrinsic::IntrinsicCurve& c, py::handle s) { return py::object(frames(c, s)["position"]); },
          py::arg("s"), "Positions, shape s.shape + (3,); OutOfDomainError outside [0, length].")
      .def("frames", &frames, py::arg("s"), "s, position, T, N, B (s.shape + (3,)), kappa, tau (s.shape).")
      .def(
          "to_nurbs",
          [](const intrinsic::IntrinsicCurve& c, double tolerance) {
            const py::gil_scoped_release release;
            return intrinsic::fit_nurbs(c, {.tolerance = tolerance});
          },
          py::arg("tolerance") = 1e-9, "A quintic NurbsFit within `tolerance` model units of the curve.");

  m.def(
      "reconstruct",
      [](py::handle kappa, py::handle tau, double length, py::handle point, py::handle tangent, py::handle normal,
         double tolerance, const std::string& parameter) {
        const law::Context context;
        const law::Law k = law_argument(kappa, parameter, context, "kappa");
        const law::Law t = law_argument(tau, parameter, context, "tau");
        intrinsic::StartFrame start;
        start.point = as_point(point, "point");
        start.tangent = as_point(tangent, "tangent");
        start.normal = as_point(normal, "normal");
        intrinsic::ReconstructionOptions o;
        o.tolerance = tolerance;
        const py::gil_scoped_release release;
        return intrinsic::reconstruct(k, t, parameter, length, start, o);
      },
      py::arg("kappa"), py::arg("tau") = 0.0, py::kw_only(), py::arg("length"),
      py::arg("point") = std::vector<double>{0.0, 0.0, 0.0}, py::arg("tangent") = std::vector<double>{1.0, 0.0, 0.0},
      py::arg("normal") = std::vector<double>{0.0, 1.0, 0.0}, py::arg("tolerance") = 1e-10, py::arg("parameter") = "s",
      "The curve with curvature kappa(s) and torsion tau(s) (1/model units; Law, text or number) for s in\n"
      "[0, length] (thesis 8.2.2), starting at `point` with unit tangent and normal (defaults: origin, +x, +y).\n"
      "tau = 0 gives a planar curve with signed kappa (eq. 34); otherwise Frenet-Serret is integrated.");
}

}  // namespace hula::python
