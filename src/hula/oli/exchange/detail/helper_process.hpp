// SPDX-License-Identifier: MIT
// Runs the exchange helper as a child process under limits: fork, then in the
// child (async-signal-safe calls only) a new process group, RLIMIT_AS, no core
// dump, stdin from /dev/null, stdout/stderr to a log file, execv. The parent
// polls waitpid with a growing sleep (1 → 20 ms) until the deadline, then
// kills the whole process group.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace hula::oli::detail {

/// How the helper ended.
struct HelperOutcome {
  enum class Kind { Exited, Signalled, TimedOut };
  Kind kind = Kind::Exited;
  int status = 0;   ///< exit status (Exited) or signal number (Signalled)
  std::string log;  ///< what the helper wrote to stdout/stderr (last 4 KiB)
};

/// Runs `program args...` with the limits and waits for it.
/// @param log_path file receiving the child's stdout and stderr
/// @throws hula::Error(Errc::HelperFailure) naming the program if it cannot be started
[[nodiscard]] HelperOutcome run_helper(const std::filesystem::path& program, const std::vector<std::string>& args,
                                       double time_limit, std::size_t memory_limit,
                                       const std::filesystem::path& log_path);

}  // namespace hula::oli::detail
