// SPDX-License-Identifier: MIT
// `hula convert IN -o OUT [--format F] [--from F]`: curves from one exchange
// format to another in one step (oli::convert_file: an import into an
// in-memory document, then an export), formats by extension or by name.
#include <memory>
#include <optional>
#include <string>

#include "commands/common.hpp"
#include "hula/oli/file_convert.hpp"

namespace hula::cli {

namespace {

struct ConvertArgs {
  std::string input;
  std::string output;
  std::string format;
  std::string from;
  double tolerance = io::SvgPathOptions{}.tolerance;
};

int run_convert(const ConvertArgs& a) {
  oli::ConvertOptions options;
  if (!a.format.empty()) options.output_format = oli::file_format_from_name(a.format);
  if (!a.from.empty()) options.input_format = oli::file_format_from_name(a.from);
  options.svg_tolerance = a.tolerance;
  const oli::ConvertReport r = oli::convert_file(a.input, a.output, options);
  Json out = Json::object();
  out["input"] = a.input;
  out["input_format"] = std::string(oli::file_format_name(r.input_format));
  out["file"] = a.output;
  out["format"] = std::string(oli::file_format_name(r.output_format));
  out["curves"] = r.curves;
  out["skipped"] = r.skipped;
  out["max_deviation"] = r.max_deviation;
  out["warnings"] = r.warnings;
  print_result(out, a.output);
  return kExitOk;
}

}  // namespace

Command add_convert(CLI::App& app) {
  auto a = std::make_shared<ConvertArgs>();
  CLI::App* sub = app.add_subcommand(
      "convert", "Convert curves between JSON, STEP, IGES, DXF and SVG (formats by extension or --format)");
  sub->add_option("input", a->input, "Input file: .json (curve file or hula-document), .step/.stp, .iges/.igs, .dxf")
      ->required();
  sub->add_option("-o,--output", a->output, "Output file (.json, .step/.stp, .iges/.igs, .dxf, .svg), or - for stdout")
      ->required();
  sub->add_option("--format", a->format,
                  "Output format when the extension does not tell: json | step | step-ap214 | step-ap242 | iges | "
                  "dxf | svg")
      ->check(CLI::IsMember({"json", "step", "step-ap214", "step-ap242", "iges", "dxf", "svg"}));
  sub->add_option("--from", a->from,
                  "Input format when the extension does not tell (`-`: standard input): json | dxf | step | iges")
      ->check(CLI::IsMember({"json", "step", "step-ap214", "step-ap242", "iges", "dxf"}));
  sub->add_option("--tolerance", a->tolerance,
                  "SVG: largest deviation of the cubic Bezier pieces of rational or degree > 3 curves, model units "
                  "(default 1e-6); curves of degree <= 3 are exact")
      ->check(CLI::PositiveNumber);
  return {sub, [a] { return run_convert(*a); }};
}

}  // namespace hula::cli
