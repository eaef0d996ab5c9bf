// SPDX-License-Identifier: MIT
// Island model quality (docs/benchmarks.md "Islands"): K = 4 islands of 50
// against one population of 200 at the same number of evaluations, on
// Rastrigin-30 and Schwefel-30 (Flexo's real-coded GA, best objective) and
// ZDT1 / ZDT3 (NSGA-II, hypervolume of the final front, reference 1.1 per
// objective; populations 4 x 52 and 208, NSGA-II needing multiples of 4),
// over 10 seeds, and beside pagmo2's archipelago (sga / nsga2 on thread
// islands, ring topology, pagmo's default select-best / fair-replace
// migration) with the same sizes in the same run. A last column runs NSGA-II
// as one island of N: the islands' external archive without the islands, to
// show what the archive alone is worth. Prints a Markdown table of medians
// (and quartiles). Not a Google Benchmark: it measures quality, not time.
//
//   build/bench/bench/optim/bench_optim_islands_quality [generations=500] [seeds=10] [problems=all]
//       [interval=10] [migrants=2]
//
// problems: a comma-separated subset of rastrigin,schwefel,zdt1,zdt3.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <pagmo/algorithm.hpp>
#include <pagmo/algorithms/nsga2.hpp>
#include <pagmo/algorithms/sga.hpp>
#include <pagmo/archipelago.hpp>
#include <pagmo/islands/thread_island.hpp>
#include <pagmo/population.hpp>
#include <pagmo/problem.hpp>
#include <pagmo/problems/rastrigin.hpp>
#include <pagmo/problems/schwefel.hpp>
#include <pagmo/problems/zdt.hpp>
#include <pagmo/topologies/ring.hpp>
#include <pagmo/utils/hypervolume.hpp>
#include <string>
#include <vector>

#include "hula/optim/islands.hpp"
#include "hula/optim/pareto.hpp"
#include "hula/optim/test_problems.hpp"

namespace {

using namespace hula::optim;  // NOLINT(google-build-using-namespace): a benchmark program

constexpr std::size_t kIslands = 4;
// Migration settings (arguments 4 and 5): generations between migrations, Flexo's migrants per neighbour.
std::size_t g_interval = 10;  // NOLINT(cppcoreguidelines-avoid-non-const-global-variables): set once by main
std::size_t g_migrants = 2;   // NOLINT(cppcoreguidelines-avoid-non-const-global-variables): set once by main

struct Stats {
  double q1, median, q3;
};

Stats quartiles(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const auto at = [&](double q) {
    const double pos = q * static_cast<double>(v.size() - 1);
    const auto lo = static_cast<std::size_t>(pos);
    const std::size_t hi = std::min(lo + 1, v.size() - 1);
    return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
  };
  return {at(0.25), at(0.5), at(0.75)};
}

double hv(const std::vector<Solution>& front) {
  std::vector<double> pts;
  for (const Solution& s : front)
    if (s.violation == 0.0) pts.insert(pts.end(), s.objectives.begin(), s.objectives.end());
  const std::vector<double> ref{1.1, 1.1};
  return hypervolume(pts, 2, ref);
}

double pagmo_hv(const std::vector<pagmo::vector_double>& f) {
  std::vector<double> pts;
  for (const auto& p : f) pts.insert(pts.end(), p.begin(), p.end());
  const std::vector<double> ref{1.1, 1.1};
  return hypervolume(pts, 2, ref);
}

// pagmo's first front of a set of objective vectors.
std::vector<pagmo::vector_double> pagmo_front(const std::vector<pagmo::vector_double>& f) {
  std::vector<double> flat;
  for (const auto& p : f) flat.insert(flat.end(), p.begin(), p.end());
  const ParetoRanking r = non_dominated_sort(flat, 2);
  std::vector<pagmo::vector_double> out;
  for (std::size_t i = 0; i < f.size(); ++i)
    if (r.rank[i] == 0 && f[i][0] <= 1.1 && f[i][1] <= 1.1) out.push_back(f[i]);
  return out;
}

pagmo::problem pagmo_problem(const std::string& name) {
  if (name == "rastrigin") return pagmo::problem(pagmo::rastrigin(30));
  if (name == "schwefel") return pagmo::problem(pagmo::schwefel(30));
  if (name == "zdt1") return pagmo::problem(pagmo::zdt(1, 30));
  return pagmo::problem(pagmo::zdt(3, 30));
}

pagmo::algorithm pagmo_algorithm(bool multi, unsigned gen, unsigned seed) {
  if (multi) return pagmo::algorithm(pagmo::nsga2(gen, 0.95, 10., 0.01, 50., seed));
  return pagmo::algorithm(pagmo::sga(gen, .90, 1., .02, 1., 2u, "sbx", "polynomial", "tournament", seed));
}

// pagmo: one population of `single` for `generations`, or an archipelago of kIslands x `per_island`
// evolving g_interval generations between migrations (pagmo migrates its default one individual).
double run_pagmo(const std::string& name, bool archipelago, std::size_t single, std::size_t per_island,
                 std::size_t generations, unsigned seed) {
  const bool multi = name.starts_with("zdt");
  const pagmo::problem prob = pagmo_problem(name);
  if (!archipelago) {
    pagmo::population pop(prob, single, seed);
    pop = pagmo_algorithm(multi, static_cast<unsigned>(generations), seed).evolve(pop);
    if (multi) return pagmo_hv(pagmo_front(pop.get_f()));
    return pop.champion_f()[0];
  }
  pagmo::archipelago archi{pagmo::topology{pagmo::ring{}}};
  for (std::size_t i = 0; i < kIslands; ++i) {
    archi.push_back(pagmo::thread_island{}, pagmo_algorithm(multi, g_interval, seed * 100 + static_cast<unsigned>(i)),
                    prob, per_island, seed * 100 + i);
  }
  archi.evolve(static_cast<unsigned>(generations / g_interval));
  archi.wait_check();
  if (multi) {
    std::vector<pagmo::vector_double> all;
    for (const auto& isl : archi) {
      const auto f = isl.get_population().get_f();
      all.insert(all.end(), f.begin(), f.end());
    }
    return pagmo_hv(pagmo_front(all));
  }
  double best = 1e300;
  for (const auto& f : archi.get_champions_f()) best = std::min(best, f[0]);
  return best;
}

// Flexo with `k` islands of `population` (k = 0: the plain algorithm, no island machinery; k = 1: one
// island, which for NSGA-II adds the islands' external archive and nothing else).
double run_flexo(const std::string& name, std::size_t k, std::size_t population, std::size_t generations,
                 std::uint64_t seed) {
  const bool multi = name.starts_with("zdt");
  const Problem p = name == "rastrigin"  ? rastrigin(30)
                    : name == "schwefel" ? schwefel(30)
                    : name == "zdt1"     ? zdt(1, 30)
                                         : zdt(3, 30);
  IslandOptions o;
  o.islands = k;
  o.interval = g_interval;
  o.migrants = g_migrants;
  if (multi) {
    Nsga2Options a;
    a.population = population;
    a.run.seed = seed;
    a.run.stop.generations = generations;
    if (k > 0) return hv(solve_islands(p, a, o).front);
    return hv(solve_nsga2(p, a).front);
  }
  RealGaOptions a;
  a.population = population;
  a.run.seed = seed;
  a.run.stop.generations = generations;
  if (k > 0) return solve_islands(p, a, o).best.objectives[0];
  return solve_real_ga(p, a).best.objectives[0];
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t generations = argc > 1 ? std::strtoul(argv[1], nullptr, 10) : 500;
  const std::size_t seeds = argc > 2 ? std::strtoul(argv[2], nullptr, 10) : 10;
  const std::string problems = argc > 3 ? argv[3] : "rastrigin,schwefel,zdt1,zdt3";
  if (argc > 4) g_interval = std::strtoul(argv[4], nullptr, 10);
  if (argc > 5) g_migrants = std::strtoul(argv[5], nullptr, 10);
  std::printf("generations %zu (+ the initial one), %zu seeds, migration every %zu generations, %zu migrants, ring\n\n",
              generations, seeds, g_interval, g_migrants);
  std::printf(
      "| problem | measure | Flexo 1 x N | Flexo 4 x N/4 islands | pagmo 1 x N | pagmo archipelago 4 x N/4 | Flexo 1 "
      "x N + the islands' archive |\n");
  std::printf("|---|---|---|---|---|---|---|\n");
  for (const std::string name : {"rastrigin", "schwefel", "zdt1", "zdt3"}) {
    if (("," + problems + ",").find("," + name + ",") == std::string::npos) continue;
    const bool multi = name.starts_with("zdt");
    const std::size_t single = multi ? 208 : 200;
    const std::size_t per = multi ? 52 : 50;
    std::vector<double> a, b, c, d, e;
    for (std::size_t s = 1; s <= seeds; ++s) {
      a.push_back(run_flexo(name, 0, single, generations, s));
      b.push_back(run_flexo(name, kIslands, per, generations, s));
      if (multi) e.push_back(run_flexo(name, 1, single, generations, s));
      c.push_back(run_pagmo(name, false, single, per, generations, static_cast<unsigned>(s)));
      d.push_back(run_pagmo(name, true, single, per, generations, static_cast<unsigned>(s)));
    }
    // Six digits: the ZDT hypervolumes differ in the fourth and fifth.
    const auto cell = [](const std::vector<double>& v) {
      if (v.empty()) return std::string("—");
      const Stats q = quartiles(v);
      char buf[96];
      std::snprintf(buf, sizeof buf, "%.6g [%.6g, %.6g]", q.median, q.q1, q.q3);
      return std::string(buf);
    };
    std::printf("| %s-30 (N = %zu) | %s | %s | %s | %s | %s | %s |\n", name.c_str(), single,
                multi ? "hypervolume (higher is better)" : "best f (lower is better)", cell(a).c_str(), cell(b).c_str(),
                cell(c).c_str(), cell(d).c_str(), cell(e).c_str());
    std::fflush(stdout);
  }
  return 0;
}
