// SPDX-License-Identifier: MIT
// The entry point of the pagmo plugin (libhula_pagmo.so, pagmo_plugin.cpp): the part of
// solve_with_pagmo that calls pagmo2, loaded with dlopen on first use (hula/core/plugin.hpp) so that
// programs that never run a pagmo algorithm do not load libpagmo and run its static initialisers.
// The caller (pagmo_adapter.cpp) has validated the problem and the options.
#pragma once

#include <cstddef>
#include <optional>

#include "hula/optim/pagmo_adapter.hpp"
#include "hula/optim/problem.hpp"

namespace hula::optim::detail {

/// What one pagmo run gives back: the result (best or front, evaluations) and how many evaluations
/// returned finite values and how many did not.
struct PagmoRun {
  PagmoResult result{};
  std::size_t succeeded = 0;
  std::size_t failed = 0;
  /// Set when the run ended early (PagmoOptions::cancel, wall_time_seconds): why, and the complete
  /// generations made after the initial population.
  std::optional<Termination> stopped{};
  std::size_t generations = 0;
};

/// The entry point's name in the plugin and its type. pagmo's std::invalid_argument (an algorithm
/// refusing the problem) propagates to the caller.
inline constexpr const char* kPagmoRunSymbol = "hula_pagmo_run";
using PagmoRunFunction = void (*)(const Problem& problem, const PagmoOptions& options, PagmoRun& run);

}  // namespace hula::optim::detail
