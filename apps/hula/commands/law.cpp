// SPDX-License-Identifier: MIT
// `hula law EXPR`: evaluate, differentiate and analyse a law expression given
// on the command line (grammar in docs/formats.md), with JSON output. Values
// at --at have the shape of `hula eval` ({"results": [{"t", "derivatives":
// [[value], [first], ...]}]}, scalars as one-element arrays); also, on request,
// the printed N-th derivative, all roots, the extrema and the integral on an
// interval (io::law_answer; its values are io/law_values.hpp's, shared with `hula eval` and the HTTP API).
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "commands/common.hpp"
#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/law_analysis.hpp"

namespace hula::cli {

namespace {

constexpr double kDefaultToNurbsTolerance = 1e-6;

struct LawArgs {
  std::string expression;
  std::string parameter = "t";
  std::string at;
  std::string format = "json";
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

int run_law(const LawArgs& a) {
  if (!a.output.empty()) io::check_output_path(a.output, "--output");
  if (a.format != "json" && a.at.empty())
    throw Error(Errc::InvalidArgument,
                "--format " + a.format + ": the table formats print the values at --at; give --at",
                ErrorWhere{.field = "format"});
  io::LawQuery q;
  q.expression = a.expression;
  q.parameter = a.parameter;
  if (!a.at.empty()) q.at = parse_number_list(a.at, a.parameter);
  q.derivatives = a.derivatives;
  q.print_derivative = a.print_derivative;
  if (!a.roots.empty()) q.roots = interval(a.roots, "roots");
  q.roots_text = a.roots;
  if (!a.extrema.empty()) q.extrema = interval(a.extrema, "extrema");
  if (!a.integrate.empty()) q.integrate = integration_interval(a.integrate);
  q.integrate_text = a.integrate;
  q.allow_unconverged = a.allow_unconverged;
  if (!a.singularities.empty()) q.singularities = interval(a.singularities, "singularities");
  if (!a.to_nurbs.empty()) {
    q.to_nurbs = interval(a.to_nurbs, "to-nurbs");
    if (a.output.empty())
      throw Error(Errc::InvalidArgument, "--to-nurbs needs -o FILE for the curve file", ErrorWhere{.field = "output"});
    q.to_nurbs_tolerance = a.tolerance.value_or(kDefaultToNurbsTolerance);
    q.to_nurbs_output = a.output;
  }
  const io::LawAnswer answer = io::law_answer(q);
  // -o -: the curve file alone is what stdout carries.
  if (answer.curve) io::write_curve_file(a.output, *answer.curve);
  if (!answer.curve || !io::is_std_stream(a.output))
    print_formatted(answer.json, a.format, [&](const Json& d) {
      return io::derivative_table(d["results"], d["dimension"].get<std::size_t>(),
                                  static_cast<std::size_t>(a.derivatives));
    });
  return kExitOk;
}

}  // namespace

Command add_law(CLI::App& app) {
  auto args = std::make_shared<LawArgs>();
  CLI::App* sub = app.add_subcommand("law", "Evaluate, differentiate and analyse a law expression");
  sub->add_option("expression", args->expression, "Law expression, e.g. 'vec(2*cos(t), 2*sin(t), 0.5*t)'")->required();
  sub->add_option("--parameter", args->parameter, "Parameter name (default t)");
  sub->add_option("--at", args->at, "Parameters t0,t1,... at which to evaluate");
  add_format_option(sub, args->format, "one --at result per line, as hula eval; the other queries only in json");
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
