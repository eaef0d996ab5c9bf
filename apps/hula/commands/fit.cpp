// SPDX-License-Identifier: MIT
// `hula fit`: scanned points to a class-A curve (studies::fit_scan, thesis
// chapter 3). Takes a "fit" study file, or the points and settings as options;
// writes the faired curve, prints the figures before and after fairing with the
// strays by index, and with --svg draws the cloud with the curve and the
// curvature plot before and after fairing.
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "commands/common.hpp"
#include "commands/study_common.hpp"
#include "hula/core/error.hpp"
#include "hula/diffgeom/plot.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/fit_study_file.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/points_file.hpp"

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

// Signed curvature against arc length of both curves (the thesis's curvature plot).
io::SvgFigure curvature_figure(const studies::ScanFitResult& r) {
  io::SvgFigure fig(800, 500);
  fig.set_title("Signed curvature before (tolerance fit) and after fairing");
  fig.set_axes("arc length s", r.faired.dimension() == 2 ? "signed curvature" : "curvature");
  diffgeom::PlotOptions o;
  o.quantity = r.faired.dimension() == 2 ? diffgeom::PlotQuantity::SignedCurvature : diffgeom::PlotQuantity::Curvature;
  o.abscissa = diffgeom::PlotAbscissa::ArcLength;
  o.samples = 800;
  const diffgeom::Plot before = diffgeom::plot(r.fit, o);
  const diffgeom::Plot after = diffgeom::plot(r.faired, o);
  fig.add_polyline(before.x, before.y, io::SvgStyle{.stroke = "#999999", .width = 1.2, .fill = {}, .dash = "6 4"},
                   "before: " + std::to_string(r.before.inflections) + " inflections, " +
                       std::to_string(r.before.curvature_extrema) + " extrema");
  fig.add_polyline(after.x, after.y, io::SvgStyle{.stroke = "#d62728", .width = 1.8, .fill = {}, .dash = {}},
                   "after: " + std::to_string(r.after.inflections) + " inflections, " +
                       std::to_string(r.after.curvature_extrema) + " extrema");
  return fig;
}

// The cloud (kept points grey, strays red) and the faired curve, XY view.
io::SvgFigure cloud_figure(std::span<const Vec3> points, const studies::ScanFitResult& r) {
  io::SvgFigure fig(900, 600);
  fig.set_title("Scanned points, strays and the faired curve (XY)");
  fig.set_equal_aspect(true);
  std::vector<double> kx, ky, sx, sy;
  for (const std::size_t i : r.order) {
    kx.push_back(points[i].x);
    ky.push_back(points[i].y);
  }
  for (const std::size_t i : r.strays) {
    sx.push_back(points[i].x);
    sy.push_back(points[i].y);
  }
  fig.add_points(kx, ky, io::SvgStyle{.stroke = "#aaaaaa", .width = 0.5, .fill = {}, .dash = {}}, 1.0, "kept points");
  fig.add_points(sx, sy, io::SvgStyle{.stroke = "#d62728", .width = 1.0, .fill = {}, .dash = {}}, 3.0, "strays");
  constexpr int kSamples = 1000;
  std::vector<double> cx(kSamples + 1), cy(kSamples + 1);
  const auto dom = r.faired.domain();
  for (int i = 0; i <= kSamples; ++i) {
    const Vec3 c = r.faired.evaluate(dom.start + (dom.end - dom.start) * i / kSamples);
    cx[static_cast<std::size_t>(i)] = c.x;
    cy[static_cast<std::size_t>(i)] = c.y;
  }
  fig.add_polyline(cx, cy, io::SvgStyle{.stroke = "#1f77b4", .width = 1.8, .fill = {}, .dash = {}}, "faired curve");
  return fig;
}

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
  const studies::ScanFitResult r = studies::fit_scan(study.points, study.options);
  io::write_curve_file(a.output, r.faired);
  if (a.save_study) io::write_file_atomically(*a.save_study, fit_study_to_json(study).dump(2) + "\n");
  if (a.svg) {
    write_svg(*a.svg, "fit", cloud_figure(study.points, r));
    write_svg(*a.svg, "curvature", curvature_figure(r));
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
