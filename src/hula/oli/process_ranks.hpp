// SPDX-License-Identifier: MIT
// The MPI job of a front end that owns its process (the `hula` CLI): whether
// this process is one rank of an mpirun job, an optimisation run as one
// island per rank, and the item hand-out of a campaign across ranks. Built as
// the target hula::oli_ranks, the only one besides hula::optim_mpi that links
// Open MPI (HULA_MPI builds; without it every process is a job of one rank),
// so the CLI reaches MPI through oli like every other engine entry and the
// server and Python link no MPI.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "hula/optim/solve.hpp"

namespace hula::oli {

/// A solve and where its islands ran.
struct RankedSolve {
  optim::SolveResult result;
  std::string transport = "threads";  ///< "threads" (this process) or "mpi" (one island per rank)
};

/// True in HULA_MPI builds: campaigns and islands can run one per rank under an MPI launcher.
[[nodiscard]] bool runs_mpi() noexcept;

/// True when this process is one rank of an mpirun job with more than one rank and the build runs MPI
/// (optim::launched_by_mpi in HULA_MPI builds; false otherwise).
[[nodiscard]] bool launched_by_mpi() noexcept;

/// Runs optim::solve, or, with options.islands under mpirun (HULA_MPI builds), this rank's island of one
/// island per rank (optim::solve_islands_mpi; options.islands->islands must equal the number of ranks).
/// @returns the result, or nothing on a rank other than 0 (rank 0 has the merged result)
/// @throws as optim::solve and optim::solve_islands_mpi
[[nodiscard]] std::optional<RankedSolve> solve_on_ranks(const optim::Problem& problem,
                                                        const optim::SolveOptions& options);

/// The ranks of a campaign: rank 0 hands out item indices, every other rank asks for one, runs it and sends
/// its record (text: it crosses processes) with the next request. Joins the MPI job (MPI_Init) when launched
/// by mpirun and leaves it (MPI_Finalize) when destroyed; otherwise a job of one rank whose messages are
/// never called for.
class CampaignRanks {
 public:
  CampaignRanks();
  ~CampaignRanks();
  CampaignRanks(const CampaignRanks&) = delete;
  CampaignRanks& operator=(const CampaignRanks&) = delete;

  [[nodiscard]] int rank() const noexcept { return rank_; }
  [[nodiscard]] int ranks() const noexcept { return ranks_; }

  /// A worker (rank > 0): sends the record of its last item (empty on the first request) to rank 0 and
  /// waits for the next item's index; nothing = no item is left, stop.
  [[nodiscard]] std::optional<std::size_t> next_item(const std::string& record);

  /// A worker's request waiting at rank 0: who asks, and the record of its last item (empty on its first).
  struct Request {
    int worker = 0;
    std::string record;
  };
  /// Rank 0: the next waiting request, if any (does not block).
  [[nodiscard]] std::optional<Request> poll();
  /// Rank 0: answers a request with the next item's index, or nothing = stop.
  void reply(int worker, std::optional<std::size_t> index);

 private:
  bool joined_ = false;
  int rank_ = 0;
  int ranks_ = 1;
};

}  // namespace hula::oli
