// SPDX-License-Identifier: MIT
#include "hula/studies/fair_knots_study.hpp"

namespace hula::studies {

std::string_view fairing_method_name(FairingMethod method) noexcept {
  switch (method) {
    case FairingMethod::None:
      return "none";
    case FairingMethod::Ga:
      return "ga";
    case FairingMethod::Deterministic:
      return "deterministic";
    case FairingMethod::Both:
      break;
  }
  return "both";
}

const FairingResult* FairKnotsOutcome::best() const noexcept {
  const FairingResult* best = ga ? &*ga : nullptr;
  if (deterministic && (best == nullptr || deterministic->best.energy < best->best.energy)) best = &*deterministic;
  return best;
}

FairKnotsOutcome run_fair_knots_study(const FairKnotsStudy& study, optim::RunLog* log) {
  const KnotFairingSetup& setup = study.setup;
  FairKnotsOutcome out;
  const std::vector<double> chord = chord_length_parameters(setup);
  out.chord_length = evaluate_parameters(setup, chord);
  if (study.parameters) out.given = evaluate_parameters(setup, *study.parameters);
  if (study.map) {
    out.map = energy_map(setup, chord, *study.map);
    // 201 nodes: smooth cross-section curves (Figures 56-57) for about 200 spline evaluations each.
    constexpr std::size_t kSectionNodes = 201;
    for (const double k1 : study.sections)
      out.sections.push_back(map_section(setup, chord, *study.map, k1, kSectionNodes));
  }
  if (study.method == FairingMethod::Ga || study.method == FairingMethod::Both)
    out.ga = fair_knots_ga(setup, chord, study.ga, log);
  if (study.method == FairingMethod::Deterministic || study.method == FairingMethod::Both)
    out.deterministic = fair_knots_deterministic(setup, chord, study.deterministic);
  return out;
}

}  // namespace hula::studies
