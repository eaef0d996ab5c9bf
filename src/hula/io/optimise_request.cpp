// SPDX-License-Identifier: MIT
// Optimisation requests and their answers (optimise_request.hpp).
#include "hula/io/optimise_request.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <type_traits>
#include <variant>

#include "hula/core/error.hpp"
#include "hula/io/run_report_json.hpp"
#include "hula/optim/pareto.hpp"
#include "hula/optim/test_problems.hpp"

namespace hula::io {

namespace {

// Refuses a setting the chosen algorithm does not take (no silent no-ops).
void refuse(bool given, const char* field, const std::string& algorithm) {
  if (given)
    throw Error(Errc::InvalidOption, std::string("--") + field + " is not supported by algorithm " + algorithm,
                {.field = field});
}

template <class Options>
void fill_run(Options& o, const SolverRequest& q) {
  if (q.population) o.population = *q.population;
  o.run.seed = q.seed.value_or(0);
  o.run.threads = q.threads.value_or(1);
  if (q.generations) o.run.stop.generations = *q.generations;
  if (q.evaluations) {
    o.run.stop.max_evaluations = *q.evaluations;
    o.run.stop.generations = *q.evaluations / std::max<std::size_t>(o.population, 1);
  }
  if (q.time) o.run.stop.wall_time_seconds = *q.time;
  o.run.stop.cancel = q.cancel;
  o.run.on_generation = q.on_generation;
  if (q.crossover) o.crossover_probability = *q.crossover;
  if (q.mutation) o.mutation_probability = *q.mutation;
}

}  // namespace

std::vector<std::string> algorithm_names() { return optim::solver_names(); }

optim::SolverOptions solver_options(const SolverRequest& q) {
  optim::SolverOptions named = optim::solver_from_name(q.algorithm);
  if (!std::holds_alternative<optim::BinaryGaOptions>(named)) refuse(q.boost.has_value(), "boost", q.algorithm);
  if (auto* o = std::get_if<optim::RealGaOptions>(&named)) {
    fill_run(*o, q);
  } else if (auto* b = std::get_if<optim::BinaryGaOptions>(&named)) {
    fill_run(*b, q);
    if (q.boost) {
      b->boost_start = q.boost->first;
      b->boost_end = q.boost->second;
    }
  } else if (auto* n = std::get_if<optim::Nsga2Options>(&named)) {
    fill_run(*n, q);
  } else if (auto* m = std::get_if<optim::NelderMeadOptions>(&named)) {
    // A deterministic local method from the centre of the bounds: no population, generations, seed,
    // operators or threads.
    refuse(q.population.has_value(), "population", q.algorithm);
    refuse(q.generations.has_value(), "generations", q.algorithm);
    refuse(q.seed.has_value(), "seed", q.algorithm);
    refuse(q.crossover.has_value(), "crossover", q.algorithm);
    refuse(q.mutation.has_value(), "mutation", q.algorithm);
    refuse(q.threads.value_or(1) != 1, "threads", q.algorithm);
    refuse(q.log, "log", q.algorithm);
    refuse(q.islands, "islands", q.algorithm);
    if (q.evaluations) m->max_evaluations = *q.evaluations;
    if (q.time) m->wall_time_seconds = *q.time;
    m->cancel = q.cancel;
    m->on_generation = q.on_generation;  // progress: one generation per simplex iteration
  } else {
    // pagmo runs its own loop: of the stop criteria only the wall time and cancellation reach it (the
    // adapter looks at them before each evaluation), and no evaluation threads; its progress is counted from
    // its evaluations (PagmoOptions::on_generation).
    refuse(q.evaluations.has_value(), "evaluations", q.algorithm);
    refuse(q.log, "log", q.algorithm);
    refuse(q.crossover.has_value(), "crossover", q.algorithm);
    refuse(q.mutation.has_value(), "mutation", q.algorithm);
    refuse(q.threads.value_or(1) != 1, "threads", q.algorithm);
    refuse(q.islands, "islands", q.algorithm);
    auto& p = std::get<optim::PagmoOptions>(named);
    if (q.population) p.population = *q.population;
    if (q.generations) p.generations = *q.generations;
    p.seed = q.seed.value_or(0);
    if (q.time) p.wall_time_seconds = *q.time;
    p.cancel = q.cancel;
    p.on_generation = q.on_generation;
  }
  return named;
}

std::pair<optim::Problem, std::vector<double>> builtin_problem(const std::string& name, std::size_t dimension,
                                                               std::size_t objectives) {
  optim::Problem problem = optim::test_problem(name, dimension, objectives);
  std::vector<double> reference(problem.objectives, 1.1);
  return {std::move(problem), std::move(reference)};
}

Json solution_to_json(const optim::Solution& s, bool with_violation) {
  Json o = Json::object();
  o["variables"] = s.variables;
  o["objectives"] = s.objectives;
  if (with_violation) o["violation"] = s.violation;
  return o;
}

namespace {

// Smallest objective among the (feasible) solutions, lowest index on ties.
const optim::Solution& best_of(const std::vector<optim::Solution>& solutions) {
  const auto better = [](const optim::Solution& x, const optim::Solution& y) {
    if (x.violation != y.violation) return x.violation < y.violation;
    return x.objectives.at(0) < y.objectives.at(0);
  };
  return *std::min_element(solutions.begin(), solutions.end(), better);
}

}  // namespace

double feasible_hypervolume(std::span<const optim::Solution> solutions, std::size_t objectives,
                            std::span<const double> reference) {
  std::vector<double> points;
  for (const optim::Solution& s : solutions)
    if (s.violation == 0.0) points.insert(points.end(), s.objectives.begin(), s.objectives.end());
  return optim::hypervolume(points, objectives, reference);
}

Json solve_result_to_json(const optim::SolveResult& result, const optim::Problem& problem,
                          const std::optional<std::vector<double>>& reference) {
  const bool constrained = problem.inequality_constraints + problem.equality_constraints > 0;
  Json doc = Json::object();
  if (problem.objectives == 1) {
    doc["best"] = result.solutions.empty() ? Json(nullptr) : solution_to_json(best_of(result.solutions), constrained);
    return doc;
  }
  // Lexicographic order of the objectives: a stable, readable listing.
  std::vector<optim::Solution> front = result.solutions;
  std::stable_sort(front.begin(), front.end(),
                   [](const optim::Solution& x, const optim::Solution& y) { return x.objectives < y.objectives; });
  Json list = Json::array();
  for (const optim::Solution& s : front) list.push_back(solution_to_json(s, constrained));
  doc["front"] = std::move(list);
  if (reference) {
    doc["hypervolume"] = feasible_hypervolume(front, problem.objectives, *reference);
    doc["reference"] = *reference;
  } else {
    doc["hypervolume"] = nullptr;
    doc["reference"] = nullptr;
  }
  return doc;
}

Json islands_to_json(const optim::IslandOptions& o, const optim::SolveResult& result, const optim::Problem& problem,
                     const std::string& transport) {
  Json per = Json::array();
  for (const optim::IslandReport& i : result.islands) {
    Json migrations = Json::array();
    for (const optim::MigrationEvent& e : i.migrations)
      migrations.push_back(
          Json{{"generation", e.generation}, {"from", e.from}, {"received", e.received}, {"accepted", e.accepted}});
    Json j = Json::object();
    j["island"] = i.island;
    j["seed"] = i.seed;
    if (problem.objectives == 1) j["best"] = Json{{"variables", i.best.variables}, {"objectives", i.best.objectives}};
    j.update(run_report_to_json(i.report));
    j["sent"] = i.sent;
    j["received"] = i.received;
    j["accepted"] = i.accepted;
    if (problem.objectives > 1) j["archive"] = i.archive.size();
    j["migrations"] = std::move(migrations);
    per.push_back(std::move(j));
  }
  return Json{{"count", o.islands},
              {"interval", o.interval},
              {"migrants", o.migrants},
              {"topology", std::string(optim::topology_name(o.topology))},
              {"topology_seed", o.topology_seed},
              {"mode", o.asynchronous ? "asynchronous" : "synchronous"},
              {"transport", transport},
              {"per_island", std::move(per)}};
}

GenerationProgress generation_progress(const optim::GenerationLog& g, std::span<const double> reference) {
  GenerationProgress p;
  p.generation = g.generation;
  p.evaluations = g.evaluations;
  const std::size_t m = g.objectives;
  const std::size_t n = g.size();
  p.best.assign(m, std::numeric_limits<double>::quiet_NaN());
  // The feasible, successfully evaluated members with finite objectives.
  std::vector<double> feasible;
  for (std::size_t i = 0; i < n; ++i) {
    const bool ok = g.failed[i] == 0 && (g.violation.empty() || g.violation[i] == 0.0);
    if (!ok) continue;
    const std::span<const double> f(g.objective_values.data() + i * m, m);
    if (!std::all_of(f.begin(), f.end(), [](double v) { return std::isfinite(v); })) continue;
    for (std::size_t k = 0; k < m; ++k)
      if (!(f[k] >= p.best[k])) p.best[k] = f[k];
    feasible.insert(feasible.end(), f.begin(), f.end());
  }
  if (m < 2 || feasible.empty() || feasible.size() / m > kMaxProgressFrontSort) return p;
  const optim::ParetoRanking ranking = optim::non_dominated_sort(feasible, m);
  std::vector<double> front;
  for (std::size_t i = 0; i < ranking.rank.size(); ++i)
    if (ranking.rank[i] == 0) front.insert(front.end(), feasible.begin() + i * m, feasible.begin() + (i + 1) * m);
  p.front_size = front.size() / m;
  if (reference.size() == m && m <= kMaxProgressHypervolumeObjectives)
    p.hypervolume = optim::hypervolume(front, m, reference);
  return p;
}

Json generation_progress_json(const optim::GenerationLog& g, std::span<const double> reference) {
  const optim::GenerationStatistics s = optim::statistics(g);
  Json line = Json::object();
  line["generation"] = g.generation;
  line["evaluations"] = g.evaluations;
  line["best"] = std::isfinite(s.best) ? Json(s.best) : Json(nullptr);
  const GenerationProgress p = generation_progress(g, reference);
  Json objectives = Json::array();
  for (const double v : p.best) objectives.push_back(std::isfinite(v) ? Json(v) : Json(nullptr));
  line["objectives"] = std::move(objectives);
  if (g.objectives > 1) {
    line["front_size"] = p.front_size ? Json(*p.front_size) : Json(nullptr);
    line["hypervolume"] = p.hypervolume ? Json(*p.hypervolume) : Json(nullptr);
  }
  return line;
}

std::string generation_progress_line(const optim::GenerationLog& g, std::span<const double> reference) {
  const GenerationProgress p = generation_progress(g, reference);
  const auto number = [](double v) { return std::isfinite(v) ? format_number(v) : std::string("-"); };
  std::string line = "generation " + std::to_string(p.generation) + "  evaluations " + std::to_string(p.evaluations);
  if (p.best.size() == 1) return line + "  best " + number(p.best[0]);
  line += "  best";
  for (std::size_t k = 0; k < p.best.size() && k < 4; ++k) line += (k == 0 ? " " : ", ") + number(p.best[k]);
  if (p.best.size() > 4) line += ", ...";
  if (p.front_size) line += "  front " + std::to_string(*p.front_size);
  if (p.hypervolume) line += "  hypervolume " + number(*p.hypervolume);
  return line;
}

}  // namespace hula::io
