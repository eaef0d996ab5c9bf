// SPDX-License-Identifier: MIT
// `hula approximate --points P --tolerance TOL -o OUT`: the least-squares
// B-spline through data points with the fewest control points that keeps every
// point within the tolerance (nurbs::approximate_to_tolerance, whose search is
// documented in nurbs/approximate.hpp), or with a given count (--control-points).
#include "hula/nurbs/approximate.hpp"

#include <memory>
#include <optional>

#include "commands/common.hpp"
#include "hula/core/error.hpp"
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
  const io::PointSet set = io::read_points_file(a.points);
  nurbs::ApproximationOptions o;
  o.degree = a.degree;
  o.dimension = set.dimension;
  o.parameterisation = io::parameterisation_from_name(a.parameterisation, "parameterisation");
  std::size_t fits = 1;
  auto run = [&]() -> nurbs::ApproximationResult {
    if (a.tolerance) {
      nurbs::ToleranceFitResult r = nurbs::approximate_to_tolerance(set.points, *a.tolerance, o);
      fits = r.fits;
      return std::move(r.fit);
    }
    o.control_points = *a.control_points;
    return nurbs::approximate(set.points, o);
  };
  const nurbs::ApproximationResult fit = run();
  io::write_curve_file(a.output, fit.curve);
  Json doc = Json::object();
  doc["output"] = a.output;
  doc["points"] = set.points.size();
  doc["degree"] = fit.curve.degree();
  doc["control_points"] = fit.curve.control_points().size();
  if (a.tolerance) doc["tolerance"] = *a.tolerance;
  doc["max_deviation"] = fit.max_deviation;
  doc["max_deviation_index"] = fit.max_deviation_index;
  doc["fits"] = fits;
  print_json(doc);
  return kExitOk;
}

}  // namespace

Command add_approximate(CLI::App& app) {
  auto a = std::make_shared<ApproximateArgs>();
  CLI::App* sub = app.add_subcommand(
      "approximate", "Least-squares B-spline through points within a tolerance (fewest control points)");
  sub->add_option("--points", a->points, "Points file: JSON [[x,y,z],...] or CSV lines x,y[,z]")->required();
  sub->add_option("--tolerance", a->tolerance, "Largest distance of a data point from the curve (model units)")
      ->check(CLI::PositiveNumber);
  sub->add_option("--control-points", a->control_points, "Fixed number of control points instead of --tolerance");
  sub->add_option("--degree", a->degree, "Degree p in [1, 9] (default 3)")->check(CLI::Range(1, 9));
  sub->add_option("--parameterisation", a->parameterisation, "uniform | chord | centripetal | foley (default chord)");
  sub->add_option("-o,--output", a->output, "Curve file to write (atomically)")->required();
  return {sub, [a] { return run_approximate(*a); }};
}

}  // namespace hula::cli
