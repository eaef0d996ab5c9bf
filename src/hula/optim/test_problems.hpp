// SPDX-License-Identifier: MIT
// Built-in benchmark problems, as defined in the literature (and in pagmo2,
// against which the benchmarks compare): single-objective sphere, Rastrigin,
// Rosenbrock, Ackley and Schwefel in any dimension, OneMax (binary), the
// bi-objective ZDT1-4 and ZDT6 (Zitzler, Deb & Thiele 2000) and DTLZ2 (Deb et
// al. 2002) with any number of objectives.
#pragma once

#include <cstddef>
#include <string_view>

#include "hula/optim/problem.hpp"

namespace hula::optim {

/// Sphere f(x) = sum x_i^2 on [-5.12, 5.12]^d; minimum 0 at 0.
/// @throws hula::Error(Errc::InvalidOption) if dimension == 0.
[[nodiscard]] Problem sphere(std::size_t dimension);
/// Rastrigin f(x) = 10 d + sum (x_i^2 - 10 cos(2 pi x_i)) on [-5.12, 5.12]^d; minimum 0 at 0.
/// @throws hula::Error(Errc::InvalidOption) if dimension == 0.
[[nodiscard]] Problem rastrigin(std::size_t dimension);
/// Rosenbrock f(x) = sum 100 (x_{i+1} - x_i^2)^2 + (1 - x_i)^2 on [-5, 10]^d; minimum 0 at 1.
/// @throws hula::Error(Errc::InvalidOption) if dimension < 2.
[[nodiscard]] Problem rosenbrock(std::size_t dimension);
/// Ackley on [-15, 30]^d (pagmo's bounds); minimum 0 at 0.
/// @throws hula::Error(Errc::InvalidOption) if dimension == 0.
[[nodiscard]] Problem ackley(std::size_t dimension);
/// Schwefel f(x) = 418.9828872724339 d - sum x_i sin(sqrt|x_i|) on [-500, 500]^d; minimum ~0 at 420.9687.
/// @throws hula::Error(Errc::InvalidOption) if dimension == 0.
[[nodiscard]] Problem schwefel(std::size_t dimension);
/// OneMax: d variables in [0, 1] with precision 1 (one bit each); f = d - sum round(x_i); minimum 0.
/// @throws hula::Error(Errc::InvalidOption) if dimension == 0.
[[nodiscard]] Problem onemax(std::size_t dimension);
/// ZDT problem `which` in {1, 2, 3, 4, 6}, two objectives. Default dimensions:
/// 30 for ZDT1-3, 10 for ZDT4 and ZDT6 (pass 0 for the default).
/// Pareto fronts: ZDT1 f2 = 1 - sqrt(f1); ZDT2 f2 = 1 - f1^2; ZDT3
/// f2 = 1 - sqrt(f1) - f1 sin(10 pi f1) (disconnected); ZDT4 as ZDT1;
/// ZDT6 f2 = 1 - f1^2 with f1 in [0.2808, 1].
/// @throws hula::Error(Errc::InvalidOption) if `which` is not 1, 2, 3, 4 or 6
///   or the dimension is < 2.
[[nodiscard]] Problem zdt(unsigned which, std::size_t dimension = 0);
/// DTLZ2 with `objectives` >= 2 objectives and objectives + 9 variables by
/// default (pass dimension 0); Pareto front: the unit sphere's positive orthant.
/// @throws hula::Error(Errc::InvalidOption) if objectives < 2 or dimension < objectives.
[[nodiscard]] Problem dtlz2(std::size_t objectives, std::size_t dimension = 0);

/// A built-in problem by name ("sphere", "rastrigin", "rosenbrock", "ackley",
/// "schwefel", "onemax", "zdt1".."zdt4", "zdt6", "dtlz2").
/// @param dimension variables (0 = the problem's default, 10 for single-objective ones).
/// @param objectives for dtlz2 only (0 = 3).
/// @throws hula::Error(Errc::InvalidArgument) naming the unknown problem.
[[nodiscard]] Problem test_problem(std::string_view name, std::size_t dimension = 0, std::size_t objectives = 0);

}  // namespace hula::optim
