// SPDX-License-Identifier: MIT
// `hula fair-knots STUDY`: the knot-vector studies of thesis 7.2–7.4 from a
// "fair-knots" study file — chord-length start, the given parameters,
// the energy map, GA and/or deterministic fairing — run by oli::run_study as
// every door runs it, as JSON, with the before/after curves (curvature fins),
// the energy map and the convergence graphs as SVG and the map as CSV under
// --svg DIR. `--occt` adds Open CASCADE's fairing baselines
// (oli/fairing_baselines.hpp) with the best curve's end tangents and
// curvatures, their energies and deviations from the data points under
// "occt", and `baselines.svg` with every curve and its curvature comb.
#include <memory>
#include <variant>

#include "commands/common.hpp"
#include "commands/study_common.hpp"

namespace hula::cli {

namespace {

int run_fair_knots(const StudyArgs& args, bool occt) {
  const oli::StudyOutcome run = run_study_command(args, "fair-knots");
  Json out = run.result;
  if (occt) out["occt"] = occt_baselines(run, args);
  // Only the GA has generations to log (method "deterministic" writes no log).
  if (args.log && std::get<oli::FairKnotsValues>(run.values).outcome.ga) io::write_run_log_file(run.log, *args.log);
  print_json(out);
  return kExitOk;
}

}  // namespace

Command add_fair_knots(CLI::App& app) {
  auto args = std::make_shared<StudyArgs>();
  CLI::App* sub = app.add_subcommand(
      "fair-knots",
      "Knot-vector studies (thesis 7.2-7.4): chord-length start, evaluation of given parameters, energy map, "
      "GA and deterministic fairing of the data parameters of a cubic spline");
  add_study_options(sub, *args);
  sub->footer(
      "--svg DIR writes curve_before.svg, curve_after.svg (curves with curvature fins), convergence.svg, and with "
      "a \"map\" energy_map.svg, energy_map.csv and (with map.sections) energy_sections.svg. --log writes the GA's run "
      "log (all rounds).");
  auto occt = std::make_shared<bool>(false);
  sub->add_flag("--occt", *occt,
                "Add Open CASCADE's fairing baselines (FairCurve_Batten fixed and sliding, FairCurve_MinimalVariation) "
                "with the best curve's end tangents and curvatures: \"occt\" in the output, baselines.svg under --svg");
  return {sub, [args, occt] { return run_fair_knots(*args, *occt); }};
}

}  // namespace hula::cli
