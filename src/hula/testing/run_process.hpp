// SPDX-License-Identifier: MIT
// Runs a program (no shell) and captures its stdout, stderr and exit code, for
// tests that drive the `hula` binary (CLI contract tests, golden CLI output).
#pragma once

#include <sys/types.h>

#include <chrono>
#include <optional>
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

/// A program started by start_process and still running: its stdout and
/// stderr go to temporary files that can be read while it runs (e.g. to wait
/// for a "ready" line before sending it a signal).
class RunningProcess {
 public:
  RunningProcess(pid_t pid, std::string out_path, std::string err_path, std::string in_path = {});
  /// Kills (SIGKILL) and reaps the process if wait() was not called, and removes the files.
  ~RunningProcess();
  RunningProcess(const RunningProcess&) = delete;
  RunningProcess& operator=(const RunningProcess&) = delete;

  [[nodiscard]] pid_t pid() const noexcept { return pid_; }
  /// What the process has written to stderr so far.
  [[nodiscard]] std::string err_so_far() const;
  /// Whether the process has installed a handler for `signal` (the SigCgt mask of /proc/<pid>/status, Linux).
  [[nodiscard]] bool catches(int signal) const;
  /// Waits, polling every 5 ms, until the process catches `signal` (a handler is installed) or `timeout` passes:
  /// what a test waits for before sending SIGINT, instead of sleeping and hoping. @returns whether it does.
  [[nodiscard]] bool wait_until_catches(int signal, std::chrono::milliseconds timeout) const;
  /// Sends a signal (e.g. SIGINT). @returns false if kill() failed.
  bool send(int signal) const noexcept;
  /// Waits for the process to end and collects its output (once).
  /// @throws std::runtime_error if waitpid fails or wait() was already called
  [[nodiscard]] ProcessResult wait();

 private:
  pid_t pid_;
  std::string out_path_, err_path_;
  std::string in_path_;  ///< stdin data file, removed with the others
  bool waited_ = false;
};

/// How the child's standard streams are set up (fault and pipe tests).
struct ProcessOptions {
  /// Bytes fed to the child's stdin; absent: stdin is /dev/null.
  std::optional<std::string> stdin_data{};
  /// A file opened as the child's stdout instead of capturing it (e.g. "/dev/full").
  std::optional<std::string> stdout_path{};
  /// Start the child with stdout closed (`>&-`).
  bool close_stdout = false;
};

/// Starts `program` with `args` as run_process does, without waiting.
/// @throws std::runtime_error if the program cannot be started
[[nodiscard]] RunningProcess start_process(const std::string& program, const std::vector<std::string>& args,
                                           const ProcessOptions& options = {});

/// Runs `program` with `args` (argv[1..]) via posix_spawn, stdin from /dev/null
/// (or options.stdin_data), stdout and stderr captured through temporary
/// files, and waits for it.
/// @throws std::runtime_error if the program cannot be started
[[nodiscard]] ProcessResult run_process(const std::string& program, const std::vector<std::string>& args,
                                        const ProcessOptions& options = {});

}  // namespace hula::testing
