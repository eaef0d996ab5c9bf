// SPDX-License-Identifier: MIT
#include "hula/optim/ga.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "hula/core/error.hpp"
#include "hula/core/rng.hpp"
#include "hula/optim/crossover.hpp"
#include "hula/optim/detail/engine.hpp"
#include "hula/optim/encoding.hpp"
#include "hula/optim/mutation.hpp"
#include "hula/optim/selection.hpp"

namespace hula::optim {
namespace {
using detail::Population;

void check_single_objective(const Problem& problem, const char* algorithm) {
  if (problem.objectives != 1) {
    throw Error(Errc::InvalidOption,
                "objectives = " + std::to_string(problem.objectives) + ": " + algorithm +
                    " is single-objective; use solve_nsga2 for several objectives",
                {.field = "objectives"});
  }
}

void check_tournament(std::size_t size, std::size_t population) {
  if (size == 0 || size > population) {
    throw Error(Errc::InvalidOption,
                "tournament_size = " + std::to_string(size) +
                    " must be in [1, population = " + std::to_string(population) + "]",
                {.field = "tournament_size"});
  }
}

void check_elites(std::size_t elites, std::size_t population) {
  if (elites >= population) {
    throw Error(Errc::InvalidOption,
                "elites = " + std::to_string(elites) + " must be < population = " + std::to_string(population),
                {.field = "elites"});
  }
}

// Deterministic total order: better first, then lower index.
auto ranking(const Population& pop) {
  return [&pop](std::size_t a, std::size_t b) { return pop.better(a, b) || (!pop.better(b, a) && a < b); };
}

double progress_of(const detail::Champion& champion) {
  return champion.found && champion.rank_violation == 0.0 ? champion.score : std::numeric_limits<double>::quiet_NaN();
}

void random_real(std::span<double> x, const std::vector<double>& lo, const std::vector<double>& hi, Rng& rng) {
  for (std::size_t j = 0; j < x.size(); ++j) x[j] = hi[j] > lo[j] ? rng.uniform(lo[j], hi[j]) : lo[j];
}
}  // namespace

double boosted_fitness(double evaluation, double power) noexcept {
  if (!std::isfinite(evaluation)) return 0.0;
  return std::pow(1.0 / (1.0 + evaluation), power);
}

double boost_power(double start, double end, std::size_t generation, std::size_t generations) noexcept {
  if (generations == 0) return start;
  return start + (end - start) * static_cast<double>(generation) / static_cast<double>(generations);
}

void RealGaOptions::validate() const {
  detail::check_population(population, 2);
  check_tournament(tournament_size, population);
  detail::check_probability(crossover_probability, "crossover_probability");
  detail::check_probability(crossover_variable_probability, "crossover_variable_probability");
  if (mutation_probability) detail::check_probability(*mutation_probability, "mutation_probability");
  detail::check_eta(crossover_eta, "crossover_eta");
  detail::check_eta(mutation_eta, "mutation_eta");
  if (survival == Survival::Generational) check_elites(elites, population);
  run.validate();
  detail::check_budget(run.stop, population);
}

void BinaryGaOptions::validate() const {
  detail::check_population(population, 2);
  if (selection == Selection::Tournament) check_tournament(tournament_size, population);
  detail::check_probability(crossover_probability, "crossover_probability");
  detail::check_probability(mutation_probability, "mutation_probability");
  if (crossover_level > 9) {
    throw Error(Errc::InvalidOption, "crossover_level = " + std::to_string(crossover_level) + " must be in [0, 9]",
                {.field = "crossover_level"});
  }
  if (mutation_level > 9) {
    throw Error(Errc::InvalidOption, "mutation_level = " + std::to_string(mutation_level) + " must be in [0, 9]",
                {.field = "mutation_level"});
  }
  if (!std::isfinite(boost_start) || boost_start <= 0.0) {
    throw Error(Errc::InvalidOption, "boost_start = " + format_number(boost_start) + " must be finite and > 0",
                {.field = "boost_start"});
  }
  if (!std::isfinite(boost_end) || boost_end <= 0.0) {
    throw Error(Errc::InvalidOption, "boost_end = " + format_number(boost_end) + " must be finite and > 0",
                {.field = "boost_end"});
  }
  check_elites(elites, population);
  run.validate();
  detail::check_budget(run.stop, population);
}

GaResult solve_real_ga(const Problem& problem, const RealGaOptions& options) {
  problem.validate();
  options.validate();
  check_single_objective(problem, "the real-coded GA");
  options.run.validate_initial(problem.variables, options.population);
  const std::size_t n = options.population;
  const std::size_t d = problem.dimension();
  const RunSettings& run = options.run;
  std::vector<double> lo(d), hi(d);
  for (std::size_t j = 0; j < d; ++j) {
    lo[j] = problem.variables[j].lower;
    hi[j] = problem.variables[j].upper;
  }
  const double pm = options.mutation_probability.value_or(1.0 / static_cast<double>(d));
  const SbxSettings sbx{.eta = options.crossover_eta, .variable_probability = options.crossover_variable_probability};

  // Rows [0, n) hold the parents, [n, 2n) the offspring.
  Population pop;
  Population next;
  pop.allocate(2 * n, d, problem.values_per_point(), 1, 0);
  next.allocate(n, d, problem.values_per_point(), 1, 0);
  std::vector<std::size_t> order(2 * n);
  detail::Evaluator evaluator(problem, run);
  detail::RunControl control(run.stop, n);
  detail::Champion champion;
  GenerationLog buffer;

  for (std::size_t i = 0; i < n; ++i) {
    Rng rng(run.seed, i);
    random_real(pop.var(i), lo, hi, rng);
  }
  // Seeded individuals (10.1.1) replace the first random ones; the streams of the others are unchanged.
  for (std::size_t i = 0; i < run.initial.size(); ++i)
    std::copy(run.initial[i].begin(), run.initial[i].end(), pop.var(i).begin());
  evaluator.evaluate(pop, 0, n);
  for (std::size_t i = 0; i < n; ++i) champion.offer(pop, i);
  detail::emit_generation(run.on_generation, buffer, pop, n, 0, evaluator.evaluations(), pop.score);

  std::size_t g = 0;
  Termination reason = Termination::MaxGenerations;
  const auto better = [&pop](std::size_t a, std::size_t b) { return pop.better(a, b); };
  while (true) {
    if (const auto stop = control.check(g, evaluator.evaluations(), progress_of(champion))) {
      reason = *stop;
      break;
    }
    ++g;
    for (std::size_t j = 0; j < n / 2; ++j) {
      Rng rng(run.seed, detail::pair_stream(g, j));
      const std::size_t a = tournament_select(n, options.tournament_size, rng, better);
      const std::size_t b = tournament_select(n, options.tournament_size, rng, better);
      detail::real_offspring(pop.var(a), pop.var(b), pop.var(n + 2 * j), pop.var(n + 2 * j + 1), lo, hi,
                             options.crossover_probability, sbx, pm, options.mutation_eta, rng);
    }
    evaluator.evaluate(pop, n, 2 * n);
    for (std::size_t i = n; i < 2 * n; ++i) champion.offer(pop, i);

    std::iota(order.begin(), order.end(), std::size_t{0});
    if (options.survival == Survival::Plus) {
      std::partial_sort(order.begin(), order.begin() + static_cast<std::ptrdiff_t>(n), order.end(), ranking(pop));
    } else {
      // Elites from the parents, the rest from the best offspring.
      const auto mid = order.begin() + static_cast<std::ptrdiff_t>(n);
      std::sort(order.begin(), mid, ranking(pop));
      std::sort(mid, order.end(), ranking(pop));
      std::copy(mid, mid + static_cast<std::ptrdiff_t>(n - options.elites),
                order.begin() + static_cast<std::ptrdiff_t>(options.elites));
    }
    for (std::size_t i = 0; i < n; ++i) next.copy_row_from(pop, order[i], i);
    for (std::size_t i = 0; i < n; ++i) pop.copy_row_from(next, i, i);
    for (const std::size_t i : detail::migrate(run, evaluator, pop, n, g, better)) champion.offer(pop, i);
    detail::emit_generation(run.on_generation, buffer, pop, n, g, evaluator.evaluations(), pop.score);
  }
  if (!champion.found) detail::throw_no_finite(evaluator);
  GaResult result;
  result.best = std::move(champion.solution);
  result.report.evaluations = evaluator.evaluations();
  result.report.failed_evaluations = evaluator.failed();
  control.finish(result.report, reason, g);
  return result;
}

GaResult solve_binary_ga(const Problem& problem, const BinaryGaOptions& options) {
  problem.validate();
  options.validate();
  check_single_objective(problem, "the binary-coded GA");
  options.run.validate_initial(problem.variables, options.population);
  const BinaryEncoding encoding(problem.variables);
  const std::size_t n = options.population;
  const std::size_t d = problem.dimension();
  const std::size_t length = encoding.length();
  const RunSettings& run = options.run;
  const std::size_t generations = run.stop.generations;

  Population pop;
  Population next;
  pop.allocate(n, d, problem.values_per_point(), 1, length);
  next.allocate(n, d, problem.values_per_point(), 1, length);
  std::vector<double> fitness(n);
  std::vector<std::size_t> parent_order(n), child_order(n);
  RouletteWheel wheel;
  detail::Evaluator evaluator(problem, run);
  detail::RunControl control(run.stop, n);
  detail::Champion champion;
  GenerationLog buffer;

  // Eq. 32-33 on the penalised evaluation e = f + penalty x violation, shifted
  // so that the generation's smallest e is >= 0 (1/(1+e) needs e > -1).
  const auto compute_fitness = [&](std::size_t generation) {
    const double power = boost_power(options.boost_start, options.boost_end, generation, generations);
    double shift = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (pop.failed[i] == 0) shift = std::min(shift, pop.values[i * pop.k] + run.penalty * pop.violation[i]);
    }
    for (std::size_t i = 0; i < n; ++i) {
      const double e = pop.failed[i] ? detail::kInf : pop.values[i * pop.k] + run.penalty * pop.violation[i] - shift;
      fitness[i] = boosted_fitness(e, power);
    }
  };

  for (std::size_t i = 0; i < n; ++i) {
    Rng rng(run.seed, i);
    auto c = pop.chrom(i);
    std::uint64_t word = 0;
    for (std::size_t b = 0; b < length; ++b) {
      if (b % 64 == 0) word = rng();
      c[b] = static_cast<std::uint8_t>((word >> (b % 64)) & 1U);
    }
    if (i < run.initial.size()) {
      // A seeded individual (10.1.1), coded to its nearest grid value.
      const std::vector<std::uint8_t> coded = encoding.encode(run.initial[i]);
      std::copy(coded.begin(), coded.end(), c.begin());
    }
    encoding.decode(c, pop.var(i));
  }
  evaluator.evaluate(pop, 0, n);
  for (std::size_t i = 0; i < n; ++i) champion.offer(pop, i);
  compute_fitness(0);
  detail::emit_generation(run.on_generation, buffer, pop, n, 0, evaluator.evaluations(), fitness);

  std::size_t g = 0;
  Termination reason = Termination::MaxGenerations;
  const auto better = [&pop](std::size_t a, std::size_t b) { return pop.better(a, b); };
  while (true) {
    if (const auto stop = control.check(g, evaluator.evaluations(), progress_of(champion))) {
      reason = *stop;
      break;
    }
    ++g;
    if (options.selection == Selection::Roulette) wheel.reset(fitness);
    for (std::size_t j = 0; j < n / 2; ++j) {
      Rng rng(run.seed, detail::pair_stream(g, j));
      const auto pick = [&] {
        return options.selection == Selection::Roulette ? wheel.spin(rng)
                                                        : tournament_select(n, options.tournament_size, rng, better);
      };
      const std::size_t a = pick();
      const std::size_t b = pick();
      const auto c1 = next.chrom(2 * j);
      const auto c2 = next.chrom(2 * j + 1);
      if (chance(rng, options.crossover_probability, options.crossover_level)) {
        if (options.crossover == BinaryCrossover::SinglePoint) {
          single_point_crossover(pop.chrom(a), pop.chrom(b), c1, c2, rng);
        } else {
          uniform_crossover(pop.chrom(a), pop.chrom(b), c1, c2, rng);
        }
      } else {
        std::copy(pop.chrom(a).begin(), pop.chrom(a).end(), c1.begin());
        std::copy(pop.chrom(b).begin(), pop.chrom(b).end(), c2.begin());
      }
      bit_mutation(c1, options.mutation_probability, options.mutation_level, rng);
      bit_mutation(c2, options.mutation_probability, options.mutation_level, rng);
      encoding.decode(c1, next.var(2 * j));
      encoding.decode(c2, next.var(2 * j + 1));
    }
    evaluator.evaluate(next, 0, n);
    for (std::size_t i = 0; i < n; ++i) champion.offer(next, i);
    if (options.elites > 0) {
      // Elitism: the best parents replace the worst children.
      std::iota(parent_order.begin(), parent_order.end(), std::size_t{0});
      std::iota(child_order.begin(), child_order.end(), std::size_t{0});
      const auto elites = static_cast<std::ptrdiff_t>(options.elites);
      std::partial_sort(parent_order.begin(), parent_order.begin() + elites, parent_order.end(), ranking(pop));
      // The `elites` worst children, worst first (ranking is a strict total order, so this is the tail of
      // the fully sorted order reversed, without sorting the rest).
      const auto rank_next = ranking(next);
      std::partial_sort(child_order.begin(), child_order.begin() + elites, child_order.end(),
                        [&rank_next](std::size_t a, std::size_t b) { return rank_next(b, a); });
      for (std::size_t q = 0; q < options.elites; ++q) {
        next.copy_row_from(pop, parent_order[q], child_order[q]);
      }
    }
    std::swap(pop, next);
    for (const std::size_t i : detail::migrate(run, evaluator, pop, n, g, better)) {
      // Migrants come from islands of the same problem and coding: their variables are on this grid.
      const std::vector<std::uint8_t> bits = encoding.encode(pop.var(i));
      std::copy(bits.begin(), bits.end(), pop.chrom(i).begin());
      champion.offer(pop, i);
    }
    compute_fitness(g);
    detail::emit_generation(run.on_generation, buffer, pop, n, g, evaluator.evaluations(), fitness);
  }
  if (!champion.found) detail::throw_no_finite(evaluator);
  GaResult result;
  result.best = std::move(champion.solution);
  result.report.evaluations = evaluator.evaluations();
  result.report.failed_evaluations = evaluator.failed();
  control.finish(result.report, reason, g);
  return result;
}

}  // namespace hula::optim
