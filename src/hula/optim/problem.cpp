// SPDX-License-Identifier: MIT
#include "hula/optim/problem.hpp"

#include <cmath>
#include <exception>
#include <limits>
#include <mutex>

#include "hula/core/error.hpp"
#include "hula/core/nan.hpp"
#include "hula/core/parallel.hpp"

namespace hula::optim {
namespace {
std::string var_field(std::size_t i, const char* member) { return "variables[" + std::to_string(i) + "]." + member; }
}  // namespace

std::size_t bits_for(const Variable& variable, std::size_t index) {
  const double range = variable.upper - variable.lower;
  if (!std::isfinite(variable.precision) || variable.precision <= 0.0) {
    throw Error(
        Errc::InvalidOption,
        var_field(index, "precision") + " = " + format_number(variable.precision) + " must be > 0 for binary coding",
        {.field = var_field(index, "precision"), .index = index});
  }
  if (range <= 0.0) return 1;
  // Smallest b with range / (2^b - 1) <= precision, i.e. 2^b >= range/precision + 1.
  const double levels = range / variable.precision + 1.0;
  const double b = std::ceil(std::log2(levels));
  if (!(b <= 52.0)) {
    throw Error(Errc::InvalidOption,
                var_field(index, "precision") + " = " + format_number(variable.precision) + " over range " +
                    format_number(range) + " needs " + format_number(b) + " bits, finer than the 52 bits of a double",
                {.field = var_field(index, "precision"), .index = index});
  }
  std::size_t bits = b < 1.0 ? 1 : static_cast<std::size_t>(b);
  // log2 may round: make sure the resolution really meets the precision.
  while (bits < 52 && range / (std::ldexp(1.0, static_cast<int>(bits)) - 1.0) > variable.precision) ++bits;
  return bits;
}

void Problem::validate() const {
  if (variables.empty()) {
    throw Error(Errc::InvalidOption, "variables is empty: a problem needs at least one variable",
                {.field = "variables"});
  }
  for (std::size_t i = 0; i < variables.size(); ++i) {
    const Variable& v = variables[i];
    if (!std::isfinite(v.lower)) {
      throw Error(Errc::InvalidOption, var_field(i, "lower") + " = " + format_number(v.lower) + " must be finite",
                  {.field = var_field(i, "lower"), .index = i});
    }
    if (!std::isfinite(v.upper)) {
      throw Error(Errc::InvalidOption, var_field(i, "upper") + " = " + format_number(v.upper) + " must be finite",
                  {.field = var_field(i, "upper"), .index = i});
    }
    if (v.lower > v.upper) {
      throw Error(Errc::InvalidOption,
                  var_field(i, "lower") + " = " + format_number(v.lower) + " > upper = " + format_number(v.upper) +
                      ": inverted bounds",
                  {.field = var_field(i, "lower"), .index = i});
    }
    // The samplers compute lower + (upper - lower) * u: the width must be a finite double.
    if (!std::isfinite(v.upper - v.lower)) {
      throw Error(Errc::InvalidOption,
                  var_field(i, "lower") + " = " + format_number(v.lower) + ", upper = " + format_number(v.upper) +
                      ": the width upper - lower overflows a double (at most ~1.8e308)",
                  {.field = var_field(i, "lower"), .index = i});
    }
    if (std::isnan(v.precision) || v.precision < 0.0) {
      throw Error(Errc::InvalidOption, var_field(i, "precision") + " = " + format_number(v.precision) + " must be >= 0",
                  {.field = var_field(i, "precision"), .index = i});
    }
    if (v.precision > 0.0) (void)bits_for(v, i);
  }
  if (objectives == 0) {
    throw Error(Errc::InvalidOption, "objectives = 0 must be >= 1", {.field = "objectives"});
  }
  if (!std::isfinite(equality_tolerance) || equality_tolerance < 0.0) {
    throw Error(Errc::InvalidOption,
                "equality_tolerance = " + format_number(equality_tolerance) + " must be finite and >= 0",
                {.field = "equality_tolerance"});
  }
  if (!evaluate && !evaluate_many)
    throw Error(Errc::InvalidOption, "evaluate is empty: set the evaluation function", {.field = "evaluate"});
}

double Problem::violation(std::span<const double> values) const noexcept {
  // NaN first: ordered comparisons with NaN raise FE_INVALID (trapped in Debug tests).
  for (std::size_t i = objectives; i < values_per_point(); ++i) {
    if (std::isnan(values[i])) return std::numeric_limits<double>::quiet_NaN();
  }
  double v = 0.0;
  const std::size_t g0 = objectives;
  for (std::size_t i = 0; i < inequality_constraints; ++i) v += std::max(0.0, values[g0 + i]);
  const std::size_t h0 = g0 + inequality_constraints;
  for (std::size_t j = 0; j < equality_constraints; ++j) {
    v += std::max(0.0, std::fabs(values[h0 + j]) - equality_tolerance);
  }
  return v;
}

BatchReport evaluate_batch(const Problem& problem, std::span<const double> points, std::span<double> values,
                           std::span<std::uint8_t> failed, const BatchOptions& options) {
  const std::size_t d = problem.dimension();
  const std::size_t k = problem.values_per_point();
  if (d == 0 || points.size() % d != 0) {
    throw Error(
        Errc::InvalidArgument,
        "points has " + std::to_string(points.size()) + " numbers, not a multiple of dimension " + std::to_string(d),
        {.field = "points"});
  }
  const std::size_t n = points.size() / d;
  if (values.size() != n * k) {
    throw Error(Errc::InvalidArgument,
                "values has " + std::to_string(values.size()) + " numbers, expected " + std::to_string(n * k),
                {.field = "values"});
  }
  if (failed.size() != n) {
    throw Error(Errc::InvalidArgument,
                "failed has " + std::to_string(failed.size()) + " flags, expected " + std::to_string(n),
                {.field = "failed"});
  }
  BatchReport report;
  std::mutex mutex;
  auto mark_failed = [&](std::size_t i, const std::string& message) {
    failed[i] = 1;
    for (std::size_t j = 0; j < k; ++j) values[i * k + j] = kNaN;
    const std::scoped_lock lock(mutex);
    ++report.failed;
    if (i < report.first_failed) {
      report.first_failed = i;
      report.first_message = message;
    }
  };
  if (problem.evaluate_many) {
    problem.evaluate_many(points, values);
    for (std::size_t i = 0; i < n; ++i) {
      failed[i] = 0;
      for (std::size_t j = 0; j < k; ++j) {
        if (!std::isfinite(values[i * k + j])) {
          mark_failed(i, "non-finite value at position " + std::to_string(j));
          break;
        }
      }
    }
    return report;
  }
  parallel_for(0, n,
               [&](std::size_t i) {
                 const auto x = points.subspan(i * d, d);
                 const auto out = values.subspan(i * k, k);
                 failed[i] = 0;
                 try {
                   problem.evaluate(x, out);
                 } catch (const std::exception& e) {
                   mark_failed(i, e.what());
                   if (options.rethrow) throw;
                   return;
                 } catch (...) {
                   mark_failed(i, "unknown exception");
                   if (options.rethrow) throw;
                   return;
                 }
                 for (std::size_t j = 0; j < k; ++j) {
                   if (!std::isfinite(out[j])) {
                     mark_failed(i, "non-finite value at position " + std::to_string(j));
                     return;
                   }
                 }
               },
               {.threads = options.threads, .grain = 1});
  return report;
}

std::vector<BoundHit> bound_hits(std::span<const Variable> variables, std::span<const double> x, double fraction) {
  if (x.size() != variables.size())
    throw Error(
        Errc::InvalidArgument,
        "bound_hits: " + std::to_string(x.size()) + " values for " + std::to_string(variables.size()) + " variables",
        {.field = "x"});
  if (!(fraction >= 0.0 && fraction < 0.5))
    throw Error(Errc::InvalidArgument, "bound_hits: fraction = " + format_number(fraction) + " must be in [0, 0.5)",
                {.field = "fraction"});
  std::vector<BoundHit> hits;
  for (std::size_t j = 0; j < x.size(); ++j) {
    const double width = variables[j].upper - variables[j].lower;
    if (!(width > 0.0)) continue;
    if (x[j] <= variables[j].lower + fraction * width)
      hits.push_back({j, false, x[j]});
    else if (x[j] >= variables[j].upper - fraction * width)
      hits.push_back({j, true, x[j]});
  }
  return hits;
}

std::vector<std::string> bound_warnings(std::span<const Variable> variables, std::span<const BoundHit> hits) {
  std::vector<std::string> lines;
  for (const BoundHit& h : hits) {
    const Variable& v = variables[h.variable];
    const std::string name = v.name.empty() ? "x" + std::to_string(h.variable) : v.name;
    lines.push_back(name + " = " + format_number(h.value) + " is on its " + (h.upper ? "upper" : "lower") + " bound " +
                    format_number(h.upper ? v.upper : v.lower) +
                    ": the optimum may lie beyond it (widen the bounds or re-run re-centred)");
  }
  return lines;
}

}  // namespace hula::optim
