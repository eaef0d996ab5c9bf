// SPDX-License-Identifier: MIT
// `hula orthotomic A --pole x,y[,z] [--k 2] -o OUT` and `hula polar A --centre
// x,y [--radius 1] -o OUT`: the mapping techniques of thesis 6.3.2 (K-orthotomic
// and polar map), io::orthotomic_answer / polar_answer (diffgeom/mapping.hpp and
// the codec); the mapped curve is written as a curve file (a law curve when the
// input is one) and the answer without it printed.
#include <memory>
#include <optional>
#include <vector>

#include "commands/common.hpp"
#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/offset_json.hpp"

namespace hula::cli {

namespace {

struct MappingArgs {
  std::string curve;
  std::string point;
  std::optional<double> k;
  std::optional<double> radius;
  std::optional<double> tolerance;
  std::string output;
};

Vec3 parse_point(const std::string& text, const char* field) {
  const std::vector<double> v = parse_number_list(text, field);
  if (v.size() != 2 && v.size() != 3)
    throw Error(Errc::InvalidArgument,
                std::string("--") + field + " needs 2 or 3 numbers, got " + std::to_string(v.size()),
                ErrorWhere{.field = field});
  return {v[0], v[1], v.size() == 3 ? v[2] : 0.0};
}

int finish(const MappingArgs& args, Json answer) {
  // The answer's own curve file, as io::write_curve_file writes it.
  io::write_file_atomically(args.output, io::to_file_text(answer["curve"]));
  answer.erase("curve");
  Json doc = Json::object();
  doc["input"] = args.curve;
  for (auto& [key, value] : answer.items()) doc[key] = std::move(value);
  doc["output"] = args.output;
  print_result(doc, args.output);
  return kExitOk;
}

diffgeom::MappingOptions options_of(const MappingArgs& args) {
  diffgeom::MappingOptions o;
  if (args.tolerance) o.tolerance = *args.tolerance;
  return o;
}

void add_common(CLI::App* sub, MappingArgs& a) {
  sub->add_option("curve", a.curve, "Curve file (JSON)")->required();
  add_real_option(sub, "--tolerance", a.tolerance, 1e-12, 1e-2, false,
                  "Largest distance of the mapped curve's NURBS from it, in [1e-12, 1e-2] (default 1e-6)");
  sub->add_option("-o,--output", a.output, "Curve file to write (a law curve when the input is one); - = stdout")
      ->required();
}

}  // namespace

Command add_orthotomic(CLI::App& app) {
  auto a = std::make_shared<MappingArgs>();
  CLI::App* sub = app.add_subcommand(
      "orthotomic",
      "K-orthotomic of a curve about a pole: P + K (foot of the perpendicular from P on the tangent - P)");
  add_common(sub, *a);
  sub->add_option("--pole", a->point, "The pole P: x,y[,z]")->required();
  add_real_option(sub, "--k", a->k, -1e300, 1e300, false, "K (default 2, the orthotomic; 1 is the pedal curve)");
  return {sub, [a] {
            io::check_output_path(a->output, "--output");
            const curve::Curve c = io::read_curve_file(a->curve);
            return finish(*a,
                          io::orthotomic_answer(c, parse_point(a->point, "pole"), a->k.value_or(2.0), options_of(*a)));
          }};
}

Command add_polar(CLI::App& app) {
  auto a = std::make_shared<MappingArgs>();
  CLI::App* sub = app.add_subcommand(
      "polar", "Polar map of a plane curve: the poles of its tangent lines about a circle (inflections show as cusps)");
  add_common(sub, *a);
  sub->add_option("--centre", a->point, "Centre of the circle: x,y")->required();
  add_real_option(sub, "--radius", a->radius, 0.0, 1e300, true, "Radius of the circle (default 1)");
  return {sub, [a] {
            io::check_output_path(a->output, "--output");
            const curve::Curve c = io::read_curve_file(a->curve);
            return finish(
                *a, io::polar_answer(c, parse_point(a->point, "centre"), a->radius.value_or(1.0), options_of(*a)));
          }};
}

}  // namespace hula::cli
