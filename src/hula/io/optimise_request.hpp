// SPDX-License-Identifier: MIT
// An optimisation run as the front ends ask for it and as they print it: the
// solver settings given by name (`hula optimise --algorithm ... --population
// ...`, a server problem job's members) read into optim::SolverOptions by one
// reader, the built-in test problems with their hypervolume reference, and
// the JSON of solutions, fronts, island runs and progress lines
// (docs/cli.md "hula optimise", docs/server.md "Problem jobs"). The optim
// types of a run (Problem, SolveOptions, SolveResult, islands) come with this
// header.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "hula/io/json_curve.hpp"
#include "hula/optim/islands.hpp"
#include "hula/optim/run_log.hpp"
#include "hula/optim/solve.hpp"

namespace hula::io {

/// The settings a front end was given. Absent members keep the algorithm's defaults.
struct SolverRequest {
  std::string algorithm;  ///< as optim::solver_from_name reads it
  std::optional<std::size_t> population{}, generations{}, evaluations{}, threads{};
  std::optional<std::uint64_t> seed{};
  std::optional<double> crossover{}, mutation{};     ///< probabilities
  std::optional<std::pair<double, double>> boost{};  ///< ga-binary's fitness power start, end
  std::optional<double> time{};                      ///< wall-time limit, seconds
  bool islands = false;                              ///< an island run is asked for
  bool log = false;                                  ///< a per-generation log is asked for
  const optim::CancellationToken* cancel = nullptr;
  optim::GenerationCallback on_generation{};
};

/// The algorithm's options: its defaults (optim::solver_from_name) with the request's settings. A budget of
/// evaluations also bounds the generations (evaluations / population), so the binary GA's boosting schedule
/// spans what the budget allows. Settings the algorithm does not take are refused, never ignored:
/// Nelder–Mead takes no population, generations, seed, operators, threads, log or islands; pagmo's take no
/// evaluations, log, operators, threads or islands (their time and cancel stop them between evaluations,
/// optim::PagmoOptions::cancel); only ga-binary takes boost. Every algorithm takes
/// progress and on_generation (Nelder–Mead: a generation per simplex iteration; pagmo's: per `population`
/// evaluations, optim::PagmoOptions::on_generation).
/// @throws hula::Error(Errc::InvalidOption) naming the refused setting ("--population is not supported by
///   algorithm nelder-mead"); as optim::solver_from_name
[[nodiscard]] optim::SolverOptions solver_options(const SolverRequest& request);
/// The algorithm names solver_options accepts (the CLI's choices and completions).
[[nodiscard]] std::vector<std::string> algorithm_names();

/// A built-in test problem (optim::test_problem) and its hypervolume reference, 1.1 per objective (the built-in
/// problems are normalised so that it bounds their Pareto fronts).
/// @throws as optim::test_problem
[[nodiscard]] std::pair<optim::Problem, std::vector<double>> builtin_problem(const std::string& name,
                                                                             std::size_t dimension,
                                                                             std::size_t objectives);

/// {"variables", "objectives", "violation"?} (violation with `with_violation`).
[[nodiscard]] Json solution_to_json(const optim::Solution& solution, bool with_violation);

/// The answer of a run: {"best": solution or null} for one objective (the smallest objective among the
/// least-violating, lowest index on ties), else {"front": [solutions in lexicographic order of objectives],
/// "hypervolume" (of the feasible members, null without reference), "reference"}; violations are written for
/// constrained problems.
[[nodiscard]] Json solve_result_to_json(const optim::SolveResult& result, const optim::Problem& problem,
                                        const std::optional<std::vector<double>>& reference);

/// {"count", "interval", "migrants", "topology", "topology_seed", "mode", "transport", "per_island": [...]}
/// with each island's champion (one objective), run report and migration log.
[[nodiscard]] Json islands_to_json(const optim::IslandOptions& options, const optim::SolveResult& result,
                                   const optim::Problem& problem, const std::string& transport);

/// The progress figures of one generation.
struct GenerationProgress {
  std::size_t generation = 0;
  std::size_t evaluations = 0;
  /// The smallest value of each objective among the feasible members (NaN when none is finite).
  std::vector<double> best{};
  /// Several objectives: the feasible members no other feasible member dominates (absent with one
  /// objective, or above kMaxProgressFrontSort feasible members, where the sort would slow the run).
  std::optional<std::size_t> front_size{};
  /// The hypervolume of that front w.r.t. `reference` (absent without a reference of the objectives'
  /// size, or above kMaxProgressHypervolumeObjectives objectives).
  std::optional<double> hypervolume{};
};
/// The largest population whose front a progress report sorts.
inline constexpr std::size_t kMaxProgressFrontSort = 10'000;
/// The hypervolume of the feasible members of `solutions` (violation 0) w.r.t. `reference`: the "hypervolume"
/// member of solve_result_to_json, and Python's OptimiseResult.hypervolume.
[[nodiscard]] double feasible_hypervolume(std::span<const optim::Solution> solutions, std::size_t objectives,
                                          std::span<const double> reference);

/// The most objectives whose hypervolume a progress report measures (optim::hypervolume is meant for <= 5).
inline constexpr std::size_t kMaxProgressHypervolumeObjectives = 5;

/// The progress of generation `g`; `reference` is the hypervolume reference (empty: none).
[[nodiscard]] GenerationProgress generation_progress(const optim::GenerationLog& g,
                                                     std::span<const double> reference = {});

/// One progress line of `--progress`: {"generation", "evaluations", "best" (objective 0, null when none is
/// finite), "objectives" (the best of each objective, null when none is finite), and with several objectives
/// "front_size" and "hypervolume" (null when generation_progress leaves them out)}.
[[nodiscard]] Json generation_progress_json(const optim::GenerationLog& generation,
                                            std::span<const double> reference = {});

/// The terminal's progress line (no newline): "generation 12  evaluations 1300  best 0.0123", with several
/// objectives "generation 12  evaluations 1300  best 0.01, 0.2  front 23  hypervolume 0.651".
[[nodiscard]] std::string generation_progress_line(const optim::GenerationLog& generation,
                                                   std::span<const double> reference = {});

}  // namespace hula::io
