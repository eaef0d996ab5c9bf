// SPDX-License-Identifier: MIT
// `hula hermite STUDY`: Hermite editing (thesis 7.5.2). The C2 cubic spline
// through the points, its tangent and normal handles at the knots, the edits
// (rotations in degrees, scales) applied to P' and P'', and the curve rebuilt
// by the quintic (C2) or cubic (C1) Hermite. JSON out: both curves and the
// handles per knot; --svg DIR draws the spline and the edited curve with their
// handles (cf. thesis figures 69–71).
#include <memory>
#include <string>

#include "commands/common.hpp"
#include "commands/study_common.hpp"
#include "hula/io/json_curve.hpp"

namespace hula::cli {

namespace {

struct HermiteArgs {
  StudyArgs study;
  std::string output;
};

int run_hermite(const HermiteArgs& a) {
  if (!a.output.empty()) io::check_output_path(a.output, "--output");
  const oli::StudyOutcome run = run_study_command(a.study, "hermite");
  Json out = run.result;
  if (!a.output.empty()) io::write_curve_file(a.output, run.curves.front().curve);
  record_run(out, a.study);
  print_result(out, a.output);
  return kExitOk;
}

}  // namespace

Command add_hermite(CLI::App& app) {
  auto args = std::make_shared<HermiteArgs>();
  CLI::App* sub = app.add_subcommand(
      "hermite", "Hermite editing (thesis 7.5.2): rotate and scale the tangent/normal handles of a spline");
  add_study_options(sub, args->study, false);
  sub->add_option("-o,--output", args->output, "Write the edited curve file, atomically");
  return {sub, [args] { return run_hermite(*args); }};
}

}  // namespace hula::cli
