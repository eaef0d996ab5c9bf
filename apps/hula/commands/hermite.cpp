// SPDX-License-Identifier: MIT
// `hula hermite STUDY`: Hermite editing (thesis 7.5.2). The C2 cubic spline
// through the points, its tangent and normal handles at the knots, the edits
// (rotations in degrees, scales) applied to P' and P'', and the curve rebuilt
// by the quintic (C2) or cubic (C1) Hermite. JSON out: both curves and the
// handles per knot; --svg DIR draws the spline and the edited curve with their
// handles (cf. thesis figures 69–71). `hula hermite-frenet HANDLES -o OUT`:
// the C3 septic Hermite curve through handles that fix the tangent, the
// curvature with its normal and the torsion at every knot
// (io::hermite_frenet_curve, nurbs::hermite_frenet).
#include <memory>
#include <string>

#include "commands/common.hpp"
#include "commands/study_common.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/curve_edits.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/json_read.hpp"

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

struct FrenetArgs {
  std::string handles;
  std::string output;
};

int run_hermite_frenet(const FrenetArgs& a) {
  io::check_output_path(a.output, "--output");
  const io::MadeCurveAnswer answer =
      io::hermite_frenet_answer(io::json::parse_json_text(io::read_text_file(a.handles), "handles file"));
  io::write_curve_file(a.output, answer.curve);
  Json doc = Json::object();
  doc["input"] = a.handles;
  doc["output"] = a.output;
  doc.update(answer.report);
  print_result(doc, a.output);
  return kExitOk;
}

}  // namespace

Command add_hermite_frenet(CLI::App& app) {
  auto args = std::make_shared<FrenetArgs>();
  CLI::App* sub = app.add_subcommand(
      "hermite-frenet", "C3 curve through handles fixing tangent, curvature with its normal, and torsion at each knot");
  sub->add_option("handles", args->handles, "Frenet handle file (JSON, docs/formats.md)")->required();
  sub->add_option("-o,--output", args->output, "Curve file to write (atomically); - = stdout")->required();
  return {sub, [args] { return run_hermite_frenet(*args); }};
}

Command add_hermite(CLI::App& app) {
  auto args = std::make_shared<HermiteArgs>();
  CLI::App* sub = app.add_subcommand(
      "hermite", "Hermite editing (thesis 7.5.2): rotate and scale the tangent/normal handles of a spline");
  add_study_options(sub, args->study, false);
  sub->add_option("-o,--output", args->output, "Write the edited curve file, atomically");
  return {sub, [args] { return run_hermite(*args); }};
}

}  // namespace hula::cli
