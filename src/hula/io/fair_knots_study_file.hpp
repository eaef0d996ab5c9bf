// SPDX-License-Identifier: MIT
// The codec of the "fair-knots" study kind (docs/formats.md, Study kind
// "fair-knots"; studies/fair_knots_study.hpp): read and checked before any
// run, and written back resolved (every default filled in) so a run can be
// repeated exactly; the energy map as CSV.
#pragma once

#include <string>

#include "hula/io/study_file.hpp"
#include "hula/studies/fair_knots_study.hpp"

namespace hula::io {

/// Reads the members of a fair-knots study document and checks everything a
/// run needs (setup, parameters, map indices, options) before any run.
/// @param document a parsed study document of kind "fair-knots"
/// @returns the study
/// @throws hula::Error(Errc::ParseError) naming the member for an unknown member, a wrong
///   type or an unknown name (energy, method, algorithm, end condition)
/// @throws hula::Error from KnotFairingSetup::validate, check_parameters,
///   EnergyMapOptions::validate and the options' validate(), naming the member
[[nodiscard]] studies::FairKnotsStudy fair_knots_study_from_json(const StudyDocument& document);

/// The resolved study (all defaults written) as a study document.
[[nodiscard]] Json fair_knots_study_to_json(const studies::FairKnotsStudy& study);

/// One evaluated parameter vector: {"parameters", "energy", "bending", "variation", "curve"} (a curve file).
[[nodiscard]] Json fairing_evaluation_to_json(const studies::ParameterEvaluation& evaluation);

/// A fairing run (GA or deterministic): its best evaluation plus "improvement" (1 − E / chord_energy, 0
/// when chord_energy is 0), "evaluations", "rounds", "seconds", "stopped", "termination" and "message" (why
/// the last optimiser run ended, optim::termination_name) and, for the GA, "bounds".
[[nodiscard]] Json fairing_result_to_json(const studies::FairingResult& result, double chord_energy);

/// A fair-knots run's result document, what every door returns (docs/formats.md): "study" (resolved),
/// "energy" (its name), "chord_length", "given"?, "map"? {"knots": [first, second], "grid", "min":
/// {"energy", "k1", "k2"}, "sections"?: [{"k1", "k2", "energy" (null where undefined)}]}, "ga"?,
/// "deterministic"? and, when both ran, "agreement" {"relative_energy": E_ga / E_det − 1, "max_parameter":
/// the largest parameter difference}.
[[nodiscard]] Json fair_knots_result_to_json(const studies::FairKnotsStudy& study,
                                             const studies::FairKnotsOutcome& outcome);

/// The energy map as CSV: header `k1,k2,energy`, one row per grid node (k1
/// fastest), the energy empty where the cell is outside k1 < k2 or failed.
/// Doubles are written to round-trip (shortest form).
[[nodiscard]] std::string energy_map_csv(const studies::EnergyMap& map);

}  // namespace hula::io
