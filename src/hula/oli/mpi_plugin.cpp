// SPDX-License-Identifier: MIT
// The MPI plugin (libhula_mpi.so; HULA_MPI builds): the entry point of detail/mpi_plugin.hpp, the only code
// of `hula` that links Open MPI: the islands of optim::solve_islands_mpi (hula::optim_mpi, linked into the
// plugin) and the campaign's item hand-out. Loaded by process_ranks_mpi.cpp through hula/core/plugin.hpp.
#include "hula/oli/detail/mpi_plugin.hpp"

#include <dlfcn.h>
#include <mpi.h>

#include <mutex>

#include "hula/core/error.hpp"
#include "hula/optim/islands_mpi.hpp"

namespace hula::oli {
namespace {

constexpr int kTagResult = 11;  // worker -> 0: a result record (JSON text; empty on the first request)
constexpr int kTagItem = 12;    // 0 -> worker: an item index, or -1 = stop

// Open MPI's components (mca_*.so, dlopened by MPI_Init) do not link libmpi / libopen-pal: they expect
// their symbols in the global scope, where a plugin loaded with RTLD_LOCAL does not put them. So libmpi,
// already loaded with the plugin, is promoted to the global scope (with its dependencies) before MPI_Init,
// as mpi4py does for the same reason.
void make_mpi_global() {
  static std::once_flag once;
  std::call_once(once, [] {
    Dl_info info{};
    if (::dladdr(reinterpret_cast<void*>(&MPI_Init), &info) == 0 || info.dli_fname == nullptr)
      throw Error(Errc::IoError, "the MPI plugin cannot find the library that holds MPI_Init", {.field = "mpi"});
    if (::dlopen(info.dli_fname, RTLD_NOW | RTLD_GLOBAL | RTLD_NOLOAD) == nullptr) {
      const char* why = ::dlerror();
      throw Error(Errc::IoError,
                  std::string("the MPI plugin cannot make ") + info.dli_fname +
                      " global: " + (why != nullptr ? why : "unknown reason"),
                  {.field = "mpi"});
    }
  });
}

void solve_islands(const optim::Problem& problem, const optim::IslandAlgorithm& algorithm,
                   const optim::IslandOptions& options, std::optional<optim::IslandsResult>& merged) {
  make_mpi_global();
  merged = optim::solve_islands_mpi(problem, algorithm, options);
}

void join(int& rank, int& ranks) {
  make_mpi_global();
  MPI_Init(nullptr, nullptr);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
}

void leave() { MPI_Finalize(); }

int next_item(const std::string& record) {
  MPI_Send(record.data(), static_cast<int>(record.size()), MPI_CHAR, 0, kTagResult, MPI_COMM_WORLD);
  int index = -1;
  MPI_Recv(&index, 1, MPI_INT, 0, kTagItem, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return index;
}

bool poll(int& worker, std::string& record) {
  int flag = 0;
  MPI_Status status;
  MPI_Iprobe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &flag, &status);
  if (flag == 0) return false;
  int count = 0;
  MPI_Get_count(&status, MPI_CHAR, &count);
  worker = status.MPI_SOURCE;
  record.assign(static_cast<std::size_t>(count), '\0');
  MPI_Recv(record.data(), count, MPI_CHAR, status.MPI_SOURCE, kTagResult, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return true;
}

void reply(int worker, int index) { MPI_Send(&index, 1, MPI_INT, worker, kTagItem, MPI_COMM_WORLD); }

}  // namespace
}  // namespace hula::oli

HULA_PLUGIN_EXPORT const hula::oli::detail::MpiPlugin* hula_mpi_plugin() {
  static const hula::oli::detail::MpiPlugin plugin{
      .solve_islands = &hula::oli::solve_islands,
      .join = &hula::oli::join,
      .leave = &hula::oli::leave,
      .next_item = &hula::oli::next_item,
      .poll = &hula::oli::poll,
      .reply = &hula::oli::reply,
  };
  return &plugin;
}
