// SPDX-License-Identifier: MIT
// The answer of `hula law` (law_analysis.hpp).
#include "hula/io/law_analysis.hpp"

#include <cmath>

#include "hula/core/error.hpp"
#include "hula/io/law_values.hpp"
#include "hula/law/antiderivative.hpp"
#include "hula/law/convert.hpp"
#include "hula/law/derive.hpp"
#include "hula/law/parser.hpp"
#include "hula/law/roots.hpp"
#include "hula/law/singularities.hpp"

namespace hula::io {

namespace {

const char* kind_name(law::ExtremumKind k) {
  switch (k) {
    case law::ExtremumKind::Minimum:
      return "minimum";
    case law::ExtremumKind::Maximum:
      return "maximum";
    case law::ExtremumKind::Stationary:
      return "stationary";
  }
  return "?";
}

Json extremum_json(const law::Extremum& e) {
  Json j = Json::object();
  j["t"] = e.t;
  j["value"] = e.value;
  j["kind"] = kind_name(e.kind);
  return j;
}

Json bound_json(double x) {
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return x;
}

void require_scalar(const law::Law& l, const char* option) {
  if (l.dimension() != 1)
    throw Error(Errc::InvalidArgument,
                std::string("--") + option + " needs a scalar law, got a " + std::to_string(l.dimension()) + "-vector",
                ErrorWhere{.field = option});
}

}  // namespace

LawAnswer law_answer(const LawQuery& q) {
  law::Context ctx;
  law::ParseOptions po;
  po.parameters = {q.parameter};
  const law::Law l = law::parse(q.expression, ctx, po);
  LawAnswer out;
  Json& doc = out.json;
  doc = law_evaluation_json(l, q.parameter, q.at, q.derivatives);
  if (q.print_derivative >= 0) {
    Json d = Json::object();
    d["order"] = q.print_derivative;
    // A derivative's text writes each shared subexpression once per use and can grow
    // exponentially with the order: up to the parser's input limit it is printed whole (it reads
    // back), beyond it with its shared subexpressions named once.
    const law::Law der = law::derivative(l, q.parameter, q.print_derivative);
    const std::size_t length = law::printed_length(der);
    if (length <= law::ParseOptions{}.max_length) {
      d["expression"] = law::print(der);
    } else {
      law::SharedPrint shared = law::print_shared(der);
      d["expression"] = std::move(shared.expression);
      Json defs = Json::array();
      for (auto& def : shared.definitions) {
        Json j = Json::object();
        j["name"] = std::move(def.name);
        j["expression"] = std::move(def.expression);
        defs.push_back(std::move(j));
      }
      d["definitions"] = std::move(defs);
      d["printed_length"] = length;
    }
    doc["derivative"] = std::move(d);
  }
  if (q.roots) {
    require_scalar(l, "roots");
    const auto [lo, hi] = *q.roots;
    Json r = Json::object();
    r["interval"] = Json::array({lo, hi});
    const law::RootReport found = law::find_roots(l, q.parameter, lo, hi);
    if (!found.converged() && !q.allow_unconverged)
      throw Error(Errc::NumericalFailure,
                  "--roots " + q.roots_text + ": the sign change at " + q.parameter + " = " +
                      format_number(found.unresolved.front()) +
                      " did not converge to a root (a pole or a jump); pass --allow-unconverged to list it",
                  ErrorWhere{.field = "roots"});
    Json list = Json::array();
    for (double t : found.roots) list.push_back(t);
    r["roots"] = std::move(list);
    Json unresolved = Json::array();
    for (double t : found.unresolved) unresolved.push_back(t);
    r["unresolved"] = std::move(unresolved);
    r["converged"] = found.converged();
    doc["roots"] = std::move(r);
  }
  if (q.extrema) {
    require_scalar(l, "extrema");
    const auto [lo, hi] = *q.extrema;
    const law::ExtremaResult e = law::extrema(l, q.parameter, lo, hi);
    Json r = Json::object();
    r["interval"] = Json::array({lo, hi});
    Json pts = Json::array();
    for (const auto& p : e.points) pts.push_back(extremum_json(p));
    r["points"] = std::move(pts);
    r["minimum"] = extremum_json(e.minimum);
    r["maximum"] = extremum_json(e.maximum);
    doc["extrema"] = std::move(r);
  }
  if (q.integrate) {
    require_scalar(l, "integrate");
    const auto [lo, hi] = *q.integrate;
    const law::DefiniteIntegralResult r = law::definite_integral(l, q.parameter, lo, hi);
    if (r.divergent && !q.allow_unconverged) {
      std::string where;
      for (const law::SingularPoint& p : r.singular_points)
        if (!p.integrable && where.empty())
          where = std::isinf(p.t)
                      ? std::string(p.t > 0 ? "towards +inf" : "towards -inf") + " (|f| decays like |" + q.parameter +
                            "|^" + format_number(p.exponent) + ")"
                      : "at " + q.parameter + " = " + format_number(p.t) + " (|f| grows like |" + q.parameter + " - " +
                            format_number(p.t) + "|^" + format_number(p.exponent) + ", " + p.expression + ")";
      throw Error(Errc::NumericalFailure,
                  "--integrate " + q.integrate_text + ": divergent: the integrand is not integrable " + where +
                      "; pass --allow-unconverged to print the analysis",
                  ErrorWhere{.field = "integrate"});
    }
    if (!r.converged && !q.allow_unconverged)
      throw Error(Errc::NumericalFailure,
                  "--integrate " + q.integrate_text + ": the quadrature did not converge (error estimate " +
                      format_number(r.error_estimate) + " for the value " + format_number(r.value) +
                      "; unresolved integrand); pass --allow-unconverged to print it",
                  ErrorWhere{.field = "integrate"});
    Json j = Json::object();
    j["interval"] = Json::array({bound_json(lo), bound_json(hi)});
    j["value"] = r.divergent ? Json(nullptr) : Json(r.value);
    j["error_estimate"] = r.divergent ? Json(nullptr) : Json(r.error_estimate);
    j["method"] = r.method == law::IntegralMethod::Symbolic ? "symbolic" : "numeric";
    j["converged"] = r.converged;
    j["divergent"] = r.divergent;
    if (r.method == law::IntegralMethod::Symbolic) j["antiderivative"] = law::print(r.antiderivative);
    if (r.method == law::IntegralMethod::Numeric) j["numeric_reason"] = r.numeric_reason;
    Json points = Json::array();
    for (const law::SingularPoint& p : r.singular_points) {
      Json e = Json::object();
      e[q.parameter] = bound_json(p.t);
      e["exponent"] = std::isfinite(p.exponent) ? Json(p.exponent) : bound_json(p.exponent);
      e["integrable"] = p.integrable;
      e["expression"] = p.expression;
      points.push_back(std::move(e));
    }
    j["singular_points"] = std::move(points);
    doc["integral"] = std::move(j);
  }
  if (q.singularities) {
    const auto [lo, hi] = *q.singularities;
    const law::SingularityReport rep = law::singularities(l, q.parameter, lo, hi);
    Json j = Json::object();
    j["interval"] = Json::array({lo, hi});
    Json pts = Json::array();
    for (const law::Singularity& p : rep.points) {
      Json e = Json::object();
      e[q.parameter] = p.t;
      e["kind"] = law::singularity_kind_name(p.kind);
      e["expression"] = p.expression;
      pts.push_back(std::move(e));
    }
    j["points"] = std::move(pts);
    Json und = Json::array();
    for (const law::UndefinedInterval& u : rep.undefined) und.push_back(Json::array({u.start, u.end}));
    j["undefined"] = std::move(und);
    j["smooth"] = rep.smooth();
    doc["singularities"] = std::move(j);
  }
  if (q.to_nurbs) {
    const auto [lo, hi] = *q.to_nurbs;
    law::ToNurbsOptions o;
    o.tolerance = q.to_nurbs_tolerance;
    law::ToNurbsResult n = law::to_nurbs(l, q.parameter, lo, hi, o);
    Json j = Json::object();
    j["output"] = q.to_nurbs_output;
    j["domain"] = Json::array({lo, hi});
    j["tolerance"] = o.tolerance;
    j["max_deviation"] = n.max_deviation;
    j["degree"] = n.curve.degree();
    j["control_points"] = n.control_points;
    j["segments"] = n.segments;
    doc["nurbs"] = std::move(j);
    out.curve = curve::Curve(std::move(n.curve));
  }
  return out;
}

}  // namespace hula::io
