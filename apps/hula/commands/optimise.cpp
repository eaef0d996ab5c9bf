// SPDX-License-Identifier: MIT
// `hula optimise`: runs a Flexo algorithm (binary or real-coded GA, NSGA-II)
// or one of pagmo2's through the adapter on a built-in test problem or a
// problem file (io/problem_file.hpp), and
// prints the best solution (one objective) or the final non-dominated front
// with its hypervolume (several objectives) and the run report (thesis
// appendix 1.5 "flexible optimisation wheel").
//
// Ctrl-C (SIGINT) sets a CancellationToken (InterruptGuard, study_common.hpp);
// the algorithm notices it between generations and returns the best so far
// with termination "Cancelled". `--time` sets the wall-time stop criterion the
// same way. The --log file streams as the run goes and replaces its target
// only when the run is done.
#include <signal.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "commands/common.hpp"
#include "commands/islands.hpp"
#include "commands/study_common.hpp"
#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/problem_file.hpp"
#include "hula/io/run_report_json.hpp"
#include "hula/optim/pareto.hpp"
#include "hula/optim/run_log.hpp"
#include "hula/optim/solve.hpp"
#include "hula/optim/test_problems.hpp"

namespace hula::cli {

namespace {

using optim::Problem;
using optim::RunReport;
using optim::Solution;

struct OptimiseArgs {
  std::string problem;
  std::string problem_file;
  std::optional<std::size_t> dimension;
  std::optional<std::size_t> objectives;
  std::string algorithm;
  std::optional<std::size_t> population;
  std::optional<std::size_t> generations;
  std::optional<std::size_t> evaluations;
  std::optional<std::uint64_t> seed;
  std::optional<std::size_t> threads;
  std::optional<double> crossover;
  std::optional<double> mutation;
  std::optional<std::string> lower;
  std::optional<std::string> upper;
  std::optional<double> precision;
  std::optional<std::string> boost;
  std::optional<double> time;
  std::optional<std::string> log;
  std::optional<std::string> reference;
  bool progress = false;
  IslandArgs islands;
};

enum class Algorithm { BinaryGa, RealGa, Nsga2, NelderMead, Pagmo };

struct AlgorithmChoice {
  Algorithm kind = Algorithm::RealGa;
  optim::PagmoAlgorithm pagmo = optim::PagmoAlgorithm::Nsga2;
};

// The algorithm named `name` (optim::solver_from_name, the one reader of algorithm names).
AlgorithmChoice parse_algorithm(const std::string& name) {
  const optim::SolverOptions o = optim::solver_from_name(name);
  if (std::holds_alternative<optim::BinaryGaOptions>(o)) return {Algorithm::BinaryGa};
  if (std::holds_alternative<optim::RealGaOptions>(o)) return {Algorithm::RealGa};
  if (std::holds_alternative<optim::Nsga2Options>(o)) return {Algorithm::Nsga2};
  if (std::holds_alternative<optim::NelderMeadOptions>(o)) return {Algorithm::NelderMead};
  return {Algorithm::Pagmo, std::get<optim::PagmoOptions>(o).algorithm};
}

// Refuses an option the chosen algorithm does not take (no silent no-ops).
void refuse(bool given, const char* field, const std::string& algorithm) {
  if (given) {
    throw Error(Errc::InvalidOption, std::string("--") + field + " is not supported by algorithm " + algorithm,
                {.field = field});
  }
}

// Applies --lower/--upper/--precision to every variable.
void apply_bounds(Problem& problem, const OptimiseArgs& a) {
  const auto apply = [&](const std::string& text, const char* field, auto member) {
    const std::vector<double> values = parse_number_list(text, field);
    if (values.size() != problem.dimension()) {
      throw Error(Errc::InvalidOption,
                  std::string("--") + field + " has " + std::to_string(values.size()) + " values but the problem has " +
                      std::to_string(problem.dimension()) + " variables",
                  {.field = field, .index = std::min(values.size(), problem.dimension())});
    }
    for (std::size_t i = 0; i < values.size(); ++i) problem.variables[i].*member = values[i];
  };
  if (a.lower) apply(*a.lower, "lower", &optim::Variable::lower);
  if (a.upper) apply(*a.upper, "upper", &optim::Variable::upper);
  if (a.precision)
    for (optim::Variable& v : problem.variables) v.precision = *a.precision;
  // The samplers draw lower + (upper - lower) * u: refuse bounds whose width
  // overflows here, naming the options, before any individual is made.
  for (std::size_t i = 0; i < problem.variables.size(); ++i) {
    const optim::Variable& v = problem.variables[i];
    if (std::isfinite(v.lower) && std::isfinite(v.upper) && !std::isfinite(v.upper - v.lower))
      throw Error(Errc::InvalidOption,
                  "--lower/--upper: variable " + std::to_string(i) + " has bounds [" + format_number(v.lower) + ", " +
                      format_number(v.upper) + "] whose width overflows a double (at most ~1.8e308)",
                  {.field = a.lower ? "lower" : "upper", .index = i});
  }
}

std::vector<double> parse_boost(const std::string& text) {
  std::vector<double> b = parse_number_list(text, "boost");
  if (b.size() != 2) {
    throw Error(Errc::InvalidOption,
                "--boost " + text + ": must be two numbers start,end (got " + std::to_string(b.size()) + ")",
                {.field = "boost"});
  }
  return b;
}

optim::StopCriteria stop_criteria(const OptimiseArgs& a, std::size_t population) {
  optim::StopCriteria stop;
  if (a.generations) stop.generations = *a.generations;
  if (a.evaluations) {
    stop.max_evaluations = *a.evaluations;
    // The budget binds before the generation count, and the binary GA's
    // boosting schedule (eq. 33) spans the generations the budget allows.
    stop.generations = *a.evaluations / std::max<std::size_t>(population, 1);
  }
  if (a.time) stop.wall_time_seconds = *a.time;
  stop.cancel = &interrupt_token();
  return stop;
}

// The per-generation callback: streams the run log to its file and prints progress lines.
optim::GenerationCallback generation_callback(const OptimiseArgs& a, io::RunLogFile* log) {
  if (!log && !a.progress) return {};
  return [&a, log](const optim::GenerationLog& g) {
    if (log) log->append(g);
    if (a.progress) {
      const optim::GenerationStatistics s = optim::statistics(g);
      Json line = Json::object();
      line["generation"] = g.generation;
      line["evaluations"] = g.evaluations;
      line["best"] = std::isfinite(s.best) ? Json(s.best) : Json(nullptr);
      std::cerr << line.dump() << '\n';
      std::cerr.flush();
    }
  };
}

template <class Options>
void fill_run(Options& o, const OptimiseArgs& a, io::RunLogFile* log) {
  if (a.population) o.population = *a.population;
  o.run.seed = a.seed.value_or(0);
  o.run.threads = a.threads.value_or(1);
  o.run.stop = stop_criteria(a, o.population);
  o.run.on_generation = generation_callback(a, log);
  if (a.crossover) o.crossover_probability = *a.crossover;
  if (a.mutation) o.mutation_probability = *a.mutation;
}

// The algorithm's options from the command line, refusing the options it does not take.
optim::SolverOptions solver_options(const OptimiseArgs& a, const AlgorithmChoice& choice, io::RunLogFile* log) {
  const bool islands = a.islands.islands > 0;
  switch (choice.kind) {
    case Algorithm::RealGa: {
      optim::RealGaOptions o;
      fill_run(o, a, log);
      return o;
    }
    case Algorithm::BinaryGa: {
      optim::BinaryGaOptions o;
      fill_run(o, a, log);
      if (a.boost) {
        const std::vector<double> b = parse_boost(*a.boost);
        o.boost_start = b[0];
        o.boost_end = b[1];
      }
      return o;
    }
    case Algorithm::Nsga2: {
      optim::Nsga2Options o;
      fill_run(o, a, log);
      return o;
    }
    case Algorithm::NelderMead: {
      // A deterministic local method from the centre of the bounds: no population, generations, seed,
      // operators or threads.
      refuse(a.population.has_value(), "population", a.algorithm);
      refuse(a.generations.has_value(), "generations", a.algorithm);
      refuse(a.seed.has_value(), "seed", a.algorithm);
      refuse(a.crossover.has_value(), "crossover", a.algorithm);
      refuse(a.mutation.has_value(), "mutation", a.algorithm);
      refuse(a.threads.value_or(1) != 1, "threads", a.algorithm);
      refuse(a.log.has_value(), "log", a.algorithm);
      refuse(a.progress, "progress", a.algorithm);
      refuse(islands, "islands", a.algorithm);
      optim::NelderMeadOptions o;
      if (a.evaluations) o.max_evaluations = *a.evaluations;
      if (a.time) o.wall_time_seconds = *a.time;
      o.cancel = &interrupt_token();
      return o;
    }
    case Algorithm::Pagmo:
      break;
  }
  // pagmo runs its own loop: no per-generation callback, stop criteria,
  // cancellation or evaluation threads reach it through the adapter.
  refuse(a.evaluations.has_value(), "evaluations", a.algorithm);
  refuse(a.time.has_value(), "time", a.algorithm);
  refuse(a.log.has_value(), "log", a.algorithm);
  refuse(a.progress, "progress", a.algorithm);
  refuse(a.crossover.has_value(), "crossover", a.algorithm);
  refuse(a.mutation.has_value(), "mutation", a.algorithm);
  refuse(a.threads.value_or(1) != 1, "threads", a.algorithm);
  refuse(islands, "islands", a.algorithm);
  optim::PagmoOptions o;
  o.algorithm = choice.pagmo;
  if (a.population) o.population = *a.population;
  if (a.generations) o.generations = *a.generations;
  o.seed = a.seed.value_or(0);
  return o;
}

Json solution_json(const Solution& s, bool constrained) {
  Json o = Json::object();
  o["variables"] = s.variables;
  o["objectives"] = s.objectives;
  if (constrained) o["violation"] = s.violation;
  return o;
}

Json report_json(const RunReport& r, const OptimiseArgs& a, const Problem& problem, std::size_t threads) {
  return io::run_report_to_json(
      r, {.seed = a.seed.value_or(0), .threads = threads, .algorithm = a.algorithm, .problem = problem.name});
}

// Smallest objective among the (feasible) solutions, lowest index on ties.
const Solution& best_of(const std::vector<Solution>& solutions) {
  const auto better = [](const Solution& x, const Solution& y) {
    if (x.violation != y.violation) return x.violation < y.violation;
    return x.objectives.at(0) < y.objectives.at(0);
  };
  return *std::min_element(solutions.begin(), solutions.end(), better);
}

Json front_json(std::vector<Solution> front, const Problem& problem, const std::optional<std::vector<double>>& ref) {
  // Lexicographic order of the objectives: a stable, readable listing.
  std::stable_sort(front.begin(), front.end(),
                   [](const Solution& x, const Solution& y) { return x.objectives < y.objectives; });
  const bool constrained = problem.inequality_constraints + problem.equality_constraints > 0;
  Json doc = Json::object();
  Json list = Json::array();
  std::vector<double> points;
  for (const Solution& s : front) {
    list.push_back(solution_json(s, constrained));
    if (s.violation == 0.0) points.insert(points.end(), s.objectives.begin(), s.objectives.end());
  }
  doc["front"] = std::move(list);
  if (ref) {
    doc["hypervolume"] = optim::hypervolume(points, problem.objectives, *ref);
    doc["reference"] = *ref;
  } else {
    doc["hypervolume"] = nullptr;
    doc["reference"] = nullptr;
  }
  return doc;
}

int run_optimise(const OptimiseArgs& a) {
  const AlgorithmChoice algorithm = parse_algorithm(a.algorithm);
  if (a.objectives && a.problem != "dtlz2") {
    throw Error(Errc::InvalidOption,
                "--objectives " + std::to_string(*a.objectives) + ": only dtlz2 takes a number of objectives",
                {.field = "objectives"});
  }
  Problem problem;
  std::optional<std::vector<double>> reference;
  if (!a.problem_file.empty()) {
    io::ProblemFile file = io::read_problem_file(a.problem_file);
    problem = std::move(file.problem);
    reference = std::move(file.reference);
  } else {
    problem = optim::test_problem(a.problem, a.dimension.value_or(0), a.objectives.value_or(0));
    // Built-in test problems are normalised so that 1.1 per objective bounds
    // their Pareto fronts (the reference of the benchmarks).
    reference = std::vector<double>(problem.objectives, 1.1);
  }
  apply_bounds(problem, a);
  // Binary coding needs a resolution per variable; a built-in problem has none unless --precision gives it.
  if (algorithm.kind == Algorithm::BinaryGa)
    for (std::size_t i = 0; i < problem.variables.size(); ++i)
      if (!(problem.variables[i].precision > 0.0))
        throw Error(Errc::InvalidOption,
                    "--precision: ga-binary needs the binary-coding resolution of the variables (variable " +
                        std::to_string(i) + " has none), e.g. --precision 1e-6",
                    {.field = "precision", .index = i});
  if (a.reference) {
    if (problem.objectives == 1) {
      throw Error(Errc::InvalidOption,
                  "--reference: a hypervolume reference applies to problems with several objectives; " + problem.name +
                      " has one",
                  {.field = "reference"});
    }
    reference = parse_number_list(*a.reference, "reference");
    if (reference->size() != problem.objectives) {
      throw Error(Errc::InvalidOption,
                  "--reference has " + std::to_string(reference->size()) + " values but the problem has " +
                      std::to_string(problem.objectives) + " objectives",
                  {.field = "reference"});
    }
  }
  if (algorithm.kind != Algorithm::BinaryGa) refuse(a.boost.has_value(), "boost", a.algorithm);
  // The Flexo algorithms make offspring in pairs.
  if (algorithm.kind != Algorithm::Pagmo && algorithm.kind != Algorithm::NelderMead && a.population)
    (void)parse_integer_option(std::to_string(*a.population), "--population", 2, kMaxPopulation, true);
  if (a.log) io::check_output_path(*a.log, "--log");

  // One log and one progress stream per run: the islands' generations interleave.
  const bool islands = a.islands.islands > 0;
  refuse(islands && a.log.has_value(), "log", a.algorithm + " with --islands");
  refuse(islands && a.progress, "progress", a.algorithm + " with --islands");
  // The log streams to its temporary file as the run goes, and replaces the target only when the run is done.
  std::optional<io::RunLogFile> log;
  if (a.log && algorithm.kind != Algorithm::Pagmo && algorithm.kind != Algorithm::NelderMead) log.emplace(*a.log);
  optim::SolveOptions options;
  options.algorithm = solver_options(a, algorithm, log ? &*log : nullptr);
  if (islands) options.islands = island_options(a.islands);
  // pagmo never looks at the token: Ctrl-C ends it at once, as the shell would.
  std::optional<InterruptGuard> guard;
  if (algorithm.kind != Algorithm::Pagmo) guard.emplace();
  std::optional<IslandRun> run = run_islands_or_solve(problem, options);
  if (log) log->commit();
  if (!run) return kExitOk;  // an MPI rank other than 0: rank 0 prints the result
  const optim::SolveResult& out = run->result;

  Json doc = Json::object();
  if (problem.objectives == 1) {
    const bool constrained = problem.inequality_constraints + problem.equality_constraints > 0;
    doc["best"] = out.solutions.empty() ? Json(nullptr) : solution_json(best_of(out.solutions), constrained);
  } else {
    doc = front_json(out.solutions, problem, reference);
  }
  doc["report"] = report_json(out.report, a, problem, a.threads.value_or(1));
  if (islands) doc["islands"] = islands_json(*options.islands, out, problem, run->transport);
  print_json(doc);
  return kExitOk;
}

}  // namespace

Command add_optimise(CLI::App& app) {
  auto a = std::make_shared<OptimiseArgs>();
  CLI::App* sub = app.add_subcommand(
      "optimise", "Run an optimiser (Flexo's GAs, NSGA-II or Nelder-Mead, or pagmo2's) on an optimisation problem");
  CLI::Option_group* source = sub->add_option_group("problem source", "Exactly one of --problem, --problem-file");
  CLI::Option* problem = source->add_option(
      "--problem", a->problem,
      "Built-in test problem: sphere, rastrigin, rosenbrock, ackley, schwefel, onemax, zdt1, zdt2, zdt3, zdt4, "
      "zdt6, dtlz2");
  CLI::Option* file = source->add_option("--problem-file", a->problem_file, "Problem file (JSON, docs/formats.md)");
  source->require_option(1);
  add_integer_option(sub, "--dimension", a->dimension, 1, kMaxDimension,
                     "Number of variables (default: the problem's own; at most 100000)")
      ->needs(problem)
      ->excludes(file);
  add_integer_option(sub, "--objectives", a->objectives, 2, kMaxObjectives,
                     "Number of objectives of dtlz2 (default 3; at most 64)")
      ->needs(problem)
      ->excludes(file);
  sub->add_option("--algorithm", a->algorithm,
                  "ga-binary | ga-real | nsga2 | nelder-mead | pagmo-<cmaes|de|sade|pso|sga|moead|nsga2>")
      ->required();
  add_integer_option(sub, "--population", a->population, 1, kMaxPopulation,
                     "Individuals per generation (default: the algorithm's own; even for the Flexo algorithms; at "
                     "most 1000000)");
  CLI::Option* gens = add_integer_option(sub, "--generations", a->generations, 0, kMaxGenerations,
                                         "Generations after the initial one (default 100)");
  add_integer_option(sub, "--evaluations", a->evaluations, 1, kMaxEvaluations,
                     "Evaluation budget, initial population included")
      ->excludes(gens);
  add_integer_option(sub, "--seed", a->seed, 0, kMaxSeed,
                     "Seed in [0, 2^63-1] (default 0); the same seed gives the same result on any thread count");
  add_integer_option(sub, "--threads", a->threads, 0, kMaxThreads, "Evaluation threads; 0 = all cores (default 1)");
  add_real_option(sub, "--crossover", a->crossover, 0.0, 1.0, false, "Crossover probability in [0, 1]");
  add_real_option(sub, "--mutation", a->mutation, 0.0, 1.0, false,
                  "Mutation probability in [0, 1] (per variable, or per bit for ga-binary)");
  sub->add_option("--lower", a->lower, "Lower bounds l1,l2,... (one per variable)");
  sub->add_option("--upper", a->upper, "Upper bounds u1,u2,... (one per variable)");
  add_real_option(sub, "--precision", a->precision, 0.0, std::numeric_limits<double>::max(), true,
                  "Binary-coding resolution of every variable (ga-binary), > 0");
  sub->add_option("--boost", a->boost, "ga-binary fitness power start,end (eq. 33; default 1,1)");
  add_real_option(sub, "--time", a->time, 0.0, std::numeric_limits<double>::max(), true,
                  "Wall-time limit in seconds, > 0 (default: none); ends with the best so far");
  sub->add_option("--log", a->log, "Write the run log: CSV if FILE ends in .csv, else JSON");
  sub->add_option("--reference", a->reference, "Hypervolume reference r1,r2,... (default 1.1 per objective)");
  sub->add_flag("--progress", a->progress, "Print one JSON line per generation on stderr");
  add_island_options(sub, a->islands);
  return {sub, [a] { return run_optimise(*a); }};
}

}  // namespace hula::cli
