// SPDX-License-Identifier: MIT
// `hula analyse`: the analysis of a curve file (thesis 6.1–6.4) at parameters
// or arc lengths — diffgeom::analyse_curve written by io::curve_analysis_json,
// the answer POST .../analysis and hulahoops.analyse give for the same
// options: columns t, s, points, frames {T, N, B}, curvature, torsion,
// curvature_derivative, speed, bishop {U, V}, with null where a quantity is
// undefined; fins, planarity and, with --features, the features. Law curves
// are analysed exactly from the law; NURBS from the kernel.
#include <limits>
#include <memory>
#include <optional>

#include "commands/common.hpp"
#include "commands/study_common.hpp"
#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/curve_analysis_json.hpp"
#include "hula/io/curve_figures.hpp"

namespace hula::cli {

namespace {

struct AnalyseArgs {
  std::string curve;
  std::string at;
  int samples = 0;
  std::string by = "parameter";
  bool features = false;
  std::string svg;
  std::optional<std::string> fins;
  std::optional<double> fin_scale;
  std::optional<int> fin_density;
  std::string view = "auto";
  std::string format = "json";
};

// Fins per comb when --fin-density is not given (docs/cli.md).
constexpr int kDefaultFinDensity = 120;

int run_analyse(const AnalyseArgs& a) {
  if (!a.svg.empty()) check_svg_directory(a.svg);  // before the computation, not after
  diffgeom::AnalysisOptions options;
  options.by = *diffgeom::sample_by_from_name(a.by);  // CLI11 checked the name
  if (!a.at.empty())
    options.at = parse_number_list(a.at, options.by == diffgeom::SampleBy::ArcLength ? "s" : "t");
  else
    options.samples = a.samples;
  options.arc_lengths = true;
  options.bishop = true;
  options.features = a.features;
  if (a.fins) options.fins = io::parse_fin_kinds(*a.fins, "--fins");
  options.fin_scale = a.fin_scale;
  options.fin_density = a.fin_density.value_or(kDefaultFinDensity);
  io::CurveFigureOptions figure_options;
  if (a.fins) figure_options.fins = options.fins;
  figure_options.fin_scale = a.fin_scale;
  figure_options.fin_density = options.fin_density;
  figure_options.view = io::parse_curve_view(a.view, "--view");
  const curve::Curve subject = io::read_curve_file(a.curve);
  const std::string text = io::analyse_curve_json(subject, options, true);
  if (!a.svg.empty())
    for (const io::NamedFigure& f : io::curve_figures(subject, figure_options).figures)
      write_svg(a.svg, f.name, f.figure);
  if (const auto table = io::table_format_from_name(a.format))
    print_text(io::format_table(io::analysis_table(io::json::parse_json_text(text, "the analysis")), *table));
  else
    print_text(text);
  return kExitOk;
}
}  // namespace

Command add_analyse(CLI::App& app) {
  auto args = std::make_shared<AnalyseArgs>();
  CLI::App* sub = app.add_subcommand(
      "analyse", "Differential geometry of a curve file: Frenet and Bishop frames, curvature, torsion, speed");
  sub->add_option("curve", args->curve, "Curve file (JSON)")->required();
  auto* at = sub->add_option("--at", args->at, "Parameters (or arc lengths with --by arclength) x0,x1,...");
  auto* n = sub->add_option("--samples", args->samples, "N equally spaced samples over the domain, N in [1, 1000000]")
                ->check(CLI::Range(1, 1000000));
  at->excludes(n);
  sub->add_option("--by", args->by, "Abscissa of --at / --samples: parameter | arclength (default parameter)")
      ->check(CLI::IsMember({"parameter", "arclength"}));
  sub->add_flag("--features", args->features,
                "Add \"features\": inflections (planar curves), curvature and torsion extrema, knot continuity (curves "
                "with knots), curvature monotonicity, maximum curvature, self-intersections");
  sub->add_option("--svg", args->svg,
                  "Write curve.svg (the curve and its fins, curvature and torsion unless --fins), kappa.svg, tau.svg, "
                  "radius.svg (range-limited radius of curvature), speed.svg and logcurvature.svg into this directory");
  sub->add_option("--fins", args->fins,
                  "Fin kinds, comma-separated: curvature, torsion, normal, binormal, bishop (U and V), bishop-u, "
                  "bishop-v, combescure (the Combescure compound P + s(tau/kappa T + B)); adds \"fins\" to the "
                  "output and draws them in curve.svg");
  add_real_option(sub, "--fin-scale", args->fin_scale, 0.0, std::numeric_limits<double>::max(), true,
                  "Fin scale s > 0 for every kind (default: the longest fin a fifth of the curve's size)");
  add_integer_option(sub, "--fin-density", args->fin_density, 2, 100000, "Fins per kind, in [2, 100000] (default 120)");
  sub->add_option("--view", args->view, "View of curve.svg: auto | xy | yz | zx | isometric (default auto)")
      ->check(CLI::IsMember({"auto", "xy", "yz", "zx", "isometric"}));
  add_format_option(sub, args->format,
                    "one sample per line: t, s, point, T, N, B, curvature, torsion, curvature_derivative, speed, "
                    "U, V; fins, features and planarity only in json");
  return {sub, [args, sub] {
            if (sub->count("--at") == 0 && sub->count("--samples") == 0)
              throw Error(Errc::InvalidArgument, "give --at or --samples", {.field = "at"});
            return run_analyse(*args);
          }};
}

}  // namespace hula::cli
