// SPDX-License-Identifier: MIT
// The "match-curvature" study (thesis 8.2.1, appendix 5):
// settings of the GA, hybrid and direct routes and the run. The study file kind
// "match-curvature" (docs/formats.md) is read and written by io/match_study_file.hpp.
//
// Methods: "ga" runs Flexo's binary GA (thesis: roulette, single-point
// crossover, power boost 3 -> 5, appendix 5) or the real-coded GA; "hybrid"
// runs the same GA and then refine_levenberg_marquardt on the best. A third
// method is one more MatchMethod value, one name in match_method_from_name and
// one case in run_curvature_match.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hula/optim/ga.hpp"
#include "hula/optim/run_log.hpp"
#include "hula/optim/sweep.hpp"
#include "hula/studies/curvature_match.hpp"
#include "hula/studies/direct_reconstruction.hpp"
#include "hula/studies/hybrid_refine.hpp"
#include "hula/studies/study.hpp"

namespace hula::studies {

/// How the study is solved.
enum class MatchMethod {
  /// GA alone (thesis 8.2.1).
  Ga,
  /// GA, then Levenberg–Marquardt on the residuals.
  Hybrid,
  /// No search: the natural-equation solver integrates the target profile (as an arc-length profile)
  /// from the start point and frame, optionally held to the end point / end tangent
  /// (direct_reconstruction.hpp).
  Direct,
};

/// "ga" | "hybrid" | "direct".
[[nodiscard]] std::string_view match_method_name(MatchMethod m) noexcept;
/// @throws hula::Error(Errc::ParseError) naming `field` and the accepted names for any other name
[[nodiscard]] MatchMethod match_method_from_name(std::string_view name, std::string_view field);

/// GA settings of the study.
struct MatchGaSettings {
  /// Binary-coded (thesis) or real-coded GA.
  enum class Algorithm {
    Binary,  ///< solve_binary_ga: the thesis's coding, roulette and power boost
    Real,    ///< solve_real_ga: SBX and polynomial mutation
  };
  Algorithm algorithm = Algorithm::Binary;
  /// Individuals per generation, even, >= 2. Default 50 (thesis).
  std::size_t population = 50;
  /// Generations after the initial one. Default 50 (thesis).
  std::size_t generations = 50;
  /// Fitness power at the first and last generation (binary GA; appendix 5: 3 -> 5).
  double boost_start = 3.0;
  double boost_end = 5.0;
  /// Crossover probability. Default 1 (appendix 6.3.2).
  double crossover_probability = 1.0;
  /// Mutation probability: per bit (binary) or per variable (real; unset there = 1 / dimension). Default 0.01.
  std::optional<double> mutation_probability{};
  /// Binary coding resolution in model units, > 0. Default 1e-3.
  double precision = 1e-3;
  /// Roulette (thesis) or tournament selection for the binary GA.
  optim::Selection selection = optim::Selection::Roulette;
  /// Put the start design into the initial population (thesis 10.1.1, optim::RunSettings::initial). Default false.
  bool seed_start = false;
  /// Return the best `distinct` mutually distinct designs the GA evaluated (optim::distinct_best); 0 = none
  /// (default).
  std::size_t distinct = 0;
  /// Their niche radius (normalised by the bounds), in (0, 1]. Default 0.05.
  double distinct_radius = 0.05;
};

/// Settings of the direct method.
struct MatchDirectSettings {
  /// Curve length L; unset = the arc length of the spline through the start points.
  std::optional<double> length{};
  /// Hold the reconstructed curve's end at the last data point (boundary-value version). Default false.
  bool end_point = false;
  /// Hold its end tangent at the study's end_tangent (which must then be given). Default false.
  bool end_tangent = false;
  /// Degree of the Bernstein correction of the profile when an end is held. Default 5.
  int correction_degree = 5;
  /// Let the length vary too when an end is held (the profile fixes the shape, not the size). Default false.
  bool vary_length = false;
  /// Weight of (ΔL / L)² against the correction when the length varies; > 0. Default 1.
  double length_weight = 1.0;
  /// End tolerance relative to L (DirectReconstructionOptions::end_tolerance). Default 1e-9; sampled
  /// (piecewise-linear) targets integrate to about 1e-7 relative, so they need about 1e-6.
  double end_tolerance = 1e-9;
};

/// A design variable within this fraction of its box width from a bound is reported "on the bound" and starts
/// a re-centred round: a GA's best pressing against a bound rarely lands exactly on it (Example
/// 3's GA stops at x = 49.8 of 50 with a box of 20).
inline constexpr double kOnBoundFraction = 0.02;

/// The variables of x on a bound of `variables` (optim::bound_hits with kOnBoundFraction).
[[nodiscard]] std::vector<optim::BoundHit> match_bound_hits(std::span<const optim::Variable> variables,
                                                            std::span<const double> x);

/// One round of the re-centred re-runs (thesis 7.4.1, 8.2.1): round 0 is the run on the study's own bounds.
struct RecentreRound {
  /// The round's design variables and bounds (round k > 0: centred on round k − 1's result, same widths).
  std::vector<optim::Variable> variables{};
  /// The round's result (the best design; the best compromise of the curvature + torsion study).
  std::vector<double> best{};
  /// Its distances from the targets.
  MatchDistances after{};
  /// Its variables on a bound of this round's box (match_bound_hits).
  std::vector<optim::BoundHit> on_bound{};
  /// Fitness evaluations of the round.
  std::size_t evaluations = 0;
};

/// What one round of run_recentred reports back.
struct RoundOutcome {
  /// The round's result in the design variables of the round's problem.
  std::vector<double> best{};
  /// Its fitness evaluations.
  std::size_t evaluations = 0;
  /// The round was cut short (wall time, cancellation): no further round runs.
  bool stopped = false;
};

/// The setup re-centred on design x (thesis 7.4.1): the data points moved to x, the offsets (the box widths) and
/// everything else kept; the proximity regularisation still pulls towards the original start
/// (CurvatureMatchSetup::proximity_centre).
/// @param x match.dimension() values
[[nodiscard]] CurvatureMatchSetup recentred_setup(const CurvatureMatch& match, std::span<const double> x);

/// The re-centred re-runs of thesis 7.4.1: runs `run` on `match`; while the round's result sits on a bound
/// (match_bound_hits) and fewer than `max_recentres` re-runs have been made, runs it again on the problem
/// re-centred on that result (recentred_setup: same widths, free to leave the first box, which is what the
/// thesis's remedy needs; optim::rerun_recentred shrinks inside the first box instead), unless the round was
/// stopped (RoundOutcome::stopped). The free coordinates are
/// the same in every round, so each round's design variables are the first problem's.
/// @param run runs one round on the given problem (valid during the call) with its round number (0 first)
/// @returns every round, the first one first; the last round's result is the study's
[[nodiscard]] std::vector<RecentreRound> run_recentred(
    const CurvatureMatch& match, std::size_t max_recentres,
    const std::function<RoundOutcome(const CurvatureMatch&, std::size_t round)>& run);

/// A fitness map over two design variables with the others held at the result (thesis appendix 6.1, 8.2.1
/// "fitness function test"; the match studies' `map` member).
struct MatchMapSettings {
  /// Names of the two mapped variables (CurvatureMatch::variables(), e.g. "points[2].x"): columns, rows.
  std::array<std::string, 2> variables{};
  /// Samples per axis, 2 … 500 (bounds included). Default 21.
  std::size_t grid = 21;
  /// Ranges of the two variables; unset = the bounds of the round that gave the result.
  std::optional<std::array<double, 2>> from{}, to{};

  /// The indices of the two variables.
  /// @throws hula::Error(Errc::InvalidOption) naming `map.variables[k]` (with the names there are) for an
  ///   unknown or repeated name, `map.grid` out of range, `map.from` / `map.to` not finite
  [[nodiscard]] std::array<std::size_t, 2> axes(std::span<const optim::Variable> candidates) const;
};

/// The map: optim::sweep of `problem` (the study's fitness problem with the result's box as its bounds) over the
/// two variables, the others at `at`.
/// @throws hula::Error(Errc::InvalidOption) as MatchMapSettings::axes
[[nodiscard]] optim::SweepResult match_fitness_map(const optim::Problem& problem, std::span<const double> at,
                                                   const MatchMapSettings& settings, std::size_t threads);

/// A complete study: everything needed to repeat a run.
struct MatchStudy {
  /// Envelope: seed and threads.
  StudyHeader header{};
  /// Points, bounds, tangents, target, samples.
  CurvatureMatchSetup setup{};
  /// ga | hybrid.
  MatchMethod method = MatchMethod::Ga;
  /// GA settings.
  MatchGaSettings ga{};
  /// Levenberg–Marquardt settings (hybrid).
  LmOptions lm{};
  /// Direct-method settings.
  MatchDirectSettings direct{};
  /// Re-runs with the bounds re-centred on a result that sits on a bound (run_recentred; GA and hybrid
  /// methods). Default 0 = none.
  std::size_t max_recentres = 0;
  /// The fitness map around the result, when asked for.
  std::optional<MatchMapSettings> map{};
};

/// Outcome of a run.
struct MatchResult {
  /// Start and best design variables (the free coordinates), and the GA's best. For the hybrid method, best is
  /// the LM result unless that has a larger mean distance (eq. 31) than the GA's best (LM minimises squares).
  std::vector<double> start{}, ga_best{}, best{};
  /// Distances at the start, after the GA and at the end.
  MatchDistances before{}, after_ga{}, after{};
  /// GA report (generations, evaluations, seconds).
  optim::RunReport ga_report{};
  /// Best mean distance so far after each generation (generation 0 first).
  std::vector<double> convergence{};
  /// The LM report for the hybrid method.
  std::optional<LmResult> lm{};
  /// Where the hybrid's refinement started: "ga" (the GA's best) or "direct" (LmOptions::direct_start).
  std::string lm_start{};
  /// The reconstruction of the direct method (no GA runs then: start, best and the distances
  /// are those of the start points, the direct curve's own errors are in here).
  std::optional<DirectReconstructionResult> direct{};
  /// The direct method's curve at the data points' abscissae (each start point's arc-length fraction on the
  /// start spline, times the reconstructed length); empty for the GA routes.
  std::vector<Vec3> direct_points{};
  /// Every individual of every generation, when asked for.
  optim::RunLog log{};
  /// The best mutually distinct designs of the GA (MatchGaSettings::distinct), best first.
  std::vector<optim::Solution> distinct{};
  /// The design variables and bounds of the round that gave `best` (the study's own without re-centring).
  std::vector<optim::Variable> variables{};
  /// The re-centred rounds (MatchStudy::max_recentres), the first run first; empty for the direct method.
  std::vector<RecentreRound> rounds{};
  /// The fitness map (MatchStudy::map) of the GA's objective (mean distance + proximity penalty) around `best`.
  std::optional<optim::SweepResult> map{};
  /// The validity of `best` (the direct route: of its curve) when the setup requires something
  /// (CurvatureMatchSetup::validity); an invalid one is refused by the study's report with these reasons.
  std::optional<ValidityCheck> validity{};
  /// Total wall time in seconds.
  double seconds = 0.0;
};

/// Runs the study's method on the problem.
/// @param match the problem (built from study.setup)
/// @param study method and settings; header.seed and header.threads are used
/// @param keep_log collect every individual into MatchResult::log (every round's)
/// @throws hula::Error(Errc::InvalidOption) for invalid GA, LM or map settings (before any evaluation)
/// @throws hula::Error(Errc::NumericalFailure) if no candidate could be evaluated
/// @note with validity requirements the GA prefers valid designs (CurvatureMatchSetup::validity), the start
///   replaces the GA's best and the refinement replaces it only when that keeps or gains validity, and
///   `validity` reports the result's; the report refuses an invalid result.
[[nodiscard]] MatchResult run_curvature_match(const CurvatureMatch& match, const MatchStudy& study,
                                              bool keep_log = false);

/// The curve a run found, as a value: the direct method's NURBS fit (none when it made no fit), or the
/// spline through the best data points (MatchResult::best) for the GA and hybrid methods; none when the
/// result is refused as a design (MatchResult::validity not valid).
[[nodiscard]] std::optional<nurbs::NurbsCurve> match_result_curve(const CurvatureMatch& match,
                                                                  const MatchResult& result);

}  // namespace hula::studies
