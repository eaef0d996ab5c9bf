// SPDX-License-Identifier: MIT
// Curvature and torsion as two objectives (the thesis's 8.2.1
// discussion: "there is no facility in the GA to include a second,
// independent evaluation function"). The design variables are the free data
// coordinates of a curvature-matching problem (curvature_match.hpp) whose
// setup carries both targets; NSGA-II (optim/nsga2.hpp) minimises
//
//   f1 = mean_i |κ(u_i) − κ*(u_i)|   (eq. 31)
//   f2 = mean_i |τ(u_i) − τ*(u_i)|   over the samples where τ is defined
//
// and returns the Pareto set of curves, each with both errors. Optionally
// (`polish`) the front member with the smallest max(f1, f2) is refined by
// Levenberg–Marquardt on the stacked residuals [κ − κ*; τ − τ*] and added to
// the set: where one curve meets both targets, the GA brings it into the
// basin and the local solver reaches it.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "hula/optim/nsga2.hpp"
#include "hula/optim/run_log.hpp"
#include "hula/studies/curvature_match.hpp"
#include "hula/studies/hybrid_refine.hpp"
#include "hula/studies/match_study.hpp"
#include "hula/studies/study.hpp"

namespace hula::studies {

/// The two-objective Flexo problem (f1, f2) above (CurvatureMatch::mean_distances); one workspace per
/// thread; `match` must outlive it. A candidate whose torsion is undefined at every sample fails.
/// @throws hula::Error(Errc::InvalidArgument) if the setup has no torsion target or is planar
[[nodiscard]] optim::Problem curvature_torsion_problem(const CurvatureMatch& match);

/// Settings of the curvature + torsion study.
struct TorsionMatchSettings {
  /// NSGA-II individuals, even, >= 4. Default 100.
  std::size_t population = 100;
  /// Generations after the initial one. Default 250.
  std::size_t generations = 250;
  /// SBX crossover probability and distribution index; polynomial mutation index and
  /// per-variable probability (unset = 1 / dimension).
  double crossover_probability = 1.0;
  double crossover_eta = 20.0;
  double mutation_eta = 20.0;
  std::optional<double> mutation_probability{};
  /// Refine the best compromise by Levenberg–Marquardt on both residuals. Default true.
  bool polish = true;
  /// Weight of the torsion residuals in the polish, > 0. Default 1.
  double torsion_weight = 1.0;
  /// Levenberg–Marquardt settings of the polish.
  LmOptions lm{};
  /// Re-runs with the bounds re-centred on the best compromise while it sits on a bound (run_recentred).
  /// Default 0 = none.
  std::size_t max_recentres = 0;
  /// The map of both objectives around the best compromise, when asked for.
  std::optional<MatchMapSettings> map{};
  /// The run's deadline, shared by every round: each ends with its front so far once it passes
  /// (`--time`; not a file member). Default none.
  optim::Deadline deadline{};
  /// Cancellation token (SIGINT), not owned; the run ends with its front so far. Not a file member.
  const optim::CancellationToken* cancel = nullptr;
  /// Called with each NSGA-II generation (progress of a server job). Not a file member. Default none.
  optim::GenerationCallback on_generation{};
  /// @throws hula::Error(Errc::InvalidOption) naming `nsga2.<field>` / `lm.<field>` out of range
  void validate() const;
};

/// One curve of the Pareto set.
struct TorsionFrontMember {
  /// Design variables (the free coordinates).
  std::vector<double> variables{};
  /// Mean curvature and torsion errors.
  double curvature = 0.0;
  double torsion = 0.0;
  /// True for the member added by the polish.
  bool polished = false;
  /// Why the curve is not a valid design (CurvatureMatchSetup::validity); empty for a valid one.
  std::vector<std::string> invalid{};
};

/// Outcome of run_curvature_torsion_match.
struct TorsionMatchResult {
  /// Non-dominated curves, sorted by increasing curvature error (the polished curve included; when it
  /// matches both targets it dominates every other and the set collapses to it).
  std::vector<TorsionFrontMember> front{};
  /// NSGA-II's own first front before the polish, sorted by increasing curvature error.
  std::vector<TorsionFrontMember> nsga2_front{};
  /// Index in `front` of the best compromise (smallest max(curvature, torsion)); `front` is empty when every
  /// candidate broke the validity requirements.
  std::size_t compromise = 0;
  /// Pareto members refused as invalid designs (with TorsionFrontMember::invalid), the polished one included.
  std::vector<TorsionFrontMember> refused{};
  /// Errors of the start curve.
  double start_curvature = 0.0;
  double start_torsion = 0.0;
  /// NSGA-II report.
  optim::RunReport report{};
  /// Best curvature and torsion errors in the population after each generation.
  std::vector<double> best_curvature{}, best_torsion{};
  /// The polish report, when run.
  std::optional<LmResult> lm{};
  /// Every individual of every generation (of every round), when asked for.
  optim::RunLog log{};
  /// The design variables and bounds of the round that gave the result.
  std::vector<optim::Variable> variables{};
  /// The re-centred rounds (TorsionMatchSettings::max_recentres), the first run first; the last is the result.
  std::vector<RecentreRound> rounds{};
  /// The map (TorsionMatchSettings::map) of both objectives (SweepResult::values: curvature + proximity
  /// penalty, torsion) around the best compromise.
  std::optional<optim::SweepResult> map{};
  /// Total wall time in seconds.
  double seconds = 0.0;
};

/// Runs NSGA-II (and the optional polish) on a curvature + torsion matching problem.
/// @param match a 3-D problem with both targets
/// @param settings the algorithm settings; @param seed, threads as every Flexo run
/// @param keep_log collect every individual into the result's log
/// @throws hula::Error(Errc::InvalidArgument) if the problem has no torsion target or is planar
/// @throws hula::Error(Errc::InvalidOption) for invalid settings, map included (before any evaluation)
/// @throws hula::Error(Errc::NumericalFailure) if no candidate could be evaluated
[[nodiscard]] TorsionMatchResult run_curvature_torsion_match(const CurvatureMatch& match,
                                                             const TorsionMatchSettings& settings, std::uint64_t seed,
                                                             std::size_t threads = 1, bool keep_log = false);

/// A "match-curvature-torsion" study (docs/formats.md): everything needed to repeat a run.
struct TorsionMatchStudy {
  /// Envelope: seed and threads.
  StudyHeader header{};
  /// Points, bounds, tangents, both targets, samples (3-D only).
  CurvatureMatchSetup setup{};
  /// NSGA-II and polish settings.
  TorsionMatchSettings settings{};
};

}  // namespace hula::studies
