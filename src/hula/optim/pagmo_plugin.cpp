// SPDX-License-Identifier: MIT
// The pagmo plugin (libhula_pagmo.so): a Flexo Problem solved by one of pagmo2's algorithms,
// the only code of HulaHoops that links libpagmo. Loaded by solve_with_pagmo through
// hula/core/plugin.hpp (detail/pagmo_plugin.hpp holds the entry point's type).
#include "hula/optim/detail/pagmo_plugin.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/cmaes.hpp>
#include <pagmo/algorithms/de.hpp>
#include <pagmo/algorithms/moead.hpp>
#include <pagmo/algorithms/nsga2.hpp>
#include <pagmo/algorithms/pso.hpp>
#include <pagmo/algorithms/sade.hpp>
#include <pagmo/algorithms/sga.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <pagmo/utils/multi_objective.hpp>
#include <string>
#include <utility>
#include <vector>

#include "hula/core/error.hpp"

namespace hula::optim {
namespace {

// One generation of the progress callback, gathered evaluation by evaluation (PagmoOptions::on_generation):
// the points evaluated since the last full generation, handed over when the next evaluation starts (so the
// last one, which the final population replaces, is never sent).
struct Window {
  const GenerationCallback* callback = nullptr;
  std::size_t population = 0;
  std::size_t evaluations = 0;
  GenerationLog log{};

  void add(const pagmo::vector_double& x, const pagmo::vector_double& values, std::size_t objectives, bool ok) {
    ++evaluations;
    if (callback == nullptr || !*callback) return;
    if (log.size() == population) {
      (*callback)(log);
      ++log.generation;
      clear();
    }
    log.evaluations = evaluations;
    log.variables.insert(log.variables.end(), x.begin(), x.end());
    log.objective_values.insert(log.objective_values.end(), values.begin(),
                                values.begin() + static_cast<std::ptrdiff_t>(objectives));
    log.violation.push_back(0.0);
    log.fitness.push_back(std::numeric_limits<double>::quiet_NaN());
    log.failed.push_back(ok ? 0 : 1);
  }
  void clear() {
    log.variables.clear();
    log.objective_values.clear();
    log.violation.clear();
    log.fitness.clear();
    log.failed.clear();
  }
};

// Thrown from the problem's fitness to unwind pagmo's loop when the run is asked to stop; never leaves the
// plugin (hula_pagmo_run catches it).
struct StopRequested {};

// What a stopped run returns, gathered as the run goes (only when the run can be stopped): the best
// evaluation (one objective) or the non-dominated set of the successful evaluations (several).
struct BestSoFar {
  std::size_t objectives = 1;
  bool found = false;
  std::vector<double> x{}, f{};  // one objective: the best point and its values (Flexo's layout)
  std::vector<std::pair<std::vector<double>, std::vector<double>>> front{};  // several: (x, objectives)

  void offer(const pagmo::vector_double& x_in, const std::vector<double>& values) {
    if (objectives == 1) {
      if (found && !(values[0] < f[0])) return;  // the first of equal values stays
      found = true;
      x = x_in;
      f = values;
      return;
    }
    const auto covers = [this](const std::vector<double>& a, const std::vector<double>& b) {  // a <= b everywhere
      for (std::size_t j = 0; j < objectives; ++j)
        if (!(a[j] <= b[j])) return false;
      return true;
    };
    const std::vector<double> mine(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(objectives));
    if (objectives == 2) {
      offer_two(x_in, mine);
      return;
    }
    for (const auto& member : front)
      if (covers(member.second, mine)) return;  // dominated by, or equal to, a member
    std::erase_if(front, [&](const auto& member) { return covers(mine, member.second); });
    front.emplace_back(x_in, mine);
  }

  // Two objectives (the common case, offered at every evaluation of every run): the front kept sorted by
  // the first objective, so the second falls along it, and a point is judged in O(log n) instead of
  // against every member. The same set as the general loop: a point covered by (dominated by, or equal
  // to) a member is dropped, and a new point removes the members it covers (a contiguous run).
  void offer_two(const pagmo::vector_double& x_in, const std::vector<double>& mine) {
    const auto first_after = std::upper_bound(front.begin(), front.end(), mine[0],
                                              [](double a, const auto& member) { return a < member.second[0]; });
    // The members with f0 ≤ mine's: the last of them has the smallest f1.
    if (first_after != front.begin() && std::prev(first_after)->second[1] <= mine[1]) return;
    const auto from = std::lower_bound(front.begin(), first_after, mine[0],
                                       [](const auto& member, double a) { return member.second[0] < a; });
    auto to = from;
    while (to != front.end() && to->second[1] >= mine[1]) ++to;  // f0 ≥ mine's and f1 ≥ mine's: covered
    const auto at = front.erase(from, to);
    front.emplace(at, x_in, mine);
  }
};

struct Counters {
  std::atomic<std::size_t> failed{0};
  std::atomic<std::size_t> succeeded{0};
  // pagmo's algorithms here call the problem's fitness serially, on the thread that called evolve.
  Window window{};
  // Stopping early: the token and the wall-clock limit (PagmoOptions::cancel, wall_time_seconds), looked at
  // before each evaluation once one has succeeded; the reason once met; the best so far, kept only when a
  // stop is possible.
  const CancellationToken* cancel = nullptr;
  double wall_time_seconds = 0.0;  // 0 = none
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  std::optional<Termination> stopped{};
  bool stoppable = false;
  BestSoFar best{};

  [[nodiscard]] bool stop_requested() {
    if (succeeded == 0) return false;
    if (wall_time_seconds > 0.0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() >= wall_time_seconds)
      stopped = Termination::WallTime;
    else if (cancel != nullptr && cancel->is_cancelled())
      stopped = Termination::Cancelled;
    return stopped.has_value();
  }
};

// pagmo user-defined problem wrapping a Flexo Problem. pagmo orders the
// fitness vector as objectives, equality constraints, inequality constraints;
// Flexo writes objectives, inequality, equality, so the adapter reorders.
struct Udp {
  const Problem* problem = nullptr;
  std::shared_ptr<Counters> counters{};

  [[nodiscard]] pagmo::vector_double fitness(const pagmo::vector_double& x) const {
    const Problem& p = *problem;
    if (counters->stoppable && counters->stop_requested()) throw StopRequested{};
    pagmo::vector_double values(p.values_per_point());
    bool ok = true;
    try {
      if (p.evaluate)
        p.evaluate(x, values);
      else
        p.evaluate_many(x, values);  // a batch of one point
      for (const double v : values) ok = ok && std::isfinite(v);
    } catch (...) {
      ok = false;
    }
    if (!ok) {
      ++counters->failed;
      for (double& v : values) v = std::numeric_limits<double>::max();
    } else {
      ++counters->succeeded;
      if (counters->stoppable) counters->best.offer(x, values);
    }
    counters->window.add(x, values, p.objectives, ok);
    pagmo::vector_double out(values.size());
    const std::size_t m = p.objectives;
    const std::size_t ni = p.inequality_constraints;
    const std::size_t ne = p.equality_constraints;
    std::copy_n(values.begin(), m, out.begin());
    std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(m + ni), ne, out.begin() + static_cast<std::ptrdiff_t>(m));
    std::copy_n(values.begin() + static_cast<std::ptrdiff_t>(m), ni, out.begin() + static_cast<std::ptrdiff_t>(m + ne));
    return out;
  }
  [[nodiscard]] std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const {
    pagmo::vector_double lo, hi;
    for (const auto& v : problem->variables) {
      lo.push_back(v.lower);
      hi.push_back(v.upper);
    }
    return {lo, hi};
  }
  [[nodiscard]] pagmo::vector_double::size_type get_nobj() const { return problem->objectives; }
  [[nodiscard]] pagmo::vector_double::size_type get_nec() const { return problem->equality_constraints; }
  [[nodiscard]] pagmo::vector_double::size_type get_nic() const { return problem->inequality_constraints; }
  [[nodiscard]] std::string get_name() const { return problem->name.empty() ? "flexo problem" : problem->name; }
};

pagmo::algorithm make_algorithm(const PagmoOptions& o) {
  const auto gen = static_cast<unsigned>(o.generations);
  const auto seed = static_cast<unsigned>(o.seed);
  switch (o.algorithm) {
    case PagmoAlgorithm::Cmaes:
      return pagmo::algorithm(pagmo::cmaes(gen, -1, -1, -1, -1, 0.5, 1e-6, 1e-6, false, true, seed));
    case PagmoAlgorithm::De:
      return pagmo::algorithm(pagmo::de(gen, 0.8, 0.9, 2u, 1e-6, 1e-6, seed));
    case PagmoAlgorithm::Sade:
      return pagmo::algorithm(pagmo::sade(gen, 2u, 1u, 1e-6, 1e-6, false, seed));
    case PagmoAlgorithm::Pso:
      return pagmo::algorithm(pagmo::pso(gen, 0.7298, 2.05, 2.05, 0.5, 5u, 2u, 4u, false, seed));
    case PagmoAlgorithm::Sga:
      return pagmo::algorithm(pagmo::sga(gen, .90, 1., .02, 1., 2u, "exponential", "polynomial", "tournament", seed));
    case PagmoAlgorithm::Moead:
      return pagmo::algorithm(pagmo::moead(gen, "grid", "tchebycheff", 20u, 1.0, 0.5, 20., 0.9, 2u, true, seed));
    case PagmoAlgorithm::Nsga2:
      return pagmo::algorithm(pagmo::nsga2(gen, 0.95, 10., 0.01, 50., seed));
  }
  throw InternalError("unknown PagmoAlgorithm");
}

Solution solution_of(const Problem& p, const pagmo::vector_double& x, const pagmo::vector_double& f) {
  Solution s;
  s.variables = x;
  s.objectives.assign(f.begin(), f.begin() + static_cast<std::ptrdiff_t>(p.objectives));
  // Recompute the violation in Flexo's convention from pagmo's layout.
  std::vector<double> values(p.values_per_point());
  const std::size_t m = p.objectives;
  const std::size_t ne = p.equality_constraints;
  const std::size_t ni = p.inequality_constraints;
  std::copy_n(f.begin(), m, values.begin());
  std::copy_n(f.begin() + static_cast<std::ptrdiff_t>(m + ne), ni, values.begin() + static_cast<std::ptrdiff_t>(m));
  std::copy_n(f.begin() + static_cast<std::ptrdiff_t>(m), ne, values.begin() + static_cast<std::ptrdiff_t>(m + ni));
  s.violation = p.violation(values);
  return s;
}
// The result of a run stopped before evaluation `counters.window.evaluations + 1`: the best so far, the
// last complete generation handed to the callback (a partial one is dropped), the counts.
void stopped_result(const Problem& problem, const PagmoOptions& options, Counters& counters, detail::PagmoRun& run) {
  Window& window = counters.window;
  if (window.callback != nullptr && *window.callback && window.log.size() == window.population)
    (*window.callback)(window.log);
  const std::size_t evaluations = window.evaluations;
  run.result.report.evaluations = evaluations;
  run.succeeded = counters.succeeded;
  run.failed = counters.failed;
  run.stopped = counters.stopped;
  run.generations = evaluations >= 2 * options.population ? evaluations / options.population - 1 : 0;
  const BestSoFar& best = counters.best;
  const auto solution = [&problem](const std::vector<double>& x, const std::vector<double>& values) {
    Solution s;
    s.variables = x;
    s.objectives.assign(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(problem.objectives));
    s.violation = problem.violation(values);
    return s;
  };
  if (problem.objectives == 1) {
    if (best.found) run.result.best = solution(best.x, best.f);
  } else {
    for (const auto& [x, f] : best.front) run.result.front.push_back(solution(x, f));
  }
}

}  // namespace
}  // namespace hula::optim

HULA_PLUGIN_EXPORT void hula_pagmo_run(const hula::optim::Problem& problem, const hula::optim::PagmoOptions& options,
                                       hula::optim::detail::PagmoRun& run) {
  using namespace hula::optim;
  auto counters = std::make_shared<Counters>();
  counters->window.callback = &options.on_generation;
  counters->window.population = options.population;
  counters->window.log.dimension = problem.dimension();
  counters->window.log.objectives = problem.objectives;
  counters->cancel = options.cancel;
  counters->wall_time_seconds = options.wall_time_seconds;
  counters->stoppable = counters->cancel != nullptr || counters->wall_time_seconds > 0.0;
  counters->best.objectives = problem.objectives;
  pagmo::problem prob(Udp{&problem, counters});
  pagmo::algorithm algo = make_algorithm(options);
  pagmo::population pop;
  try {
    pagmo::population initial(prob, options.population, options.seed);
    pop = algo.evolve(initial);
  } catch (const StopRequested&) {
    stopped_result(problem, options, *counters, run);
    return;
  }
  run.result.report.evaluations = static_cast<std::size_t>(pop.get_problem().get_fevals());
  if (options.on_generation) {
    // The last generation: the final population (no constraints here: pagmo's fitness is the objectives).
    GenerationLog& last = counters->window.log;
    counters->window.clear();
    last.evaluations = run.result.report.evaluations;
    for (std::size_t i = 0; i < pop.size(); ++i) {
      const pagmo::vector_double& f = pop.get_f()[i];
      const pagmo::vector_double& x = pop.get_x()[i];
      last.variables.insert(last.variables.end(), x.begin(), x.end());
      last.objective_values.insert(last.objective_values.end(), f.begin(),
                                   f.begin() + static_cast<std::ptrdiff_t>(problem.objectives));
      last.violation.push_back(0.0);
      last.fitness.push_back(std::numeric_limits<double>::quiet_NaN());
      last.failed.push_back(f[0] == std::numeric_limits<double>::max() ? 1 : 0);
    }
    options.on_generation(last);
  }
  run.succeeded = counters->succeeded;
  run.failed = counters->failed;
  if (run.succeeded == 0) return;
  if (problem.objectives == 1) {
    run.result.best = solution_of(problem, pop.champion_x(), pop.champion_f());
  } else {
    const auto& f = pop.get_f();
    const auto ndf = pagmo::fast_non_dominated_sorting(f);
    for (const auto i : std::get<0>(ndf).front()) {
      if (f[i][0] == std::numeric_limits<double>::max()) continue;
      run.result.front.push_back(solution_of(problem, pop.get_x()[i], f[i]));
    }
  }
}
