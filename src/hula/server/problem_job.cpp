// SPDX-License-Identifier: MIT
// Optimisation problems as server jobs (problem_job.hpp).
#include "hula/server/problem_job.hpp"

#include <chrono>
#include <cmath>
#include <memory>
#include <utility>
#include <variant>

#include "hula/io/json_read.hpp"
#include "hula/io/problem_file.hpp"
#include "hula/io/run_report_json.hpp"
#include "hula/optim/solve.hpp"

namespace hula::server {

namespace {

using io::json::JsonPath;
using io::json::root_path;

enum class Algorithm { RealGa, BinaryGa, Nsga2 };

struct ProblemJob {
  optim::Problem problem;
  Algorithm algorithm = Algorithm::RealGa;
  std::string algorithm_name = "ga-real";
  std::optional<std::size_t> population;
  std::size_t generations = 100;
  std::uint64_t seed = 0;
};

Json solution_json(const optim::Solution& s) {
  Json o = Json::object();
  o["variables"] = s.variables;
  o["objectives"] = s.objectives;
  o["violation"] = s.violation;
  return o;
}

Json finite_or_null(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

}  // namespace

// The first front of NSGA-II is fitness = rank 0.
Json generation_event(const optim::GenerationLog& g, double elapsed) {
  Json e = Json::object();
  e["generation"] = g.generation;
  e["evaluations"] = g.evaluations;
  std::size_t best = g.size();
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (g.failed[i]) continue;
    if (best == g.size()) {
      best = i;
      continue;
    }
    const double vi = g.violation[i], vb = g.violation[best];
    if (vi < vb || (vi == vb && g.objective_values[i * g.objectives] < g.objective_values[best * g.objectives]))
      best = i;
  }
  Json best_objectives = Json::array();
  if (best < g.size())
    for (std::size_t k = 0; k < g.objectives; ++k)
      best_objectives.push_back(finite_or_null(g.objective_values[best * g.objectives + k]));
  e["best"] = std::move(best_objectives);
  if (g.objectives > 1) {
    Json front = Json::array();
    for (std::size_t i = 0; i < g.size(); ++i) {
      if (g.failed[i] || g.fitness[i] != 0.0) continue;
      Json point = Json::array();
      for (std::size_t k = 0; k < g.objectives; ++k)
        point.push_back(finite_or_null(g.objective_values[i * g.objectives + k]));
      front.push_back(std::move(point));
    }
    e["front"] = std::move(front);
  }
  e["elapsed"] = elapsed;
  return e;
}

namespace {

Json report_json(const optim::RunReport& r, const ProblemJob& job) {
  return io::run_report_to_json(r, {.seed = job.seed, .algorithm = job.algorithm_name, .problem = job.problem.name});
}

// The job's algorithm and its options; with a context, its progress events and cancellation.
optim::SolverOptions solver_options(const ProblemJob& job, JobContext* context) {
  const auto start = std::chrono::steady_clock::now();
  const auto fill_run = [&](auto& o) {
    if (job.population) o.population = *job.population;
    o.run.seed = job.seed;
    o.run.stop.generations = job.generations;
    if (context == nullptr) return;
    o.run.stop.cancel = &context->cancel;
    o.run.on_generation = [start, context](const optim::GenerationLog& g) {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      context->publish(generation_event(g, elapsed));
    };
  };
  if (job.algorithm == Algorithm::Nsga2) {
    optim::Nsga2Options o;
    fill_run(o);
    return o;
  }
  if (job.algorithm == Algorithm::RealGa) {
    optim::RealGaOptions o;
    fill_run(o);
    return o;
  }
  optim::BinaryGaOptions o;
  fill_run(o);
  return o;
}

JobOutcome run(const ProblemJob& job, JobContext& context) {
  optim::SolveOptions options;
  options.algorithm = solver_options(job, &context);
  const optim::SolveResult r = optim::solve(job.problem, options);
  JobOutcome out;
  out.result = Json::object();
  if (job.algorithm == Algorithm::Nsga2) {
    Json front = Json::array();
    for (const optim::Solution& s : r.solutions) front.push_back(solution_json(s));
    out.result["front"] = std::move(front);
  } else {
    out.result["best"] = solution_json(r.solutions.front());
  }
  out.report = report_json(r.report, job);
  out.cancelled = r.report.termination == optim::Termination::Cancelled;
  return out;
}

}  // namespace

JobWork problem_job(const Json& request) {
  const JsonPath root;
  io::json::reject_unknown_members(request, root, {"problem", "algorithm", "population", "generations", "seed"});
  auto job = std::make_shared<ProblemJob>();
  const Json& problem = io::json::require_member(request, root, "problem");
  if (!problem.is_object()) io::json::type_error(problem, root_path("problem"), "a problem object (docs/formats.md)");
  job->problem = io::parse_problem_json(problem.dump()).problem;
  if (const Json* a = io::json::optional_member(request, "algorithm")) {
    job->algorithm_name = io::json::get_string(*a, root_path("algorithm"));
    if (job->algorithm_name == "ga-real")
      job->algorithm = Algorithm::RealGa;
    else if (job->algorithm_name == "ga-binary")
      job->algorithm = Algorithm::BinaryGa;
    else if (job->algorithm_name == "nsga2")
      job->algorithm = Algorithm::Nsga2;
    else
      throw Error(Errc::InvalidOption,
                  "algorithm = \"" + job->algorithm_name + "\" is not one of ga-real, ga-binary, nsga2",
                  ErrorWhere{.field = "algorithm"});
  }
  if (const Json* p = io::json::optional_member(request, "population"))
    job->population = static_cast<std::size_t>(io::json::get_integer(*p, root_path("population"), 2, 100000));
  if (const Json* g = io::json::optional_member(request, "generations"))
    job->generations = static_cast<std::size_t>(io::json::get_integer(*g, root_path("generations"), 1, 100000));
  if (const Json* s = io::json::optional_member(request, "seed"))
    job->seed = static_cast<std::uint64_t>(io::json::get_integer(*s, root_path("seed"), 0, (1ll << 53)));
  // Validate the options the run will use now, so a bad population is a 400, not a failed job.
  std::visit([](const auto& o) { o.validate(); }, solver_options(*job, nullptr));
  if (job->algorithm == Algorithm::Nsga2) {
    if (job->problem.objectives < 2)
      throw Error(Errc::InvalidOption,
                  "algorithm nsga2 needs a problem with at least 2 objectives; '" + job->problem.name +
                      "' has 1 (use ga-real or ga-binary)",
                  ErrorWhere{.field = "algorithm"});
  }
  if (job->algorithm != Algorithm::Nsga2 && job->problem.objectives != 1)
    throw Error(Errc::InvalidOption,
                "algorithm " + job->algorithm_name + " solves one objective; '" + job->problem.name + "' has " +
                    std::to_string(job->problem.objectives) + " (use nsga2)",
                ErrorWhere{.field = "algorithm"});
  return [job](JobContext& context) { return run(*job, context); };
}

}  // namespace hula::server
