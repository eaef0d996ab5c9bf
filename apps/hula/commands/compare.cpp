// SPDX-License-Identifier: MIT
// Two-curve commands. `hula deviation A B`: the sampled distance between two
// curves (nurbs::deviation: thesis 10.2.2's position distance at equal
// normalised parameters, or the closest-point distance) with max, mean, RMS
// and per-axis figures. `hula continuity A B`: the continuity of the join of
// A's end with B's start (diffgeom::join_continuity: C0–C3, G0–G3, tangent
// angle, curvature on each side, the derivative table of thesis Table 3).
// The answers are io::deviation_answer and io::join_continuity_answer.
#include <memory>

#include "commands/common.hpp"
#include "hula/core/error.hpp"
#include "hula/io/curve_queries.hpp"

namespace hula::cli {

namespace {

struct TwoCurves {
  std::string a;
  std::string b;
  std::size_t samples = 1001;
  std::string mode = "parameter";
  std::string format = "json";
};

int run_deviation(const TwoCurves& args) {
  const curve::Curve a = io::read_curve_file(args.a);
  const curve::Curve b = io::read_curve_file(args.b);
  nurbs::DeviationOptions o;
  o.samples = args.samples;
  if (args.mode == "parameter")
    o.mode = nurbs::DeviationMode::Parameter;
  else if (args.mode == "closest")
    o.mode = nurbs::DeviationMode::Closest;
  else
    throw Error(Errc::InvalidArgument, "--mode " + args.mode + ": expected parameter or closest",
                ErrorWhere{.field = "mode"});
  Json doc = Json::object();
  doc["a"] = args.a;
  doc["b"] = args.b;
  doc.update(io::deviation_answer(a, b, o, args.mode));
  print_formatted(doc, args.format, [](const Json& d) { return io::record_table(d); });
  return kExitOk;
}

int run_continuity(const TwoCurves& args) {
  const curve::Curve a = io::read_curve_file(args.a);
  const curve::Curve b = io::read_curve_file(args.b);
  Json doc = Json::object();
  doc["a"] = args.a;
  doc["b"] = args.b;
  doc.update(io::join_continuity_answer(a, b));
  print_json(doc);
  return kExitOk;
}

}  // namespace

Command add_deviation(CLI::App& app) {
  auto a = std::make_shared<TwoCurves>();
  CLI::App* sub = app.add_subcommand("deviation", "Distance between two curves: max, mean, RMS, per axis");
  sub->add_option("a", a->a, "Reference curve file (JSON)")->required();
  sub->add_option("b", a->b, "Compared curve file (JSON)")->required();
  sub->add_option("--samples", a->samples, "Samples, ends included, >= 2 (default 1001)")
      ->check(CLI::Range(std::size_t{2}, std::size_t{10'000'000}));
  set_choices(sub->add_option("--mode", a->mode,
                              "parameter: A(s) vs B(s) at equal normalised parameters (thesis 10.2.2, default); "
                              "closest: A(s) vs the nearest point of B"),
              {"parameter", "closest"});
  add_format_option(sub, a->format,
                    "the summary as one record: a, b, mode, samples, max, max_at, mean, rms, "
                    "mean_axis, max_axis");
  return {sub, [a] { return run_deviation(*a); }};
}

Command add_continuity(CLI::App& app) {
  auto a = std::make_shared<TwoCurves>();
  CLI::App* sub = app.add_subcommand("continuity", "Continuity (C0-C3, G0-G3) of the join of A's end with B's start");
  sub->add_option("a", a->a, "First curve file (its end)")->required();
  sub->add_option("b", a->b, "Second curve file (its start)")->required();
  return {sub, [a] { return run_continuity(*a); }};
}

}  // namespace hula::cli
