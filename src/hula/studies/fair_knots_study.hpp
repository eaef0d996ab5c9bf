// SPDX-License-Identifier: MIT
// The "fair-knots" study file (docs/formats.md, Study kind "fair-knots"): the
// whole setup of a knot-vector study of thesis 7.2–7.4 — data points, end
// conditions, energy, method and its settings, an optional energy map and an
// optional parameter vector to evaluate — read and checked before any run,
// and written back resolved (every default filled in) so a run can be
// repeated exactly.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hula/studies/knot_fairing.hpp"
#include "hula/studies/study_file.hpp"

namespace hula::studies {

/// Which optimisers a fair-knots study runs.
enum class FairingMethod {
  None,           ///< evaluate only (chord length, the given parameters, the map)
  Ga,             ///< fair_knots_ga
  Deterministic,  ///< fair_knots_deterministic
  Both,           ///< both, for comparison
};

/// "none", "ga", "deterministic" or "both".
[[nodiscard]] std::string_view fairing_method_name(FairingMethod method) noexcept;

/// A parsed fair-knots study.
struct FairKnotsStudy {
  /// Envelope (seed, threads).
  StudyHeader header{};
  /// Points, end conditions, energy.
  KnotFairingSetup setup{};
  /// Which optimisers run. Default Both.
  FairingMethod method = FairingMethod::Both;
  /// GA settings; its seeds and threads are the header's.
  GaFairingOptions ga{};
  /// Nelder–Mead settings.
  optim::NelderMeadOptions deterministic{};
  /// The energy map, when asked for.
  std::optional<EnergyMapOptions> map{};
  /// Values of the map's first parameter at which cross sections are taken
  /// (Figures 56–57); only with a map. Default none.
  std::vector<double> sections{};
  /// A parameter vector to evaluate (the interactive evaluation of 7.2), when given.
  std::optional<std::vector<double>> parameters{};
};

/// Reads the members of a fair-knots study document and checks everything a
/// run needs (setup, parameters, map indices, options) before any run.
/// @param document a parsed study document of kind "fair-knots"
/// @returns the study
/// @throws hula::Error(Errc::ParseError) naming the member for an unknown member, a wrong
///   type or an unknown name (energy, method, algorithm, end condition)
/// @throws hula::Error from KnotFairingSetup::validate, check_parameters,
///   EnergyMapOptions::validate and the options' validate(), naming the member
[[nodiscard]] FairKnotsStudy fair_knots_study_from_json(const StudyDocument& document);

/// The resolved study (all defaults written) as a study document.
[[nodiscard]] Json fair_knots_study_to_json(const FairKnotsStudy& study);

/// The energy map as CSV: header `k1,k2,energy`, one row per grid node (k1
/// fastest), the energy empty where the cell is outside k1 < k2 or failed.
/// Doubles are written to round-trip (shortest form).
[[nodiscard]] std::string energy_map_csv(const EnergyMap& map);

}  // namespace hula::studies
