// SPDX-License-Identifier: MIT
// The MPI job of the process (HULA_MPI builds); see process_ranks.hpp. Every call to Open MPI goes through
// the MPI plugin (detail/mpi_plugin.hpp), loaded the first time this process turns out to be one rank of
// an mpirun job: nothing here links Open MPI.
#include "hula/core/plugin.hpp"
#include "hula/oli/detail/mpi_plugin.hpp"
#include "hula/oli/process_ranks.hpp"
#include "hula/optim/islands_mpi.hpp"

namespace hula::oli {

namespace {

// Loaded on first use; a failed load (an IoError naming the plugin and the files tried) is retried next time.
const detail::MpiPlugin& mpi() {
  static const detail::MpiPlugin* const plugin =
      reinterpret_cast<detail::MpiPluginFunction>(plugin_symbol("mpi", detail::kMpiPluginSymbol))();
  return *plugin;
}

}  // namespace

bool runs_mpi() noexcept { return true; }

bool launched_by_mpi() noexcept { return optim::launched_by_mpi(); }

std::optional<RankedSolve> solve_on_ranks(const optim::Problem& problem, const optim::SolveOptions& options) {
  if (options.islands && optim::launched_by_mpi()) {
    std::optional<optim::IslandsResult> merged;
    mpi().solve_islands(problem, optim::island_algorithm(options.algorithm), *options.islands, merged);
    if (!merged) return std::nullopt;
    return RankedSolve{optim::solve_result(problem, std::move(*merged)), "mpi"};
  }
  return RankedSolve{optim::solve(problem, options), "threads"};
}

CampaignRanks::CampaignRanks() {
  if (!optim::launched_by_mpi()) return;
  mpi().join(rank_, ranks_);
  joined_ = true;
}

CampaignRanks::~CampaignRanks() {
  if (joined_) mpi().leave();
}

std::optional<std::size_t> CampaignRanks::next_item(const std::string& record) {
  const int index = mpi().next_item(record);
  if (index < 0) return std::nullopt;
  return static_cast<std::size_t>(index);
}

std::optional<CampaignRanks::Request> CampaignRanks::poll() {
  if (!joined_) return std::nullopt;
  Request request;
  if (!mpi().poll(request.worker, request.record)) return std::nullopt;
  return request;
}

void CampaignRanks::reply(int worker, std::optional<std::size_t> index) {
  mpi().reply(worker, index ? static_cast<int>(*index) : -1);
}

}  // namespace hula::oli
