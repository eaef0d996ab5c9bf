// SPDX-License-Identifier: MIT
// Islands across processes and machines: one island per MPI rank of
// MPI_COMM_WORLD, migrating by point-to-point messages, with exactly the
// migration code of the threaded island model (islands.hpp run_island). The
// synchronous mode gives the same result as solve_islands with K = the
// number of ranks, to the last bit. Rank 0 gathers the islands' reports and
// merges them (champion, or the non-dominated set of the merged populations).
//
// Built only with HULA_MPI=ON (Open MPI from Debian's libopenmpi-dev), as the
// separate target hula::optim_mpi, linked by the MPI plugin of the CLI (libhula_mpi.so,
// oli/detail/mpi_plugin.hpp) so that no program loads Open MPI at start-up.
//
// Failure: if a rank dies (killed, crashed), Open MPI's mpirun ends every
// rank of the job and exits non-zero naming the rank and the signal; no
// partial result is printed. If an island throws (bad input, evaluation
// failure), its rank tells its neighbours, every rank stops at its next
// migration, and rank 0 reports the failing island's error.
#pragma once

#include <optional>
#include <vector>

#include "hula/optim/islands.hpp"

namespace hula::optim {

/// The bytes of an island's report as its rank sends them to rank 0 at the end of a run.
[[nodiscard]] std::vector<char> write_island_report(const IslandReport& report);

/// Reads the bytes write_island_report wrote. Every count read is bounded by the bytes that remain before
/// anything is allocated, so a short or hostile message cannot make rank 0 allocate more than its size.
/// @throws hula::Error(Errc::IoError) with field "mpi", "truncated island report: …" naming the count and the
///   byte where the message ends or is too short
[[nodiscard]] IslandReport read_island_report(const std::vector<char>& bytes);

/// True when this process runs under mpirun / mpiexec with more than one rank
/// (Open MPI's OMPI_COMM_WORLD_SIZE, or PMI_SIZE / PMIX_SIZE of other launchers). It reads the
/// environment only, so it is defined in hula::optim (islands.cpp), not with the MPI calls: the
/// CLI asks it before it loads the MPI plugin.
[[nodiscard]] bool launched_by_mpi() noexcept;

/// Runs this rank's island of an archipelago of one island per rank.
/// Initialises and finalises MPI itself (once per process).
/// @param options options.islands must equal the number of ranks (or be 0 = take it).
/// @returns the merged result on rank 0, nullopt on the other ranks.
/// @throws hula::Error(Errc::InvalidOption) naming "islands" if it differs from the number of ranks;
///   the failing island's error (on rank 0; other ranks throw "another island failed").
[[nodiscard]] std::optional<IslandsResult> solve_islands_mpi(const Problem& problem, const IslandAlgorithm& algorithm,
                                                             IslandOptions options);

}  // namespace hula::optim
