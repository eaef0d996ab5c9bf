// SPDX-License-Identifier: MIT
// `hula info`: the analysis of a curve file (kind, degree, knots, control
// points, weights, domain, rational, dimension, arc length, end derivatives,
// planarity) and, for the interpolated kind, the stored inputs.
#include <memory>

#include "commands/common.hpp"

namespace hula::cli {

namespace {
int run_info(const std::string& path) {
  const io::CurveFile file = io::read_curve_file(path);
  Json doc = Json::object();
  doc["file"] = path;
  doc["kind"] = std::string(io::curve_kind_name(file.kind));
  const Json analysis = analyse(file.curve);
  for (const auto& [key, value] : analysis.items()) doc[key] = value;
  if (file.inputs) doc["inputs"] = io::interpolated_to_json(*file.inputs);
  if (file.law) {
    // The analysis above is of the stand-in NURBS; say what it stands for and how closely.
    Json l = io::law_to_json(*file.law);
    l.erase("kind");
    l["approximation_deviation"] = file.law->approximation_deviation;
    doc["law"] = std::move(l);
  }
  print_json(doc);
  return kExitOk;
}
}  // namespace

Command add_info(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  CLI::App* sub = app.add_subcommand("info", "Describe a curve file: degree, knots, length, planarity, ...");
  sub->add_option("curve", *path, "Curve file (JSON)")->required();
  return {sub, [path] { return run_info(*path); }};
}

}  // namespace hula::cli
