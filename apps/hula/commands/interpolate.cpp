// SPDX-License-Identifier: MIT
// `hula interpolate`: reads data points (JSON or CSV), fits the global C2
// cubic spline (thesis 7.1.2, 10.2.1; nurbs::interpolate_cubic) and writes the
// curve file atomically — the resolved "nurbs" kind, or with --keep-inputs the
// "interpolated" kind that stores the inputs; --lagrange: the polynomial of
// degree N − 1 through the points (thesis 5.3.1; nurbs::interpolate_lagrange)
// as a NURBS (io::lagrange_curve); --closed: the periodic C2 cubic back to the
// first point (io::closed_cubic_curve). Prints a JSON summary.
#include <memory>

#include "commands/common.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/curve_edits.hpp"
#include "hula/io/points_file.hpp"

namespace hula::cli {

namespace {
struct InterpolateArgs {
  std::string points;
  std::string parameterisation = "chord";
  std::string start = "natural";
  std::string end = "natural";
  std::string knots;
  std::string output;
  bool keep_inputs = false;
  bool lagrange = false;
  bool closed = false;
};

// --lagrange: the Bézier curve of degree N − 1 through the points at the given (--knots) or
// --parameterisation parameters. The summary has no end conditions (a polynomial has none).
int run_lagrange(const InterpolateArgs& a, const io::PointSet& set) {
  const std::vector<double> parameters = a.knots.empty() ? std::vector<double>{} : parse_number_list(a.knots, "knots");
  const auto rule = a.knots.empty() ? io::parameterisation_from_name(a.parameterisation, "parameterisation")
                                    : nurbs::Parameterisation::ChordLength;  // unused: the knots are given
  const auto curve = io::lagrange_curve(set, parameters, rule);
  io::write_curve_file(a.output, curve);
  Json summary = Json::object();
  summary["output"] = a.output;
  summary["kind"] = "nurbs";
  summary["method"] = "lagrange";
  summary["points"] = set.points.size();
  summary.update(io::curve_shape_summary(curve));
  summary["parameterisation"] = a.knots.empty() ? a.parameterisation : std::string("given");
  print_result(summary, a.output);
  return kExitOk;
}

// --closed: the periodic C2 cubic back to the first point (io::closed_interpolation_answer), no end conditions.
int run_closed(const InterpolateArgs& a, const io::PointSet& set) {
  const std::vector<double> given = a.knots.empty() ? std::vector<double>{} : parse_number_list(a.knots, "knots");
  const io::MadeCurveAnswer answer = io::closed_interpolation_answer(set, given, a.parameterisation);
  io::write_curve_file(a.output, answer.curve);
  Json summary = Json::object();
  summary["output"] = a.output;
  summary.update(answer.report);
  print_result(summary, a.output);
  return kExitOk;
}

int run_interpolate(const InterpolateArgs& a) {
  io::check_output_path(a.output, "--output");
  io::PointSet set = io::read_points_file(a.points);
  if (a.lagrange) return run_lagrange(a, set);
  if (a.closed) return run_closed(a, set);
  curve::InterpolatedData in;
  in.points = std::move(set.points);
  in.dimension = set.dimension;
  in.parameterisation = io::parameterisation_from_name(a.parameterisation, "parameterisation");
  if (!a.knots.empty()) in.parameters = parse_number_list(a.knots, "knots");
  in.start = parse_end_condition(a.start, "start");
  in.end = parse_end_condition(a.end, "end");
  const curve::Curve resolved = io::interpolated_curve(in, "knots");
  if (a.keep_inputs)
    io::write_curve_file(a.output, resolved);
  else
    io::write_curve_file(a.output, resolved.nurbs());

  Json summary = Json::object();
  summary["output"] = a.output;
  summary["kind"] = a.keep_inputs ? "interpolated" : "nurbs";
  summary["points"] = in.points.size();
  summary.update(io::curve_shape_summary(resolved.nurbs()));
  summary["parameterisation"] =
      in.parameters.empty() ? std::string(io::parameterisation_name(in.parameterisation)) : std::string("given");
  summary["start"] = io::end_condition_to_json(in.start, in.dimension);
  summary["end"] = io::end_condition_to_json(in.end, in.dimension);
  print_result(summary, a.output);
  return kExitOk;
}
}  // namespace

Command add_interpolate(CLI::App& app) {
  auto args = std::make_shared<InterpolateArgs>();
  CLI::App* sub = app.add_subcommand("interpolate", "Fit a C2 cubic spline through points and write a curve file");
  sub->add_option(
         "--points", args->points,
         "Points file: JSON [[x,y,z],...] or lines x y [z] (whitespace, comma or semicolon separated); - reads stdin")
      ->required();
  sub->add_option("--parameterisation", args->parameterisation,
                  "uniform | chord | centripetal | foley (default chord)");
  sub->add_option("--start", args->start,
                  "Start condition: natural | bessel | not-a-knot | occt | direction:x,y,z | clamped:x,y,z");
  sub->add_option("--end", args->end,
                  "End condition: natural | bessel | not-a-knot | occt | direction:x,y,z | clamped:x,y,z");
  sub->add_option("--knots", args->knots,
                  "Given data parameters k0,k1,... (one per point, strictly increasing; mapped to [0, 1])");
  sub->add_option("-o,--output", args->output,
                  "Curve file to write (atomically); - writes it to stdout instead of the summary")
      ->required();
  auto* keep = sub->add_flag("--keep-inputs", args->keep_inputs,
                             "Write the \"interpolated\" kind (the inputs) instead of NURBS");
  auto* lagrange = sub->add_flag("--lagrange", args->lagrange,
                                 "Lagrange interpolation: the polynomial of degree N - 1 through the N points (at most "
                                 "65), a Bezier curve, instead of the cubic spline; no --start/--end");
  lagrange->excludes(keep);
  auto* closed = sub->add_flag("--closed", args->closed,
                               "Closed (periodic) spline: back to the first point, C2 there too; --knots then has "
                               "one more value, the closure's; no --start/--end");
  closed->excludes(keep);
  closed->excludes(lagrange);
  closed->excludes("--start");
  closed->excludes("--end");
  lagrange->excludes("--start");
  lagrange->excludes("--end");
  return {sub, [args] { return run_interpolate(*args); }};
}

}  // namespace hula::cli
