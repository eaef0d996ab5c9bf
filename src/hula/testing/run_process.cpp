// SPDX-License-Identifier: MIT
// posix_spawn-based run_process and start_process (see run_process.hpp).
#include "hula/testing/run_process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

extern char** environ;

namespace hula::testing {
namespace {

std::string temp_name(const char* tag) {
  std::string pattern =
      (std::filesystem::temp_directory_path() / (std::string("hula-run-") + tag + "-XXXXXX")).string();
  const int fd = ::mkstemp(pattern.data());
  if (fd < 0) throw std::runtime_error("mkstemp failed: " + std::string(std::strerror(errno)));
  ::close(fd);
  return pattern;
}

std::string slurp_and_remove(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  std::filesystem::remove(path);
  return s.str();
}

}  // namespace

RunningProcess::RunningProcess(pid_t pid, std::string out_path, std::string err_path, std::string in_path)
    : pid_(pid), out_path_(std::move(out_path)), err_path_(std::move(err_path)), in_path_(std::move(in_path)) {}

RunningProcess::~RunningProcess() {
  std::error_code ec;
  if (!in_path_.empty()) std::filesystem::remove(in_path_, ec);
  if (waited_) return;
  ::kill(pid_, SIGKILL);
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
  }
  std::filesystem::remove(out_path_, ec);
  std::filesystem::remove(err_path_, ec);
}

std::string RunningProcess::err_so_far() const {
  std::ifstream in(err_path_, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool RunningProcess::catches(int signal) const {
  std::ifstream in("/proc/" + std::to_string(pid_) + "/status");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("SigCgt:", 0) != 0) continue;
    const unsigned long long mask = std::strtoull(line.c_str() + 7, nullptr, 16);
    return signal >= 1 && signal <= 64 && ((mask >> (signal - 1)) & 1ULL) != 0;
  }
  return false;
}

bool RunningProcess::wait_until_catches(int signal, std::chrono::milliseconds timeout) const {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!catches(signal)) {
    if (std::chrono::steady_clock::now() >= deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

bool RunningProcess::send(int signal) const noexcept { return ::kill(pid_, signal) == 0; }

ProcessResult RunningProcess::wait() {
  if (waited_) throw std::runtime_error("RunningProcess::wait called twice");
  int status = 0;
  while (::waitpid(pid_, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error("waitpid failed: " + std::string(std::strerror(errno)));
  }
  waited_ = true;
  ProcessResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.out = slurp_and_remove(out_path_);
  result.err = slurp_and_remove(err_path_);
  return result;
}

RunningProcess start_process(const std::string& program, const std::vector<std::string>& args,
                             const ProcessOptions& options) {
  std::string out_path = temp_name("out"), err_path = temp_name("err"), in_path;
  if (options.stdin_data) {
    in_path = temp_name("in");
    std::ofstream in(in_path, std::ios::binary);
    in << *options.stdin_data;
  }
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, in_path.empty() ? "/dev/null" : in_path.c_str(), O_RDONLY,
                                   0);
  if (options.close_stdout)
    posix_spawn_file_actions_addclose(&actions, STDOUT_FILENO);
  else
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO,
                                     options.stdout_path ? options.stdout_path->c_str() : out_path.c_str(),
                                     O_WRONLY | O_TRUNC, 0);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err_path.c_str(), O_WRONLY | O_TRUNC, 0);

  std::vector<std::string> storage;
  storage.push_back(program);
  storage.insert(storage.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& s : storage) argv.push_back(s.data());
  argv.push_back(nullptr);

  pid_t pid = 0;
  const int rc = ::posix_spawn(&pid, program.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) {
    std::filesystem::remove(out_path);
    std::filesystem::remove(err_path);
    if (!in_path.empty()) std::filesystem::remove(in_path);
    throw std::runtime_error("cannot start " + program + ": " + std::strerror(rc));
  }
  return RunningProcess(pid, std::move(out_path), std::move(err_path), std::move(in_path));
}

ProcessResult run_process(const std::string& program, const std::vector<std::string>& args,
                          const ProcessOptions& options) {
  return start_process(program, args, options).wait();
}

}  // namespace hula::testing
