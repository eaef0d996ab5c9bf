// SPDX-License-Identifier: MIT
// HulaHoops::io_studies alone: a run report written by its codec reads back with the same
// termination, generations and evaluations.
#include <cstdio>

#include "hula/io/run_report_json.hpp"

int main() {
  hula::optim::RunReport report;
  report.termination = hula::optim::Termination::Stagnation;
  report.message = "no improvement in 20 generations";
  report.generations = 42;
  report.evaluations = 4200;
  const hula::io::Json json = hula::io::run_report_to_json(report, {.seed = 7});
  const hula::optim::RunReport back = hula::io::run_report_from_json(json);
  std::printf("io_studies: %s\n", json.dump().c_str());
  return back.termination == report.termination && back.generations == 42 && back.evaluations == 4200 &&
                 back.message == report.message && json.at("seed") == 7
             ? 0
             : 1;
}
