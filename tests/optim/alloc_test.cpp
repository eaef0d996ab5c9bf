// SPDX-License-Identifier: MIT
// The algorithms allocate nothing per individual (DESIGN "no allocation in
// per-point loops"): with a counting global operator new, the allocations a
// generation costs do not grow with the population and stay at a small
// constant (the std::function wrapping a batch for parallel_for).
#include <gtest/gtest.h>

#include "hula/optim/ga.hpp"
#include "hula/optim/nsga2.hpp"
#include "hula/optim/run_log.hpp"
#include "hula/optim/test_problems.hpp"
#include "hula/testing/counting_allocator.hpp"

namespace hula::optim {
namespace {

// Allocations per generation between the callbacks of generations 5 and 25
// of one run (the result built at the end of a run is not counted).
template <class Solve>
long per_generation(const Solve& solve, std::size_t population) {
  long at5 = 0;
  long at25 = 0;
  solve(population, [&](const GenerationLog& g) {
    if (g.generation == 5) at5 = testing::allocation_count();
    if (g.generation == 25) at25 = testing::allocation_count();
  });
  return (at25 - at5) / 20;
}

// checks: allocations per generation of NSGA-II (2 and 3 objectives), the real GA and the binary GA against population
// size (counting allocator)
TEST(OptimAlloc, NoAllocationPerIndividual) {
  const auto nsga2 = [](std::size_t m) {
    return [m](std::size_t population, const GenerationCallback& callback) {
      Nsga2Options o;
      o.population = population;
      o.run.stop.generations = 25;
      o.run.on_generation = callback;
      (void)solve_nsga2(m == 2 ? zdt(1) : dtlz2(3), o);
    };
  };
  const auto real = [](std::size_t population, const GenerationCallback& callback) {
    RealGaOptions o;
    o.population = population;
    o.run.stop.generations = 25;
    o.run.on_generation = callback;
    (void)solve_real_ga(rastrigin(10), o);
  };
  const auto binary = [](std::size_t population, const GenerationCallback& callback) {
    BinaryGaOptions o;
    o.population = population;
    o.run.stop.generations = 25;
    o.run.on_generation = callback;
    Problem p = rastrigin(5);
    for (auto& v : p.variables) v.precision = 1e-4;
    (void)solve_binary_ga(p, o);
  };
  for (const std::size_t m : {2U, 3U}) {
    const long small = per_generation(nsga2(m), 20);
    const long large = per_generation(nsga2(m), 200);
    EXPECT_EQ(small, large) << "NSGA-II m = " << m;
    EXPECT_LE(large, 2) << "NSGA-II m = " << m;
  }
  EXPECT_EQ(per_generation(real, 20), per_generation(real, 200));
  EXPECT_LE(per_generation(real, 200), 2);
  EXPECT_EQ(per_generation(binary, 20), per_generation(binary, 200));
  EXPECT_LE(per_generation(binary, 200), 2);
}

}  // namespace
}  // namespace hula::optim
