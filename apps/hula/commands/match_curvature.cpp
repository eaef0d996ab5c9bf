// SPDX-License-Identifier: MIT
// `hula match-curvature STUDY [--method ga|hybrid|direct] [--seed N] [--threads N] [--log FILE] [--svg DIR]`:
// a prescribed curvature profile matched over data points (thesis 8.2.1,
// appendix 5) by Flexo's GA, optionally refined by Levenberg–Marquardt
// (studies/match_study.hpp), run by oli::run_study as every door runs it.
// Prints the result JSON (start/best points, distances before/after,
// evaluations, time, the curve, the resolved study). --method and --abscissa
// replace the study file's members of those names, so a further method needs
// no change here beyond the help text.
//
// `hula match-curvature-torsion STUDY [--seed N] [--threads N] [--log FILE] [--svg DIR]`: curvature and
// torsion as two objectives by NSGA-II, with the optional LM polish of the best compromise
// (studies/curvature_torsion_match.hpp). Prints the Pareto set with both errors of every curve.
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands/common.hpp"
#include "commands/study_common.hpp"

namespace hula::cli {

namespace {

struct MatchArgs {
  StudyArgs study;
  std::optional<std::string> method;
  std::optional<std::string> abscissa;
  bool occt = false;
};

void print_warnings(const Json& out) {
  if (const auto it = out.find("warnings"); it != out.end())
    for (const auto& w : *it) std::cerr << "hula: warning: " << w.get<std::string>() << "\n";
}

int run_match(const MatchArgs& a) {
  // --method and --abscissa replace the file's members before it is read (a target given "of_points" is
  // derived in the replaced abscissa).
  std::vector<StudyOverride> overrides;
  if (a.method) overrides.push_back({"method", "--method", *a.method});
  if (a.abscissa) overrides.push_back({"abscissa", "--abscissa", *a.abscissa});
  const oli::StudyOutcome run = run_study_command(a.study, "match-curvature", overrides);
  if (a.study.log) io::write_run_log_file(run.log, *a.study.log);
  Json out = run.result;
  // Open CASCADE's fairing baselines with the ends of the best curve, measured against the best points.
  if (a.occt) out["occt"] = occt_baselines(run, a.study);
  print_warnings(out);
  print_json(out);
  return kExitOk;
}

int run_match_torsion(const StudyArgs& a, const std::string& format) {
  const oli::StudyOutcome run = run_study_command(a, "match-curvature-torsion");
  if (a.log) io::write_run_log_file(run.log, *a.log);
  print_warnings(run.result);
  print_formatted(run.result, format, [](const Json& d) { return io::records_table(d["front"]); });
  return kExitOk;
}

}  // namespace

Command add_match_curvature_torsion(CLI::App& app) {
  auto a = std::make_shared<StudyArgs>();
  auto format = std::make_shared<std::string>("json");
  CLI::App* sub = app.add_subcommand(
      "match-curvature-torsion",
      "Match prescribed curvature and torsion profiles as two objectives (NSGA-II, optional LM polish)");
  add_study_options(sub, *a);
  sub->footer(
      "--svg DIR writes curve_before.svg, curve_after.svg, profile.svg, torsion_profile.svg, pareto.svg, "
      "convergence.svg, and with a \"map\" fitness_map.svg, torsion_map.svg and fitness_map.csv.");
  add_format_option(sub, *format,
                    "one member of the front per line: curvature, torsion, polished; the curves only in json");
  return {sub, [a, format] { return run_match_torsion(*a, *format); }};
}

Command add_match_curvature(CLI::App& app) {
  auto a = std::make_shared<MatchArgs>();
  CLI::App* sub = app.add_subcommand(
      "match-curvature",
      "Match a prescribed curvature profile by moving data points (GA, or GA + Levenberg-Marquardt)");
  add_study_options(sub, a->study);
  sub->footer(
      "--svg DIR writes curve_before.svg, curve_after.svg, profile.svg, convergence.svg, and with a \"map\" "
      "fitness_map.svg and fitness_map.csv.");
  sub->add_option("--method", a->method, "ga | hybrid | direct (overrides the study file's \"method\")");
  sub->add_option("--abscissa", a->abscissa,
                  "arclength | parameter: what the target's u measures (overrides the study file's \"abscissa\"; "
                  "direct converts a parameter target to arc length through the start spline)");
  sub->add_flag("--occt", a->occt,
                "Add Open CASCADE's fairing baselines between the best curve's ends with its end tangents and "
                "curvatures: \"occt\" in the output, baselines.svg under --svg (planar studies)");
  return {sub, [a] { return run_match(*a); }};
}

}  // namespace hula::cli
