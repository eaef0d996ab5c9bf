// SPDX-License-Identifier: MIT
#include "hula/optim/nsga2.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "hula/core/error.hpp"
#include "hula/core/rng.hpp"
#include "hula/optim/crossover.hpp"
#include "hula/optim/detail/engine.hpp"
#include "hula/optim/encoding.hpp"
#include "hula/optim/mutation.hpp"
#include "hula/optim/pareto.hpp"
#include "hula/optim/selection.hpp"

namespace hula::optim {
namespace {
using detail::Population;

// Sum of per-objective minima over feasible individuals: decreases while the
// front advances; used for the stagnation criterion.
double front_progress(const Population& pop, std::size_t n) {
  double sum = 0.0;
  bool any = false;
  for (std::size_t j = 0; j < pop.m; ++j) {
    double best = detail::kInf;
    for (std::size_t i = 0; i < n; ++i) {
      if (pop.failed[i] == 0 && pop.violation[i] == 0.0) best = std::min(best, pop.objectives[i * pop.m + j]);
    }
    if (best < detail::kInf) {
      sum += best;
      any = true;
    }
  }
  return any ? sum : std::numeric_limits<double>::quiet_NaN();
}

Solution solution_of(const Population& pop, std::size_t i) {
  Solution s;
  s.variables.assign(pop.var(i).begin(), pop.var(i).end());
  s.objectives.assign(pop.obj(i).begin(), pop.obj(i).end());
  s.violation = pop.failed[i] ? std::numeric_limits<double>::quiet_NaN() : pop.violation[i];
  return s;
}
}  // namespace

void Nsga2Options::validate() const {
  detail::check_population(population, 4);
  detail::check_probability(crossover_probability, "crossover_probability");
  detail::check_probability(crossover_variable_probability, "crossover_variable_probability");
  if (mutation_probability) detail::check_probability(*mutation_probability, "mutation_probability");
  detail::check_eta(crossover_eta, "crossover_eta");
  detail::check_eta(mutation_eta, "mutation_eta");
  run.validate();
  detail::check_budget(run.stop, population);
}

Nsga2Result solve_nsga2(const Problem& problem, const Nsga2Options& options) {
  problem.validate();
  options.validate();
  const bool binary = options.coding == Coding::Binary;
  const std::optional<BinaryEncoding> encoding =
      binary ? std::optional<BinaryEncoding>(BinaryEncoding(problem.variables)) : std::nullopt;
  const std::size_t n = options.population;
  const std::size_t d = problem.dimension();
  const std::size_t m = problem.objectives;
  const std::size_t length = binary ? encoding->length() : 0;
  const RunSettings& run = options.run;
  std::vector<double> lo(d), hi(d);
  for (std::size_t j = 0; j < d; ++j) {
    lo[j] = problem.variables[j].lower;
    hi[j] = problem.variables[j].upper;
  }
  const double pm = options.mutation_probability.value_or(1.0 / static_cast<double>(binary ? length : d));
  const SbxSettings sbx{.eta = options.crossover_eta, .variable_probability = options.crossover_variable_probability};

  // Rows [0, n) hold the parents, [n, 2n) the offspring. Survivors are copied into `next`, which then
  // becomes the population (a swap, not a second copy back).
  Population pop;
  Population next;
  pop.allocate(2 * n, d, problem.values_per_point(), m, length);
  next.allocate(2 * n, d, problem.values_per_point(), m, length);
  std::vector<double> rank(2 * n, 0.0), crowd(2 * n, 0.0), rank_next(2 * n, 0.0), crowd_next(2 * n, 0.0);
  std::vector<std::size_t> order(2 * n), scratch(2 * n), count(2 * n + 2), chosen(n), by_f0(2 * n), cursor(2 * n + 2);
  NonDominatedSorter sorter;
  detail::Evaluator evaluator(problem, run);
  detail::RunControl control(run.stop, n);
  GenerationLog buffer;
  bool any_success = false;

  // Ranks the first `rows` individuals and computes crowding per front;
  // afterwards order[0, rows) lists them by front (counting sort on rank).
  const auto rank_and_crowd = [&](std::size_t rows) {
    const auto r = sorter.sort(std::span<const double>(pop.objectives).first(rows * m), m,
                               std::span<const double>(pop.violation).first(rows));
    const std::size_t fronts = sorter.fronts();
    std::fill(count.begin(), count.begin() + static_cast<std::ptrdiff_t>(fronts + 1), std::size_t{0});
    for (std::size_t i = 0; i < rows; ++i) {
      rank[i] = static_cast<double>(r[i]);
      ++count[r[i] + 1];
    }
    for (std::size_t f = 0; f < fronts; ++f) count[f + 1] += count[f];
    std::copy_n(count.begin(), fronts + 1, cursor.begin());
    for (std::size_t i = 0; i < rows; ++i) order[count[r[i]]++] = i;
    // count[f] is now the end of front f. by_f0 holds the same fronts with the feasible ones in the
    // sorter's objective order, so crowding finds its first objective already sorted; `order` keeps
    // index order within fronts, which decides the rows of the survivors.
    const auto feasible = sorter.feasible();
    for (const std::size_t i : feasible) by_f0[cursor[r[i]]++] = i;
    std::size_t feasible_fronts = 0;
    for (const std::size_t i : feasible) feasible_fronts = std::max(feasible_fronts, r[i] + 1);
    for (std::size_t i = 0; i < rows; ++i) {
      if (r[i] >= feasible_fronts) by_f0[cursor[r[i]]++] = i;
    }
    std::size_t begin = 0;
    for (std::size_t f = 0; f < fronts; ++f) {
      const std::size_t end = count[f];
      if (pop.failed[order[begin]] != 0) {
        // Failed evaluations form the last rank alone; their objectives are NaN.
        for (std::size_t q = begin; q < end; ++q) crowd[order[q]] = 0.0;
        begin = end;
        continue;
      }
      crowding_distance(pop.objectives, m, std::span<const std::size_t>(by_f0).subspan(begin, end - begin), crowd,
                        scratch);
      begin = end;
    }
    return fronts;
  };

  for (std::size_t i = 0; i < n; ++i) {
    Rng rng(run.seed, i);
    if (binary) {
      auto c = pop.chrom(i);
      std::uint64_t word = 0;
      for (std::size_t b = 0; b < length; ++b) {
        if (b % 64 == 0) word = rng();
        c[b] = static_cast<std::uint8_t>((word >> (b % 64)) & 1U);
      }
      encoding->decode(c, pop.var(i));
    } else {
      auto x = pop.var(i);
      for (std::size_t j = 0; j < d; ++j) x[j] = hi[j] > lo[j] ? rng.uniform(lo[j], hi[j]) : lo[j];
    }
  }
  evaluator.evaluate(pop, 0, n);
  any_success = evaluator.failed() < evaluator.evaluations();
  rank_and_crowd(n);
  detail::emit_generation(run.on_generation, buffer, pop, n, 0, evaluator.evaluations(), rank);

  // Crowded-comparison tournament of two (Deb 2002): lower rank, then larger crowding.
  const auto crowded_pick = [&](Rng& rng) {
    const auto a = static_cast<std::size_t>(rng.below(n));
    const auto b = static_cast<std::size_t>(rng.below(n));
    if (rank[a] != rank[b]) return rank[a] < rank[b] ? a : b;
    return crowd[b] > crowd[a] ? b : a;
  };

  std::size_t g = 0;
  Termination reason = Termination::MaxGenerations;
  while (true) {
    if (const auto stop = control.check(g, evaluator.evaluations(), front_progress(pop, n))) {
      reason = *stop;
      break;
    }
    ++g;
    for (std::size_t j = 0; j < n / 2; ++j) {
      Rng rng(run.seed, detail::pair_stream(g, j));
      const std::size_t a = crowded_pick(rng);
      const std::size_t b = crowded_pick(rng);
      const std::size_t r1 = n + 2 * j;
      const std::size_t r2 = r1 + 1;
      if (binary) {
        const auto c1 = pop.chrom(r1);
        const auto c2 = pop.chrom(r2);
        if (rng.uniform() < options.crossover_probability) {
          if (options.binary_crossover == BinaryCrossover::SinglePoint) {
            single_point_crossover(pop.chrom(a), pop.chrom(b), c1, c2, rng);
          } else {
            uniform_crossover(pop.chrom(a), pop.chrom(b), c1, c2, rng);
          }
        } else {
          std::copy(pop.chrom(a).begin(), pop.chrom(a).end(), c1.begin());
          std::copy(pop.chrom(b).begin(), pop.chrom(b).end(), c2.begin());
        }
        bit_mutation(c1, pm, 0, rng);
        bit_mutation(c2, pm, 0, rng);
        encoding->decode(c1, pop.var(r1));
        encoding->decode(c2, pop.var(r2));
      } else {
        detail::real_offspring(pop.var(a), pop.var(b), pop.var(r1), pop.var(r2), lo, hi, options.crossover_probability,
                               sbx, pm, options.mutation_eta, rng);
      }
    }
    const std::size_t failed_before = evaluator.failed();
    evaluator.evaluate(pop, n, 2 * n);
    any_success = any_success || evaluator.failed() - failed_before < n;

    // (mu + lambda) survival: whole fronts while they fit, then the most
    // crowded-distant members of the splitting front.
    const std::size_t fronts = rank_and_crowd(2 * n);
    std::size_t taken = 0;
    std::size_t begin = 0;
    for (std::size_t f = 0; f < fronts && taken < n; ++f) {
      const std::size_t end = count[f];
      const std::size_t size = end - begin;
      if (taken + size > n) {
        std::sort(order.begin() + static_cast<std::ptrdiff_t>(begin), order.begin() + static_cast<std::ptrdiff_t>(end),
                  [&](std::size_t a, std::size_t b) { return crowd[a] > crowd[b] || (crowd[a] == crowd[b] && a < b); });
      }
      const std::size_t take = std::min(size, n - taken);
      std::copy_n(order.begin() + static_cast<std::ptrdiff_t>(begin), take,
                  chosen.begin() + static_cast<std::ptrdiff_t>(taken));
      taken += take;
      begin = end;
    }
    for (std::size_t i = 0; i < n; ++i) {
      next.copy_row_from(pop, chosen[i], i);
      rank_next[i] = rank[chosen[i]];
      crowd_next[i] = crowd[chosen[i]];
    }
    std::swap(pop, next);
    std::swap(rank, rank_next);
    std::swap(crowd, crowd_next);
    const auto ranks_before = [&](std::size_t a, std::size_t b) {
      if (rank[a] != rank[b]) return rank[a] < rank[b];
      return crowd[a] > crowd[b];
    };
    const std::vector<std::size_t> migrants = detail::migrate(run, evaluator, pop, n, g, ranks_before);
    if (!migrants.empty()) {
      for (const std::size_t i : migrants) any_success = any_success || pop.failed[i] == 0;
      if (binary) {
        for (const std::size_t i : migrants) {
          const std::vector<std::uint8_t> bits = encoding->encode(pop.var(i));
          std::copy(bits.begin(), bits.end(), pop.chrom(i).begin());
        }
      }
      rank_and_crowd(n);
    }
    detail::emit_generation(run.on_generation, buffer, pop, n, g, evaluator.evaluations(), rank);
  }
  if (!any_success) detail::throw_no_finite(evaluator);

  Nsga2Result result;
  // Rank the final population on its own so `front` is its first front.
  rank_and_crowd(n);
  result.population.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    result.population.push_back(solution_of(pop, i));
    if (rank[i] == 0.0 && pop.failed[i] == 0 && pop.violation[i] == 0.0) result.front.push_back(solution_of(pop, i));
  }
  result.report.evaluations = evaluator.evaluations();
  result.report.failed_evaluations = evaluator.failed();
  control.finish(result.report, reason, g);
  return result;
}

}  // namespace hula::optim
