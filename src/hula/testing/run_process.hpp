// SPDX-License-Identifier: MIT
// Runs a program (no shell) and captures its stdout, stderr and exit code, for
// tests that drive the `hula` binary (CLI contract tests, golden CLI output).
#pragma once

#include <string>
#include <vector>

namespace hula::testing {

/// What a finished process left behind.
struct ProcessResult {
  /// Exit status (0–255), or 128 + signal number when killed by a signal.
  int exit_code = -1;
  std::string out;  ///< everything written to stdout
  std::string err;  ///< everything written to stderr
};

/// Runs `program` with `args` (argv[1..]) via posix_spawn, stdin from /dev/null,
/// stdout and stderr captured through temporary files, and waits for it.
/// @throws std::runtime_error if the program cannot be started
[[nodiscard]] ProcessResult run_process(const std::string& program, const std::vector<std::string>& args);

}  // namespace hula::testing
