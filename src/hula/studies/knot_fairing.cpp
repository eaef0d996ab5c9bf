// SPDX-License-Identifier: MIT
#include "hula/studies/knot_fairing.hpp"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <limits>
#include <span>
#include <string>

#include "hula/core/error.hpp"
#include "hula/optim/problem.hpp"

namespace hula::studies {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Shortest round-trip form (0.7, not 0.69999999999999996).
std::string num(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

nurbs::InterpolationOptions interpolation_options(const KnotFairingSetup& setup, std::span<const double> parameters) {
  nurbs::InterpolationOptions o;
  o.parameters.assign(parameters.begin(), parameters.end());
  o.start = setup.start;
  o.end = setup.end;
  o.dimension = setup.dimension;
  return o;
}

double energy_of(const KnotFairingSetup& setup, const nurbs::NurbsCurve& curve) {
  return setup.energy == FairingEnergy::Bending
             ? diffgeom::bending_energy(curve, setup.energy_options).value
             : diffgeom::curvature_variation_energy(curve, setup.energy_options).value;
}

void check_internal_index(std::size_t index, std::size_t points, std::string_view field) {
  if (index == 0 || index + 1 >= points) {
    throw Error(Errc::InvalidArgument,
                std::string(field) + " = " + std::to_string(index) + " is not an internal parameter (1 … " +
                    std::to_string(points - 2) + ")",
                ErrorWhere{.field = std::string(field)});
  }
}

}  // namespace

std::string_view fairing_energy_name(FairingEnergy energy) noexcept {
  return energy == FairingEnergy::Bending ? "bending" : "variation";
}

void KnotFairingSetup::validate() const {
  if (points.size() < 3) {
    throw Error(Errc::TooFewPoints,
                "knot fairing needs at least 3 points (one internal parameter), got " + std::to_string(points.size()),
                ErrorWhere{.field = "points"});
  }
  interpolation_options(*this, {}).validate();
  energy_options.validate();
  // parameterise checks finiteness and coincident points, naming them.
  (void)nurbs::parameterise(points, nurbs::Parameterisation::ChordLength);
}

std::vector<double> chord_length_parameters(const KnotFairingSetup& setup) {
  setup.validate();
  return nurbs::parameterise(setup.points, nurbs::Parameterisation::ChordLength);
}

void check_parameters(const KnotFairingSetup& setup, std::span<const double> parameters) {
  const std::size_t n = setup.points.size();
  if (parameters.size() != n) {
    throw Error(Errc::InvalidArgument,
                "parameters has " + std::to_string(parameters.size()) + " values for " + std::to_string(n) + " points",
                ErrorWhere{.field = "parameters"});
  }
  for (std::size_t i = 0; i < n; ++i) {
    const ErrorWhere where{.field = "parameters", .index = i};
    const std::string name = "parameters[" + std::to_string(i) + "] = " + num(parameters[i]);
    if (!std::isfinite(parameters[i])) throw Error(Errc::NonFiniteInput, name + " is not finite", where);
    if (i == 0 && parameters[i] != 0.0) throw Error(Errc::InvalidArgument, name + " must be 0 (the start)", where);
    if (i + 1 == n && parameters[i] != 1.0) throw Error(Errc::InvalidArgument, name + " must be 1 (the end)", where);
    if (i > 0 && !(parameters[i] > parameters[i - 1])) {
      throw Error(Errc::InvalidArgument,
                  name + " must be greater than parameters[" + std::to_string(i - 1) + "] = " + num(parameters[i - 1]) +
                      " (strictly increasing)",
                  where);
    }
  }
}

ParameterEvaluation evaluate_parameters(const KnotFairingSetup& setup, std::span<const double> parameters) {
  setup.validate();
  check_parameters(setup, parameters);
  ParameterEvaluation e;
  e.parameters.assign(parameters.begin(), parameters.end());
  e.curve = nurbs::interpolate_cubic(setup.points, interpolation_options(setup, parameters));
  e.bending = diffgeom::bending_energy(e.curve, setup.energy_options).value;
  e.variation = diffgeom::curvature_variation_energy(e.curve, setup.energy_options).value;
  e.energy = setup.energy == FairingEnergy::Bending ? e.bending : e.variation;
  return e;
}

double fairing_energy(const KnotFairingSetup& setup, std::span<const double> parameters) {
  return energy_of(setup, nurbs::interpolate_cubic(setup.points, interpolation_options(setup, parameters)));
}

void EnergyMapOptions::validate(std::size_t points) const {
  if (first == 0 || first + 1 >= points) {
    throw Error(Errc::InvalidOption,
                "map.knots[0] = " + std::to_string(first) + " is not an internal parameter (1 … " +
                    std::to_string(points - 2) + ")",
                ErrorWhere{.field = "map", .index = 0});
  }
  if (second <= first || second + 1 >= points) {
    throw Error(Errc::InvalidOption,
                "map.knots[1] = " + std::to_string(second) + " must be an internal parameter after map.knots[0] = " +
                    std::to_string(first) + " (… " + std::to_string(points - 2) + ")",
                ErrorWhere{.field = "map", .index = 1});
  }
  if (grid < 2 || grid > 2000) {
    throw Error(Errc::InvalidOption, "map.grid = " + std::to_string(grid) + " must be in 2 … 2000",
                ErrorWhere{.field = "map"});
  }
}

namespace {

// The open ranges of the two mapped parameters (the neighbours held fixed).
struct MapRanges {
  double lo1, hi1, lo2, hi2;
};

MapRanges map_ranges(std::span<const double> base, const EnergyMapOptions& options) {
  const std::size_t i1 = options.first;
  const std::size_t i2 = options.second;
  const bool adjacent = i2 == i1 + 1;
  return {base[i1 - 1], adjacent ? base[i2 + 1] : base[i1 + 1], adjacent ? base[i1 - 1] : base[i2 - 1], base[i2 + 1]};
}

double node(double lo, double hi, std::size_t i, std::size_t count) {
  return lo + (hi - lo) * static_cast<double>(i + 1) / static_cast<double>(count + 1);
}

bool strictly_increasing(std::span<const double> p) {
  for (std::size_t i = 1; i < p.size(); ++i)
    if (!(p[i] > p[i - 1])) return false;
  return true;
}

double energy_or_nan(const KnotFairingSetup& setup, std::span<const double> p) {
  if (!strictly_increasing(p)) return std::numeric_limits<double>::quiet_NaN();
  try {
    return fairing_energy(setup, p);
  } catch (const Error&) {
    return std::numeric_limits<double>::quiet_NaN();  // a singular system leaves the cell blank
  }
}

}  // namespace

EnergyMap energy_map(const KnotFairingSetup& setup, std::span<const double> base, const EnergyMapOptions& options) {
  setup.validate();
  check_parameters(setup, base);
  options.validate(base.size());
  const MapRanges r = map_ranges(base, options);
  const std::size_t g = options.grid;
  EnergyMap m;
  m.first = options.first;
  m.second = options.second;
  m.k1.resize(g);
  m.k2.resize(g);
  for (std::size_t i = 0; i < g; ++i) {
    m.k1[i] = node(r.lo1, r.hi1, i, g);
    m.k2[i] = node(r.lo2, r.hi2, i, g);
  }
  m.energy.assign(g * g, std::numeric_limits<double>::quiet_NaN());
  m.min_energy = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> p(base.begin(), base.end());
  for (std::size_t j = 0; j < g; ++j) {
    for (std::size_t i = 0; i < g; ++i) {
      p[m.first] = m.k1[i];
      p[m.second] = m.k2[j];
      const double e = energy_or_nan(setup, p);
      m.energy[j * g + i] = e;
      if (std::isfinite(e) && !(e >= m.min_energy)) {
        m.min_energy = e;
        m.min_k1 = m.k1[i];
        m.min_k2 = m.k2[j];
      }
    }
  }
  return m;
}

MapSection map_section(const KnotFairingSetup& setup, std::span<const double> base, const EnergyMapOptions& options,
                       double k1, std::size_t nodes) {
  setup.validate();
  check_parameters(setup, base);
  options.validate(base.size());
  const MapRanges r = map_ranges(base, options);
  if (!(k1 > r.lo1 && k1 < r.hi1)) {
    throw Error(Errc::InvalidArgument,
                "section k1 = " + num(k1) + " is outside the map's range (" + num(r.lo1) + ", " + num(r.hi1) + ")",
                ErrorWhere{.field = "sections"});
  }
  if (nodes < 2) {
    throw Error(Errc::InvalidArgument, "a section needs at least 2 nodes, got " + std::to_string(nodes),
                ErrorWhere{.field = "sections"});
  }
  MapSection s;
  s.k1 = k1;
  s.k2.resize(nodes);
  s.energy.resize(nodes);
  std::vector<double> p(base.begin(), base.end());
  p[options.first] = k1;
  for (std::size_t j = 0; j < nodes; ++j) {
    s.k2[j] = node(r.lo2, r.hi2, j, nodes);
    p[options.second] = s.k2[j];
    s.energy[j] = energy_or_nan(setup, p);
  }
  return s;
}

std::vector<double> energy_section(const KnotFairingSetup& setup, std::span<const double> base, std::size_t index,
                                   std::span<const double> values) {
  setup.validate();
  check_parameters(setup, base);
  check_internal_index(index, base.size(), "index");
  std::vector<double> out(values.size(), std::numeric_limits<double>::quiet_NaN());
  std::vector<double> p(base.begin(), base.end());
  for (std::size_t k = 0; k < values.size(); ++k) {
    p[index] = values[k];
    if (!(p[index] > p[index - 1] && p[index] < p[index + 1])) continue;
    try {
      out[k] = fairing_energy(setup, p);
    } catch (const Error&) {
      // NaN: a singular system.
    }
  }
  return out;
}

KnotBounds knot_bounds(std::span<const double> parameters, double resolution) {
  if (!(std::isfinite(resolution) && resolution > 0.0)) {
    throw Error(Errc::InvalidArgument, "resolution = " + num(resolution) + " must be finite and > 0",
                ErrorWhere{.field = "resolution"});
  }
  const std::size_t n = parameters.size();
  if (n < 3) {
    throw Error(Errc::InvalidArgument, "knot_bounds needs at least one internal parameter",
                ErrorWhere{.field = "parameters"});
  }
  KnotBounds b;
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const double lo = i == 1 ? parameters[0] + resolution
                             : parameters[i - 1] + (parameters[i] - parameters[i - 1]) / 2.0 + resolution;
    const double hi = i + 2 == n ? parameters[n - 1] - resolution
                                 : parameters[i + 1] - (parameters[i + 1] - parameters[i]) / 2.0 - resolution;
    if (!(lo <= parameters[i] && parameters[i] <= hi)) {
      throw Error(Errc::InvalidArgument,
                  "the 7.4.1 bounds of parameters[" + std::to_string(i) + "] = " + num(parameters[i]) +
                      " do not contain it (an interval shorter than 2 × resolution " + num(resolution) + ")",
                  ErrorWhere{.field = "parameters", .index = i});
    }
    b.lower.push_back(lo);
    b.upper.push_back(hi);
  }
  return b;
}

void GaFairingOptions::validate() const {
  if (!(std::isfinite(resolution) && resolution > 0.0 && resolution < 1e-2)) {
    throw Error(Errc::InvalidOption, "resolution = " + num(resolution) + " must be in (0, 0.01)",
                ErrorWhere{.field = "resolution"});
  }
  if (!(recentre_fraction > 0.0 && recentre_fraction < 0.5)) {
    throw Error(Errc::InvalidOption, "recentre_fraction = " + num(recentre_fraction) + " must be in (0, 0.5)",
                ErrorWhere{.field = "recentre_fraction"});
  }
  if (!(std::isfinite(precision_fraction) && precision_fraction > 0.0 && precision_fraction < 0.5)) {
    throw Error(Errc::InvalidOption, "precision_fraction = " + num(precision_fraction) + " must be in (0, 0.5)",
                ErrorWhere{.field = "precision_fraction"});
  }
  if (!(recentre_improvement >= 0.0 && recentre_improvement < 1.0)) {
    throw Error(Errc::InvalidOption, "recentre_improvement = " + num(recentre_improvement) + " must be in [0, 1)",
                ErrorWhere{.field = "recentre_improvement"});
  }
  binary.validate();
  real.validate();
}

FairingResult fair_knots_ga(const KnotFairingSetup& setup, std::span<const double> start,
                            const GaFairingOptions& options, optim::RunLog* log) {
  const auto t0 = Clock::now();
  setup.validate();
  check_parameters(setup, start);
  options.validate();
  const std::size_t n = start.size();
  const std::size_t m = n - 2;

  FairingResult result;
  // The start is the reference: the GA minimises E / E_start, a scale-free
  // objective whose fitness 1/(1+e) separates candidates whatever the model units.
  double best_energy = fairing_energy(setup, start);
  ++result.evaluations;
  if (!(std::isfinite(best_energy) && best_energy > 0.0)) {
    throw Error(Errc::NumericalFailure, "the start parameters' energy " + num(best_energy) + " is not finite and > 0",
                ErrorWhere{.field = "parameters"});
  }
  const double scale = best_energy;
  std::vector<double> best(start.begin(), start.end());
  std::vector<double> centre = best;
  double running_best = best_energy;
  optim::GenerationLog study_log;  // a generation in energy units, reused

  for (std::size_t round = 0; round <= options.max_recentres; ++round) {
    result.bounds = knot_bounds(centre, options.resolution);
    optim::Problem problem;
    problem.name = "fair-knots";
    for (std::size_t i = 0; i < m; ++i) {
      const double width = result.bounds.upper[i] - result.bounds.lower[i];
      problem.variables.push_back(optim::Variable{.name = "p" + std::to_string(i + 1),
                                                  .lower = result.bounds.lower[i],
                                                  .upper = result.bounds.upper[i],
                                                  .precision = width * options.precision_fraction});
    }
    problem.evaluate = [&setup, n, scale](std::span<const double> x, std::span<double> f) {
      thread_local std::vector<double> p;
      p.resize(n);
      p[0] = 0.0;
      p[n - 1] = 1.0;
      std::copy(x.begin(), x.end(), p.begin() + 1);
      f[0] = fairing_energy(setup, p) / scale;
    };
    // The log and the caller's own callback (the progress line, a server job's events, Python's callback)
    // see every round's generations in the study's terms, as the deterministic optimiser reports them and
    // as `convergence` holds them: energies E, not the GA's objective E / E_start (the fitness column stays
    // the GA's selection fitness).
    optim::GenerationCallback on_generation = [&](const optim::GenerationLog& g) {
      const optim::GenerationStatistics s = optim::statistics(g);
      if (std::isfinite(s.best)) running_best = std::min(running_best, s.best * scale);
      result.convergence.push_back(running_best);
      const optim::GenerationCallback& caller =
          options.algorithm == FairingGa::Binary ? options.binary.run.on_generation : options.real.run.on_generation;
      if (log == nullptr && !caller) return;
      study_log = g;
      for (double& v : study_log.objective_values) v *= scale;
      if (log != nullptr) log->append(study_log);
      if (caller) caller(study_log);
    };
    optim::GaResult r;
    if (options.algorithm == FairingGa::Binary) {
      optim::BinaryGaOptions o = options.binary;
      o.run.seed = options.binary.run.seed + round;
      o.run.on_generation = on_generation;
      r = optim::solve_binary_ga(problem, o);
    } else {
      optim::RealGaOptions o = options.real;
      o.run.seed = options.real.run.seed + round;
      o.run.on_generation = on_generation;
      r = optim::solve_real_ga(problem, o);
    }
    result.evaluations += r.report.evaluations;
    ++result.rounds;
    result.termination = r.report.termination;
    result.message = "round " + std::to_string(round) + ": " + r.report.message;
    const double e = r.best.objectives.at(0) * scale;
    const double before = best_energy;
    if (e < best_energy) {
      best_energy = e;
      best[0] = 0.0;
      best[n - 1] = 1.0;
      std::copy(r.best.variables.begin(), r.best.variables.end(), best.begin() + 1);
    }
    // Re-centre when the run's best sits on a bound of its box (7.4.1).
    // optim::rerun_recentred does not fit: it shrinks boxes inside the
    // original bounds, while here the new 7.4.1 boxes around the best must be
    // able to leave the chord-length boxes (7.4.2 Example 3's optimum does).
    bool on_bound = false;
    for (std::size_t i = 0; i < m; ++i) {
      const double x = r.best.variables[i];
      const double lo = result.bounds.lower[i];
      const double hi = result.bounds.upper[i];
      const double margin = options.recentre_fraction * (hi - lo);
      // The outer bounds at p_0 + resolution and p_{N-1} - resolution cannot move.
      const bool movable_lo = i > 0;
      const bool movable_hi = i + 1 < m;
      if ((movable_lo && x - lo <= margin) || (movable_hi && hi - x <= margin)) on_bound = true;
    }
    // "The bound should be re-initialised through the optimisation, based on the
    // best solution found so far" (7.4.1): also while a round still improves.
    const bool improving = best_energy < before * (1.0 - options.recentre_improvement);
    if (!(on_bound || improving) || round == options.max_recentres || result.stopped()) break;
    centre = best;
  }
  result.best = evaluate_parameters(setup, best);
  result.seconds = seconds_since(t0);
  return result;
}

std::vector<double> widths_to_log_ratios(std::span<const double> parameters) {
  std::vector<double> y;
  if (parameters.size() < 3) return y;
  const double w0 = parameters[1] - parameters[0];
  for (std::size_t i = 2; i < parameters.size(); ++i) y.push_back(std::log((parameters[i] - parameters[i - 1]) / w0));
  return y;
}

std::vector<double> log_ratios_to_parameters(std::span<const double> y) {
  const std::size_t n = y.size() + 2;
  std::vector<double> p(n, 0.0);
  // Widths w_0 = 1, w_{i+1} = exp(y_i), normalised to sum 1; shift by the max for overflow safety.
  double ymax = 0.0;
  for (const double v : y) ymax = std::max(ymax, v);
  double total = std::exp(-ymax);
  for (const double v : y) total += std::exp(v - ymax);
  double acc = std::exp(-ymax);
  p[1] = acc / total;
  for (std::size_t i = 0; i < y.size(); ++i) {
    acc += std::exp(y[i] - ymax);
    p[i + 2] = acc / total;
  }
  p[n - 1] = 1.0;
  return p;
}

FairingResult fair_knots_deterministic(const KnotFairingSetup& setup, std::span<const double> start,
                                       const optim::NelderMeadOptions& options) {
  const auto t0 = Clock::now();
  setup.validate();
  check_parameters(setup, start);
  const std::vector<double> y0 = widths_to_log_ratios(start);
  const double scale = fairing_energy(setup, start);
  if (!(std::isfinite(scale) && scale > 0.0)) {
    throw Error(Errc::NumericalFailure, "the start parameters' energy " + num(scale) + " is not finite and > 0",
                ErrorWhere{.field = "parameters"});
  }
  std::vector<double> p(start.size());
  auto f = [&](std::span<const double> y) {
    p = log_ratios_to_parameters(y);
    for (std::size_t i = 1; i < p.size(); ++i) {
      if (!(p[i] > p[i - 1])) return std::numeric_limits<double>::quiet_NaN();  // widths underflowed
    }
    try {
      return fairing_energy(setup, p) / scale;
    } catch (const Error&) {
      return std::numeric_limits<double>::quiet_NaN();
    }
  };
  // The caller's callback sees the study's own terms: the simplex vertices as internal parameters
  // p_1..p_{N-2} (the GA's variables) and their energies E, not log-ratios and E / E_start.
  optim::NelderMeadOptions nm = options;
  optim::GenerationLog study_log;
  if (options.on_generation) {
    nm.on_generation = [&](const optim::GenerationLog& g) {
      study_log = g;
      const std::size_t d = g.dimension;
      for (std::size_t k = 0; k < g.size(); ++k) {
        const std::vector<double> q = log_ratios_to_parameters(std::span(g.variables).subspan(k * d, d));
        std::copy(q.begin() + 1, q.end() - 1, study_log.variables.begin() + static_cast<std::ptrdiff_t>(k * d));
      }
      for (double& v : study_log.objective_values) v *= scale;
      for (double& v : study_log.fitness) v *= scale;
      options.on_generation(study_log);
    };
  }
  const optim::NelderMeadResult r = optim::nelder_mead(f, y0, nm);
  FairingResult result;
  result.evaluations = r.report.evaluations + 1;
  result.rounds = 1;
  result.termination = r.report.termination;
  result.message = r.report.message;
  result.convergence.reserve(r.history.size());
  for (const double h : r.history) result.convergence.push_back(h * scale);
  std::vector<double> best = log_ratios_to_parameters(r.x);
  if (!(r.value * scale < scale)) best.assign(start.begin(), start.end());
  result.best = evaluate_parameters(setup, best);
  result.seconds = seconds_since(t0);
  return result;
}

}  // namespace hula::studies
