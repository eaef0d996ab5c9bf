// SPDX-License-Identifier: MIT
// Knot-vector studies (thesis 7.2–7.4): the cubic spline through fixed data
// points is shaped by the parameter ("knot") of each data point, first 0,
// last 1 — the thesis's "knot vector". This file holds
//  - the chord-length start (eq. 29) and the evaluation of a given parameter
//    vector (the interactive tool of 7.2): the interpolant and its energies
//    ∫κ² ds (eq. 30) and ∫(dκ/ds)² ds;
//  - the energy map over two internal parameters (Figures 55–58) and its
//    cross sections (Figures 56–57);
//  - GA fairing over the internal parameters with the strictly increasing
//    bounds of 7.4.1, re-centred on the best when it sits on a bound;
//  - a deterministic optimiser on the same objective (Nelder–Mead on the
//    log-ratios of the interval widths, which keep the parameters strictly
//    increasing without bounds), to check the GA.
#pragma once

#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/diffgeom/energy.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/nurbs/nurbs_curve.hpp"
#include "hula/optim/ga.hpp"
#include "hula/optim/nelder_mead.hpp"
#include "hula/optim/run_log.hpp"

namespace hula::studies {

/// Which fairness energy is minimised.
enum class FairingEnergy {
  Bending,    ///< ∫κ² ds (thesis eq. 30)
  Variation,  ///< ∫(dκ/ds)² ds
};

/// "bending" or "variation".
[[nodiscard]] std::string_view fairing_energy_name(FairingEnergy energy) noexcept;

/// The fixed part of a knot-fairing study: data points, end conditions, energy.
struct KnotFairingSetup {
  /// Data points, N >= 3 (at least one internal parameter), no two consecutive coincident.
  std::vector<Vec3> points{};
  /// 2 for planar points (z = 0), else 3. Default 3.
  int dimension = 3;
  /// End conditions of the cubic spline. Default natural at both ends, as in the thesis.
  nurbs::EndCondition start = nurbs::EndCondition::natural();
  nurbs::EndCondition end = nurbs::EndCondition::natural();
  /// The energy minimised. Default Bending.
  FairingEnergy energy = FairingEnergy::Bending;
  /// Quadrature options of the energies. Default relative tolerance 1e-10.
  diffgeom::EnergyOptions energy_options{};

  /// Checks the setup before any work.
  /// @throws hula::Error(Errc::TooFewPoints) for fewer than 3 points
  /// @throws hula::Error(Errc::NonFiniteInput) naming points[i]
  /// @throws hula::Error(Errc::CoincidentPoints) naming the pair
  /// @throws hula::Error(Errc::InvalidOption) for bad end conditions, dimension or energy options
  void validate() const;
};

/// A parameter vector and what it gives.
struct ParameterEvaluation {
  /// The parameters, first 0, last 1, strictly increasing.
  std::vector<double> parameters{};
  /// The interpolating cubic (knots at the parameters); a default-constructed
  /// evaluation holds the unit segment of the x axis as a placeholder.
  nurbs::NurbsCurve curve{1, {0.0, 0.0, 1.0, 1.0}, {Vec3{0.0, 0.0, 0.0}, Vec3{1.0, 0.0, 0.0}}};
  /// ∫κ² ds, model units^-1.
  double bending = 0.0;
  /// ∫(dκ/ds)² ds, model units^-3.
  double variation = 0.0;
  /// The setup's energy (bending or variation).
  double energy = 0.0;
};

/// The chord-length parameters of the setup's points (eq. 29), first 0, last 1.
/// @throws as KnotFairingSetup::validate
[[nodiscard]] std::vector<double> chord_length_parameters(const KnotFairingSetup& setup);

/// Checks a parameter vector for the setup: one per point, finite, first 0,
/// last 1, strictly increasing.
/// @throws hula::Error(Errc::InvalidArgument) naming parameters[i] and its value
/// @throws hula::Error(Errc::NonFiniteInput) naming parameters[i]
void check_parameters(const KnotFairingSetup& setup, std::span<const double> parameters);

/// The interactive evaluation of 7.2: the interpolant at the given
/// parameters and both energies.
/// @param setup a valid setup
/// @param parameters one per point, 0 = p_0 < p_1 < … < p_{N-1} = 1
/// @returns the curve and its energies
/// @throws as check_parameters and KnotFairingSetup::validate
/// @throws hula::Error(Errc::NumericalFailure) if the spline system is singular
[[nodiscard]] ParameterEvaluation evaluate_parameters(const KnotFairingSetup& setup,
                                                      std::span<const double> parameters);

/// The objective alone (the setup's energy), for the optimisers: no checks
/// beyond the interpolation's own.
/// @throws as nurbs::interpolate_cubic
[[nodiscard]] double fairing_energy(const KnotFairingSetup& setup, std::span<const double> parameters);

/// Options of energy_map.
struct EnergyMapOptions {
  /// Indices of the two internal parameters varied, 1 <= first < second <= N - 2. Default 1, 2.
  std::size_t first = 1;
  std::size_t second = 2;
  /// Grid nodes per axis over each parameter's admissible range (open interval between
  /// the fixed neighbours), >= 2. Default 50.
  std::size_t grid = 50;
  /// Checks the options against the number of points.
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate(std::size_t points) const;
};

/// An energy map over two internal parameters (Figures 55, 58).
struct EnergyMap {
  std::size_t first = 0;       ///< index of the parameter on the x axis (k1)
  std::size_t second = 0;      ///< index of the parameter on the y axis (k2)
  std::vector<double> k1{};    ///< x-axis nodes
  std::vector<double> k2{};    ///< y-axis nodes
  std::vector<double> energy;  ///< energy[j * k1.size() + i] at (k1[i], k2[j]); NaN outside k1 < k2 or if it failed
  /// Smallest finite energy, and where.
  double min_energy = 0.0;
  double min_k1 = 0.0;
  double min_k2 = 0.0;
};

/// Maps the energy over parameters `first` and `second`, the others held at
/// `base`. Nodes run over the open range between the fixed neighbours
/// (k1 from base[first-1] to base[first+1] ... ) excluding the ends; cells with
/// k1 >= k2 (or any ordering violation) are NaN.
/// @param setup a valid setup
/// @param base a valid parameter vector (check_parameters)
/// @param options indices and grid size
/// @returns the map (grid^2 evaluations at most)
/// @throws as check_parameters and EnergyMapOptions::validate
[[nodiscard]] EnergyMap energy_map(const KnotFairingSetup& setup, std::span<const double> base,
                                   const EnergyMapOptions& options = {});

/// A cross section of an energy map at a fixed k1 (Figures 56–57).
struct MapSection {
  double k1 = 0.0;             ///< the fixed value of parameter `first`
  std::vector<double> k2{};    ///< nodes of parameter `second`, as the map's y axis
  std::vector<double> energy;  ///< energy at each node; NaN where k2 <= k1 or it failed
};

/// The cross section of energy_map(setup, base, options) at parameter
/// options.first = k1: `nodes` nodes over the same open range of parameter
/// options.second as the map's (options.grid is ignored).
/// @param k1 inside the map's range of parameter `first`
/// @param nodes >= 2
/// @throws hula::Error(Errc::InvalidArgument) naming k1 if it is outside the range, or nodes < 2
/// @throws as energy_map
[[nodiscard]] MapSection map_section(const KnotFairingSetup& setup, std::span<const double> base,
                                     const EnergyMapOptions& options, double k1, std::size_t nodes);

/// A cross section: the energy as parameter `index` runs over `values`, the
/// others held at `base` (Figures 56–57, 60). Values that break the strict
/// ordering give NaN.
/// @throws as check_parameters; InvalidArgument if index is not internal
[[nodiscard]] std::vector<double> energy_section(const KnotFairingSetup& setup, std::span<const double> base,
                                                 std::size_t index, std::span<const double> values);

/// The bounds of 7.4.1 around a parameter vector: internal parameter i lies in
/// [mid(p_{i-1}, p_i) + resolution, mid(p_i, p_{i+1}) - resolution], except that
/// the first internal one starts at p_0 + resolution and the last ends at
/// p_{N-1} - resolution (the thesis's listing). The boxes do not overlap, so
/// any point in them is strictly increasing.
struct KnotBounds {
  std::vector<double> lower{};  ///< one per internal parameter
  std::vector<double> upper{};  ///< one per internal parameter
};

/// The 7.4.1 bounds of `parameters` with the given resolution.
/// @throws hula::Error(Errc::InvalidArgument) if a box would not contain its parameter
///   (an interval shorter than 2 × resolution) or resolution is not finite and > 0
[[nodiscard]] KnotBounds knot_bounds(std::span<const double> parameters, double resolution);

/// Which GA runs the fairing.
enum class FairingGa {
  Binary,  ///< the thesis's binary GA (appendix 2, 6): roulette, single point, boosting
  Real,    ///< the real-coded GA (SBX, polynomial mutation)
};

/// Options of fair_knots_ga.
struct GaFairingOptions {
  /// Which GA. Default Real (the binary GA's roulette on the flat energy
  /// landscape stops within ~1e-2 of the optimum; the real GA within ~1e-5).
  FairingGa algorithm = FairingGa::Real;
  /// Binary GA settings (algorithm = Binary). Default the thesis's run: 50
  /// individuals, 50 generations, boosting 1 → 8 (appendix 6), roulette, single point.
  optim::BinaryGaOptions binary = [] {
    optim::BinaryGaOptions o;
    o.population = 50;
    o.run.stop.generations = 50;
    o.boost_end = 8.0;
    return o;
  }();
  /// Real GA settings (algorithm = Real). Default 50 individuals, 50 generations.
  optim::RealGaOptions real = [] {
    optim::RealGaOptions o;
    o.population = 50;
    o.run.stop.generations = 50;
    return o;
  }();
  /// Resolution of the 7.4.1 bounds (the thesis's resabs). In (0, 0.01). Default 1e-6.
  double resolution = 1e-6;
  /// Binary coding precision of each variable as a fraction of its box width, in
  /// (0, 0.5). Default 1e-4 (14 bits per variable).
  double precision_fraction = 1e-4;
  /// A best parameter within this fraction of its box width from a bound
  /// triggers a re-centred run. In (0, 0.5). Default 0.1 (with 0.02 the GA
  /// stopped short of the optimum on 7.4.2 Example 3, whose optimum lies
  /// outside the chord-length boxes).
  double recentre_fraction = 0.1;
  /// A round that lowers the best energy by more than this relative amount
  /// also triggers a re-centred run (the thesis: re-initialise the bounds
  /// "through the optimisation, based on the best solution found so far").
  /// In [0, 1). Default 1e-4.
  double recentre_improvement = 1e-4;
  /// Most re-centred runs after the first. Default 10.
  std::size_t max_recentres = 10;
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// Result of an optimiser.
struct FairingResult {
  /// The optimised parameters and their curve and energies.
  ParameterEvaluation best{};
  /// Energy evaluations.
  std::size_t evaluations = 0;
  /// Wall-clock seconds.
  double seconds = 0.0;
  /// GA: runs made (1 + re-centrings); deterministic: simplex restarts + 1.
  std::size_t rounds = 0;
  /// GA: the 7.4.1 bounds of the last run.
  KnotBounds bounds{};
  /// Best energy so far after each generation (GA, all rounds in turn) or iteration (simplex).
  std::vector<double> convergence{};
  /// Why the (last) optimiser run ended, and its message: WallTime or Cancelled
  /// (the options' run.stop, NelderMeadOptions) mean it ended early and `best`
  /// is the best so far.
  optim::Termination termination = optim::Termination::MaxGenerations;
  std::string message{};
  /// True when a wall-time limit or a cancellation token ended the optimiser early.
  [[nodiscard]] bool stopped() const noexcept { return optim::stopped_early(termination); }
};

/// GA fairing (7.4): the internal parameters are the variables, boxed by the
/// 7.4.1 bounds of `start`; when the best lies within recentre_fraction of a
/// bound, or the round improved the best by more than recentre_improvement,
/// the bounds are rebuilt around the best and the GA runs again (at most
/// max_recentres times; round r uses seed + r).
/// The result is never worse than `start` (the start is kept if nothing beats it).
/// @param setup a valid setup
/// @param start the start parameters (chord length in the thesis)
/// @param options GA, bounds and re-centring settings
/// The GA minimises E / E_start; the log and the options' run.on_generation receive every generation of
/// every round in the study's terms, as fair_knots_deterministic's callback does: the variables are the
/// internal parameters and the objective values the energies E (E / E_start × E_start); the fitness column
/// is the GA's own selection fitness. The run is the same with or without them.
/// @param log when not null, receives every generation of every run
/// @throws as check_parameters, knot_bounds, options.validate and the GA
[[nodiscard]] FairingResult fair_knots_ga(const KnotFairingSetup& setup, std::span<const double> start,
                                          const GaFairingOptions& options = {}, optim::RunLog* log = nullptr);

/// The unconstrained coordinates of a parameter vector: y_i = ln(w_{i+1} / w_0)
/// for the N - 1 interval widths w (N - 2 values).
[[nodiscard]] std::vector<double> widths_to_log_ratios(std::span<const double> parameters);
/// The parameter vector of log-ratio coordinates (inverse of widths_to_log_ratios).
[[nodiscard]] std::vector<double> log_ratios_to_parameters(std::span<const double> y);

/// Deterministic fairing: Nelder–Mead on the log-ratio coordinates, from `start`.
/// `options.on_generation`, when set, receives each simplex in the study's terms: its vertices as the
/// internal parameters p_1..p_{N-2} and their energies E (not E / E_start); the run is the same with or
/// without it.
/// @throws as check_parameters and optim::nelder_mead
[[nodiscard]] FairingResult fair_knots_deterministic(const KnotFairingSetup& setup, std::span<const double> start,
                                                     const optim::NelderMeadOptions& options = {});

}  // namespace hula::studies
