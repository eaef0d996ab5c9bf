// SPDX-License-Identifier: MIT
// The entry point of the Ceres plugin (libhula_ceres.so, ceres_plugin.cpp): LsqSolver::Ceres's solve in
// refine_levenberg_marquardt, loaded with dlopen on first use (hula/core/plugin.hpp) so that a program
// which never refines with Ceres (every `hula` command but the matching studies) does not load Ceres and
// its linear-algebra stack (glog, CHOLMOD, LAPACK, BLAS, gfortran, METIS) at start-up. The caller
// (hybrid_refine.cpp) has validated the problem, the options and the start.
#pragma once

#include <chrono>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "hula/optim/run_report.hpp"
#include "hula/studies/hybrid_refine.hpp"

namespace hula::studies::detail {

/// What one Ceres solve gives back besides the variables: the iterations, Ceres's own verdict (CONVERGENCE
/// = Converged, NO_CONVERGENCE = MaxGenerations, FAILURE = Stagnation) with its message, and whether the
/// caller's limits (time budget, accepted steps) ended it.
struct CeresRun {
  std::size_t iterations = 0;
  optim::Termination termination = optim::Termination::Stagnation;
  std::string message{};
  bool out_of_time = false;
  bool out_of_steps = false;
};

/// The entry point's name and type: minimises ‖r(x)‖² over the box from x (updated in place) with the
/// coordinates listed in `fixed` (zero-width bounds, not all of them) held; `evaluations` counts residual
/// evaluations; `start` is when the refinement began (LmOptions::time_budget_seconds counts from it).
/// An exception of the problem's functions propagates to the caller.
inline constexpr const char* kCeresSolveSymbol = "hula_ceres_solve";
using CeresSolveFunction = void (*)(const LeastSquaresProblem& problem, const LmOptions& options,
                                    std::span<const int> fixed, std::chrono::steady_clock::time_point start,
                                    std::vector<double>& x, std::size_t& evaluations, CeresRun& run);

}  // namespace hula::studies::detail
