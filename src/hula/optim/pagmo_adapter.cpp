// SPDX-License-Identifier: MIT
#include "hula/optim/pagmo_adapter.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "hula/core/error.hpp"
#include "hula/core/plugin.hpp"
#include "hula/optim/detail/pagmo_plugin.hpp"

namespace hula::optim {
namespace {

bool is_multi_objective(PagmoAlgorithm a) { return a == PagmoAlgorithm::Moead || a == PagmoAlgorithm::Nsga2; }

const char* name_of(PagmoAlgorithm a) {
  switch (a) {
    case PagmoAlgorithm::Cmaes:
      return "cmaes";
    case PagmoAlgorithm::De:
      return "de";
    case PagmoAlgorithm::Sade:
      return "sade";
    case PagmoAlgorithm::Pso:
      return "pso";
    case PagmoAlgorithm::Sga:
      return "sga";
    case PagmoAlgorithm::Moead:
      return "moead";
    case PagmoAlgorithm::Nsga2:
      return "nsga2";
  }
  return "?";
}

}  // namespace

PagmoAlgorithm pagmo_algorithm(std::string_view name) {
  for (const auto a : {PagmoAlgorithm::Cmaes, PagmoAlgorithm::De, PagmoAlgorithm::Sade, PagmoAlgorithm::Pso,
                       PagmoAlgorithm::Sga, PagmoAlgorithm::Moead, PagmoAlgorithm::Nsga2}) {
    if (name == name_of(a)) return a;
  }
  throw Error(Errc::InvalidArgument,
              "algorithm = \"" + std::string(name) + "\" is not one of cmaes, de, sade, pso, sga, moead, nsga2",
              {.field = "algorithm"});
}

void PagmoOptions::validate() const {
  if (population == 0) throw Error(Errc::InvalidOption, "population = 0 must be >= 1", {.field = "population"});
  if (generations == 0) throw Error(Errc::InvalidOption, "generations = 0 must be >= 1", {.field = "generations"});
  if (!std::isfinite(wall_time_seconds) || wall_time_seconds < 0.0)
    throw Error(Errc::InvalidOption, "wall_time_seconds = " + format_number(wall_time_seconds) + " must be >= 0",
                {.field = "wall_time_seconds"});
}

PagmoResult solve_with_pagmo(const Problem& problem, const PagmoOptions& options) {
  problem.validate();
  options.validate();
  const bool multi = problem.objectives > 1;
  if (multi != is_multi_objective(options.algorithm)) {
    throw Error(Errc::InvalidOption,
                std::string("algorithm = ") + name_of(options.algorithm) +
                    " cannot solve a problem with objectives = " + std::to_string(problem.objectives),
                {.field = "algorithm"});
  }
  if (problem.inequality_constraints + problem.equality_constraints > 0) {
    throw Error(Errc::InvalidOption,
                std::string("algorithm = ") + name_of(options.algorithm) +
                    " does not handle constraints; use solve_real_ga or solve_nsga2",
                {.field = "algorithm"});
  }
  // Loaded on the first pagmo run only (detail/pagmo_plugin.hpp); a failed load is retried next time.
  static const auto run_pagmo =
      reinterpret_cast<detail::PagmoRunFunction>(plugin_symbol("pagmo", detail::kPagmoRunSymbol));
  const auto start = std::chrono::steady_clock::now();
  detail::PagmoRun run;
  try {
    run_pagmo(problem, options, run);
  } catch (const std::invalid_argument& e) {
    throw Error(Errc::InvalidOption, std::string("pagmo ") + name_of(options.algorithm) + " refused: " + e.what(),
                {.field = "algorithm"});
  }
  if (run.succeeded == 0) {
    throw Error(
        Errc::NumericalFailure,
        "no evaluation returned finite values in " + std::to_string(run.result.report.evaluations) + " evaluations",
        {.field = "evaluate"});
  }
  PagmoResult result = std::move(run.result);
  result.report.failed_evaluations = run.failed;
  const std::string of_pagmo = " generations of pagmo " + std::string(name_of(options.algorithm));
  if (run.stopped) {
    result.report.termination = *run.stopped;
    result.report.generations = run.generations;
    result.report.message = (*run.stopped == Termination::Cancelled
                                 ? std::string("cancelled")
                                 : "wall time " + format_number(options.wall_time_seconds) + " s elapsed") +
                            " after " + std::to_string(run.generations) + of_pagmo;
  } else {
    result.report.termination = Termination::MaxGenerations;
    result.report.generations = options.generations;
    result.report.message = std::to_string(options.generations) + of_pagmo;
  }
  result.report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace hula::optim
