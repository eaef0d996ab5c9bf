// SPDX-License-Identifier: MIT
#include "hula/optim/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>

#include "hula/core/error.hpp"
#include "hula/core/nan.hpp"

namespace hula::optim {
namespace {

void check_axis(const Problem& p, const SweepAxis& a, const char* name) {
  const std::string field = name;
  if (a.variable >= p.dimension()) {
    throw Error(
        Errc::InvalidOption,
        field + ".variable = " + std::to_string(a.variable) + " must be < dimension = " + std::to_string(p.dimension()),
        {.field = field + ".variable"});
  }
  if (a.steps < 2) {
    throw Error(Errc::InvalidOption, field + ".steps = " + std::to_string(a.steps) + " must be >= 2",
                {.field = field + ".steps"});
  }
  if (std::isinf(a.from)) {
    throw Error(Errc::InvalidOption, field + ".from = " + format_number(a.from) + " must be finite",
                {.field = field + ".from"});
  }
  if (std::isinf(a.to)) {
    throw Error(Errc::InvalidOption, field + ".to = " + format_number(a.to) + " must be finite",
                {.field = field + ".to"});
  }
}

std::vector<double> samples(const Problem& p, const SweepAxis& a) {
  const double from = std::isnan(a.from) ? p.variables[a.variable].lower : a.from;
  const double to = std::isnan(a.to) ? p.variables[a.variable].upper : a.to;
  std::vector<double> v(a.steps);
  for (std::size_t i = 0; i < a.steps; ++i) {
    v[i] = i + 1 == a.steps ? to : from + (to - from) * static_cast<double>(i) / static_cast<double>(a.steps - 1);
  }
  return v;
}
}  // namespace

void SweepOptions::validate(const Problem& problem) const {
  problem.validate();
  if (nominal.size() != problem.dimension()) {
    throw Error(Errc::InvalidOption,
                "nominal has " + std::to_string(nominal.size()) +
                    " values, expected dimension = " + std::to_string(problem.dimension()),
                {.field = "nominal"});
  }
  for (std::size_t i = 0; i < nominal.size(); ++i) {
    if (!std::isfinite(nominal[i])) {
      throw Error(Errc::InvalidOption, "nominal[" + std::to_string(i) + "] = " + format_number(nominal[i]),
                  {.field = "nominal", .index = i});
    }
  }
  check_axis(problem, x, "x");
  if (y) check_axis(problem, *y, "y");
  if (objective >= problem.objectives) {
    throw Error(
        Errc::InvalidOption,
        "objective = " + std::to_string(objective) + " must be < objectives = " + std::to_string(problem.objectives),
        {.field = "objective"});
  }
  if (!std::isfinite(power) || power <= 0.0) {
    throw Error(Errc::InvalidOption, "power = " + format_number(power) + " must be finite and > 0", {.field = "power"});
  }
}

SweepResult sweep(const Problem& problem, const SweepOptions& options) {
  options.validate(problem);
  SweepResult r;
  r.x_values = samples(problem, options.x);
  if (options.y) r.y_values = samples(problem, *options.y);
  const std::size_t nx = r.x_values.size();
  const std::size_t ny = options.y ? r.y_values.size() : 1;
  const std::size_t d = problem.dimension();
  const std::size_t k = problem.values_per_point();
  std::vector<double> points(nx * ny * d);
  for (std::size_t row = 0; row < ny; ++row) {
    for (std::size_t col = 0; col < nx; ++col) {
      double* x = &points[(row * nx + col) * d];
      std::copy(options.nominal.begin(), options.nominal.end(), x);
      x[options.x.variable] = r.x_values[col];
      if (options.y) x[options.y->variable] = r.y_values[row];
    }
  }
  std::vector<double> values(nx * ny * k);
  std::vector<std::uint8_t> failed(nx * ny);
  r.failed = evaluate_batch(problem, points, values, failed, {.threads = options.threads}).failed;
  r.objective.resize(nx * ny);
  r.violation.resize(nx * ny);
  r.fitness.resize(nx * ny);
  double shift = 0.0;
  for (std::size_t i = 0; i < nx * ny; ++i) {
    r.objective[i] = failed[i] ? kNaN : values[i * k + options.objective];
    r.violation[i] = failed[i] ? kNaN : problem.violation({&values[i * k], k});
    if (!failed[i]) shift = std::min(shift, r.objective[i]);
  }
  for (std::size_t i = 0; i < nx * ny; ++i) {
    r.fitness[i] = failed[i] ? 0.0 : boosted_fitness(r.objective[i] - shift, options.power);
    if (failed[i]) std::fill_n(values.begin() + static_cast<std::ptrdiff_t>(i * k), k, kNaN);
  }
  r.values = std::move(values);
  return r;
}

Problem recentred(const Problem& problem, std::span<const double> centre, double shrink) {
  problem.validate();
  if (!(shrink > 0.0 && shrink <= 1.0)) {
    throw Error(Errc::InvalidOption, "shrink = " + format_number(shrink) + " must be in (0, 1]", {.field = "shrink"});
  }
  if (centre.size() != problem.dimension()) {
    throw Error(Errc::InvalidOption,
                "centre has " + std::to_string(centre.size()) +
                    " values, expected dimension = " + std::to_string(problem.dimension()),
                {.field = "centre"});
  }
  Problem out = problem;
  for (std::size_t i = 0; i < centre.size(); ++i) {
    const Variable& v = problem.variables[i];
    if (!(centre[i] >= v.lower && centre[i] <= v.upper)) {
      throw Error(Errc::InvalidOption,
                  "centre[" + std::to_string(i) + "] = " + format_number(centre[i]) + " is outside [" +
                      format_number(v.lower) + ", " + format_number(v.upper) + "]",
                  {.field = "centre", .index = i});
    }
    const double half = 0.5 * shrink * (v.upper - v.lower);
    out.variables[i].lower = std::max(v.lower, centre[i] - half);
    out.variables[i].upper = std::min(v.upper, centre[i] + half);
  }
  return out;
}

RecentredRunResult rerun_recentred(const Problem& problem, const RealGaOptions& options, std::size_t rounds,
                                   double shrink) {
  if (!(shrink > 0.0 && shrink <= 1.0)) {
    throw Error(Errc::InvalidOption, "shrink = " + format_number(shrink) + " must be in (0, 1]", {.field = "shrink"});
  }
  RecentredRunResult result;
  RealGaOptions o = options;
  Problem current = problem;
  for (std::size_t round = 0; round <= rounds; ++round) {
    o.run.seed = options.run.seed + round;
    GaResult r = solve_real_ga(current, o);
    result.reports.push_back(r.report);
    const bool improved = result.round_best.empty() || r.best.objectives[0] < result.best.objectives[0];
    if (improved) result.best = r.best;
    result.round_best.push_back(r.best.objectives[0]);
    if (round < rounds) current = recentred(current, result.best.variables, shrink);
  }
  return result;
}

ConvergenceSummary convergence(const RunLog& log, std::size_t window) {
  if (window < 2) {
    throw Error(Errc::InvalidOption, "window = " + std::to_string(window) + " must be >= 2", {.field = "window"});
  }
  ConvergenceSummary s;
  for (const auto& g : log.generations()) s.generations.push_back(statistics(g));
  // Least squares of best-so-far b(g) against g over the last `window` generations.
  const std::size_t n = s.generations.size();
  if (n < 2) {
    s.slope = kNaN;
    return s;
  }
  std::vector<double> best_so_far(n);
  double running = kNaN;
  for (std::size_t i = 0; i < n; ++i) {
    const double b = s.generations[i].best;
    if (!std::isnan(b) && (std::isnan(running) || b < running)) running = b;
    best_so_far[i] = running;
  }
  const std::size_t first = n > window ? n - window : 0;
  double sg = 0, sb = 0, sgg = 0, sgb = 0;
  std::size_t count = 0;
  for (std::size_t i = first; i < n; ++i) {
    if (std::isnan(best_so_far[i])) continue;
    const auto g = static_cast<double>(s.generations[i].generation);
    sg += g;
    sb += best_so_far[i];
    sgg += g * g;
    sgb += g * best_so_far[i];
    ++count;
  }
  const double c = static_cast<double>(count);
  const double denominator = c * sgg - sg * sg;
  s.slope = count >= 2 && denominator > 0 ? (c * sgb - sg * sb) / denominator : kNaN;
  return s;
}

std::vector<Solution> distinct_best(const RunLog& log, std::span<const Variable> variables, std::size_t count,
                                    double radius) {
  if (count == 0) throw Error(Errc::InvalidOption, "distinct_best: count must be >= 1", {.field = "count"});
  if (!(radius > 0.0 && radius <= 1.0))
    throw Error(Errc::InvalidOption, "distinct_best: radius = " + format_number(radius) + " must be in (0, 1]",
                {.field = "radius"});
  const std::size_t d = variables.size();
  struct Entry {
    const GenerationLog* generation;
    std::size_t index;
  };
  std::vector<Entry> all;
  for (const GenerationLog& g : log.generations()) {
    if (g.dimension != d)
      throw Error(
          Errc::InvalidOption,
          "distinct_best: the log has " + std::to_string(g.dimension) + " variables, the problem " + std::to_string(d),
          {.field = "log"});
    for (std::size_t i = 0; i < g.size(); ++i)
      if (!g.failed[i] && std::isfinite(g.objective_values[i * g.objectives])) all.push_back({&g, i});
  }
  auto objective = [](const Entry& e) { return e.generation->objective_values[e.index * e.generation->objectives]; };
  auto violation = [](const Entry& e) { return e.generation->violation[e.index]; };
  std::stable_sort(all.begin(), all.end(), [&](const Entry& a, const Entry& b) {
    if (violation(a) != violation(b)) return violation(a) < violation(b);
    return objective(a) < objective(b);
  });
  std::vector<Solution> kept;
  for (const Entry& e : all) {
    if (kept.size() == count) break;
    const double* x = e.generation->variables.data() + e.index * d;
    bool distinct = true;
    for (const Solution& k : kept) {
      double sum = 0.0;
      for (std::size_t j = 0; j < d; ++j) {
        const double w = variables[j].upper - variables[j].lower;
        if (w > 0.0) sum += ((x[j] - k.variables[j]) / w) * ((x[j] - k.variables[j]) / w);
      }
      if (std::sqrt(sum / static_cast<double>(std::max<std::size_t>(d, 1))) <= radius) {
        distinct = false;
        break;
      }
    }
    if (!distinct) continue;
    Solution s;
    s.variables.assign(x, x + d);
    const std::size_t k = e.generation->objectives;
    s.objectives.assign(e.generation->objective_values.begin() + static_cast<std::ptrdiff_t>(e.index * k),
                        e.generation->objective_values.begin() + static_cast<std::ptrdiff_t>((e.index + 1) * k));
    s.violation = violation(e);
    kept.push_back(std::move(s));
  }
  return kept;
}

}  // namespace hula::optim
