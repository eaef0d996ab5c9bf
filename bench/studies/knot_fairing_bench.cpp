// SPDX-License-Identifier: MIT
// Knot fairing (thesis 7.4): the cost of one objective evaluation (the
// interpolating cubic at given parameters + its energy by adaptive
// quadrature) and of whole fairing runs on 7.4.2 Example 3 (6 points).
#include <benchmark/benchmark.h>

#include <vector>

#include "hula/studies/knot_fairing.hpp"

namespace {

using hula::studies::FairingEnergy;
using hula::studies::KnotFairingSetup;

KnotFairingSetup example3(FairingEnergy energy) {
  KnotFairingSetup s;
  s.points = {{0, 0, 0}, {10, 0, 0}, {29, 0, 0}, {31, 2, 0}, {31, 31, 0}, {31, 41, 0}};
  s.dimension = 2;
  s.energy = energy;
  return s;
}

// One evaluation of the fairing objective (interpolate + energy), as the GA and the simplex call it.
void BM_FairingEnergy(benchmark::State& state) {
  const KnotFairingSetup s = example3(state.range(0) == 0 ? FairingEnergy::Bending : FairingEnergy::Variation);
  const std::vector<double> p = hula::studies::chord_length_parameters(s);
  for (auto _ : state) benchmark::DoNotOptimize(hula::studies::fairing_energy(s, p));
  state.SetItemsProcessed(state.iterations());
  state.SetLabel(state.range(0) == 0 ? "bending" : "variation");
}
BENCHMARK(BM_FairingEnergy)->Arg(0)->Arg(1);

// The deterministic optimiser from chord length to convergence.
void BM_FairKnotsDeterministic(benchmark::State& state) {
  const KnotFairingSetup s = example3(FairingEnergy::Bending);
  const std::vector<double> p = hula::studies::chord_length_parameters(s);
  for (auto _ : state) benchmark::DoNotOptimize(hula::studies::fair_knots_deterministic(s, p));
}
BENCHMARK(BM_FairKnotsDeterministic)->Unit(benchmark::kMillisecond);

// The thesis's 50 x 50 GA run, one round (no re-centring).
void BM_FairKnotsGaOneRound(benchmark::State& state) {
  const KnotFairingSetup s = example3(FairingEnergy::Bending);
  const std::vector<double> p = hula::studies::chord_length_parameters(s);
  hula::studies::GaFairingOptions o;
  o.max_recentres = 0;
  for (auto _ : state) benchmark::DoNotOptimize(hula::studies::fair_knots_ga(s, p, o));
}
BENCHMARK(BM_FairKnotsGaOneRound)->Unit(benchmark::kMillisecond);

}  // namespace
