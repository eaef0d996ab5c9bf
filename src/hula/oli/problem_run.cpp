// SPDX-License-Identifier: MIT
// Optimisation problem runs for front ends without a solver (problem_run.hpp).
#include "hula/oli/problem_run.hpp"

#include <chrono>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>

#include "hula/core/error.hpp"
#include "hula/io/optimise_request.hpp"
#include "hula/io/problem_file.hpp"
#include "hula/io/run_report_json.hpp"
#include "hula/optim/solve.hpp"

namespace hula::oli {

using io::json::JsonPath;
using io::json::root_path;

struct ProblemRun::State {
  optim::Problem problem;
  std::string algorithm_name = "ga-real";
  optim::SolverOptions algorithm = optim::RealGaOptions{};
  std::optional<std::size_t> population;
  std::size_t generations = 100;
  std::uint64_t seed = 0;
};

namespace {

// The state's algorithm with its run settings; with a flag and a callback, cancellation and progress.
optim::SolverOptions solver_options(const ProblemRun::State& s, const CancellationToken* cancel,
                                    const std::function<void(Json)>* on_event) {
  io::SolverRequest q{.algorithm = s.algorithm_name,
                      .population = s.population,
                      .generations = s.generations,
                      .seed = s.seed,
                      .cancel = cancel};
  const auto start = std::chrono::steady_clock::now();
  if (on_event != nullptr && *on_event)
    q.on_generation = [start, on_event](const optim::GenerationLog& g) {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      (*on_event)(io::generation_event_json(g, elapsed));
    };
  return io::solver_options(q);
}

}  // namespace

ProblemRun ProblemRun::from_json(const Json& request) {
  const JsonPath root;
  io::json::reject_unknown_members(request, root, {"problem", "algorithm", "population", "generations", "seed"});
  auto state = std::make_shared<State>();
  const Json& problem = io::json::require_member(request, root, "problem");
  if (!problem.is_object()) io::json::type_error(problem, root_path("problem"), "a problem object (docs/formats.md)");
  state->problem = io::problem_from_json(problem).problem;
  if (const Json* a = io::json::optional_member(request, "algorithm")) {
    state->algorithm_name = io::json::get_string(*a, root_path("algorithm"));
    // Named as every door names an algorithm; a run here is a population algorithm (progress per generation).
    try {
      state->algorithm = optim::solver_from_name(state->algorithm_name);
    } catch (const Error&) {
      state->algorithm = optim::NelderMeadOptions{};  // not a population algorithm: refused below
    }
    if (!std::holds_alternative<optim::RealGaOptions>(state->algorithm) &&
        !std::holds_alternative<optim::BinaryGaOptions>(state->algorithm) &&
        !std::holds_alternative<optim::Nsga2Options>(state->algorithm))
      throw Error(Errc::InvalidOption,
                  "algorithm = \"" + state->algorithm_name + "\" is not one of ga-real, ga-binary, nsga2",
                  ErrorWhere{.field = "algorithm"});
  }
  if (const Json* p = io::json::optional_member(request, "population"))
    state->population = static_cast<std::size_t>(io::json::get_integer(*p, root_path("population"), 2, 100000));
  if (const Json* g = io::json::optional_member(request, "generations"))
    state->generations = static_cast<std::size_t>(io::json::get_integer(*g, root_path("generations"), 1, 100000));
  if (const Json* s = io::json::optional_member(request, "seed"))
    state->seed = static_cast<std::uint64_t>(io::json::get_integer(*s, root_path("seed"), 0, (1ll << 53)));
  // The options the run will use, checked now: a bad population is refused, not a failed run.
  std::visit([](const auto& o) { o.validate(); }, solver_options(*state, nullptr, nullptr));
  const bool nsga2 = std::holds_alternative<optim::Nsga2Options>(state->algorithm);
  if (nsga2 && state->problem.objectives < 2)
    throw Error(Errc::InvalidOption,
                "algorithm nsga2 needs a problem with at least 2 objectives; '" + state->problem.name +
                    "' has 1 (use ga-real or ga-binary)",
                ErrorWhere{.field = "algorithm"});
  if (!nsga2 && state->problem.objectives != 1)
    throw Error(Errc::InvalidOption,
                "algorithm " + state->algorithm_name + " solves one objective; '" + state->problem.name + "' has " +
                    std::to_string(state->problem.objectives) + " (use nsga2)",
                ErrorWhere{.field = "algorithm"});
  return ProblemRun(std::move(state));
}

ProblemRunOutcome ProblemRun::run(const CancellationToken* cancel, const std::function<void(Json)>& on_event) const {
  const State& s = *state_;
  optim::SolveOptions options;
  options.algorithm = solver_options(s, cancel, &on_event);
  const optim::SolveResult r = optim::solve(s.problem, options);
  ProblemRunOutcome out;
  if (std::holds_alternative<optim::Nsga2Options>(s.algorithm)) {
    Json front = Json::array();
    for (const optim::Solution& x : r.solutions) front.push_back(io::solution_to_json(x, true));
    out.result["front"] = std::move(front);
  } else {
    out.result["best"] = io::solution_to_json(r.solutions.front(), true);
  }
  out.report =
      io::run_report_to_json(r.report, {.seed = s.seed, .algorithm = s.algorithm_name, .problem = s.problem.name});
  out.cancelled = r.report.termination == optim::Termination::Cancelled;
  return out;
}

}  // namespace hula::oli
