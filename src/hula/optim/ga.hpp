// SPDX-License-Identifier: MIT
// The single-objective genetic algorithms of Flexo.
//
// Real-coded GA: tournament selection, simulated binary crossover, polynomial
// mutation and elitism (Deb 2001). Binary-coded GA as in the thesis (chapter
// 2.3, appendix 2): bits per variable from bounds and precision, roulette or
// tournament selection, single-point or uniform crossover and bit mutation,
// each with a probability and a "level" (decimal digits of that
// probability), and the fitness 1/(1 + e) of eq. 32 raised to a power that
// rises linearly from a start to an end value over the generations (eq. 33,
// appendix 6.2).
//
// Reproducibility: individual i of the initial population draws from
// Rng(seed, i), and offspring pair j of generation g from Rng(seed, g 2^32 + j),
// all on the calling thread; only evaluations run in parallel, each into its
// own row. The run log is therefore identical on any number of threads.
#pragma once

#include <cstddef>
#include <optional>

#include "hula/optim/problem.hpp"
#include "hula/optim/solution.hpp"

namespace hula::optim {

/// How the next population is formed.
enum class Survival {
  /// Offspring replace the parents, except the `elites` best parents, which
  /// replace the worst offspring.
  Generational,
  /// (mu + lambda): the best `population` of parents and offspring survive.
  Plus,
};

/// Options of the real-coded GA.
struct RealGaOptions {
  /// Individuals per generation; even (offspring come in pairs), >= 2. Default 100.
  std::size_t population = 100;
  /// Tournament size, 1..population (1 = random selection). Default 2.
  std::size_t tournament_size = 2;
  /// Probability that a pair is recombined by SBX, in [0, 1]. Default 0.9.
  double crossover_probability = 0.9;
  /// SBX distribution index eta_c, finite, >= 0. Default 15.
  double crossover_eta = 15.0;
  /// Per-variable SBX probability, in [0, 1]. Default 0.5.
  double crossover_variable_probability = 0.5;
  /// Per-variable mutation probability in [0, 1]; unset = 1 / dimension. Default unset.
  std::optional<double> mutation_probability{};
  /// Polynomial mutation distribution index eta_m, finite, >= 0. Default 20.
  double mutation_eta = 20.0;
  /// Survival scheme. Default Plus (elitist by construction).
  Survival survival = Survival::Plus;
  /// Parents kept by Generational survival, < population. Default 2.
  std::size_t elites = 2;
  /// Seed, threads, stop criteria, log callback, constraint handling.
  RunSettings run{};

  /// @throws hula::Error(Errc::InvalidOption) before any work, naming the
  ///   field and its value: population 0 or odd, tournament_size 0 or >
  ///   population, a probability outside [0, 1] or NaN, a negative or
  ///   non-finite eta, elites >= population, stop.max_evaluations set below
  ///   population, or invalid run settings.
  void validate() const;
};

/// Selection scheme of the binary GA.
enum class Selection { Roulette, Tournament };
/// Crossover scheme of the binary GA.
enum class BinaryCrossover { SinglePoint, Uniform };

/// Options of the binary-coded GA (appendix 2; defaults from appendix 6).
struct BinaryGaOptions {
  /// Individuals per generation; even, >= 2. Default 50 (appendix 6).
  std::size_t population = 50;
  /// Roulette wheel (thesis) or tournament. Default Roulette.
  Selection selection = Selection::Roulette;
  /// Tournament size for Selection::Tournament, 1..population. Default 2.
  std::size_t tournament_size = 2;
  /// Single-point (thesis) or uniform crossover. Default SinglePoint.
  BinaryCrossover crossover = BinaryCrossover::SinglePoint;
  /// Probability that a pair is crossed, in [0, 1]. Default 1 (appendix 6.3.2 found 1 best).
  double crossover_probability = 1.0;
  /// Decimal digits to which crossover_probability is resolved, 0..9 (0 = full
  /// resolution). Default 2 (appendix 6).
  unsigned crossover_level = 2;
  /// Per-bit mutation probability, in [0, 1]. Default 0.01 (appendix 6.3.1).
  double mutation_probability = 0.01;
  /// Decimal digits to which mutation_probability is resolved, 0..9. Default 2.
  unsigned mutation_level = 2;
  /// Fitness power at generation 0 (eq. 33), finite, > 0. Default 1 (no boost).
  double boost_start = 1.0;
  /// Fitness power at the last generation, finite, > 0. Default 1; the thesis
  /// found 1 -> 8 best (appendix 6.2).
  double boost_end = 1.0;
  /// Best parents copied unchanged into the next generation, < population. Default 1.
  std::size_t elites = 1;
  /// Seed, threads, stop criteria, log callback, constraint handling (the
  /// roulette always uses the penalised objective e = f + penalty x violation).
  RunSettings run{};

  /// @throws hula::Error(Errc::InvalidOption) before any work, naming the
  ///   field and its value: population 0 or odd, a probability outside
  ///   [0, 1], a level > 9, a boost power <= 0 or not finite, tournament_size
  ///   0 or > population, elites >= population, stop.max_evaluations set
  ///   below population, or invalid run settings.
  void validate() const;
};

/// Result of a single-objective run.
struct GaResult {
  /// Best individual seen during the run (feasibility rules or penalty).
  Solution best{};
  /// Termination reason, evaluations, failures, time.
  RunReport report{};
};

/// Runs the real-coded GA on a single-objective problem.
/// @param problem a problem with objectives == 1.
/// @param options operators, survival and run settings.
/// @returns the best solution and the run report.
/// @throws hula::Error(Errc::InvalidOption) if the problem or the options are
///   invalid or the problem has several objectives (before any evaluation).
/// @throws hula::Error(Errc::NumericalFailure) if no evaluation of the run
///   returned finite values.
/// Complexity: population x (generations + 1) evaluations; O(population log
/// population) bookkeeping per generation; no allocation per individual.
[[nodiscard]] GaResult solve_real_ga(const Problem& problem, const RealGaOptions& options = {});

/// Runs the binary-coded GA of appendix 2 on a single-objective problem whose
/// variables all have a precision.
/// @param problem a problem with objectives == 1 and every precision > 0.
/// @param options selection, crossover, mutation, boosting and run settings.
/// @returns the best solution (decoded variables) and the run report.
/// @throws hula::Error(Errc::InvalidOption) as solve_real_ga, and if a
///   variable has precision 0 or needs more than 52 bits.
/// @throws hula::Error(Errc::NumericalFailure) if no evaluation returned finite values.
[[nodiscard]] GaResult solve_binary_ga(const Problem& problem, const BinaryGaOptions& options = {});

/// The fitness of eq. 32-33: (1 / (1 + e))^power.
/// @param evaluation e >= 0, the (shifted) penalised objective.
/// @param power the boosting exponent n > 0.
/// @returns a value in (0, 1]; 0 for NaN or infinite e.
[[nodiscard]] double boosted_fitness(double evaluation, double power) noexcept;

/// The boosting power at generation g of G (eq. 33 with the linear rise of
/// appendix 6.2).
/// @param start, end powers at generation 0 and G.
/// @param generation g, 0..G.
/// @param generations G.
/// @returns start + (end - start) g / G; start when G == 0.
[[nodiscard]] double boost_power(double start, double end, std::size_t generation, std::size_t generations) noexcept;

}  // namespace hula::optim
