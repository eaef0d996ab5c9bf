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
//
// The settings are read into the algorithm's options by io::solver_options (the reader a server problem
// job uses too), the answer written by io::solve_result_to_json.
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
#include <tuple>
#include <utility>
#include <vector>

#include "commands/common.hpp"
#include "commands/islands.hpp"
#include "commands/study_common.hpp"
#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/optimise_request.hpp"
#include "hula/io/problem_file.hpp"
#include "hula/io/run_report_json.hpp"
#include "hula/oli/process_ranks.hpp"

namespace hula::cli {

namespace {

using optim::Problem;

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
  std::string format = "json";
  IslandArgs islands;
};

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

std::pair<double, double> parse_boost(const std::string& text) {
  std::vector<double> b = parse_number_list(text, "boost");
  if (b.size() != 2) {
    throw Error(Errc::InvalidOption,
                "--boost " + text + ": must be two numbers start,end (got " + std::to_string(b.size()) + ")",
                {.field = "boost"});
  }
  return {b[0], b[1]};
}

// The settings of the command line, the log and progress streams (the --progress JSON lines, the
// terminal's progress line) as the per-generation callback.
io::SolverRequest solver_request(const OptimiseArgs& a, std::optional<io::RunLogFile>& log, TerminalProgress& terminal,
                                 const std::vector<double>& reference) {
  io::SolverRequest q;
  q.algorithm = a.algorithm;
  q.population = a.population;
  q.generations = a.generations;
  q.evaluations = a.evaluations;
  q.threads = a.threads;
  q.seed = a.seed;
  q.crossover = a.crossover;
  q.mutation = a.mutation;
  if (a.boost) q.boost = parse_boost(*a.boost);  // ga-binary only: run_optimise refused it for the others
  q.time = a.time;
  q.islands = a.islands.islands > 0;
  q.log = a.log.has_value();
  q.cancel = &interrupt_token();
  if (a.log || a.progress || terminal.active())
    q.on_generation = [&a, &log, &terminal, &reference](const optim::GenerationLog& g) {
      if (log) log->append(g);
      if (a.progress) {
        std::cerr << io::generation_progress_json(g, reference).dump() << '\n';
        std::cerr.flush();
      } else {
        terminal.show(g);
      }
    };
  return q;
}

int run_optimise(const OptimiseArgs& a) {
  // The algorithm by its name alone (its settings are read below, once the log can take them).
  const optim::SolverOptions named = io::solver_options({.algorithm = a.algorithm});
  const bool binary = std::holds_alternative<optim::BinaryGaOptions>(named);
  const bool flexo = binary || std::holds_alternative<optim::RealGaOptions>(named) ||
                     std::holds_alternative<optim::Nsga2Options>(named);
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
    std::tie(problem, reference) = io::builtin_problem(a.problem, a.dimension.value_or(0), a.objectives.value_or(0));
  }
  apply_bounds(problem, a);
  // Binary coding needs a resolution per variable; a built-in problem has none unless --precision gives it.
  if (binary)
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
  if (!binary && a.boost)
    throw Error(Errc::InvalidOption, "--boost is not supported by algorithm " + a.algorithm, {.field = "boost"});
  // The Flexo algorithms make offspring in pairs.
  if (flexo && a.population)
    (void)parse_integer_option(std::to_string(*a.population), "--population", 2, kMaxPopulation, true);
  if (a.log) io::check_output_path(*a.log, "--log");

  // One log and one progress stream per run: the islands' generations interleave.
  const bool islands = a.islands.islands > 0;
  for (const auto& [given, field] :
       {std::pair{islands && a.log.has_value(), "log"}, std::pair{islands && a.progress, "progress"}})
    if (given)
      throw Error(Errc::InvalidOption,
                  std::string("--") + field + " is not supported by algorithm " + a.algorithm + " with --islands",
                  {.field = field});
  // The log streams to its temporary file as the run goes, and replaces the target only when the run is done.
  std::optional<io::RunLogFile> log;
  if (a.log && flexo) log.emplace(*a.log);
  // The terminal's progress line: one run's generations (not the islands', which interleave), unless
  // --progress prints its JSON lines there.
  const std::vector<double> progress_reference = reference.value_or(std::vector<double>{});
  TerminalProgress terminal(progress_reference, !islands && !a.progress);
  optim::SolveOptions options;
  options.algorithm = io::solver_options(solver_request(a, log, terminal, progress_reference));
  if (islands) options.islands = island_options(a.islands);
  const InterruptGuard guard;  // pagmo's algorithms too: the adapter looks at the token before each evaluation
  std::optional<oli::RankedSolve> run = oli::solve_on_ranks(problem, options);
  terminal.finish();
  if (log) log->commit();
  if (!run) return kExitOk;  // an MPI rank other than 0: rank 0 prints the result
  const optim::SolveResult& out = run->result;

  Json doc = io::solve_result_to_json(out, problem, reference);
  doc["report"] = io::run_report_to_json(out.report, {.seed = a.seed.value_or(0),
                                                      .threads = a.threads.value_or(1),
                                                      .algorithm = a.algorithm,
                                                      .problem = problem.name});
  if (islands) doc["islands"] = io::islands_to_json(*options.islands, out, problem, run->transport);
  print_formatted(doc, a.format, [](const Json& d) {
    if (d.contains("front")) return io::front_table(d["front"]);
    return io::front_table(d["best"].is_null() ? Json::array() : Json::array({d["best"]}));
  });
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
  set_choices(sub->add_option("--algorithm", a->algorithm,
                              "ga-binary | ga-real | nsga2 | nelder-mead | pagmo-<cmaes|de|sade|pso|sga|moead|nsga2>"),
              io::algorithm_names())
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
  add_format_option(sub, a->format,
                    "one member of the final front (or the best solution) per line: objectives, variables; the "
                    "hypervolume and the report only in json");
  return {sub, [a] { return run_optimise(*a); }};
}

}  // namespace hula::cli
