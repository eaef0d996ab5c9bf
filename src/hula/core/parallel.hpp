// SPDX-License-Identifier: MIT
// parallel_for on oneTBB with deterministic error reporting: when several
// iterations throw, the exception of the lowest index is rethrown, so the
// reported error does not depend on the thread count (STYLE.md rule 7).
#pragma once

#include <cstddef>
#include <functional>

namespace hula {

/// Options for parallel_for.
struct ParallelOptions {
  /// Maximum worker threads; 0 = oneTBB's default (all cores). 1 runs the
  /// loop serially on the calling thread. Default 0.
  std::size_t threads = 0;
  /// Iterations handed to a worker at a time. Default 1 (fitness-sized work);
  /// raise it for cheap bodies. Must be ≥ 1.
  std::size_t grain = 1;
};

/// Calls body(i) for every i in [begin, end), possibly concurrently.
/// Every index runs even when some throw; afterwards the exception thrown by
/// the lowest index is rethrown.
/// @throws hula::Error(Errc::InvalidOption) if options.grain == 0.
void parallel_for(std::size_t begin, std::size_t end, const std::function<void(std::size_t)>& body,
                  const ParallelOptions& options = {});

}  // namespace hula
