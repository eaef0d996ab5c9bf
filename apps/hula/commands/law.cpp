// SPDX-License-Identifier: MIT
// `hula law EXPR`: evaluate, differentiate and analyse a law expression given
// on the command line (grammar in docs/formats.md), with JSON output. Values
// at --at have the shape of `hula eval` ({"results": [{"t", "derivatives":
// [[value], [first], ...]}]}, scalars as one-element arrays); also, on request,
// the printed N-th derivative, all roots, the extrema and the integral on an
// interval (io/law_values.hpp, shared with `hula eval` and the HTTP API).
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "commands/common.hpp"
#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/law_values.hpp"
#include "hula/law/antiderivative.hpp"
#include "hula/law/convert.hpp"
#include "hula/law/derive.hpp"
#include "hula/law/parser.hpp"
#include "hula/law/roots.hpp"

namespace hula::cli {

namespace {

constexpr double kDefaultToNurbsTolerance = 1e-6;

struct LawArgs {
  std::string expression;
  std::string parameter = "t";
  std::string at;
  int derivatives = 0;
  int print_derivative = -1;
  std::string roots;
  std::string extrema;
  std::string integrate;
  bool allow_unconverged = false;
  std::string singularities;
  std::string to_nurbs;
  std::optional<double> tolerance;  // --to-nurbs; default kDefaultToNurbsTolerance
  std::string output;
};

std::pair<double, double> interval(const std::string& text, const char* field) {
  const std::vector<double> v = parse_number_list(text, field);
  if (v.size() != 2 || !(v[0] < v[1]))
    throw Error(Errc::InvalidArgument, std::string("--") + field + " must be a,b with a < b, got '" + text + "'",
                ErrorWhere{.field = field});
  return {v[0], v[1]};
}

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

// --integrate a,b: numbers, or inf / -inf for an infinite bound (an improper integral).
std::pair<double, double> integration_interval(const std::string& text) {
  std::vector<double> v;
  std::size_t start = 0;
  for (std::size_t i = 0;; ++i) {
    const std::size_t comma = text.find(',', start);
    const std::string entry = text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (entry == "inf" || entry == "+inf")
      v.push_back(HUGE_VAL);
    else if (entry == "-inf")
      v.push_back(-HUGE_VAL);
    else
      v.push_back(parse_number_list(entry, "integrate").front());
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (v.size() != 2 || !(v[0] < v[1]))
    throw Error(Errc::InvalidArgument, "--integrate must be a,b with a < b (inf and -inf allowed), got '" + text + "'",
                ErrorWhere{.field = "integrate"});
  return {v[0], v[1]};
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

int run_law(const LawArgs& a) {
  if (!a.output.empty()) io::check_output_path(a.output, "--output");
  bool printed_to_stdout = false;  // -o -: the curve file alone is what stdout carries
  law::Context ctx;
  law::ParseOptions po;
  po.parameters = {a.parameter};
  const law::Law l = law::parse(a.expression, ctx, po);
  const std::vector<double> ts = a.at.empty() ? std::vector<double>{} : parse_number_list(a.at, a.parameter);
  Json doc = io::law_evaluation_json(l, a.parameter, ts, a.derivatives);
  if (a.print_derivative >= 0) {
    Json d = Json::object();
    d["order"] = a.print_derivative;
    // A derivative's text writes each shared subexpression once per use and can grow
    // exponentially with the order: up to the parser's input limit it is printed whole (it reads
    // back), beyond it with its shared subexpressions named once.
    const law::Law der = law::derivative(l, a.parameter, a.print_derivative);
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
  if (!a.roots.empty()) {
    require_scalar(l, "roots");
    const auto [lo, hi] = interval(a.roots, "roots");
    Json r = Json::object();
    r["interval"] = Json::array({lo, hi});
    const law::RootReport found = law::find_roots(l, a.parameter, lo, hi);
    if (!found.converged() && !a.allow_unconverged)
      throw Error(Errc::NumericalFailure,
                  "--roots " + a.roots + ": the sign change at " + a.parameter + " = " +
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
  if (!a.extrema.empty()) {
    require_scalar(l, "extrema");
    const auto [lo, hi] = interval(a.extrema, "extrema");
    const law::ExtremaResult e = law::extrema(l, a.parameter, lo, hi);
    Json r = Json::object();
    r["interval"] = Json::array({lo, hi});
    Json pts = Json::array();
    for (const auto& p : e.points) pts.push_back(extremum_json(p));
    r["points"] = std::move(pts);
    r["minimum"] = extremum_json(e.minimum);
    r["maximum"] = extremum_json(e.maximum);
    doc["extrema"] = std::move(r);
  }
  if (!a.integrate.empty()) {
    require_scalar(l, "integrate");
    const auto [lo, hi] = integration_interval(a.integrate);
    const law::DefiniteIntegralResult r = law::definite_integral(l, a.parameter, lo, hi);
    if (r.divergent && !a.allow_unconverged) {
      std::string where;
      for (const law::SingularPoint& p : r.singular_points)
        if (!p.integrable && where.empty())
          where = std::isinf(p.t)
                      ? std::string(p.t > 0 ? "towards +inf" : "towards -inf") + " (|f| decays like |" + a.parameter +
                            "|^" + format_number(p.exponent) + ")"
                      : "at " + a.parameter + " = " + format_number(p.t) + " (|f| grows like |" + a.parameter + " - " +
                            format_number(p.t) + "|^" + format_number(p.exponent) + ", " + p.expression + ")";
      throw Error(Errc::NumericalFailure,
                  "--integrate " + a.integrate + ": divergent: the integrand is not integrable " + where +
                      "; pass --allow-unconverged to print the analysis",
                  ErrorWhere{.field = "integrate"});
    }
    if (!r.converged && !a.allow_unconverged)
      throw Error(Errc::NumericalFailure,
                  "--integrate " + a.integrate + ": the quadrature did not converge (error estimate " +
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
      e[a.parameter] = bound_json(p.t);
      e["exponent"] = std::isfinite(p.exponent) ? Json(p.exponent) : bound_json(p.exponent);
      e["integrable"] = p.integrable;
      e["expression"] = p.expression;
      points.push_back(std::move(e));
    }
    j["singular_points"] = std::move(points);
    doc["integral"] = std::move(j);
  }
  if (!a.singularities.empty()) {
    const auto [lo, hi] = interval(a.singularities, "singularities");
    const law::SingularityReport rep = law::singularities(l, a.parameter, lo, hi);
    Json j = Json::object();
    j["interval"] = Json::array({lo, hi});
    Json pts = Json::array();
    for (const law::Singularity& p : rep.points) {
      Json e = Json::object();
      e[a.parameter] = p.t;
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
  if (!a.to_nurbs.empty()) {
    const auto [lo, hi] = interval(a.to_nurbs, "to-nurbs");
    if (a.output.empty())
      throw Error(Errc::InvalidArgument, "--to-nurbs needs -o FILE for the curve file", ErrorWhere{.field = "output"});
    law::ToNurbsOptions o;
    o.tolerance = a.tolerance.value_or(kDefaultToNurbsTolerance);
    const law::ToNurbsResult n = law::to_nurbs(l, a.parameter, lo, hi, o);
    io::write_curve_file(a.output, n.curve);
    printed_to_stdout = io::is_std_stream(a.output);
    Json j = Json::object();
    j["output"] = a.output;
    j["domain"] = Json::array({lo, hi});
    j["tolerance"] = o.tolerance;
    j["max_deviation"] = n.max_deviation;
    j["degree"] = n.curve.degree();
    j["control_points"] = n.control_points;
    j["segments"] = n.segments;
    doc["nurbs"] = std::move(j);
  }
  if (!printed_to_stdout) print_json(doc);
  return kExitOk;
}

}  // namespace

Command add_law(CLI::App& app) {
  auto args = std::make_shared<LawArgs>();
  CLI::App* sub = app.add_subcommand("law", "Evaluate, differentiate and analyse a law expression");
  sub->add_option("expression", args->expression, "Law expression, e.g. 'vec(2*cos(t), 2*sin(t), 0.5*t)'")->required();
  sub->add_option("--parameter", args->parameter, "Parameter name (default t)");
  sub->add_option("--at", args->at, "Parameters t0,t1,... at which to evaluate");
  sub->add_option("--derivatives", args->derivatives, "Highest derivative order N in [0, 16] for --at (default 0)")
      ->check(CLI::Range(0, 16));
  sub->add_option("--print-derivative", args->print_derivative, "Print the N-th derivative expression, N in [0, 8]")
      ->check(CLI::Range(0, 8));
  sub->add_option("--roots", args->roots, "All roots on a,b (scalar laws)");
  sub->add_option("--extrema", args->extrema, "Extrema on a,b (scalar laws)");
  sub->add_option("--integrate", args->integrate,
                  "Integral over a,b (scalar laws; inf and -inf allowed): symbolic when possible, improper integrals "
                  "with integrable singularities included");
  sub->add_flag("--allow-unconverged", args->allow_unconverged,
                "Print a non-converged integral or unresolved root sign changes instead of failing (exit 4)");
  sub->add_option("--singularities", args->singularities,
                  "Where the law is undefined or not smooth on a,b (kinks, jumps, poles, knots)");
  sub->add_option("--to-nurbs", args->to_nurbs, "Convert the vector law on a,b to a NURBS curve file (-o)");
  add_real_option(sub, "--tolerance", args->tolerance, 0.0, std::numeric_limits<double>::max(), true,
                  "Largest distance law-NURBS for --to-nurbs, > 0 (default 1e-6)");
  sub->add_option("-o,--output", args->output, "Curve file written by --to-nurbs");
  return {sub, [args] { return run_law(*args); }};
}

}  // namespace hula::cli
