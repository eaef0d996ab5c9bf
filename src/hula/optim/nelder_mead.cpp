// SPDX-License-Identifier: MIT
#include "hula/optim/nelder_mead.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <string>

#include "hula/core/error.hpp"

namespace hula::optim {

namespace {

[[noreturn]] void bad_option(const std::string& field, double value, const std::string& rule) {
  throw Error(Errc::InvalidOption, "NelderMeadOptions." + field + " = " + std::to_string(value) + " must be " + rule,
              ErrorWhere{.field = field});
}

// NaN ranks worst.
double rank_value(double v) { return std::isnan(v) ? std::numeric_limits<double>::infinity() : v; }

}  // namespace

void NelderMeadOptions::validate() const {
  if (!(std::isfinite(initial_step) && initial_step > 0.0)) bad_option("initial_step", initial_step, "finite and > 0");
  if (!(std::isfinite(x_tolerance) && x_tolerance >= 0.0)) bad_option("x_tolerance", x_tolerance, "finite and >= 0");
  if (!(std::isfinite(f_tolerance) && f_tolerance >= 0.0)) bad_option("f_tolerance", f_tolerance, "finite and >= 0");
  if (max_evaluations == 0) bad_option("max_evaluations", 0.0, ">= 1");
  if (!std::isfinite(wall_time_seconds) || wall_time_seconds < 0.0)
    bad_option("wall_time_seconds", wall_time_seconds, "finite and >= 0");
}

NelderMeadResult nelder_mead(const ObjectiveFn& f, std::span<const double> start, const NelderMeadOptions& options) {
  options.validate();
  const std::size_t n = start.size();
  if (n == 0) throw Error(Errc::InvalidArgument, "nelder_mead: the start point is empty", ErrorWhere{.field = "start"});
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(start[i])) {
      throw Error(Errc::NonFiniteInput, "nelder_mead: start[" + std::to_string(i) + "] is not finite",
                  ErrorWhere{.field = "start", .index = i});
    }
  }
  // Gao & Han (2012) adaptive coefficients (standard ones for n = 2).
  const double dn = static_cast<double>(n);
  const double alpha = 1.0;
  const double beta = 1.0 + 2.0 / dn;
  const double gamma = 0.75 - 1.0 / (2.0 * dn);
  const double delta = 1.0 - 1.0 / dn;

  NelderMeadResult result;
  std::vector<double> simplex((n + 1) * n);
  std::vector<double> values(n + 1);
  std::vector<std::size_t> order(n + 1);
  std::vector<double> centroid(n), trial(n), trial2(n);
  auto vertex = [&](std::size_t k) { return std::span<double>(simplex.data() + k * n, n); };
  RunReport& report = result.report;
  // The simplex as one generation of the progress callback (generation_log.generation set by the caller).
  GenerationLog generation_log;
  const auto report_simplex = [&](std::size_t generation) {
    if (!options.on_generation) return;
    GenerationLog& g = generation_log;
    g.generation = generation;
    g.evaluations = report.evaluations;
    g.dimension = n;
    g.objectives = 1;
    g.variables = simplex;
    g.objective_values = values;
    g.violation.assign(n + 1, 0.0);
    g.fitness = values;
    g.failed.resize(n + 1);
    for (std::size_t k = 0; k <= n; ++k) g.failed[k] = std::isfinite(values[k]) ? 0 : 1;
    options.on_generation(g);
  };
  auto eval = [&](std::span<const double> x) {
    ++report.evaluations;
    const double v = f(x);
    if (!std::isfinite(v)) ++report.failed_evaluations;
    return rank_value(v);
  };

  std::vector<double> best(start.begin(), start.end());
  double best_value = eval(best);
  if (!std::isfinite(best_value)) {
    throw Error(Errc::NumericalFailure, "nelder_mead: the objective is not finite at the start point");
  }
  bool converged = false;
  const auto started = std::chrono::steady_clock::now();
  const auto stop_requested = [&] {
    if (options.cancel != nullptr && options.cancel->is_cancelled()) return true;
    if (deadline_passed(options.deadline)) return true;
    return options.wall_time_seconds > 0.0 &&
           std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count() >=
               options.wall_time_seconds;
  };
  std::optional<Termination> stopped;
  std::size_t rounds = 0;
  for (std::size_t round = 0; round <= options.restarts && !stopped; ++round) {
    ++rounds;
    // Fresh simplex around the best point.
    for (std::size_t k = 0; k <= n; ++k) {
      auto v = vertex(k);
      std::copy(best.begin(), best.end(), v.begin());
      if (k > 0) v[k - 1] += options.initial_step;
      values[k] = k == 0 ? best_value : eval(v);
    }
    const double round_start = best_value;
    converged = false;
    while (report.evaluations < options.max_evaluations) {
      if (stop_requested()) {
        stopped = options.cancel != nullptr && options.cancel->is_cancelled() ? Termination::Cancelled
                                                                              : Termination::WallTime;
        break;
      }
      std::iota(order.begin(), order.end(), std::size_t{0});
      std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
      const std::size_t lo = order[0];
      const std::size_t hi = order[n];
      const std::size_t second = order[n - 1];
      result.history.push_back(values[lo]);
      report_simplex(result.history.size() - 1);
      // Convergence test.
      double x_spread = 0.0;
      for (std::size_t k = 0; k <= n; ++k) {
        for (std::size_t i = 0; i < n; ++i) x_spread = std::max(x_spread, std::abs(vertex(k)[i] - vertex(lo)[i]));
      }
      if (x_spread <= options.x_tolerance && values[hi] - values[lo] <= options.f_tolerance) {
        converged = true;
        break;
      }
      std::fill(centroid.begin(), centroid.end(), 0.0);
      for (std::size_t k = 0; k <= n; ++k) {
        if (k == hi) continue;
        for (std::size_t i = 0; i < n; ++i) centroid[i] += vertex(k)[i] / dn;
      }
      auto worst = vertex(hi);
      for (std::size_t i = 0; i < n; ++i) trial[i] = centroid[i] + alpha * (centroid[i] - worst[i]);
      const double fr = eval(trial);
      if (fr < values[lo]) {
        for (std::size_t i = 0; i < n; ++i) trial2[i] = centroid[i] + beta * (trial[i] - centroid[i]);
        const double fe = eval(trial2);
        if (fe < fr) {
          std::copy(trial2.begin(), trial2.end(), worst.begin());
          values[hi] = fe;
        } else {
          std::copy(trial.begin(), trial.end(), worst.begin());
          values[hi] = fr;
        }
        continue;
      }
      if (fr < values[second]) {
        std::copy(trial.begin(), trial.end(), worst.begin());
        values[hi] = fr;
        continue;
      }
      // Contraction: outside if the reflection beat the worst, else inside.
      const bool outside = fr < values[hi];
      for (std::size_t i = 0; i < n; ++i) {
        trial2[i] =
            outside ? centroid[i] + gamma * (trial[i] - centroid[i]) : centroid[i] - gamma * (centroid[i] - worst[i]);
      }
      const double fc = eval(trial2);
      if (fc < (outside ? fr : values[hi])) {
        std::copy(trial2.begin(), trial2.end(), worst.begin());
        values[hi] = fc;
        continue;
      }
      // Shrink towards the best vertex.
      for (std::size_t k = 0; k <= n; ++k) {
        if (k == lo) continue;
        auto v = vertex(k);
        for (std::size_t i = 0; i < n; ++i) v[i] = vertex(lo)[i] + delta * (v[i] - vertex(lo)[i]);
        values[k] = eval(v);
      }
    }
    const std::size_t lo = static_cast<std::size_t>(std::min_element(values.begin(), values.end()) - values.begin());
    if (values[lo] <= best_value) {
      best_value = values[lo];
      std::copy(vertex(lo).begin(), vertex(lo).end(), best.begin());
    }
    if (!converged) break;
    // A restart that found nothing better ends the run.
    if (round > 0 && !(best_value < round_start - options.f_tolerance)) break;
  }
  // The last generation: the final simplex (it holds the best point: a round starts from it and never
  // loses its lowest vertex).
  report_simplex(result.history.size());
  result.x = std::move(best);
  result.value = best_value;
  report.generations = result.history.size();
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  const std::string after = " after " + std::to_string(report.generations) + " iterations and " +
                            std::to_string(report.evaluations) + " evaluations";
  if (stopped) {
    report.termination = *stopped;
    report.message = (*stopped == Termination::Cancelled ? "cancelled" : "wall-time limit reached") + after;
  } else if (converged) {
    report.termination = Termination::Converged;
    report.message = "simplex within x_tolerance and f_tolerance" + after + " (" + std::to_string(rounds) +
                     (rounds == 1 ? " round)" : " rounds)");
  } else {
    report.termination = Termination::MaxEvaluations;
    report.message =
        "evaluation budget max_evaluations = " + std::to_string(options.max_evaluations) + " spent" + after;
  }
  return result;
}

}  // namespace hula::optim
