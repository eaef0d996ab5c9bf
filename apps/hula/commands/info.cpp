// SPDX-License-Identifier: MIT
// `hula info`: the analysis of a curve file (kind, degree, knots, control
// points, weights, domain, rational, dimension, arc length, end derivatives,
// planarity: io::curve_description_json) and, for the interpolated kind, the stored inputs.
#include <memory>

#include "commands/common.hpp"
#include "hula/io/curve_queries.hpp"

namespace hula::cli {

namespace {
int run_info(const std::string& path) {
  const curve::Curve c = io::read_curve_file(path);
  Json doc = Json::object();
  doc["file"] = path;
  doc["kind"] = std::string(c.kind_name());
  const Json analysis = io::curve_description_json(c.nurbs());
  for (const auto& [key, value] : analysis.items()) doc[key] = value;
  // The construction data (without the file's format tag) of the kinds that are more than a NURBS.
  if (c.kind() == curve::Kind::Nurbs || c.kind() == curve::Kind::Bezier) {
    print_json(doc);
    return kExitOk;
  }
  Json data = io::curve_to_json(c);
  data.erase("format");
  data.erase("version");
  switch (c.kind()) {
    case curve::Kind::Nurbs:
    case curve::Kind::Bezier:
      break;
    case curve::Kind::Interpolated:
    case curve::Kind::Hermite:
      doc["inputs"] = std::move(data);
      break;
    case curve::Kind::Law:
    case curve::Kind::Natural:
      // The analysis above is of the stand-in NURBS; say what it stands for and how closely.
      data.erase("kind");
      data["approximation_deviation"] = c.approximation_deviation();
      doc[c.kind() == curve::Kind::Law ? "law" : "natural"] = std::move(data);
      break;
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
