// SPDX-License-Identifier: MIT
// Optimisation problems as server jobs (problem_job.hpp).
#include "hula/server/problem_job.hpp"

#include <chrono>
#include <cmath>
#include <memory>

#include "hula/io/json_read.hpp"
#include "hula/io/problem_file.hpp"
#include "hula/io/run_report_json.hpp"
#include "hula/optim/ga.hpp"
#include "hula/optim/nsga2.hpp"

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

template <class Options>
void fill_run(Options& o, const ProblemJob& job) {
  if (job.population) o.population = *job.population;
  o.run.seed = job.seed;
  o.run.stop.generations = job.generations;
}

JobOutcome run(const ProblemJob& job, JobContext& context) {
  const auto start = std::chrono::steady_clock::now();
  const auto on_generation = [&](const optim::GenerationLog& g) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    context.publish(generation_event(g, elapsed));
  };
  JobOutcome out;
  optim::RunReport report;
  if (job.algorithm == Algorithm::Nsga2) {
    optim::Nsga2Options o;
    fill_run(o, job);
    o.run.on_generation = on_generation;
    o.run.stop.cancel = &context.cancel;
    optim::Nsga2Result r = optim::solve_nsga2(job.problem, o);
    Json front = Json::array();
    for (const optim::Solution& s : r.front) front.push_back(solution_json(s));
    out.result = Json::object();
    out.result["front"] = std::move(front);
    report = r.report;
  } else {
    optim::GaResult r;
    if (job.algorithm == Algorithm::RealGa) {
      optim::RealGaOptions o;
      fill_run(o, job);
      o.run.on_generation = on_generation;
      o.run.stop.cancel = &context.cancel;
      r = optim::solve_real_ga(job.problem, o);
    } else {
      optim::BinaryGaOptions o;
      fill_run(o, job);
      o.run.on_generation = on_generation;
      o.run.stop.cancel = &context.cancel;
      r = optim::solve_binary_ga(job.problem, o);
    }
    out.result = Json::object();
    out.result["best"] = solution_json(r.best);
    report = r.report;
  }
  out.report = report_json(report, job);
  out.cancelled = report.termination == optim::Termination::Cancelled;
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
  if (job->algorithm == Algorithm::Nsga2) {
    optim::Nsga2Options o;
    fill_run(o, *job);
    o.validate();
    if (job->problem.objectives < 2)
      throw Error(Errc::InvalidOption,
                  "algorithm nsga2 needs a problem with at least 2 objectives; '" + job->problem.name +
                      "' has 1 (use ga-real or ga-binary)",
                  ErrorWhere{.field = "algorithm"});
  } else if (job->algorithm == Algorithm::RealGa) {
    optim::RealGaOptions o;
    fill_run(o, *job);
    o.validate();
  } else {
    optim::BinaryGaOptions o;
    fill_run(o, *job);
    o.validate();
  }
  if (job->algorithm != Algorithm::Nsga2 && job->problem.objectives != 1)
    throw Error(Errc::InvalidOption,
                "algorithm " + job->algorithm_name + " solves one objective; '" + job->problem.name + "' has " +
                    std::to_string(job->problem.objectives) + " (use nsga2)",
                ErrorWhere{.field = "algorithm"});
  return [job](JobContext& context) { return run(*job, context); };
}

}  // namespace hula::server
