// SPDX-License-Identifier: MIT
// `hula approximate --points P --tolerance TOL -o OUT`: a compact fair B-spline
// of the given degree through the first and last point that keeps every point
// within the tolerance (studies::fit_within_tolerance, the engine of `hula fit`,
// without stray rejection), or the plain least-squares fit with a given count of
// control points (--control-points, nurbs::approximate): io::approximation_answer.
#include <limits>
#include <memory>
#include <optional>

#include "commands/common.hpp"
#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/curve_edits.hpp"
#include "hula/io/points_file.hpp"

namespace hula::cli {

namespace {

struct ApproximateArgs {
  std::string points;
  std::optional<double> tolerance;
  std::optional<std::size_t> control_points;
  int degree = 3;
  std::string parameterisation = "chord";
  std::string output;
};

int run_approximate(const ApproximateArgs& a) {
  if (a.tolerance.has_value() == a.control_points.has_value())
    throw Error(Errc::InvalidArgument, "give exactly one of --tolerance and --control-points",
                ErrorWhere{.field = "tolerance"});
  io::check_output_path(a.output, "--output");
  const io::PointSet set = io::read_points_file(a.points);
  const io::ApproximationAnswer fit = io::approximation_answer(
      set, {.tolerance = a.tolerance,
            .control_points = a.control_points,
            .degree = a.degree,
            .parameterisation = io::parameterisation_from_name(a.parameterisation, "parameterisation")});
  io::write_curve_file(a.output, fit.curve);
  Json doc = Json::object();
  doc["output"] = a.output;
  doc["points"] = set.points.size();
  doc.update(fit.report);
  print_result(doc, a.output);
  return kExitOk;
}

}  // namespace

Command add_approximate(CLI::App& app) {
  auto a = std::make_shared<ApproximateArgs>();
  CLI::App* sub = app.add_subcommand(
      "approximate",
      "Compact fair B-spline through points within a tolerance (or least squares with N control points)");
  sub->add_option("--points", a->points,
                  "Points file: JSON [[x,y,z],...] or lines x y [z] (whitespace, comma or semicolon separated)")
      ->required();
  add_real_option(sub, "--tolerance", a->tolerance, 0.0, std::numeric_limits<double>::max(), true,
                  "Largest distance of a data point from the curve (model units), > 0");
  sub->add_option("--control-points", a->control_points, "Fixed number of control points instead of --tolerance");
  sub->add_option("--degree", a->degree, "Degree p in [1, 9] (default 3)")->check(CLI::Range(1, 9));
  sub->add_option("--parameterisation", a->parameterisation, "uniform | chord | centripetal | foley (default chord)");
  sub->add_option("-o,--output", a->output, "Curve file to write (atomically)")->required();
  return {sub, [a] { return run_approximate(*a); }};
}

}  // namespace hula::cli
