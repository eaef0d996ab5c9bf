// SPDX-License-Identifier: MIT
// The "fair-knots" study setup: the whole setup of a knot-vector study of
// thesis 7.2–7.4 — data points, end conditions, energy, method and its
// settings, an optional energy map and an optional parameter vector to
// evaluate. Its file form (docs/formats.md, Study kind "fair-knots") is
// io/fair_knots_study_file.hpp.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hula/studies/knot_fairing.hpp"
#include "hula/studies/study.hpp"

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

/// What a fair-knots study gives (run_fair_knots_study).
struct FairKnotsOutcome {
  /// The chord-length parameters (eq. 29) and their curve: the start of both optimisers.
  ParameterEvaluation chord_length{};
  /// The study's own parameters evaluated, when it gives some.
  std::optional<ParameterEvaluation> given{};
  /// The energy map around the chord-length parameters, when asked for.
  std::optional<EnergyMap> map{};
  /// Its cross sections at the study's `sections` values (201 nodes each).
  std::vector<MapSection> sections{};
  /// The GA's and the deterministic optimiser's results, as the method asks.
  std::optional<FairingResult> ga{}, deterministic{};
  /// The optimum of lower energy (the deterministic one when it is strictly lower, else the GA's); null when
  /// no optimiser ran.
  [[nodiscard]] const FairingResult* best() const noexcept;
};

/// Runs a fair-knots study (thesis 7.2–7.4): the chord-length start, the given parameters, the energy map
/// and its sections (evaluations of the setup: their errors come before any optimiser runs), then the GA
/// and/or Nelder–Mead from the chord-length parameters, as `study.method` says.
/// @param log when not null, receives every generation of the GA (all its rounds)
/// @throws as check_parameters, energy_map, map_section, fair_knots_ga and fair_knots_deterministic
[[nodiscard]] FairKnotsOutcome run_fair_knots_study(const FairKnotsStudy& study, optim::RunLog* log = nullptr);

}  // namespace hula::studies
