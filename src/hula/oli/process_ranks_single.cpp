// SPDX-License-Identifier: MIT
// The process as a job of one rank (builds without HULA_MPI); see process_ranks.hpp.
#include "hula/core/error.hpp"
#include "hula/oli/process_ranks.hpp"

namespace hula::oli {

namespace {

[[noreturn]] void no_other_rank() {
  throw Error(Errc::InvalidArgument, "this build runs no MPI: a campaign of one rank has no other rank to message");
}

}  // namespace

bool runs_mpi() noexcept { return false; }

bool launched_by_mpi() noexcept { return false; }

std::optional<RankedSolve> solve_on_ranks(const optim::Problem& problem, const optim::SolveOptions& options) {
  return RankedSolve{optim::solve(problem, options), "threads"};
}

CampaignRanks::CampaignRanks() = default;
CampaignRanks::~CampaignRanks() = default;

std::optional<std::size_t> CampaignRanks::next_item(const std::string& /*record*/) { no_other_rank(); }

std::optional<CampaignRanks::Request> CampaignRanks::poll() { return std::nullopt; }

void CampaignRanks::reply(int /*worker*/, std::optional<std::size_t> /*index*/) { no_other_rank(); }

}  // namespace hula::oli
