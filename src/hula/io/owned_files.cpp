// SPDX-License-Identifier: MIT
// Temporaries tied to their owner process (owned_files.hpp): a pid in the
// name, checked against /proc (Linux) when the next run cleans.
#include "hula/io/owned_files.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <vector>

namespace hula::io {
namespace {

// The pid at the start of `rest`, when `rest` is digits then the end or a non-digit.
std::optional<pid_t> leading_pid(std::string_view rest) {
  long long pid = 0;
  std::size_t i = 0;
  for (; i < rest.size() && rest[i] >= '0' && rest[i] <= '9'; ++i) {
    pid = pid * 10 + (rest[i] - '0');
    if (pid > 1'000'000'000) return std::nullopt;
  }
  if (i == 0 || pid <= 0) return std::nullopt;
  return static_cast<pid_t>(pid);
}

// Seconds since the epoch at which process `pid` started, from /proc/<pid>/stat field 22 and the boot time
// (/proc/stat btime, whole seconds rounded down: the estimate is never later than the true start); +inf for a
// zombie (it has ended); none when unknown.
std::optional<double> process_start(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return std::nullopt;
  const std::size_t paren = line.rfind(')');  // the command name may hold spaces and parentheses
  if (paren == std::string::npos) return std::nullopt;
  std::istringstream fields(line.substr(paren + 1));
  std::string field;
  unsigned long long ticks = 0;
  for (int i = 3; i <= 22 && fields >> field; ++i) {
    if (i == 3 && (field == "Z" || field == "X")) return std::numeric_limits<double>::infinity();
    if (i == 22) ticks = std::strtoull(field.c_str(), nullptr, 10);
  }
  std::ifstream proc_stat("/proc/stat");
  unsigned long long boot = 0;
  while (std::getline(proc_stat, line))
    if (line.rfind("btime ", 0) == 0) boot = std::strtoull(line.c_str() + 6, nullptr, 10);
  const long hz = ::sysconf(_SC_CLK_TCK);
  if (boot == 0 || ticks == 0 || hz <= 0) return std::nullopt;
  return static_cast<double>(boot) + static_cast<double>(ticks) / static_cast<double>(hz);
}

// Whether the process that made an entry last modified at `modified` is gone.
bool owner_gone(pid_t pid, const struct timespec& modified) {
  if (pid == ::getpid()) return false;
  if (::kill(pid, 0) != 0) return errno == ESRCH;
  // A process of that id which started after the entry's last change cannot have made it (the id was reused;
  // the start estimate is never late; 1 s more absorbs a clock slewed since, so that a true owner is never
  // taken for another); a zombie has ended.
  const std::optional<double> start = process_start(pid);
  return start && *start > static_cast<double>(modified.tv_sec) + static_cast<double>(modified.tv_nsec) * 1e-9 + 1.0;
}

}  // namespace

std::string owned_name(std::string_view prefix) { return std::string(prefix) + std::to_string(::getpid()); }

void remove_orphaned(const std::filesystem::path& dir, std::string_view prefix) noexcept {
  try {
    DIR* d = ::opendir(dir.c_str());
    if (d == nullptr) return;
    std::vector<std::string> orphans;
    const uid_t me = ::geteuid();
    while (const dirent* e = ::readdir(d)) {
      const std::string_view name(e->d_name);
      if (name.size() <= prefix.size() || name.substr(0, prefix.size()) != prefix) continue;
      const std::optional<pid_t> pid = leading_pid(name.substr(prefix.size()));
      if (!pid) continue;
      struct stat st {};
      if (::fstatat(::dirfd(d), e->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0) continue;
      if (st.st_uid != me || !(S_ISREG(st.st_mode) || S_ISDIR(st.st_mode))) continue;
      if (owner_gone(*pid, st.st_mtim)) orphans.emplace_back(name);
    }
    ::closedir(d);
    for (const std::string& name : orphans) {
      std::error_code ignored;
      std::filesystem::remove_all(dir / name, ignored);  // does not follow links
    }
  } catch (...) {  // NOLINT(bugprone-empty-catch): best effort (an allocation failure while listing)
  }
}

}  // namespace hula::io
