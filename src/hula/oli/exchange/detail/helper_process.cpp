// SPDX-License-Identifier: MIT
#include "hula/oli/exchange/detail/helper_process.hpp"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstring>
#include <thread>

#include "hula/core/error.hpp"

namespace hula::oli::detail {
namespace {

// The last `limit` bytes of a file (empty if it cannot be read).
std::string tail_of(const std::filesystem::path& path, std::size_t limit) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec) return {};
  const auto start = size > limit ? size - limit : 0;
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return {};
  std::string text(static_cast<std::size_t>(size - start), '\0');
  const auto got = ::pread(fd, text.data(), text.size(), static_cast<off_t>(start));
  ::close(fd);
  text.resize(got > 0 ? static_cast<std::size_t>(got) : 0);
  return text;
}

}  // namespace

HelperOutcome run_helper(const std::filesystem::path& program, const std::vector<std::string>& args, double time_limit,
                         std::size_t memory_limit, const std::filesystem::path& log_path) {
  // Everything the child needs is prepared before fork: after fork only async-signal-safe calls.
  const std::string program_text = program.string();
  std::vector<std::string> argv_text{program_text};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  const int log_fd = ::open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
  if (log_fd < 0)
    throw Error(Errc::HelperFailure,
                "cannot create the helper log '" + log_path.string() + "': " + std::strerror(errno),
                {.field = "helper"});
  const rlimit as_limit{static_cast<rlim_t>(memory_limit), static_cast<rlim_t>(memory_limit)};
  const rlimit no_core{0, 0};

  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int e = errno;
    ::close(log_fd);
    throw Error(Errc::HelperFailure, std::string("cannot start the exchange helper: fork: ") + std::strerror(e),
                {.field = "helper"});
  }
  if (pid == 0) {
    // The helper dies with its parent: a killed `hula` must not leave it running (and writing the output
    // after its parent is gone); if the parent died before the request was made, the helper does not start.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);
    ::setpgid(0, 0);
    ::setrlimit(RLIMIT_AS, &as_limit);
    ::setrlimit(RLIMIT_CORE, &no_core);
    const int null_fd = ::open("/dev/null", O_RDONLY);
    if (null_fd >= 0) ::dup2(null_fd, STDIN_FILENO);
    ::dup2(log_fd, STDOUT_FILENO);
    ::dup2(log_fd, STDERR_FILENO);
    ::execv(argv[0], argv.data());
    // exec failed: report through the log and a distinctive status.
    const char message[] = "hula-exchange: execv failed\n";
    [[maybe_unused]] const auto written = ::write(STDERR_FILENO, message, sizeof message - 1);
    ::_exit(127);
  }
  ::close(log_fd);
  // Also from the parent, so a kill of the group cannot race the child's own setpgid.
  ::setpgid(pid, pid);

  HelperOutcome outcome;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(time_limit);
  auto pause = std::chrono::milliseconds(1);
  int status = 0;
  for (;;) {
    const pid_t r = ::waitpid(pid, &status, WNOHANG);
    if (r == pid) break;
    if (r < 0 && errno != EINTR) {
      ::kill(-pid, SIGKILL);
      throw Error(Errc::HelperFailure, std::string("waitpid on the exchange helper failed: ") + std::strerror(errno),
                  {.field = "helper"});
    }
    if (std::chrono::steady_clock::now() >= deadline) {
      ::kill(-pid, SIGKILL);
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      outcome.kind = HelperOutcome::Kind::TimedOut;
      outcome.log = tail_of(log_path, 4096);
      return outcome;
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::milliseconds(20));
  }
  // The helper may have left children in its group; they die with it.
  ::kill(-pid, SIGKILL);
  if (WIFSIGNALED(status)) {
    outcome.kind = HelperOutcome::Kind::Signalled;
    outcome.status = WTERMSIG(status);
  } else {
    outcome.kind = HelperOutcome::Kind::Exited;
    outcome.status = WEXITSTATUS(status);
  }
  outcome.log = tail_of(log_path, 4096);
  return outcome;
}

}  // namespace hula::oli::detail
