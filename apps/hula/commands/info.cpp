// SPDX-License-Identifier: MIT
// `hula info`: the analysis of a curve file (kind, degree, knots, control
// points, weights, domain, rational, dimension, arc length, end derivatives,
// planarity: io::curve_description_json, streamed by io::DescriptionWriter) and, for the kinds
// that are more than a NURBS, the stored inputs.
#include <memory>

#include "commands/common.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/curve_queries.hpp"
#include "hula/io/json_text.hpp"

namespace hula::cli {

namespace {
int run_info(const std::string& path) {
  const curve::Curve c = io::read_curve_file(path);
  // Everything that can fail is computed before the first byte is printed.
  const io::DescriptionWriter description(c.nurbs());
  // The construction data (without the file's format tag) of the kinds that are more than a NURBS.
  Json data;
  if (c.kind() != curve::Kind::Nurbs && c.kind() != curve::Kind::Bezier) {
    data = io::curve_to_json(c);
    data.erase("format");
    data.erase("version");
    if (c.kind() == curve::Kind::Law || c.kind() == curve::Kind::Natural) {
      // The analysis above is of the stand-in NURBS; say what it stands for and how closely.
      data.erase("kind");
      data["approximation_deviation"] = c.approximation_deviation();
    }
  }
  // Streamed to standard output in pieces: a million-pole curve is printed without a JSON value.
  std::string buffer;
  io::JsonText w(buffer, true, [](std::string& text) {
    io::write_stdout(text);
    text.clear();
  });
  w.begin_object();
  w.member("file").string(path);
  w.member("kind").string(c.kind_name());
  description.write_members(w);
  switch (c.kind()) {
    case curve::Kind::Nurbs:
    case curve::Kind::Bezier:
      break;
    case curve::Kind::Interpolated:
    case curve::Kind::Hermite:
      w.member("inputs").value(data);
      break;
    case curve::Kind::Law:
      w.member("law").value(data);
      break;
    case curve::Kind::Natural:
      w.member("natural").value(data);
      break;
  }
  w.end_object();
  buffer += '\n';
  io::write_stdout(buffer);
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
