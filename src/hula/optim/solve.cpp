// SPDX-License-Identifier: MIT
#include "hula/optim/solve.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "hula/core/error.hpp"

namespace hula::optim {

namespace {

[[noreturn]] void refuse(const std::string& message, const char* field) {
  throw Error(Errc::InvalidOption, message, {.field = field});
}

// Nelder–Mead on a problem: its objective inside the bounds, NaN (ranked worst) outside them.
SolveResult solve_nelder_mead(const Problem& problem, const NelderMeadOptions& options,
                              const std::vector<double>& given_start) {
  problem.validate();
  if (problem.objectives != 1)
    refuse(
        "nelder-mead minimises one objective; problem " + problem.name + " has " + std::to_string(problem.objectives),
        "algorithm");
  if (problem.inequality_constraints + problem.equality_constraints > 0)
    refuse("nelder-mead takes no constraints beyond the bounds; problem " + problem.name + " has " +
               std::to_string(problem.inequality_constraints + problem.equality_constraints),
           "algorithm");
  const std::size_t d = problem.dimension();
  std::vector<double> start = given_start;
  if (start.empty()) {
    for (const Variable& v : problem.variables) start.push_back(v.lower + 0.5 * (v.upper - v.lower));
  } else if (start.size() != d) {
    refuse(
        "start has " + std::to_string(start.size()) + " values but the problem has " + std::to_string(d) + " variables",
        "start");
  }
  for (std::size_t i = 0; i < d; ++i) {
    const Variable& v = problem.variables[i];
    if (!(start[i] >= v.lower && start[i] <= v.upper))
      throw Error(Errc::InvalidOption,
                  "start[" + std::to_string(i) + "] = " + format_number(start[i]) + " is outside the bounds [" +
                      format_number(v.lower) + ", " + format_number(v.upper) + "] of variable " + std::to_string(i) +
                      (v.name.empty() ? "" : " (" + v.name + ")"),
                  {.field = "start", .index = i});
  }
  std::vector<double> values(problem.values_per_point());
  std::vector<std::uint8_t> failed(1);
  const auto f = [&](std::span<const double> x) {
    for (std::size_t i = 0; i < d; ++i)
      if (!(x[i] >= problem.variables[i].lower && x[i] <= problem.variables[i].upper))
        return std::numeric_limits<double>::quiet_NaN();
    (void)evaluate_batch(problem, x, values, failed);
    return failed[0] ? std::numeric_limits<double>::quiet_NaN() : values[0];
  };
  NelderMeadResult r = nelder_mead(f, start, options);
  SolveResult out;
  out.solutions.push_back(Solution{std::move(r.x), {r.value}, 0.0});
  out.report = std::move(r.report);
  return out;
}

}  // namespace

SolveResult solve_result(const Problem& problem, IslandsResult islands) {
  SolveResult out;
  // NSGA-II islands return populations, merged into the front; the GAs' islands their champions.
  const bool fronts = std::any_of(islands.islands.begin(), islands.islands.end(),
                                  [](const IslandReport& i) { return !i.population.empty(); });
  if (fronts || problem.objectives > 1)
    out.solutions = std::move(islands.front);
  else
    out.solutions.push_back(std::move(islands.best));
  out.report = std::move(islands.report);
  out.islands = std::move(islands.islands);
  return out;
}

namespace {
constexpr std::string_view kPagmoPrefix = "pagmo-";
constexpr std::array<std::string_view, 7> kPagmoNames{"cmaes", "de", "sade", "pso", "sga", "moead", "nsga2"};
}  // namespace

std::vector<std::string> solver_names() {
  std::vector<std::string> names{"ga-real", "ga-binary", "nsga2", "nelder-mead"};
  for (const std::string_view pagmo : kPagmoNames) names.push_back(std::string(kPagmoPrefix) + std::string(pagmo));
  return names;
}

SolverOptions solver_from_name(std::string_view name, std::string_view field) {
  if (name == "ga-real") return RealGaOptions{};
  if (name == "ga-binary") return BinaryGaOptions{};
  if (name == "nsga2") return Nsga2Options{};
  if (name == "nelder-mead") return NelderMeadOptions{};
  if (name.starts_with(kPagmoPrefix)) {
    const std::string_view pagmo = name.substr(kPagmoPrefix.size());
    if (std::find(kPagmoNames.begin(), kPagmoNames.end(), pagmo) != kPagmoNames.end()) {
      PagmoOptions o;
      o.algorithm = pagmo_algorithm(pagmo);
      return o;
    }
  }
  throw Error(Errc::InvalidArgument,
              std::string(field) + " = \"" + std::string(name) +
                  "\" is not an algorithm (expected ga-binary, ga-real, nsga2, nelder-mead or pagmo-<name> with "
                  "<name> one of cmaes, de, sade, pso, sga, moead, nsga2)",
              {.field = std::string(field)});
}

std::string solver_name(const SolverOptions& options) {
  if (std::holds_alternative<RealGaOptions>(options)) return "ga-real";
  if (std::holds_alternative<BinaryGaOptions>(options)) return "ga-binary";
  if (std::holds_alternative<Nsga2Options>(options)) return "nsga2";
  if (std::holds_alternative<NelderMeadOptions>(options)) return "nelder-mead";
  const PagmoAlgorithm a = std::get<PagmoOptions>(options).algorithm;
  for (const std::string_view n : kPagmoNames)
    if (pagmo_algorithm(n) == a) return std::string(kPagmoPrefix) + std::string(n);
  return std::string(kPagmoPrefix);
}

IslandAlgorithm island_algorithm(const SolverOptions& algorithm) {
  if (const auto* o = std::get_if<RealGaOptions>(&algorithm)) return *o;
  if (const auto* b = std::get_if<BinaryGaOptions>(&algorithm)) return *b;
  if (const auto* n = std::get_if<Nsga2Options>(&algorithm)) return *n;
  refuse("islands run the GAs and NSGA-II only", "islands");
}

SolveResult solve(const Problem& problem, const SolveOptions& options) {
  const bool nelder_mead_chosen = std::holds_alternative<NelderMeadOptions>(options.algorithm);
  if (!options.start.empty() && !nelder_mead_chosen) refuse("start is taken by nelder-mead only", "start");
  if (options.islands)
    return solve_result(problem, solve_islands(problem, island_algorithm(options.algorithm), *options.islands));
  SolveResult out;
  if (const auto* o = std::get_if<RealGaOptions>(&options.algorithm)) {
    GaResult r = solve_real_ga(problem, *o);
    out.solutions.push_back(std::move(r.best));
    out.report = std::move(r.report);
  } else if (const auto* b = std::get_if<BinaryGaOptions>(&options.algorithm)) {
    GaResult r = solve_binary_ga(problem, *b);
    out.solutions.push_back(std::move(r.best));
    out.report = std::move(r.report);
  } else if (const auto* n = std::get_if<Nsga2Options>(&options.algorithm)) {
    Nsga2Result r = solve_nsga2(problem, *n);
    out.solutions = std::move(r.front);
    out.population = std::move(r.population);
    out.report = std::move(r.report);
  } else if (const auto* m = std::get_if<NelderMeadOptions>(&options.algorithm)) {
    return solve_nelder_mead(problem, *m, options.start);
  } else {
    PagmoResult r = solve_with_pagmo(problem, std::get<PagmoOptions>(options.algorithm));
    if (problem.objectives == 1)
      out.solutions.push_back(std::move(r.best));
    else
      out.solutions = std::move(r.front);
    out.report = std::move(r.report);
  }
  return out;
}

}  // namespace hula::optim
