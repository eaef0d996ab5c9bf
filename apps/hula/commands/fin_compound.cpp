// SPDX-License-Identifier: MIT
// `hula fin-compound STUDY`: prescribed compound fins (thesis 8.3). Method
// "projection": the normal fin compound of a projection and, given an edited
// compound, the projection whose compound it is and the 3-D curve rebuilt from
// it; method "combescure": the Combescure compound of a parent curve, or the
// parent of a prescribed compound. JSON out (curves as "nurbs" curve
// documents, measured deviations); --svg DIR writes before/after figures.
#include <memory>
#include <string>

#include "commands/common.hpp"
#include "commands/study_common.hpp"
#include "hula/io/json_curve.hpp"

namespace hula::cli {

namespace {

struct FinCompoundArgs {
  StudyArgs study;
  std::string output;
};

int run_fin_compound(const FinCompoundArgs& a) {
  if (!a.output.empty()) io::check_output_path(a.output, "--output");
  const oli::StudyOutcome run = run_study_command(a.study, "fin-compound");
  Json out = run.result;
  if (!a.output.empty()) io::write_curve_file(a.output, run.curves.front().curve);
  record_run(out, a.study);
  print_result(out, a.output);
  return kExitOk;
}

}  // namespace

Command add_fin_compound(CLI::App& app) {
  auto args = std::make_shared<FinCompoundArgs>();
  CLI::App* sub = app.add_subcommand(
      "fin-compound", "Prescribed compound fins (thesis 8.3): projection technique or Combescure transform");
  add_study_options(sub, args->study, false);
  sub->add_option("-o,--output", args->output,
                  "Write the resulting curve file (rebuilt 3-D curve, compound, or parent), atomically");
  return {sub, [args] { return run_fin_compound(*args); }};
}

}  // namespace hula::cli
