// SPDX-License-Identifier: MIT
#include "hula/studies/curvature_torsion_match.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>

#include "hula/core/error.hpp"
#include "hula/core/nan.hpp"
#include "hula/optim/pareto.hpp"

namespace hula::studies {
namespace {

void require_torsion(const CurvatureMatch& match) {
  if (match.torsion_target_samples().empty())
    throw Error(Errc::InvalidArgument, "the curvature + torsion study needs a torsion target",
                {.field = "torsion_target"});
  if (match.setup().dimension != 3)
    throw Error(Errc::InvalidArgument, "the curvature + torsion study needs 3-D points (planar curves have no torsion)",
                {.field = "points"});
}

void check(bool ok, const std::string& field, double value, const char* range) {
  if (!ok)
    throw Error(Errc::InvalidOption, field + " = " + format_number(value) + " must be " + range, {.field = field});
}

}  // namespace

optim::Problem curvature_torsion_problem(const CurvatureMatch& match) {
  require_torsion(match);
  optim::Problem p;
  p.name = "match-curvature-torsion";
  p.variables = match.variables();
  p.objectives = 2;
  const std::size_t n_points = match.setup().points.size(), n_samples = match.setup().samples;
  p.evaluate = [&match, n_points, n_samples](std::span<const double> x, std::span<double> values) {
    // One set of buffers per thread; none allocates once warm.
    thread_local SplineProfileSampler::Workspace ws;
    thread_local std::vector<Vec3> points;
    thread_local std::vector<double> kappa, tau;
    if (points.size() != n_points) points.resize(n_points);
    if (kappa.size() != n_samples) kappa.resize(n_samples);
    if (tau.size() != n_samples) tau.resize(n_samples);
    const MatchDistances d = match.mean_distances(x, ws, points, kappa, tau);
    values[0] = d.mean + match.proximity_penalty(points);
    values[1] = d.torsion_mean;
    match.validity_constraints(points, values.subspan(2));
  };
  p.inequality_constraints = match.setup().validity.count();
  return p;
}

void TorsionMatchSettings::validate() const {
  check(population >= 4 && population % 2 == 0, "nsga2.population", static_cast<double>(population), "even and >= 4");
  check(crossover_probability >= 0.0 && crossover_probability <= 1.0, "nsga2.crossover_probability",
        crossover_probability, "in [0, 1]");
  check(std::isfinite(crossover_eta) && crossover_eta >= 0.0, "nsga2.crossover_eta", crossover_eta, "finite and >= 0");
  check(std::isfinite(mutation_eta) && mutation_eta >= 0.0, "nsga2.mutation_eta", mutation_eta, "finite and >= 0");
  if (mutation_probability)
    check(*mutation_probability >= 0.0 && *mutation_probability <= 1.0, "nsga2.mutation_probability",
          *mutation_probability, "in [0, 1]");
  check(std::isfinite(torsion_weight) && torsion_weight > 0.0, "polish_torsion_weight", torsion_weight,
        "finite and > 0");
  lm.validate();
}

namespace {

// One NSGA-II run (and polish) on one problem: one round of run_recentred.
TorsionMatchResult run_once(const CurvatureMatch& match, const TorsionMatchSettings& settings, std::uint64_t seed,
                            std::size_t threads, bool keep_log) {
  const auto clock_start = std::chrono::steady_clock::now();
  const optim::Problem problem = curvature_torsion_problem(match);
  TorsionMatchResult result;

  const std::size_t n_points = match.setup().points.size(), n_samples = match.setup().samples;
  SplineProfileSampler::Workspace ws;
  std::vector<Vec3> points(n_points);
  std::vector<double> kappa(n_samples), tau(n_samples);
  const std::vector<double> start = match.start_variables();
  const MatchDistances at_start = match.mean_distances(start, ws, points, kappa, tau);
  result.start_curvature = at_start.mean;
  result.start_torsion = at_start.torsion_mean;

  optim::Nsga2Options options;
  options.population = settings.population;
  options.crossover_probability = settings.crossover_probability;
  options.crossover_eta = settings.crossover_eta;
  options.mutation_eta = settings.mutation_eta;
  options.mutation_probability = settings.mutation_probability;
  options.run.seed = seed;
  options.run.threads = threads;
  options.run.stop.generations = settings.generations;
  options.run.stop.deadline = settings.deadline;
  options.run.stop.cancel = settings.cancel;
  match.setup().validity.apply(options.run);
  options.run.on_generation = [&](const optim::GenerationLog& g) {
    double bk = std::numeric_limits<double>::infinity(), bt = bk;
    for (std::size_t i = 0; i < g.failed.size(); ++i) {
      if (g.failed[i]) continue;
      bk = std::min(bk, g.objective_values[2 * i]);
      bt = std::min(bt, g.objective_values[2 * i + 1]);
    }
    result.best_curvature.push_back(bk);
    result.best_torsion.push_back(bt);
    if (keep_log) result.log.append(g);
    if (settings.on_generation) settings.on_generation(g);
  };
  const optim::Nsga2Result run = optim::solve_nsga2(problem, options);
  result.report = run.report;
  for (const optim::Solution& s : run.front)
    result.front.push_back({s.variables, s.objectives[0], s.objectives[1], false});
  // Members that break the validity requirements are refused with their reasons (constrained domination keeps
  // them out of the front whenever a valid design was seen).
  const auto refuse_invalid = [&] {
    for (TorsionFrontMember& m : result.front) m.invalid = match.validity(m.variables).reasons;
    for (TorsionFrontMember& m : result.front)
      if (!m.invalid.empty()) result.refused.push_back(m);
    std::erase_if(result.front, [](const TorsionFrontMember& m) { return !m.invalid.empty(); });
  };
  refuse_invalid();
  std::sort(result.front.begin(), result.front.end(),
            [](const auto& a, const auto& b) { return a.curvature < b.curvature; });
  result.nsga2_front = result.front;

  const auto worst = [](const TorsionFrontMember& m) { return std::max(m.curvature, m.torsion); };
  if (settings.polish && !result.front.empty()) {
    const auto best = std::min_element(result.front.begin(), result.front.end(),
                                       [&](const auto& a, const auto& b) { return worst(a) < worst(b); });
    // Stacked residuals [κ − κ*; w (τ − τ*)]; an undefined τ contributes 0 (the
    // objective skips it the same way).
    LeastSquaresProblem ls;
    ls.variables = match.variables();
    ls.residual_count = 2 * n_samples;
    const double w = settings.torsion_weight;
    ls.residuals = [&, w](std::span<const double> x, std::span<double> r) {
      match.points_from(x, points);
      if (!match.sampler().sample(points, ws, kappa, tau)) return false;
      const auto& kt = match.target_samples();
      const auto& tt = match.torsion_target_samples();
      for (std::size_t i = 0; i < n_samples; ++i) {
        r[i] = kappa[i] - kt[i];
        r[n_samples + i] = std::isfinite(tau[i]) ? w * (tau[i] - tt[i]) : 0.0;
      }
      return true;
    };
    result.lm = refine_levenberg_marquardt(ls, best->variables, settings.lm);
    const MatchDistances d = match.mean_distances(result.lm->variables, ws, points, kappa, tau);
    if (std::isfinite(d.mean) && std::isfinite(d.torsion_mean)) {
      TorsionFrontMember polished{result.lm->variables, d.mean, d.torsion_mean, true, {}};
      polished.invalid = match.validity(polished.variables).reasons;
      // Keep the set non-dominated: drop members the (valid) polished curve dominates.
      if (polished.invalid.empty())
        std::erase_if(result.front, [&](const TorsionFrontMember& m) {
          return polished.curvature <= m.curvature && polished.torsion <= m.torsion &&
                 (polished.curvature < m.curvature || polished.torsion < m.torsion);
        });
      const bool dominated = std::any_of(result.front.begin(), result.front.end(), [&](const auto& m) {
        return m.curvature <= polished.curvature && m.torsion <= polished.torsion;
      });
      if (!polished.invalid.empty())
        result.refused.push_back(std::move(polished));
      else if (!dominated)
        result.front.push_back(std::move(polished));
    }
  }
  std::sort(result.front.begin(), result.front.end(),
            [](const auto& a, const auto& b) { return a.curvature < b.curvature; });
  result.compromise = 0;
  for (std::size_t i = 1; i < result.front.size(); ++i)
    if (worst(result.front[i]) < worst(result.front[result.compromise])) result.compromise = i;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  return result;
}

}  // namespace

TorsionMatchResult run_curvature_torsion_match(const CurvatureMatch& match, const TorsionMatchSettings& settings,
                                               std::uint64_t seed, std::size_t threads, bool keep_log) {
  require_torsion(match);
  settings.validate();
  if (settings.map) (void)settings.map->axes(match.variables());
  const auto clock_start = std::chrono::steady_clock::now();
  TorsionMatchResult result;
  // Each round's result replaces `result` (keeping the start's errors); the rounds are set after the last.
  std::vector<RecentreRound> rounds =
      run_recentred(match, settings.max_recentres, [&](const CurvatureMatch& m, std::size_t round) {
        TorsionMatchResult r = run_once(m, settings, seed + round, threads, keep_log);
        const optim::Termination t = r.report.termination;
        RoundOutcome outcome{r.front.empty() ? m.start_variables() : r.front[r.compromise].variables,
                             r.report.evaluations + (r.lm ? r.lm->evaluations : 0), optim::stopped_early(t)};
        if (round > 0) {
          // The start errors are the designer's start's; the convergence record and the log go on over the rounds.
          r.start_curvature = result.start_curvature;
          r.start_torsion = result.start_torsion;
          r.best_curvature.insert(r.best_curvature.begin(), result.best_curvature.begin(), result.best_curvature.end());
          r.best_torsion.insert(r.best_torsion.begin(), result.best_torsion.begin(), result.best_torsion.end());
          for (const optim::GenerationLog& g : r.log.generations()) result.log.append(g);
          r.log = std::move(result.log);
        }
        result = std::move(r);
        return outcome;
      });
  result.rounds = std::move(rounds);
  result.variables = result.rounds.back().variables;
  if (settings.map) {
    optim::Problem problem = curvature_torsion_problem(match);
    problem.variables = result.variables;
    result.map = match_fitness_map(problem, result.rounds.back().best, *settings.map, threads);
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - clock_start).count();
  return result;
}

}  // namespace hula::studies
