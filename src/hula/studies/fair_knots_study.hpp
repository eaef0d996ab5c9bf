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

}  // namespace hula::studies
