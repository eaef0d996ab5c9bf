// SPDX-License-Identifier: MIT
// The codecs of the curvature-matching study kinds (docs/formats.md):
// "match-curvature" (studies/match_study.hpp) and "match-curvature-torsion"
// (studies/curvature_torsion_match.hpp) — setups read with everything checked
// before any run, resolved setups written back so a run can be repeated
// exactly, and the run reports. Files a setup names (CSV profiles) are opened
// through the caller's PathResolver.
#pragma once

#include <span>
#include <string>

#include "hula/io/json_read.hpp"
#include "hula/io/path_resolver.hpp"
#include "hula/io/study_file.hpp"
#include "hula/studies/curvature_torsion_match.hpp"
#include "hula/studies/direct_reconstruction.hpp"
#include "hula/studies/match_seed.hpp"
#include "hula/studies/match_study.hpp"

namespace hula::io {

/// A "match-curvature" study as read, with its target as written (echoed in the resolved setup).
struct MatchStudyFile {
  studies::MatchStudy study{};
  Json target{};
};

/// A "match-curvature-torsion" study as read, with both targets as written.
struct TorsionMatchStudyFile {
  studies::TorsionMatchStudy study{};
  Json target{};
  Json torsion_target{};
};

/// The members of a curvature-matching setup, shared by the "match-curvature" and
/// "match-curvature-torsion" study kinds, with the targets as written (echoed in the resolved setup).
struct MatchSetupJson {
  studies::CurvatureMatchSetup setup{};
  Json target{};
  Json torsion_target{};
};
/// Reads points, lower, upper, start_tangent, end_tangent, samples, abscissa, target and (with_torsion)
/// torsion_target; the caller checks the members. Bounds are checked before any target is evaluated.
/// @param resolver opens the CSV files a target names
/// @throws hula::Error as match_study_from_json; with_torsion also refuses planar points and a known-curve
///   torsion target whose torsion is undefined at a sample (Errc::OutOfDomain)
[[nodiscard]] MatchSetupJson match_setup_from_json(const Json& body, const PathResolver& resolver, bool with_torsion);
/// Writes the setup's members into `out` (a study document).
void match_setup_to_json(const MatchSetupJson& setup, Json& out);
/// Reads the "lm" settings object.
/// @throws hula::Error(Errc::ParseError / InvalidOption) naming `lm.<field>`
[[nodiscard]] studies::LmOptions lm_options_from_json(const Json& value, const json::JsonPath& path);
/// The "lm" settings object.
[[nodiscard]] Json lm_options_to_json(const studies::LmOptions& options);

/// Reads a "match-curvature" study. Everything is checked before any run.
/// @param document the parsed study file (parse_study_json with kind "match-curvature")
/// @param resolver opens the CSV files a target names (relative_to the study's folder on the CLI)
/// @throws hula::Error(Errc::ParseError) naming the member for unknown members, wrong types and names
/// @throws hula::Error(Errc::NonFiniteInput / InvalidArgument / TooFewPoints) as CurvatureMatchSetup::validate
///   and for a target that is not finite at a sample
/// @throws hula::Error(Errc::InvalidOption) naming `ga.<field>` or `lm.<field>` for settings out of range
[[nodiscard]] MatchStudyFile match_study_from_json(const StudyDocument& document, const PathResolver& resolver);
/// The resolved study as a study file (seed included), so the run can be repeated exactly.
[[nodiscard]] Json match_study_to_json(const MatchStudyFile& file);
/// The run's report: start/best points, distances before/after (after GA / after LM for hybrid), evaluations
/// (every round's), time, the curve as a curve document, "on_bound" / "warnings" (against the box of the round
/// that gave the result), "rounds" (the re-centred re-runs), "map" (with a map member) and the resolved setup under
/// "study".
[[nodiscard]] Json match_result_to_json(const studies::CurvatureMatch& match, const MatchStudyFile& file,
                                        const studies::MatchResult& result);

/// Reads a "match-curvature-torsion" study; everything is checked before any run.
/// @throws hula::Error as match_setup_from_json (with torsion) and Errc::ParseError / InvalidOption naming
///   `nsga2.<field>`, `polish`, `torsion_weight` or `lm.<field>`
[[nodiscard]] TorsionMatchStudyFile torsion_match_study_from_json(const StudyDocument& document,
                                                                  const PathResolver& resolver);
/// The resolved study as a study file (seed included).
[[nodiscard]] Json torsion_match_study_to_json(const TorsionMatchStudyFile& file);
/// A "match-curvature-torsion" study file seeded from a curve (studies::seed_match_setup, "From selection"):
/// the seed's points, bounds, end tangents and samples, its κ and τ profiles as {"samples": [[u, v], ...]}
/// targets, abscissa "arclength", and `settings` (seed 1, one thread). It reads back with
/// torsion_match_study_from_json.
/// @throws hula::Error(Errc::InvalidArgument) naming "curve" if the seed is planar (it has no torsion target)
[[nodiscard]] Json seeded_torsion_study_to_json(const studies::MatchSeed& seed,
                                                const studies::TorsionMatchSettings& settings);
/// seeded_torsion_study_to_json of studies::seed_match_setup(curve): what the server's study-seed route answers.
/// @throws as studies::seed_match_setup and seeded_torsion_study_to_json
[[nodiscard]] Json seeded_torsion_study_to_json(const curve::Curve& curve,
                                                const studies::TorsionMatchSettings& settings);
/// The run's report: both start errors, the Pareto set (points and both errors of every curve, the best
/// compromise marked, its curve as a curve document), NSGA-II and polish reports, and the resolved study.
[[nodiscard]] Json torsion_match_result_to_json(const studies::CurvatureMatch& match, const TorsionMatchStudyFile& file,
                                                const studies::TorsionMatchResult& result);

/// A matching study's fitness map as CSV: header `x,y,<objectives...>`, one row per grid node (x fastest), a
/// value empty where the evaluation failed; doubles written to round-trip (shortest form).
/// @param objectives one name per objective of the mapped problem
[[nodiscard]] std::string match_map_csv(const optim::SweepResult& map, std::span<const std::string> objectives);

/// A JSON summary of a direct reconstruction for the CLI and study logs: planar, length, end errors,
/// profile deviations, iterations, reconstructions, seconds, the correction coefficients, and the
/// NURBS (degree, control point count, max_deviation, converged) when fitted.
[[nodiscard]] Json direct_reconstruction_summary(const studies::DirectReconstructionResult& result);

}  // namespace hula::io
