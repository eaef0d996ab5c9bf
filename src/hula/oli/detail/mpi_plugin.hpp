// SPDX-License-Identifier: MIT
// The entry point of the MPI plugin (libhula_mpi.so, mpi_plugin.cpp; HULA_MPI builds): every call of the
// process's MPI job (process_ranks.hpp) that talks to Open MPI, loaded with dlopen on first use
// (hula/core/plugin.hpp) so that a command that is not one rank of an mpirun job (every `hula` command
// run without a launcher, `hula --version` included) does not load Open MPI, hwloc, libevent and PMIx
// at start-up. Only the caller (process_ranks_mpi.cpp) decides whether MPI is needed
// (optim::launched_by_mpi, which reads the launcher's environment without MPI).
#pragma once

#include <optional>
#include <string>

#include "hula/optim/islands.hpp"
#include "hula/optim/problem.hpp"

namespace hula::oli::detail {

/// The plugin's calls, one table that lives as long as the process.
struct MpiPlugin {
  /// optim::solve_islands_mpi(problem, algorithm, options) into `merged` (nothing on a rank other than 0);
  /// its hula::Error propagates to the caller.
  void (*solve_islands)(const optim::Problem& problem, const optim::IslandAlgorithm& algorithm,
                        const optim::IslandOptions& options, std::optional<optim::IslandsResult>& merged);
  /// Joins the job (MPI_Init) and gives this process's rank and the number of ranks.
  void (*join)(int& rank, int& ranks);
  /// Leaves the job (MPI_Finalize).
  void (*leave)();
  /// A worker: sends `record` to rank 0 and waits for the next item's index; -1 = stop.
  int (*next_item)(const std::string& record);
  /// Rank 0: takes a waiting request, if any (does not block): its worker and record; false if none.
  bool (*poll)(int& worker, std::string& record);
  /// Rank 0: answers `worker` with an item's index, or -1 = stop.
  void (*reply)(int worker, int index);
};

/// The entry point's name and type.
inline constexpr const char* kMpiPluginSymbol = "hula_mpi_plugin";
using MpiPluginFunction = const MpiPlugin* (*)();

}  // namespace hula::oli::detail
