// SPDX-License-Identifier: MIT
#include "hula/optim/detail/engine.hpp"

#include <algorithm>
#include <cmath>

#include "hula/core/error.hpp"
#include "hula/optim/mutation.hpp"

namespace hula::optim::detail {

void real_offspring(std::span<const double> a, std::span<const double> b, std::span<double> c1, std::span<double> c2,
                    std::span<const double> lower, std::span<const double> upper, double crossover_probability,
                    const SbxSettings& sbx, double mutation_probability, double mutation_eta, Rng& rng) {
  if (rng.uniform() < crossover_probability) {
    sbx_crossover(a, b, lower, upper, c1, c2, sbx, rng);
  } else {
    std::copy(a.begin(), a.end(), c1.begin());
    std::copy(b.begin(), b.end(), c2.begin());
  }
  polynomial_mutation(c1, lower, upper, mutation_probability, mutation_eta, rng);
  polynomial_mutation(c2, lower, upper, mutation_probability, mutation_eta, rng);
}

void Population::allocate(std::size_t rows, std::size_t dimension, std::size_t value_count, std::size_t objective_count,
                          std::size_t chromosome_bits) {
  d = dimension;
  k = value_count;
  m = objective_count;
  bits = chromosome_bits;
  x.assign(rows * d, 0.0);
  values.assign(rows * k, 0.0);
  objectives.assign(rows * m, 0.0);
  violation.assign(rows, 0.0);
  rank_violation.assign(rows, 0.0);
  score.assign(rows, 0.0);
  failed.assign(rows, 0);
  chromosome.assign(rows * bits, 0);
}

void Population::copy_row_from(const Population& src, std::size_t from, std::size_t to) noexcept {
  std::copy_n(src.x.data() + from * d, d, x.data() + to * d);
  std::copy_n(src.values.data() + from * k, k, values.data() + to * k);
  std::copy_n(src.objectives.data() + from * m, m, objectives.data() + to * m);
  std::copy_n(src.chromosome.data() + from * bits, bits, chromosome.data() + to * bits);
  violation[to] = src.violation[from];
  rank_violation[to] = src.rank_violation[from];
  score[to] = src.score[from];
  failed[to] = src.failed[from];
}

void Evaluator::evaluate(Population& pop, std::size_t begin, std::size_t end) {
  if (end <= begin) return;
  const std::size_t n = end - begin;
  const BatchReport r = evaluate_batch(problem_, std::span<const double>(pop.x).subspan(begin * pop.d, n * pop.d),
                                       std::span<double>(pop.values).subspan(begin * pop.k, n * pop.k),
                                       std::span<std::uint8_t>(pop.failed).subspan(begin, n),
                                       {.threads = settings_.threads, .rethrow = false});
  if (r.failed > 0 && failed_ == 0) {
    first_failure_ = "evaluation " + std::to_string(evaluations_ + r.first_failed) + ": " + r.first_message;
  }
  evaluations_ += n;
  failed_ += r.failed;
  for (std::size_t i = begin; i < end; ++i) set_keys(pop, i);
}

void Evaluator::set_keys(Population& pop, std::size_t i) const {
  const bool penalty = settings_.constraints == ConstraintHandling::Penalty;
  const double* v = pop.values.data() + i * pop.k;
  std::copy_n(v, pop.m, pop.objectives.data() + i * pop.m);
  if (pop.failed[i] != 0) {
    // Failed evaluations rank after every successful one.
    pop.violation[i] = kInf;
    pop.rank_violation[i] = kInf;
    pop.score[i] = kInf;
    return;
  }
  const double viol = problem_.violation({v, pop.k});
  pop.violation[i] = viol;
  pop.rank_violation[i] = penalty ? 0.0 : viol;
  pop.score[i] = penalty ? v[0] + settings_.penalty * viol : v[0];
}

std::vector<std::size_t> migrate(const RunSettings& settings, const Evaluator& evaluator, Population& pop,
                                 std::size_t n, std::size_t generation,
                                 const std::function<bool(std::size_t, std::size_t)>& better) {
  if (!settings.migrate) return {};
  MigrationView view{.rows = n,
                     .dimension = pop.d,
                     .values_per_point = pop.k,
                     .x = std::span<double>(pop.x).first(n * pop.d),
                     .values = std::span<double>(pop.values).first(n * pop.k),
                     .failed = std::span<std::uint8_t>(pop.failed).first(n),
                     .better = better,
                     .replaced = {}};
  settings.migrate(generation, view);
  for (const std::size_t i : view.replaced) evaluator.set_keys(pop, i);
  return std::move(view.replaced);
}

RunControl::RunControl(const StopCriteria& stop, std::size_t population)
    : stop_(stop), population_(population), start_(std::chrono::steady_clock::now()) {}

double RunControl::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

std::optional<Termination> RunControl::check(std::size_t generation, std::size_t evaluations, double progress) {
  // No feasible progress value yet counts as no improvement (and never meets
  // the target); +inf keeps the comparisons below quiet (no FE_INVALID).
  if (std::isnan(progress)) progress = kInf;
  if (generation > 0 && stop_.stagnation_generations > 0) {
    if (progress < best_progress_ - stop_.stagnation_tolerance) {
      stagnant_ = 0;
    } else {
      ++stagnant_;
    }
  }
  if (progress < best_progress_) best_progress_ = progress;
  if (generation >= stop_.generations) return Termination::MaxGenerations;
  if (stop_.max_evaluations > 0 && evaluations + population_ > stop_.max_evaluations) {
    return Termination::MaxEvaluations;
  }
  if (stop_.target && progress <= *stop_.target) return Termination::TargetReached;
  if (stop_.stagnation_generations > 0 && stagnant_ >= stop_.stagnation_generations) return Termination::Stagnation;
  if (stop_.wall_time_seconds > 0.0 && seconds() >= stop_.wall_time_seconds) return Termination::WallTime;
  if (deadline_passed(stop_.deadline)) return Termination::WallTime;
  if (stop_.cancel != nullptr && stop_.cancel->is_cancelled()) return Termination::Cancelled;
  return std::nullopt;
}

void RunControl::finish(RunReport& report, Termination reason, std::size_t generation) const {
  report.termination = reason;
  report.generations = generation;
  report.seconds = seconds();
  switch (reason) {
    case Termination::MaxGenerations:
      report.message = std::to_string(generation) + " generations run";
      break;
    case Termination::MaxEvaluations:
      report.message = "evaluation budget " + std::to_string(stop_.max_evaluations) + " reached";
      break;
    case Termination::TargetReached:
      report.message = "target " + format_number(stop_.target.value_or(0.0)) + " reached";
      break;
    case Termination::Stagnation:
      report.message = "no improvement for " + std::to_string(stop_.stagnation_generations) + " generations";
      break;
    case Termination::WallTime:
      report.message = stop_.wall_time_seconds > 0.0 && seconds() >= stop_.wall_time_seconds
                           ? "wall time " + format_number(stop_.wall_time_seconds) + " s elapsed"
                           : std::string("the run's wall-time deadline passed");
      break;
    case Termination::Cancelled:
      report.message = "cancelled after " + std::to_string(generation) + " generations";
      break;
    case Termination::Converged:  // the local methods' reason; no stop criterion of a population gives it
      HULA_ASSERT(false, "a population-based run cannot end Converged");
      break;
  }
}

void Champion::offer(const Population& pop, std::size_t i) {
  if (pop.failed[i] != 0) return;
  const double rv = pop.rank_violation[i];
  const double sc = pop.score[i];
  if (found && (rv > rank_violation || (rv == rank_violation && sc >= score))) return;
  found = true;
  rank_violation = rv;
  score = sc;
  const auto xv = pop.var(i);
  const auto ov = pop.obj(i);
  solution.variables.assign(xv.begin(), xv.end());
  solution.objectives.assign(ov.begin(), ov.end());
  solution.violation = pop.violation[i];
}

void emit_generation(const GenerationCallback& callback, GenerationLog& buffer, const Population& pop, std::size_t n,
                     std::size_t generation, std::size_t evaluations, std::span<const double> fitness) {
  if (!callback) return;
  buffer.generation = generation;
  buffer.evaluations = evaluations;
  buffer.dimension = pop.d;
  buffer.objectives = pop.m;
  buffer.variables.assign(pop.x.begin(), pop.x.begin() + static_cast<std::ptrdiff_t>(n * pop.d));
  buffer.objective_values.assign(pop.objectives.begin(),
                                 pop.objectives.begin() + static_cast<std::ptrdiff_t>(n * pop.m));
  buffer.violation.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    buffer.violation[i] = pop.failed[i] ? std::numeric_limits<double>::quiet_NaN() : pop.violation[i];
  }
  buffer.fitness.assign(fitness.begin(), fitness.begin() + static_cast<std::ptrdiff_t>(n));
  buffer.failed.assign(pop.failed.begin(), pop.failed.begin() + static_cast<std::ptrdiff_t>(n));
  callback(buffer);
}

void throw_no_finite(const Evaluator& evaluator) {
  throw Error(Errc::NumericalFailure,
              "no evaluation returned finite values in " + std::to_string(evaluator.evaluations()) +
                  " evaluations (first failure: " + evaluator.first_failure() + ")",
              {.field = "evaluate"});
}

void check_probability(double value, const char* field) {
  if (std::isnan(value) || value < 0.0 || value > 1.0) {
    throw Error(Errc::InvalidOption, std::string(field) + " = " + format_number(value) + " must be in [0, 1]",
                {.field = field});
  }
}

void check_eta(double value, const char* field) {
  if (!std::isfinite(value) || value < 0.0) {
    throw Error(Errc::InvalidOption, std::string(field) + " = " + format_number(value) + " must be finite and >= 0",
                {.field = field});
  }
}

void check_population(std::size_t value, std::size_t minimum) {
  if (value < minimum || value % 2 != 0) {
    throw Error(Errc::InvalidOption,
                "population = " + std::to_string(value) + " must be even and >= " + std::to_string(minimum) +
                    " (offspring are made in pairs)",
                {.field = "population"});
  }
}

void check_budget(const StopCriteria& stop, std::size_t population) {
  if (stop.max_evaluations > 0 && stop.max_evaluations < population) {
    throw Error(Errc::InvalidOption,
                "stop.max_evaluations = " + std::to_string(stop.max_evaluations) + " is below population = " +
                    std::to_string(population) + ": the initial population alone would exceed it",
                {.field = "stop.max_evaluations"});
  }
}

}  // namespace hula::optim::detail
