// SPDX-License-Identifier: MIT
// `hula fit`: scanned points to a class-A curve (studies::fit_scan, thesis
// chapter 3). Takes a "fit" study file, or the points and settings as options;
// writes the faired curve, prints the figures before and after fairing with the
// strays by index, and with --svg draws the cloud with the curve and the
// curvature plot before and after fairing. On a terminal a progress line
// follows the search (study_common.hpp TerminalProgress).
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "commands/common.hpp"
#include "commands/study_common.hpp"
#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/fit_study_file.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/points_file.hpp"
#include "hula/io/study_figures.hpp"

namespace hula::cli {

namespace {

struct FitArgs {
  std::string study;
  std::string points;
  std::optional<std::string> surface_class;
  std::optional<double> tolerance;
  std::optional<int> degree;
  std::optional<int> min_degree;
  bool ordered = false;
  bool no_fair = false;
  std::string output;
  std::optional<std::string> svg;
  std::optional<std::string> save_study;
};

int run_fit(const FitArgs& a) {
  if (a.study.empty() == a.points.empty())
    throw Error(Errc::InvalidArgument, "give exactly one of STUDY and --points", ErrorWhere{.field = "points"});
  if (a.surface_class && a.tolerance)
    throw Error(Errc::InvalidArgument, "give at most one of --class and --tolerance", ErrorWhere{.field = "tolerance"});
  io::check_output_path(a.output, "--output");
  if (a.save_study) io::check_output_path(*a.save_study, "--save-study");
  if (a.save_study && io::is_std_stream(a.output) && io::is_std_stream(*a.save_study))
    throw Error(Errc::InvalidArgument,
                "-o and --save-study are both - (standard output): give at most one of them as -",
                ErrorWhere{.field = "save-study"});
  if (a.svg) check_svg_directory(*a.svg);
  io::FitStudy study;
  if (!a.study.empty()) {
    const io::StudyDocument doc = io::read_study_file(a.study, "fit");
    study = io::fit_study_from_json(doc, io::relative_to(std::filesystem::path(a.study).parent_path()));
  } else {
    study.header.kind = "fit";
    study.points_file = a.points;
    study.points = io::read_points_file(a.points).points;
  }
  // Options given on the command line override the study file's.
  if (a.surface_class)
    study.options.tolerance = *a.surface_class == "A" ? studies::kClassATolerance : studies::kClassBTolerance;
  if (a.tolerance) study.options.tolerance = *a.tolerance;
  if (a.degree) study.options.degree = *a.degree;
  if (a.min_degree) study.options.min_degree = *a.min_degree;
  if (a.ordered) study.options.ordered = true;
  if (a.no_fair) study.options.fair = false;
  // On a terminal, the search's progress line: one generation per candidate curve, its best the
  // candidate's largest deviation, its evaluations the least-squares solves (then the result's).
  TerminalProgress progress;
  studies::ScanFitOptions options = study.options;
  if (progress.active()) options.on_generation = [&progress](const optim::GenerationLog& g) { progress.show(g); };
  const studies::ScanFitResult r = studies::fit_scan(study.points, options);
  progress.finish();
  io::write_curve_file(a.output, r.faired);
  if (a.save_study) io::write_file_atomically(*a.save_study, fit_study_to_json(study).dump(2) + "\n");
  if (a.svg) {
    for (const io::NamedFigure& f : io::fit_figures(study.points, r).figures) write_svg(*a.svg, f.name, f.figure);
  }
  Json doc = io::fit_result_to_json(r, study.options);
  doc["output"] = a.output;
  print_result(doc, a.save_study && io::is_std_stream(*a.save_study) ? *a.save_study : a.output);
  return kExitOk;
}

}  // namespace

Command add_fit(CLI::App& app) {
  auto a = std::make_shared<FitArgs>();
  CLI::App* sub = app.add_subcommand(
      "fit", "Scanned points to a class-A curve: order, reject strays, fit within a tolerance, fair (docs/cli.md)");
  sub->add_option("study", a->study, "A \"fit\" study file (docs/formats.md); or give --points");
  sub->add_option("--points", a->points,
                  "Points file: JSON [[x,y,z],...] or lines x y [z] (whitespace, comma or semicolon separated), in "
                  "any order");
  sub->add_option("--class", a->surface_class, "A (tolerance 0.3) or B (0.5), in the data's units")
      ->check(CLI::IsMember({"A", "B"}));
  add_real_option(sub, "--tolerance", a->tolerance, 0.0, std::numeric_limits<double>::max(), true,
                  "Largest distance of a kept point from the curve, > 0 (default 0.3)");
  sub->add_option("--degree", a->degree, "Highest degree p in [3, 9] (default 5)")->check(CLI::Range(3, 9));
  sub->add_option("--min-degree", a->min_degree,
                  "Lowest degree in [3, degree], taken only when it needs fewer control points (default 3)")
      ->check(CLI::Range(3, 9));
  sub->add_flag("--ordered", a->ordered, "The points are already in order along the curve");
  sub->add_flag("--no-fair", a->no_fair, "Stop after the tolerance fit (no fairing)");
  sub->add_option("-o,--output", a->output, "Curve file to write (the faired curve, atomically)")->required();
  sub->add_option("--svg", a->svg, "Directory for fit.svg (cloud, strays, curve) and curvature.svg");
  sub->add_option("--save-study", a->save_study, "Write the resolved setup as a \"fit\" study file");
  return {sub, [a] { return run_fit(*a); }};
}

}  // namespace hula::cli
