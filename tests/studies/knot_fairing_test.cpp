// SPDX-License-Identifier: MIT
// Tests of the knot-vector studies (thesis 7.2–7.4): energies against closed
// forms, the thesis's chord lengths, the symmetry and smoothness of the energy
// map of 7.3 Example 1, the 7.4.1 bounds, and on every thesis example that the
// optimisers never end above the chord-length energy and that the GA and the
// deterministic optimiser agree.
#include "hula/studies/knot_fairing.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/optim/run_log.hpp"
#include "hula/optim/run_report.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::studies {
namespace {

KnotFairingSetup planar(std::vector<Vec3> points, FairingEnergy energy = FairingEnergy::Bending) {
  KnotFairingSetup s;
  s.points = std::move(points);
  s.dimension = 2;
  s.energy = energy;
  return s;
}

// The thesis's examples.
const std::vector<Vec3> kExample72_1{{0, 0, 0}, {40, 25, 0}, {80, -25, 0}, {120, 0, 0}};
const std::vector<Vec3> kExample73_2{{0, 0, 0}, {40, 25, 0}, {80, -40, 0}, {120, 0, 0}};
const std::vector<Vec3> kExample74_1{{0, 0, 0}, {100, 0, 0}, {100, 100, 0}};
const std::vector<Vec3> kExample74_2{{0, 0, 0}, {50, 0, 0}, {100, 0, 0}, {100, 50, 0}, {100, 100, 0}};
const std::vector<Vec3> kExample74_3{{0, 0, 0}, {10, 0, 0}, {29, 0, 0}, {31, 2, 0}, {31, 31, 0}, {31, 41, 0}};

// checks: eq. 29 on 7.2 Example 1 gives the thesis's cumulative chords 47.17 / 111.20 / 158.37, as ratios of 1
TEST(StudiesKnotFairing, ChordLengthStartMatchesThesis) {
  const std::vector<double> p = chord_length_parameters(planar(kExample72_1));
  ASSERT_EQ(p.size(), 4u);
  const double total = 2.0 * std::hypot(40.0, 25.0) + std::hypot(40.0, 50.0);
  EXPECT_NEAR(total, 158.37, 0.005);
  EXPECT_DOUBLE_EQ(p[0], 0.0);
  EXPECT_NEAR(p[1] * total, 47.17, 0.005);
  EXPECT_NEAR(p[2] * total, 111.20, 0.005);
  EXPECT_DOUBLE_EQ(p[3], 1.0);
  // 7.4.2 Example 3's chord vector, printed by the thesis as {0, 0.14, 0.4, 0.44, 0.85, 1}.
  const std::vector<double> q = chord_length_parameters(planar(kExample74_3));
  const std::vector<double> thesis{0, 0.14, 0.4, 0.44, 0.85, 1};
  for (std::size_t i = 0; i < q.size(); ++i) EXPECT_NEAR(q[i], thesis[i], 0.01) << i;
}

// checks: collinear points give a straight interpolant at any parameters, so both energies are 0
TEST(StudiesKnotFairing, StraightLineHasZeroEnergy) {
  const KnotFairingSetup s = planar({{0, 0, 0}, {1, 2, 0}, {3, 6, 0}, {4, 8, 0}});
  const std::vector<double> p{0.0, 0.1, 0.7, 1.0};
  const ParameterEvaluation e = evaluate_parameters(s, p);
  EXPECT_NEAR(e.bending, 0.0, 1e-12);
  EXPECT_NEAR(e.variation, 0.0, 1e-12);
}

// checks: the clamped spline through points of y = x^2 at t = x reproduces the parabola, whose bending
// energy is 2a [u(2u^2 + 3) / (3 (1 + u^2)^(3/2))] from u = 0 to 2a (a = 1, x in [0, 1])
TEST(StudiesKnotFairing, ParabolaBendingEnergyClosedForm) {
  KnotFairingSetup s = planar({{0, 0, 0}, {0.3, 0.09, 0}, {0.55, 0.3025, 0}, {1, 1, 0}});
  s.start = nurbs::EndCondition::clamped({1, 0, 0});
  s.end = nurbs::EndCondition::clamped({1, 2, 0});
  const std::vector<double> p{0.0, 0.3, 0.55, 1.0};
  const ParameterEvaluation e = evaluate_parameters(s, p);
  const double u = 2.0;
  const double exact = 2.0 * u * (2.0 * u * u + 3.0) / (3.0 * std::pow(1.0 + u * u, 1.5));
  EXPECT_NEAR(e.bending, exact, 1e-9 * exact);
  // dκ/ds = -24 a^3 x / (1 + 4a^2x^2)^3; ∫(dκ/ds)^2 ds = ∫ 576 x^2 / (1 + 4x^2)^(11/2) dx on [0, 1]:
  // integrated here by composite Simpson with 20000 panels (error ~1e-14).
  double variation = 0.0;
  const int n = 20000;
  for (int i = 0; i <= n; ++i) {
    const double x = static_cast<double>(i) / n;
    const double w = (i == 0 || i == n) ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
    variation += w * 576.0 * x * x / std::pow(1.0 + 4.0 * x * x, 5.5);
  }
  variation /= 3.0 * n;
  EXPECT_NEAR(e.variation, variation, 1e-8 * variation);
  EXPECT_EQ(e.energy, e.bending);
}

// checks: 7.3 Example 1 is symmetric (point reflection + reversal), so E(k1, k2) = E(1 - k2, 1 - k1) on the map
TEST(StudiesKnotFairing, EnergyMapSymmetricOnExample1) {
  const KnotFairingSetup s = planar(kExample72_1);
  const std::vector<double> base = chord_length_parameters(s);
  const EnergyMap m = energy_map(s, base, {.first = 1, .second = 2, .grid = 21});
  ASSERT_EQ(m.k1.size(), 21u);
  std::size_t finite = 0;
  for (std::size_t j = 0; j < 21; ++j) {
    for (std::size_t i = 0; i < 21; ++i) {
      const double e = m.energy[j * 21 + i];
      // Node symmetry: 1 - k1[i] = k2[20 - i].
      EXPECT_NEAR(1.0 - m.k1[i], m.k2[20 - i], 1e-15);
      if (!(m.k1[i] < m.k2[j])) {
        EXPECT_TRUE(std::isnan(e)) << i << "," << j;
        continue;
      }
      ++finite;
      const double mirror = m.energy[(20 - i) * 21 + (20 - j)];
      EXPECT_NEAR(e, mirror, 1e-8 * e) << i << "," << j;
    }
  }
  EXPECT_EQ(finite, 21u * 20u / 2u);
  // The map's minimum lies on the symmetry line k1 + k2 = 1 near the deterministic optimum (0.3224, 0.6776).
  EXPECT_NEAR(m.min_k1 + m.min_k2, 1.0, 1e-12);
  EXPECT_NEAR(m.min_k1, 0.3224, 0.05);
}

// checks: unlike the thesis's ACIS map (Figures 56-57), the cross sections at k1 = 0.2 and 0.4 are smooth
// and monotone through k2 = 0.8 and 0.6 (k1 + k2 = 1): no drop of energy
TEST(StudiesKnotFairing, NoDropOfEnergyWhereKnotsAddUpToOne) {
  const KnotFairingSetup s = planar(kExample72_1);
  for (const double k1 : {0.2, 0.4}) {
    std::vector<double> base{0.0, k1, 0.5 * (k1 + 1.0), 1.0};
    const double centre = 1.0 - k1;
    const double h = 0.005;
    std::vector<double> k2;
    for (int i = -3; i <= 3; ++i) k2.push_back(centre + i * h);
    const std::vector<double> e = energy_section(s, base, 2, k2);
    // Monotone through the centre (rising at k1 = 0.2, falling at k1 = 0.4).
    const double direction = k1 < 0.3 ? 1.0 : -1.0;
    for (std::size_t i = 1; i < e.size(); ++i) EXPECT_GT(direction * (e[i] - e[i - 1]), 0.0) << k1 << " " << k2[i];
    // Second differences vary smoothly: the one centred on k1 + k2 = 1 is the mean of its neighbours within 5 %.
    auto d2 = [&](std::size_t i) { return e[i - 1] - 2.0 * e[i] + e[i + 1]; };
    const double mean = 0.5 * (d2(2) + d2(4));
    EXPECT_GT(d2(3), 0.0);
    EXPECT_NEAR(d2(3), mean, 0.05 * std::abs(mean)) << k1;
  }
}

// checks: a map section at a grid node's k1 with as many nodes as the grid reproduces that column of the map,
// and a k1 outside the map's range is refused
TEST(StudiesKnotFairing, MapSectionIsAMapColumn) {
  const KnotFairingSetup s = planar(kExample73_2);
  const std::vector<double> base = chord_length_parameters(s);
  const EnergyMapOptions o{.first = 1, .second = 2, .grid = 9};
  const EnergyMap m = energy_map(s, base, o);
  const MapSection sec = map_section(s, base, o, m.k1[3], 9);
  for (std::size_t j = 0; j < 9; ++j) {
    EXPECT_EQ(sec.k2[j], m.k2[j]);
    const double e = m.energy[j * 9 + 3];
    if (std::isnan(e)) {
      EXPECT_TRUE(std::isnan(sec.energy[j])) << j;
    } else {
      EXPECT_EQ(sec.energy[j], e) << j;
    }
  }
  HULA_EXPECT_ERROR((void)map_section(s, base, o, 1.0, 9), Errc::InvalidArgument, "section k1 = 1 is outside");
}

// checks: the 7.4.1 bounds of 7.4.2 Example 3's chord parameters follow the thesis's listing and do not overlap
TEST(StudiesKnotFairing, BoundsFollowSection741) {
  const std::vector<double> p{0.0, 0.1, 0.4, 0.5, 0.8, 1.0};
  const KnotBounds b = knot_bounds(p, 1e-6);
  ASSERT_EQ(b.lower.size(), 4u);
  EXPECT_DOUBLE_EQ(b.lower[0], 1e-6);
  EXPECT_DOUBLE_EQ(b.upper[0], 0.25 - 1e-6);
  EXPECT_DOUBLE_EQ(b.lower[1], 0.25 + 1e-6);
  EXPECT_DOUBLE_EQ(b.upper[1], 0.45 - 1e-6);
  EXPECT_DOUBLE_EQ(b.lower[2], 0.45 + 1e-6);
  EXPECT_DOUBLE_EQ(b.upper[2], 0.65 - 1e-6);
  EXPECT_DOUBLE_EQ(b.lower[3], 0.65 + 1e-6);
  EXPECT_DOUBLE_EQ(b.upper[3], 1.0 - 1e-6);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_LT(b.lower[i], p[i + 1]);
    EXPECT_GT(b.upper[i], p[i + 1]);
  }
  HULA_EXPECT_ERROR((void)knot_bounds(std::vector<double>{0.0, 0.5, 0.5 + 1e-6, 1.0}, 1e-6), Errc::InvalidArgument,
                    "bounds of parameters[1] = 0.5 do not contain it");
}

// checks: log-ratio coordinates round-trip and give strictly increasing parameters for any y
TEST(StudiesKnotFairing, LogRatioTransformRoundTrips) {
  const std::vector<double> p{0.0, 0.14, 0.4, 0.44, 0.85, 1.0};
  const std::vector<double> back = log_ratios_to_parameters(widths_to_log_ratios(p));
  for (std::size_t i = 0; i < p.size(); ++i) EXPECT_NEAR(back[i], p[i], 1e-15) << i;
  const std::vector<double> wild = log_ratios_to_parameters(std::vector<double>{-30.0, 40.0, 0.0});
  EXPECT_EQ(wild.front(), 0.0);
  EXPECT_EQ(wild.back(), 1.0);
  for (std::size_t i = 1; i < wild.size(); ++i) EXPECT_GE(wild[i], wild[i - 1]);
}

// checks: 7.4.2 Example 1 is symmetric about the corner's diagonal, so the bending optimum is p1 = 0.5, the
// chord-length value (the thesis: "the minimum energy is in the region of 0.5")
TEST(StudiesKnotFairing, CornerExample1OptimumIsChordLength) {
  const KnotFairingSetup s = planar(kExample74_1);
  const std::vector<double> chord = chord_length_parameters(s);
  EXPECT_DOUBLE_EQ(chord[1], 0.5);
  const FairingResult d = fair_knots_deterministic(s, chord);
  EXPECT_NEAR(d.best.parameters[1], 0.5, 1e-6);
  const std::vector<double> other{0.0, 0.4, 1.0};
  EXPECT_GT(evaluate_parameters(s, other).energy, d.best.energy);
}

// checks: the deterministic optimiser's progress (7.4.2 Example 3, bending) is in the study's terms and only
// reads: the result is bit-identical with and without a callback; generations count 0, 1, 2, ... with
// evaluations growing and a best that never rises; every reported vertex is a parameter vector whose energy,
// evaluated anew, is the reported value; the last generation's best is the result's energy at the result's
// parameters. A callback that cancels the token at generation 5 ends the run there with the best so far.
TEST(StudiesKnotFairing, DeterministicProgressIsInTheStudysTerms) {
  const KnotFairingSetup s = planar(kExample74_3);
  const std::vector<double> chord = chord_length_parameters(s);
  const FairingResult plain = fair_knots_deterministic(s, chord);
  std::vector<optim::GenerationLog> seen;
  optim::NelderMeadOptions o;
  o.on_generation = [&](const optim::GenerationLog& g) { seen.push_back(g); };
  const FairingResult watched = fair_knots_deterministic(s, chord, o);
  EXPECT_EQ(watched.best.parameters, plain.best.parameters);
  EXPECT_EQ(watched.best.energy, plain.best.energy);
  EXPECT_EQ(watched.convergence, plain.convergence);
  EXPECT_EQ(watched.evaluations, plain.evaluations);
  EXPECT_EQ(watched.termination, plain.termination);
  EXPECT_EQ(watched.message, plain.message);
  ASSERT_EQ(seen.size(), plain.convergence.size() + 1);
  for (std::size_t i = 0; i < seen.size(); ++i) {
    const optim::GenerationLog& g = seen[i];
    ASSERT_EQ(g.generation, i);
    ASSERT_EQ(g.dimension, chord.size() - 2);
    ASSERT_EQ(g.size(), g.dimension + 1);
    if (i > 0) {
      EXPECT_GE(g.evaluations, seen[i - 1].evaluations);
      EXPECT_LE(optim::statistics(g).best, optim::statistics(seen[i - 1]).best);
    }
  }
  for (const std::size_t i : {std::size_t{0}, seen.size() / 2, seen.size() - 1}) {
    const optim::GenerationLog& g = seen[i];
    for (std::size_t k = 0; k < g.size(); ++k) {
      std::vector<double> p{0.0};
      p.insert(p.end(), g.variables.begin() + static_cast<std::ptrdiff_t>(k * g.dimension),
               g.variables.begin() + static_cast<std::ptrdiff_t>((k + 1) * g.dimension));
      p.push_back(1.0);
      EXPECT_NEAR(g.objective_values[k], evaluate_parameters(s, p).energy, 1e-12 * plain.best.energy);
    }
  }
  const optim::GenerationLog& last = seen.back();
  EXPECT_EQ(last.evaluations + 1, plain.evaluations);  // the start's energy, E_start, is the one more
  EXPECT_DOUBLE_EQ(optim::statistics(last).best, plain.best.energy);
  const std::size_t lo = static_cast<std::size_t>(
      std::min_element(last.objective_values.begin(), last.objective_values.end()) - last.objective_values.begin());
  for (std::size_t i = 0; i < last.dimension; ++i)
    EXPECT_EQ(last.variables[lo * last.dimension + i], plain.best.parameters[i + 1]);

  optim::CancellationToken token;
  std::size_t calls = 0;
  o.cancel = &token;
  o.on_generation = [&](const optim::GenerationLog& g) {
    ++calls;
    if (g.generation == 5) token.cancel();
  };
  const FairingResult stopped = fair_knots_deterministic(s, chord, o);
  EXPECT_EQ(stopped.termination, optim::Termination::Cancelled);
  EXPECT_EQ(calls, 7u);  // generations 0..5, then the final simplex
  EXPECT_EQ(stopped.convergence.size(), 6u);
  EXPECT_LE(stopped.best.energy, evaluate_parameters(s, chord).energy);
  EXPECT_GT(stopped.best.energy, plain.best.energy);
}

// checks: the GA reports its generations in the study's terms as the deterministic optimiser does (not its
// own objective E / E_start): every round's generations reach the callback and the log alike (the same logs),
// each reported objective value being the energy, evaluated anew, at the reported parameters; the convergence
// graph is the running minimum of the start's energy and the generations' bests; the result is bit-identical
// with and without the callback and log
TEST(StudiesKnotFairing, GaProgressIsInTheStudysTerms) {
  const KnotFairingSetup s = planar(kExample73_2);
  const std::vector<double> chord = chord_length_parameters(s);
  const double e0 = evaluate_parameters(s, chord).energy;
  GaFairingOptions o;
  o.real.population = 12;
  o.real.run.stop.generations = 6;
  o.real.run.seed = 2;
  const FairingResult plain = fair_knots_ga(s, chord, o);
  std::vector<optim::GenerationLog> seen;
  o.real.run.on_generation = [&](const optim::GenerationLog& g) { seen.push_back(g); };
  optim::RunLog log;
  const FairingResult watched = fair_knots_ga(s, chord, o, &log);
  EXPECT_EQ(watched.best.parameters, plain.best.parameters);
  EXPECT_EQ(watched.best.energy, plain.best.energy);
  EXPECT_EQ(watched.convergence, plain.convergence);
  ASSERT_EQ(seen.size(), plain.rounds * 7u);
  ASSERT_EQ(log.generations().size(), seen.size());
  double running = e0;
  for (std::size_t i = 0; i < seen.size(); ++i) {
    const optim::GenerationLog& g = seen[i];
    EXPECT_TRUE(g == log.generations()[i]) << "generation " << i;
    for (std::size_t k = 0; k < g.size(); ++k) {
      std::vector<double> p{0.0};
      p.insert(p.end(), g.variables.begin() + static_cast<std::ptrdiff_t>(k * g.dimension),
               g.variables.begin() + static_cast<std::ptrdiff_t>((k + 1) * g.dimension));
      p.push_back(1.0);
      EXPECT_NEAR(g.objective_values[k], evaluate_parameters(s, p).energy, 1e-12 * e0) << i << ", " << k;
    }
    running = std::min(running, optim::statistics(g).best);
    EXPECT_EQ(plain.convergence[i], running) << "generation " << i;
  }
  EXPECT_LT(plain.best.energy, e0);
  EXPECT_NEAR(running, plain.best.energy, 1e-12 * e0);
}

struct Case {
  const char* name;
  const std::vector<Vec3>* points;
  FairingEnergy energy;
};

// Both optimisers end at or below the chord-length
// energy, and the real GA (50 x 50 per round, bounds re-centred) agrees with Nelder-Mead: energies within a
// relative 1e-3 and parameters within 0.02 (or those of the mirrored optimum 1 - p reversed, on the symmetric
// examples whose optimum is not unique: 7.4.2 Example 1 under ∫κ'^2 ds has optima p1 = 0.3833 and 0.6167).
// Why these tolerances: the landscapes are flat (the thesis's own observation), so the GA stops within a
// relative 3e-7 .. 4.4e-4 of the optimum in energy depending on the example and seed (worst over seeds
// 0..7: 4.4e-4 on Example 3 under ∫κ'^2 ds); near a flat optimum such energy gaps allow parameter
// offsets of ~0.01, hence 0.02.
void expect_beat_chord_and_agree(const std::vector<Case>& cases) {
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const KnotFairingSetup s = planar(*c.points, c.energy);
    const std::vector<double> chord = chord_length_parameters(s);
    const double e0 = evaluate_parameters(s, chord).energy;
    const FairingResult d = fair_knots_deterministic(s, chord);
    GaFairingOptions o;
    o.real.run.seed = 7;
    const FairingResult g = fair_knots_ga(s, chord, o);
    EXPECT_LE(d.best.energy, e0);
    EXPECT_LE(g.best.energy, e0);
    EXPECT_NEAR(g.best.energy, d.best.energy, 1e-3 * d.best.energy);
    const std::size_t n = chord.size();
    double direct = 0.0;
    double mirrored = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      direct = std::max(direct, std::abs(g.best.parameters[i] - d.best.parameters[i]));
      mirrored = std::max(mirrored, std::abs(g.best.parameters[i] - (1.0 - d.best.parameters[n - 1 - i])));
    }
    EXPECT_LT(std::min(direct, mirrored), 0.02);
    EXPECT_GE(g.rounds, 1u);
    EXPECT_EQ(g.convergence.size(), g.rounds * 51u);
    EXPECT_GT(d.evaluations, 10u);
  }
}

// checks: under ∫κ² ds, on all five thesis examples, GA and Nelder-Mead beat chord length and agree
TEST(StudiesKnotFairing, OptimisersBeatChordAndAgreeBending) {
  expect_beat_chord_and_agree({{"7.2 ex1", &kExample72_1, FairingEnergy::Bending},
                               {"7.3 ex2", &kExample73_2, FairingEnergy::Bending},
                               {"7.4 ex1", &kExample74_1, FairingEnergy::Bending},
                               {"7.4 ex2", &kExample74_2, FairingEnergy::Bending},
                               {"7.4 ex3", &kExample74_3, FairingEnergy::Bending}});
}

// checks: under ∫(dκ/ds)² ds, on 7.4.2 Examples 1 and 3, GA and Nelder-Mead beat chord length and agree
TEST(StudiesKnotFairing, OptimisersBeatChordAndAgreeVariation) {
  expect_beat_chord_and_agree({{"7.4 ex1 var", &kExample74_1, FairingEnergy::Variation},
                               {"7.4 ex3 var", &kExample74_3, FairingEnergy::Variation}});
}

// checks: the GA fairing is reproducible: the same seed gives bit-identical parameters on 1 and 2 threads,
// and the run log holds every generation of every round
TEST(StudiesKnotFairing, GaIsThreadInvariant) {
  const KnotFairingSetup s = planar(kExample73_2);
  const std::vector<double> chord = chord_length_parameters(s);
  GaFairingOptions o;
  o.real.run.seed = 4;
  optim::RunLog log;
  const FairingResult one = fair_knots_ga(s, chord, o, &log);
  o.real.run.threads = 2;
  const FairingResult two = fair_knots_ga(s, chord, o);
  EXPECT_EQ(one.best.parameters, two.best.parameters);
  EXPECT_EQ(one.best.energy, two.best.energy);
  EXPECT_EQ(one.evaluations, two.evaluations);
  EXPECT_EQ(log.generations().size(), one.rounds * 51u);
}

// The bending energy ∫κ² ds of the natural cubic spline through planar points at parameters t, computed
// here without the library: the classical second-derivative (moment) form of the spline, its tridiagonal
// system solved by the Thomas algorithm, and ∫ (x'y'' - y'x'')² / |S'|^5 dt by composite 5-point
// Gauss–Legendre on `panels` panels per segment. The natural C2 cubic with knots at the parameters is the
// interpolant the study defines (KnotFairingSetup: natural ends, knots at the parameters).
double independent_bending(const std::vector<Vec3>& p, const std::vector<double>& t, int panels = 64) {
  const std::size_t n = p.size();
  std::vector<double> h(n - 1);
  for (std::size_t i = 0; i + 1 < n; ++i) h[i] = t[i + 1] - t[i];
  // Moments M (second derivatives at the points) of x and y; M_0 = M_{n-1} = 0.
  std::vector<std::array<double, 2>> m(n, {0.0, 0.0});
  if (n > 2) {
    const std::size_t k = n - 2;
    std::vector<double> diag(k), upper(k);
    std::vector<std::array<double, 2>> rhs(k);
    for (std::size_t j = 0; j < k; ++j) {
      const std::size_t i = j + 1;
      diag[j] = 2.0 * (h[i - 1] + h[i]);
      upper[j] = h[i];
      for (std::size_t c = 0; c < 2; ++c)
        rhs[j][c] = 6.0 * ((p[i + 1][c] - p[i][c]) / h[i] - (p[i][c] - p[i - 1][c]) / h[i - 1]);
    }
    for (std::size_t j = 1; j < k; ++j) {  // forward elimination: sub-diagonal entry j is h[j]
      const double f = h[j] / diag[j - 1];
      diag[j] -= f * upper[j - 1];
      for (std::size_t c = 0; c < 2; ++c) rhs[j][c] -= f * rhs[j - 1][c];
    }
    for (std::size_t j = k; j-- > 0;)
      for (std::size_t c = 0; c < 2; ++c)
        m[j + 1][c] = (rhs[j][c] - (j + 1 < k ? upper[j] * m[j + 2][c] : 0.0)) / diag[j];
  }
  const double a = std::sqrt(5.0 - 2.0 * std::sqrt(10.0 / 7.0)) / 3.0,
               b = std::sqrt(5.0 + 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
  const std::array<double, 5> x{-b, -a, 0.0, a, b};
  const double wa = (322.0 + 13.0 * std::sqrt(70.0)) / 900.0, wb = (322.0 - 13.0 * std::sqrt(70.0)) / 900.0;
  const std::array<double, 5> w{wb, wa, 128.0 / 225.0, wa, wb};
  double total = 0.0;
  for (std::size_t i = 0; i + 1 < n; ++i) {
    for (int q = 0; q < panels; ++q) {
      const double lo = t[i] + h[i] * q / panels, hi = t[i] + h[i] * (q + 1) / panels;
      for (std::size_t g = 0; g < 5; ++g) {
        const double u = 0.5 * (lo + hi) + 0.5 * (hi - lo) * x[g];
        const double before = t[i + 1] - u, after = u - t[i];
        std::array<double, 2> d1{}, d2{};
        for (std::size_t c = 0; c < 2; ++c) {
          d1[c] = -m[i][c] * before * before / (2.0 * h[i]) + m[i + 1][c] * after * after / (2.0 * h[i]) +
                  (p[i + 1][c] - p[i][c]) / h[i] - h[i] * (m[i + 1][c] - m[i][c]) / 6.0;
          d2[c] = (m[i][c] * before + m[i + 1][c] * after) / h[i];
        }
        const double cross = d1[0] * d2[1] - d1[1] * d2[0];
        const double speed = std::hypot(d1[0], d1[1]);
        total += 0.5 * (hi - lo) * w[g] * cross * cross / std::pow(speed, 5);
      }
    }
  }
  return total;
}

// The least independent bending energy over a brute-force grid of the box |t_i - centre_i| <= half_width (every
// interior parameter, nodes at centre_i + (k + 1/2) step so that none is the centre itself, strictly increasing
// vectors only), and where it is.
std::pair<double, std::vector<double>> grid_minimum(const std::vector<Vec3>& p, const std::vector<double>& centre,
                                                    double half_width, double step) {
  const std::size_t interior = centre.size() - 2;
  const int half = static_cast<int>(std::lround(half_width / step));
  std::vector<int> k(interior, -half);  // k in [-half, half - 1]
  std::pair<double, std::vector<double>> best{std::numeric_limits<double>::infinity(), {}};
  while (true) {
    std::vector<double> t = centre;
    for (std::size_t i = 0; i < interior; ++i) t[i + 1] = centre[i + 1] + (k[i] + 0.5) * step;
    bool increasing = true;
    for (std::size_t i = 0; i + 1 < t.size(); ++i) increasing = increasing && t[i] < t[i + 1];
    if (increasing) {
      const double e = independent_bending(p, t, 16);
      if (e < best.first) best = {e, t};
    }
    std::size_t i = 0;
    while (i < interior && k[i] == half - 1) k[i++] = -half;
    if (i == interior) break;
    ++k[i];
  }
  return best;
}

// checks: the study's bending energy equals the independent natural-spline computation above, at chord-length
// parameters (7.3 Example 2, 7.4.2 Examples 2 and 3), uniform ones (7.4.2 Example 2) and the thesis's printed
// vectors (7.4.2 Example 2's best, Example 3's runs 1 and 2)
TEST(StudiesKnotFairing, BendingEnergyMatchesIndependentSpline) {
  struct Vectors {
    const std::vector<Vec3>* points;
    std::vector<std::vector<double>> given;
  };
  const std::vector<Vectors> cases{
      {&kExample73_2, {}},
      {&kExample74_2, {{0, 0.25, 0.5, 0.75, 1}, {0, 0.286111, 0.50371, 0.713889, 1}}},
      {&kExample74_3,
       {{0, 0.125303, 0.419407, 0.492229, 0.777902, 1}, {0, 0.158246, 0.392588, 0.439407, 0.855499, 1}}}};
  for (const Vectors& c : cases) {
    const KnotFairingSetup s = planar(*c.points);
    std::vector<std::vector<double>> vectors = c.given;
    vectors.push_back(chord_length_parameters(s));
    for (const auto& t : vectors) {
      const double mine = independent_bending(*c.points, t);
      EXPECT_NEAR(evaluate_parameters(s, t).energy, mine, 1e-8 * mine) << c.points->size() << " points";
    }
  }
}

// checks: the deterministic optima of 7.4.2 Examples 2 and 3 (bending, natural ends) are local minima of the
// independently computed energy: no coordinate or seeded random perturbation lowers it, and no node of a
// brute-force grid of its neighbourhood (±0.1 in each parameter for Example 2, ±0.06 for Example 3) is below
// it; the thesis's vectors compare with it as the docs table says. (They are not global: ∫κ² ds is not
// scale-invariant and falls towards 0 where the parameters crowd at the ends and the spline sweeps a wide
// arc, e.g. 0.0286 at {0, 0.02, 0.04, 0.98, 1} on Example 2; docs/studies/knot-fairing.md.)
TEST(StudiesKnotFairing, OptimaOfThesisExamplesAreIndependentMinima) {
  Rng rng(74);
  struct FairingCase {
    const std::vector<Vec3>* points;
    double half_width, grid_step;
  };
  for (const FairingCase& c : {FairingCase{&kExample74_2, 0.1, 0.01}, FairingCase{&kExample74_3, 0.06, 0.02}}) {
    const KnotFairingSetup s = planar(*c.points);
    const FairingResult d = fair_knots_deterministic(s, chord_length_parameters(s));
    const std::vector<double>& t = d.best.parameters;
    const double e = independent_bending(*c.points, t);
    EXPECT_NEAR(d.best.energy, e, 1e-8 * e);
    for (const double h : {1e-2, 3e-3}) {
      for (std::size_t i = 1; i + 1 < t.size(); ++i) {
        for (const double sign : {-1.0, 1.0}) {
          std::vector<double> moved = t;
          moved[i] += sign * h;
          EXPECT_GE(independent_bending(*c.points, moved), e - 1e-9 * e) << "t[" << i << "] " << sign * h;
        }
      }
      for (int trial = 0; trial < 8; ++trial) {
        std::vector<double> moved = t;
        for (std::size_t i = 1; i + 1 < t.size(); ++i) moved[i] += h * rng.uniform(-1.0, 1.0);
        EXPECT_GE(independent_bending(*c.points, moved), e - 1e-9 * e) << "random trial " << trial;
      }
    }
    // No node of the grid around the optimum is lower, and the grid's best is a corner of the optimum's cell.
    const auto [grid_energy, grid_t] = grid_minimum(*c.points, t, c.half_width, c.grid_step);
    EXPECT_GE(grid_energy, e - 1e-9 * e) << c.points->size() << " points";
    for (std::size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(grid_t[i], t[i], c.grid_step) << i;
  }
  // Example 2 is symmetric about the corner's diagonal (reflection + reversal), so its optimum is:
  // t2 = 0.5 and t3 = 1 - t1.
  const KnotFairingSetup s2 = planar(kExample74_2);
  const FairingResult d2 = fair_knots_deterministic(s2, chord_length_parameters(s2));
  EXPECT_NEAR(d2.best.parameters[2], 0.5, 1e-3);
  EXPECT_NEAR(d2.best.parameters[1] + d2.best.parameters[3], 1.0, 1e-3);
  // The thesis's best knot vector of Example 2 is within 0.3 % of the optimum in this energy.
  const std::vector<double> thesis2{0, 0.286111, 0.50371, 0.713889, 1};
  EXPECT_NEAR(independent_bending(kExample74_2, thesis2), d2.best.energy, 0.003 * d2.best.energy);
  // The thesis's run 1 vector of Example 3 is worse than chord length in this energy (the thesis: "fails
  // to produce improved shape"); run 2 is worse too.
  const std::vector<double> chord3 = chord_length_parameters(planar(kExample74_3));
  const std::vector<double> run1{0, 0.125303, 0.419407, 0.492229, 0.777902, 1};
  const std::vector<double> run2{0, 0.158246, 0.392588, 0.439407, 0.855499, 1};
  EXPECT_GT(independent_bending(kExample74_3, run1), independent_bending(kExample74_3, run2));
  EXPECT_GT(independent_bending(kExample74_3, run2), independent_bending(kExample74_3, chord3));
}

// checks: bad parameter vectors and setups are refused with the input named
TEST(StudiesKnotFairing, ErrorsNameTheInput) {
  const KnotFairingSetup s = planar(kExample72_1);
  HULA_EXPECT_ERROR((void)evaluate_parameters(s, std::vector<double>{0.0, 0.5, 1.0}), Errc::InvalidArgument,
                    "3 values for 4 points");
  HULA_EXPECT_ERROR((void)evaluate_parameters(s, std::vector<double>{0.1, 0.3, 0.6, 1.0}), Errc::InvalidArgument,
                    "parameters[0] = 0.1 must be 0");
  HULA_EXPECT_ERROR((void)evaluate_parameters(s, std::vector<double>{0.0, 0.3, 0.6, 0.9}), Errc::InvalidArgument,
                    "parameters[3] = 0.9 must be 1");
  HULA_EXPECT_ERROR((void)evaluate_parameters(s, std::vector<double>{0.0, 0.6, 0.6, 1.0}), Errc::InvalidArgument,
                    "parameters[2] = 0.6 must be greater than parameters[1] = 0.6");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  HULA_EXPECT_ERROR((void)evaluate_parameters(s, std::vector<double>{0.0, nan, 0.6, 1.0}), Errc::NonFiniteInput,
                    "parameters[1] = nan");
  HULA_EXPECT_ERROR((void)chord_length_parameters(planar({{0, 0, 0}, {1, 0, 0}})), Errc::TooFewPoints,
                    "at least 3 points");
  HULA_EXPECT_ERROR((void)chord_length_parameters(planar({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}})), Errc::CoincidentPoints,
                    "");
  const std::vector<double> base = chord_length_parameters(s);
  HULA_EXPECT_ERROR((void)energy_map(s, base, {.first = 2, .second = 2, .grid = 5}), Errc::InvalidOption,
                    "map.knots[1] = 2");
  GaFairingOptions o;
  o.recentre_fraction = 0.5;
  HULA_EXPECT_ERROR((void)fair_knots_ga(s, base, o), Errc::InvalidOption, "recentre_fraction = 0.5");
}

}  // namespace
}  // namespace hula::studies
