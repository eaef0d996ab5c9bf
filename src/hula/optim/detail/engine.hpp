// SPDX-License-Identifier: MIT
// Machinery shared by the Flexo algorithms: preallocated populations, the
// evaluator that turns batch results into rankable keys (failed evaluations
// rank last), the stop-criteria controller, the best-so-far tracker and the
// run-log emitter. Internal to hula::optim.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/optim/crossover.hpp"
#include "hula/optim/problem.hpp"
#include "hula/optim/run_log.hpp"
#include "hula/optim/run_report.hpp"
#include "hula/optim/solution.hpp"

namespace hula::optim::detail {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

/// Rng stream of offspring pair j in generation g >= 1 (initial individual i uses stream i).
[[nodiscard]] inline std::uint64_t pair_stream(std::size_t generation, std::size_t pair) noexcept {
  return (static_cast<std::uint64_t>(generation) << 32) + pair;
}

/// Real-coded offspring of parents a and b into children c1 and c2: SBX with
/// probability `crossover_probability` (else copies), then polynomial mutation
/// of each child with per-variable probability `mutation_probability`. The
/// draws from `rng` come in that order, shared by the real GA and NSGA-II.
void real_offspring(std::span<const double> a, std::span<const double> b, std::span<double> c1, std::span<double> c2,
                    std::span<const double> lower, std::span<const double> upper, double crossover_probability,
                    const SbxSettings& sbx, double mutation_probability, double mutation_eta, Rng& rng);

/// Rows of individuals, allocated once per run.
struct Population {
  std::size_t d = 0;     // variables
  std::size_t k = 0;     // values per point
  std::size_t m = 0;     // objectives
  std::size_t bits = 0;  // chromosome length (binary coding), else 0
  std::vector<double> x, values, objectives, violation, rank_violation, score;
  std::vector<std::uint8_t> failed, chromosome;

  void allocate(std::size_t rows, std::size_t dimension, std::size_t value_count, std::size_t objective_count,
                std::size_t chromosome_bits);
  [[nodiscard]] std::span<double> var(std::size_t i) noexcept { return {x.data() + i * d, d}; }
  [[nodiscard]] std::span<const double> var(std::size_t i) const noexcept { return {x.data() + i * d, d}; }
  [[nodiscard]] std::span<std::uint8_t> chrom(std::size_t i) noexcept { return {chromosome.data() + i * bits, bits}; }
  [[nodiscard]] std::span<const double> obj(std::size_t i) const noexcept { return {objectives.data() + i * m, m}; }
  /// Copies every per-individual array of row `from` of `src` into row `to`.
  void copy_row_from(const Population& src, std::size_t from, std::size_t to) noexcept;
  /// Single-objective order: lower rank_violation, then lower score, then lower index.
  [[nodiscard]] bool better(std::size_t a, std::size_t b) const noexcept {
    if (rank_violation[a] != rank_violation[b]) return rank_violation[a] < rank_violation[b];
    if (score[a] != score[b]) return score[a] < score[b];
    return false;
  }
};

/// Evaluates rows through evaluate_batch and fills the ranking keys.
class Evaluator {
 public:
  Evaluator(const Problem& problem, const RunSettings& settings) : problem_(problem), settings_(settings) {}
  void evaluate(Population& pop, std::size_t begin, std::size_t end);
  /// Derives row i's objectives, violation and ranking keys from its values and failed flag.
  void set_keys(Population& pop, std::size_t i) const;
  [[nodiscard]] std::size_t evaluations() const noexcept { return evaluations_; }
  [[nodiscard]] std::size_t failed() const noexcept { return failed_; }
  [[nodiscard]] const std::string& first_failure() const noexcept { return first_failure_; }

 private:
  const Problem& problem_;
  const RunSettings& settings_;
  std::size_t evaluations_ = 0;
  std::size_t failed_ = 0;
  std::string first_failure_;
};

/// Stop criteria and timing.
class RunControl {
 public:
  RunControl(const StopCriteria& stop, std::size_t population);
  /// Checks after generation g (0 = initial population) in Termination order.
  /// @param progress a value to minimise for target/stagnation (NaN if none yet).
  [[nodiscard]] std::optional<Termination> check(std::size_t generation, std::size_t evaluations, double progress);
  [[nodiscard]] double seconds() const;
  /// Fills report.termination/message/seconds.
  void finish(RunReport& report, Termination reason, std::size_t generation) const;

 private:
  const StopCriteria& stop_;
  std::size_t population_;
  std::chrono::steady_clock::time_point start_;
  double best_progress_ = kInf;
  std::size_t stagnant_ = 0;
};

/// Best individual seen so far (single objective).
struct Champion {
  bool found = false;
  double rank_violation = kInf;
  double score = kInf;
  Solution solution{};
  void offer(const Population& pop, std::size_t i);
};

/// Fills `buffer` (reused between generations) and calls the callback.
void emit_generation(const GenerationCallback& callback, GenerationLog& buffer, const Population& pop, std::size_t n,
                     std::size_t generation, std::size_t evaluations, std::span<const double> fitness);

/// Offers rows [0, n) to settings.migrate after generation g (if set) and
/// re-derives the keys of the rows it replaced; returns those rows.
std::vector<std::size_t> migrate(const RunSettings& settings, const Evaluator& evaluator, Population& pop,
                                 std::size_t n, std::size_t generation,
                                 const std::function<bool(std::size_t, std::size_t)>& better);

/// Throws Errc::NumericalFailure when no evaluation ever succeeded.
[[noreturn]] void throw_no_finite(const Evaluator& evaluator);

/// Checks a probability option.
void check_probability(double value, const char* field);
/// Checks a distribution index option.
void check_eta(double value, const char* field);
/// Checks that population is even and >= minimum.
void check_population(std::size_t value, std::size_t minimum);
/// Checks that an evaluation budget, if set, covers the initial population.
void check_budget(const StopCriteria& stop, std::size_t population);

}  // namespace hula::optim::detail
