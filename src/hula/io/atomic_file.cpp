// SPDX-License-Identifier: MIT
// POSIX implementation of read_text_file and write_file_atomically (mkstemp in
// the target's directory, write loop, fsync, rename, directory fsync).
#include "hula/io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <vector>

#include "hula/core/error.hpp"

namespace hula::io {
namespace {

[[noreturn]] void throw_io(const std::filesystem::path& path, const std::string& what, int err) {
  std::string message = what + " '" + path.string() + "'";
  if (err != 0) message += ": " + std::string(std::strerror(err));
  throw Error(Errc::IoError, message, {.field = "path"});
}

// Closes a descriptor on scope exit unless released.
class FdGuard {
 public:
  explicit FdGuard(int fd) : fd_(fd) {}
  FdGuard(const FdGuard&) = delete;
  FdGuard& operator=(const FdGuard&) = delete;
  ~FdGuard() {
    if (fd_ >= 0) ::close(fd_);
  }
  [[nodiscard]] int get() const { return fd_; }
  // Closes now and reports the error of close() (it can report a deferred write error).
  int close_now() {
    const int rc = ::close(fd_);
    fd_ = -1;
    return rc;
  }

 private:
  int fd_;
};

// The process umask, read without changing it (umask(2) would race with other
// threads): the "Umask:" line of /proc/self/status, else the common 022.
mode_t current_umask() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line)) {
    if (line.rfind("Umask:", 0) == 0) {
      try {
        return static_cast<mode_t>(std::stoul(line.substr(6), nullptr, 8));
      } catch (const std::exception&) {
        break;
      }
    }
  }
  return 022;
}

}  // namespace

std::string read_text_file(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) throw_io(path, "cannot open file", errno);
  FdGuard guard(fd);
  struct stat st {};
  if (::fstat(fd, &st) != 0) throw_io(path, "cannot stat file", errno);
  if (S_ISDIR(st.st_mode)) throw_io(path, "cannot read a directory as a file:", 0);
  std::string contents;
  std::vector<char> buffer(1 << 16);
  for (;;) {
    const ssize_t n = ::read(fd, buffer.data(), buffer.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      throw_io(path, "cannot read file", errno);
    }
    if (n == 0) break;
    contents.append(buffer.data(), static_cast<std::size_t>(n));
  }
  return contents;
}

void write_file_atomically(const std::filesystem::path& path, std::string_view contents) {
  if (path.empty() || !path.has_filename()) throw_io(path, "cannot write to a path without a file name:", 0);
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::string temp = (dir / ("." + path.filename().string() + ".tmp-XXXXXX")).string();
  const int fd = ::mkstemp(temp.data());
  if (fd < 0) throw_io(path, "cannot create a temporary file next to", errno);
  FdGuard guard(fd);
  // From here on every failure removes the temporary file before throwing.
  const auto fail = [&](const std::string& what, int err) {
    const int saved = err;
    if (guard.get() >= 0) guard.close_now();
    ::unlink(temp.c_str());
    throw_io(path, what, saved);
  };

  struct stat st {};
  const mode_t mode =
      ::stat(path.c_str(), &st) == 0 ? (st.st_mode & 07777) : static_cast<mode_t>(0666 & ~current_umask());
  if (::fchmod(fd, mode) != 0) fail("cannot set permissions of the temporary file for", errno);

  const char* data = contents.data();
  std::size_t left = contents.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      fail("cannot write", errno);
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) fail("cannot flush", errno);
  if (guard.close_now() != 0) fail("cannot close the temporary file for", errno);
  if (::rename(temp.c_str(), path.c_str()) != 0) fail("cannot replace", errno);

  // Make the rename itself durable. A failure here leaves the new file in
  // place (the replacement has happened), so it is not reported.
  const int dir_fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd >= 0) {
    (void)::fsync(dir_fd);
    ::close(dir_fd);
  }
}

}  // namespace hula::io
