// SPDX-License-Identifier: MIT
// `hula energy CURVE`: the fairness energies of a curve (diffgeom/energy.hpp):
// bending ∫κ² ds and curvature variation ∫(dκ/ds)² ds, each with its
// quadrature error estimate and whether it met its tolerance. Not an error when
// it did not: the library's test is relative to the integral, so an energy that
// is zero up to rounding (∫(dκ/ds)² ds of a circle, 1e-31 ± 1e-26) reports
// "converged": false although its value is right to 1e-26. The answer is io::energy_answer.
#include <memory>

#include "commands/common.hpp"
#include "hula/io/curve_queries.hpp"

namespace hula::cli {

namespace {

int run_energy(const std::string& path) {
  const curve::Curve file = io::read_curve_file(path);
  Json doc = Json::object();
  doc["curve"] = path;
  doc.update(io::energy_answer(file));
  print_json(doc);
  return kExitOk;
}

}  // namespace

Command add_energy(CLI::App& app) {
  auto path = std::make_shared<std::string>();
  CLI::App* sub = app.add_subcommand("energy", "Bending energy and curvature-variation energy of a curve");
  sub->add_option("curve", *path, "Curve file (JSON)")->required();
  return {sub, [path] { return run_energy(*path); }};
}

}  // namespace hula::cli
