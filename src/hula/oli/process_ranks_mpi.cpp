// SPDX-License-Identifier: MIT
// The MPI job of the process (HULA_MPI builds); see process_ranks.hpp.
#include <mpi.h>

#include "hula/oli/process_ranks.hpp"
#include "hula/optim/islands_mpi.hpp"

namespace hula::oli {

namespace {

constexpr int kTagResult = 11;  // worker -> 0: a result record (JSON text; empty on the first request)
constexpr int kTagItem = 12;    // 0 -> worker: an item index, or -1 = stop

}  // namespace

bool runs_mpi() noexcept { return true; }

bool launched_by_mpi() noexcept { return optim::launched_by_mpi(); }

std::optional<RankedSolve> solve_on_ranks(const optim::Problem& problem, const optim::SolveOptions& options) {
  if (options.islands && optim::launched_by_mpi()) {
    std::optional<optim::IslandsResult> merged =
        optim::solve_islands_mpi(problem, optim::island_algorithm(options.algorithm), *options.islands);
    if (!merged) return std::nullopt;
    return RankedSolve{optim::solve_result(problem, std::move(*merged)), "mpi"};
  }
  return RankedSolve{optim::solve(problem, options), "threads"};
}

CampaignRanks::CampaignRanks() {
  if (!optim::launched_by_mpi()) return;
  MPI_Init(nullptr, nullptr);
  joined_ = true;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks_);
}

CampaignRanks::~CampaignRanks() {
  if (joined_) MPI_Finalize();
}

std::optional<std::size_t> CampaignRanks::next_item(const std::string& record) {
  MPI_Send(record.data(), static_cast<int>(record.size()), MPI_CHAR, 0, kTagResult, MPI_COMM_WORLD);
  int index = -1;
  MPI_Recv(&index, 1, MPI_INT, 0, kTagItem, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  if (index < 0) return std::nullopt;
  return static_cast<std::size_t>(index);
}

std::optional<CampaignRanks::Request> CampaignRanks::poll() {
  if (!joined_) return std::nullopt;
  int flag = 0;
  MPI_Status status;
  MPI_Iprobe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &flag, &status);
  if (flag == 0) return std::nullopt;
  int count = 0;
  MPI_Get_count(&status, MPI_CHAR, &count);
  Request request{.worker = status.MPI_SOURCE, .record = std::string(static_cast<std::size_t>(count), '\0')};
  MPI_Recv(request.record.data(), count, MPI_CHAR, status.MPI_SOURCE, kTagResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return request;
}

void CampaignRanks::reply(int worker, std::optional<std::size_t> index) {
  int value = index ? static_cast<int>(*index) : -1;
  MPI_Send(&value, 1, MPI_INT, worker, kTagItem, MPI_COMM_WORLD);
}

}  // namespace hula::oli
