// SPDX-License-Identifier: MIT
// `hula edit-projection STUDY`: replace one projection of a 3-D curve by an
// edited planar curve and rebuild the 3-D curve (thesis 8.1), matching the two
// curves by normalised parameter. JSON out: the curve, the measured deviation
// of the construction and the largest change of each coordinate; --svg DIR
// draws the three projections before and after.
#include <memory>
#include <string>

#include "commands/common.hpp"
#include "commands/study_common.hpp"
#include "hula/io/json_curve.hpp"

namespace hula::cli {

namespace {

struct EditProjectionArgs {
  StudyArgs study;
  std::string output;
};

int run_edit_projection(const EditProjectionArgs& a) {
  if (!a.output.empty()) io::check_output_path(a.output, "--output");
  const oli::StudyOutcome run = run_study_command(a.study, "edit-projection");
  Json out = run.result;
  if (!a.output.empty()) io::write_curve_file(a.output, run.curves.front().curve);
  record_run(out, a.study);
  print_result(out, a.output);
  return kExitOk;
}

}  // namespace

Command add_edit_projection(CLI::App& app) {
  auto args = std::make_shared<EditProjectionArgs>();
  CLI::App* sub = app.add_subcommand("edit-projection",
                                     "Replace one projection of a 3-D curve by an edited planar curve (thesis 8.1)");
  add_study_options(sub, args->study, false);
  sub->add_option("-o,--output", args->output, "Write the rebuilt curve file, atomically");
  return {sub, [args] { return run_edit_projection(*args); }};
}

}  // namespace hula::cli
