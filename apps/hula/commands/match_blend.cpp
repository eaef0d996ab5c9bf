// SPDX-License-Identifier: MIT
// `hula match A B --continuity G2 [--end start|end] [--to-end start|end | --at t] -o OUT`: A's end made G0–G3
// to B's end or to B at a parameter, moving A's last k + 1 poles (io::match_answer); `hula blend A B
// --continuity G3 [--end start|end] [--to-end start|end] -o OUT`: the fair Hermite blend from A's end to B's
// start, or from and to the ends named (io::blend_answer). Both write the
// new curve and print the report with the continuity reached (no report with -o -: stdout is the curve).
#include <memory>
#include <optional>

#include "commands/common.hpp"
#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/curve_queries.hpp"

namespace hula::cli {

namespace {

struct JoinArgs {
  std::string a;
  std::string b;
  std::string continuity = "G2";
  std::string end = "end";
  std::string to_end = "start";
  std::optional<double> at;
  std::optional<double> tangent_scale;
  std::string output;
};

int finish(const JoinArgs& args, io::CurveJoinAnswer answer) {
  io::write_curve_file(args.output, answer.curve);
  Json doc = Json::object();
  doc["a"] = args.a;
  doc["b"] = args.b;
  doc["output"] = args.output;
  doc.update(answer.report);
  print_result(doc, args.output);  // with -o -, stdout is the curve alone (issue 24 item 2)
  return kExitOk;
}

int run_match(const JoinArgs& args) {
  io::check_output_path(args.output, "--output");
  diffgeom::MatchOptions options;
  options.continuity = io::continuity_order_from_name(args.continuity, 0, "continuity");
  options.end = io::curve_end_from_name(args.end, "end");
  options.target_end = io::curve_end_from_name(args.to_end, "to-end");
  if (args.at) {
    options.use_parameter = true;
    options.at = *args.at;
  }
  if (args.tangent_scale) options.tangent_scale = *args.tangent_scale;
  const curve::Curve a = io::read_curve_file(args.a);
  const curve::Curve b = io::read_curve_file(args.b);
  return finish(args, io::match_answer(a, b, options));
}

int run_blend(const JoinArgs& args) {
  io::check_output_path(args.output, "--output");
  diffgeom::BlendOptions options;
  options.continuity = io::continuity_order_from_name(args.continuity, 1, "continuity");
  options.end = io::curve_end_from_name(args.end, "end");
  options.target_end = io::curve_end_from_name(args.to_end, "to-end");
  const curve::Curve a = io::read_curve_file(args.a);
  const curve::Curve b = io::read_curve_file(args.b);
  return finish(args, io::blend_answer(a, b, options));
}

}  // namespace

Command add_match(CLI::App& app) {
  auto args = std::make_shared<JoinArgs>();
  CLI::App* sub = app.add_subcommand("match", "Make A's end G0-G3 to B's end or to a point on B (moves A's end poles)");
  sub->add_option("a", args->a, "Curve file whose end moves")->required();
  sub->add_option("b", args->b, "Curve file matched to")->required();
  sub->add_option("--continuity", args->continuity, "G0, G1, G2 or G3 (default G2)");
  sub->add_option("--end", args->end, "End of A that moves: start or end (default end)");
  auto* to_end = sub->add_option("--to-end", args->to_end, "End of B matched to: start or end (default start)");
  sub->add_option("--at", args->at, "Parameter on B matched to (instead of an end)")->excludes(to_end);
  sub->add_option("--tangent-scale", args->tangent_scale, "Multiplies A's kept end speed (default 1)");
  sub->add_option("-o,--output", args->output, "Output curve file (JSON)")->required();
  return {sub, [args] { return run_match(*args); }};
}

Command add_blend(CLI::App& app) {
  auto args = std::make_shared<JoinArgs>();
  CLI::App* sub = app.add_subcommand("blend", "Fair G1-G3 Hermite blend curve from A's end to B's start");
  sub->add_option("a", args->a, "Curve file the blend leaves")->required();
  sub->add_option("b", args->b, "Curve file the blend reaches")->required();
  sub->add_option("--continuity", args->continuity, "G1, G2 or G3 (default G2)");
  sub->add_option("--end", args->end, "End of A the blend leaves: start or end (default end)");
  sub->add_option("--to-end", args->to_end, "End of B the blend reaches: start or end (default start)");
  sub->add_option("-o,--output", args->output, "Output curve file (JSON)")->required();
  return {sub, [args] { return run_blend(*args); }};
}

}  // namespace hula::cli
