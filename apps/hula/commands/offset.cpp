// SPDX-License-Identifier: MIT
// `hula offset A --distance D`: the planar offset of a plane curve, its cusps
// and loops, and the trimmed offset: io::offset_answer, the answer every door
// gives (diffgeom::planar_offset and its codec). With -o the trimmed offset
// (one piece) is written as a curve file, with --raw the untrimmed offset (a
// law curve when the input is one). `hula helical-offset A --distance D
// --twist θ [--frame frenet|bishop] -o OUT`: the helical offset (thesis
// 6.5.2), io::helical_offset_answer, written as a curve file.
#include <memory>
#include <optional>

#include "commands/common.hpp"
#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/offset_json.hpp"

namespace hula::cli {

namespace {

struct OffsetArgs {
  std::string curve;
  std::optional<double> distance;
  std::optional<double> tolerance;
  bool no_trim = false;
  bool raw = false;
  std::string output;
};

int run_offset(const OffsetArgs& args) {
  if (!args.output.empty()) io::check_output_path(args.output, "--output");
  const curve::Curve c = io::read_curve_file(args.curve);
  diffgeom::OffsetOptions options;
  if (args.tolerance) options.tolerance = *args.tolerance;
  options.trim = !args.no_trim;
  const diffgeom::PlanarOffset offset = diffgeom::planar_offset(c, *args.distance, options);
  Json doc = Json::object();
  doc["curve"] = args.curve;
  Json answer = io::planar_offset_to_json(offset, *args.distance, options);
  for (auto& [key, value] : answer.items()) doc[key] = std::move(value);
  if (!args.output.empty()) {
    if (args.raw) {
      io::write_curve_file(args.output, offset.raw);
    } else if (offset.trimmed.size() == 1) {
      io::write_curve_file(args.output, offset.trimmed.front().curve);
    } else {
      throw Error(Errc::InvalidArgument,
                  "the trimmed offset has " + std::to_string(offset.trimmed.size()) +
                      " pieces; -o writes one curve (write the untrimmed offset with --raw)",
                  {.field = "output"});
    }
    doc["output"] = args.output;
  }
  print_result(doc, args.output);
  return kExitOk;
}

struct HelicalArgs {
  std::string curve;
  std::string distance;
  std::string twist = "0";
  std::string frame = "frenet";
  std::optional<double> tolerance;
  std::string output;
};

int run_helical(const HelicalArgs& args) {
  io::check_output_path(args.output, "--output");
  const curve::Curve c = io::read_curve_file(args.curve);
  diffgeom::HelicalOffsetOptions options;
  const std::optional<diffgeom::OffsetFrame> frame = diffgeom::offset_frame_from_name(args.frame);
  if (!frame)
    throw Error(Errc::InvalidOption, "--frame must be frenet or bishop, got '" + args.frame + "'", {.field = "frame"});
  options.frame = *frame;
  if (args.tolerance) options.tolerance = *args.tolerance;
  Json doc = Json::object();
  doc["input"] = args.curve;
  const diffgeom::HelicalOffset offset = diffgeom::helical_offset(c, args.distance, args.twist, options);
  io::write_curve_file(args.output, offset.curve);
  Json answer = io::helical_offset_to_json(offset, args.distance, args.twist, options);
  answer.erase("curve");
  for (auto& [key, value] : answer.items()) doc[key] = std::move(value);
  doc["output"] = args.output;
  print_result(doc, args.output);
  return kExitOk;
}

}  // namespace

Command add_helical_offset(CLI::App& app) {
  auto a = std::make_shared<HelicalArgs>();
  CLI::App* sub = app.add_subcommand(
      "helical-offset", "Helical offset of a curve: winds around it at a distance with a twist (thesis 6.5.2)");
  sub->add_option("curve", a->curve, "Curve file (JSON)")->required();
  sub->add_option("--distance", a->distance, "Distance d as a law of the curve parameter, e.g. 0.5 or 0.2+0.1*t")
      ->required();
  sub->add_option("--twist", a->twist, "Twist angle θ (radians) as a law of the curve parameter, e.g. 8*t (default 0)");
  sub->add_option("--frame", a->frame, "frenet (N, B; the default) or bishop (rotation-minimising)");
  add_real_option(sub, "--tolerance", a->tolerance, 1e-12, 1e-2, false,
                  "Largest distance of the offset's NURBS from the offset, in [1e-12, 1e-2] (default 1e-6)");
  sub->add_option("-o,--output", a->output, "Curve file to write (a law curve when the offset is exact); - = stdout")
      ->required();
  return {sub, [a] { return run_helical(*a); }};
}

Command add_offset(CLI::App& app) {
  auto a = std::make_shared<OffsetArgs>();
  CLI::App* sub = app.add_subcommand(
      "offset", "Planar offset of a plane curve by a distance, with its cusps and loops trimmed away");
  sub->add_option("curve", a->curve, "Curve file (JSON), planar")->required();
  add_real_option(sub, "--distance", a->distance, -1e300, 1e300, false,
                  "Offset distance (model units); positive to the left of the direction of travel")
      ->required();
  add_real_option(sub, "--tolerance", a->tolerance, 1e-12, 1e-2, false,
                  "Largest distance of the offset's NURBS from the exact offset, in [1e-12, 1e-2] (default 1e-6)");
  sub->add_flag("--no-trim", a->no_trim, "Only the raw offset: no cusps, loops or trimmed pieces");
  auto* out = sub->add_option("-o,--output", a->output,
                              "Write the trimmed offset (one piece) as a curve file; with --raw the untrimmed offset");
  sub->add_flag("--raw", a->raw, "With -o: write the untrimmed offset (a law curve when the input is one)")->needs(out);
  return {sub, [a] { return run_offset(*a); }};
}

}  // namespace hula::cli
