// SPDX-License-Identifier: MIT
// POSIX implementation of the checked reads and atomic writes (see
// atomic_file.hpp): open with O_NONBLOCK + fstat so a FIFO (unless
// set_pipe_inputs) or device is refused before it can block or stream forever, a capped read loop, and for
// writing an fd-backed streambuf whose every write(2) is checked, mkstemp in
// the target's directory, fsync, lstat re-check, rename, directory fsync.
#include "hula/io/atomic_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <iostream>
#include <optional>
#include <streambuf>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/core/huge_pages.hpp"
#include "hula/io/owned_files.hpp"

namespace hula::io {
namespace {

[[noreturn]] void throw_io(const std::filesystem::path& path, std::string_view option, const std::string& what,
                           int err) {
  std::string message = what + " '" + path.string() + "'";
  if (option != "path") message = std::string(option) + ": " + message;
  if (err != 0) message += ": " + std::string(std::strerror(err));
  // ErrorWhere.field names the option without its dashes ("output" for --output).
  const std::size_t name = option.find_first_not_of('-');
  throw Error(Errc::IoError, message, {.field = std::string(option.substr(name == std::string_view::npos ? 0 : name))});
}

// What a non-regular file is, for messages.
const char* file_kind(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISSOCK(mode)) return "a socket";
  if (S_ISLNK(mode)) return "a symbolic link";
  return "not a regular file";
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
    const int rc = fd_ >= 0 ? ::close(fd_) : 0;
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

// Writes all of [data, data + size) to fd; returns 0 or the errno of the failure.
int write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    if (n == 0) return EIO;
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return 0;
}

// A buffered output streambuf over a descriptor that remembers the first
// write error (the ostream only sees "failed").
class FdStreambuf : public std::streambuf {
 public:
  explicit FdStreambuf(int fd) : fd_(fd) { setp(buffer_.data(), buffer_.data() + buffer_.size()); }
  [[nodiscard]] int error() const { return error_; }

 protected:
  int_type overflow(int_type ch) override {
    if (drain() != 0) return traits_type::eof();
    if (!traits_type::eq_int_type(ch, traits_type::eof())) {
      *pptr() = traits_type::to_char_type(ch);
      pbump(1);
    }
    return traits_type::not_eof(ch);
  }
  int sync() override { return drain() == 0 ? 0 : -1; }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    // Large blocks bypass the buffer; small ones are copied into it.
    if (n >= static_cast<std::streamsize>(buffer_.size())) {
      if (drain() != 0) return 0;
      error_ = write_all(fd_, s, static_cast<std::size_t>(n));
      return error_ == 0 ? n : 0;
    }
    return std::streambuf::xsputn(s, n);
  }

 private:
  int drain() {
    if (error_ != 0) return error_;
    const std::size_t n = static_cast<std::size_t>(pptr() - pbase());
    if (n > 0) error_ = write_all(fd_, pbase(), n);
    setp(buffer_.data(), buffer_.data() + buffer_.size());
    return error_;
  }

  int fd_;
  int error_ = 0;
  std::array<char, std::size_t{1} << 16> buffer_{};
};

constexpr std::string_view kTempInfix = ".tmp-";

// set_pipe_inputs: off unless a command line turns it on.
std::atomic<bool> g_pipe_inputs{false};

std::filesystem::path directory_of(const std::filesystem::path& path) {
  return path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
}

}  // namespace

bool is_std_stream(const std::filesystem::path& path) { return path.native() == kStdStreamName; }

void set_pipe_inputs(bool on) noexcept { g_pipe_inputs.store(on, std::memory_order_relaxed); }

std::string read_text_file(const std::filesystem::path& path, std::size_t max_bytes) {
  const bool is_stdin = is_std_stream(path);
  const std::string_view option = "path";
  int fd = STDIN_FILENO;
  std::optional<FdGuard> guard;
  std::size_t expected = 0;  // a regular file's size: read straight into the result, no copy or regrowth
  if (!is_stdin) {
    // O_NONBLOCK: opening a FIFO without a writer must not hang before the type check. A pipe read as a file
    // (set_pipe_inputs: a named pipe or a process substitution, `<(cat pts.csv)`) is opened blocking, so it
    // waits for its writer as `cat` would instead of reading an empty end-of-file, and read once to its end.
    struct stat named {};
    const bool pipe =
        g_pipe_inputs.load(std::memory_order_relaxed) && ::stat(path.c_str(), &named) == 0 && S_ISFIFO(named.st_mode);
    fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOCTTY | (pipe ? 0 : O_NONBLOCK));
    if (fd < 0) throw_io(path, option, "cannot open file", errno);
    guard.emplace(fd);
    struct stat st {};
    if (::fstat(fd, &st) != 0) throw_io(path, option, "cannot stat file", errno);
    if (!S_ISREG(st.st_mode) && !(pipe && S_ISFIFO(st.st_mode)))
      throw_io(path, option,
               std::string("cannot read ") + file_kind(st.st_mode) + " as a file (give - to read standard input):", 0);
    if (S_ISREG(st.st_mode) && static_cast<unsigned long long>(st.st_size) > max_bytes)
      throw_io(path, option,
               "the input is larger than the " + std::to_string(max_bytes) + "-byte limit on an input file:", 0);
    const int flags = ::fcntl(fd, F_GETFL);
    if (flags >= 0) (void)::fcntl(fd, F_SETFL, flags & ~O_NONBLOCK);
    if (S_ISREG(st.st_mode)) expected = static_cast<std::size_t>(st.st_size);
  }
  const std::filesystem::path shown = is_stdin ? std::filesystem::path("-") : path;
  std::string contents;
  contents.reserve(expected);
  advise_huge_pages(contents.data(), expected);
  contents.resize(expected);
  std::size_t got = 0;
  while (got < expected) {
    const ssize_t n = ::read(fd, contents.data() + got, expected - got);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw_io(shown, option, "cannot read file", errno);
    }
    if (n == 0) break;
    got += static_cast<std::size_t>(n);
  }
  contents.resize(got);
  if (got < expected) return contents;  // the file shrank while it was read
  // Standard input, a pipe, or a file that grew while it was read: the rest in pieces, within the limit.
  std::vector<char> buffer(std::size_t{1} << 16);
  for (;;) {
    const ssize_t n = ::read(fd, buffer.data(), buffer.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      throw_io(shown, option, is_stdin ? "cannot read standard input" : "cannot read file", errno);
    }
    if (n == 0) break;
    if (contents.size() + static_cast<std::size_t>(n) > max_bytes)
      throw_io(shown, option,
               "the input is larger than the " + std::to_string(max_bytes) + "-byte limit on an input file:", 0);
    contents.append(buffer.data(), static_cast<std::size_t>(n));
  }
  return contents;
}

void check_readable_size(std::size_t bytes, const std::filesystem::path& path, std::string_view option,
                         std::size_t max_bytes) {
  if (bytes <= max_bytes) return;
  const std::string shown = is_std_stream(path) ? std::string("standard output") : "'" + path.string() + "'";
  throw Error(Errc::InvalidArgument,
              "not writing " + shown + ": the file would be " + std::to_string(bytes) + " bytes, over the " +
                  std::to_string(max_bytes) +
                  "-byte limit of the readers of this kind of file (hula could not read it back)",
              ErrorWhere{.field = std::string(option)});
}

void check_output_path(const std::filesystem::path& path, std::string_view option) {
  if (is_std_stream(path)) return;
  if (path.empty() || !path.has_filename() || path.filename() == "." || path.filename() == "..")
    throw_io(path, option, "cannot write to a path without a file name:", 0);
  struct stat st {};
  if (::lstat(path.c_str(), &st) == 0) {
    if (S_ISLNK(st.st_mode))
      throw_io(path, option, "refusing to replace a symbolic link (name its target instead):", 0);
    if (!S_ISREG(st.st_mode))
      throw_io(path, option, std::string("refusing to replace ") + file_kind(st.st_mode) + ":", 0);
  } else if (errno != ENOENT) {
    throw_io(path, option, "cannot check", errno);
  }
  const std::filesystem::path dir = directory_of(path);
  struct stat ds {};
  if (::stat(dir.c_str(), &ds) != 0) throw_io(path, option, "the directory of the output does not exist for", errno);
  if (!S_ISDIR(ds.st_mode)) throw_io(path, option, "the parent of the output is not a directory:", 0);
  if (::access(dir.c_str(), W_OK | X_OK) != 0) throw_io(path, option, "cannot create files in the directory of", errno);
}

struct OutputFile::State {
  std::filesystem::path path;
  std::string option;
  std::string temp;  // empty for standard output
  int fd = -1;
  bool committed = false;
  std::unique_ptr<FdStreambuf> buf;
  std::unique_ptr<std::ostream> stream;

  void discard() noexcept {
    if (fd >= 0 && !temp.empty()) ::close(fd);
    fd = -1;
    if (!temp.empty()) ::unlink(temp.c_str());
  }
};

OutputFile::OutputFile(const std::filesystem::path& path, std::string_view option) : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.path = path;
  s.option = std::string(option);
  if (is_std_stream(path)) {
    std::cout.flush();  // keep anything already printed in order
    s.fd = STDOUT_FILENO;
  } else {
    check_output_path(path, option);
    const std::filesystem::path dir = directory_of(path);
    const std::string name = path.filename().string();
    // What a killed writer of this target left (its pid is gone) goes; a live writer's temporary stays.
    remove_orphaned(dir, "." + name + std::string(kTempInfix));
    s.temp = (dir / (owned_name("." + name + std::string(kTempInfix)) + "-XXXXXX")).string();
    s.fd = ::mkstemp(s.temp.data());
    if (s.fd < 0) {
      const int err = errno;
      s.temp.clear();
      throw_io(path, option, "cannot create a temporary file next to", err);
    }
    struct stat st {};
    const mode_t mode =
        ::stat(path.c_str(), &st) == 0 ? (st.st_mode & 07777) : static_cast<mode_t>(0666 & ~current_umask());
    if (::fchmod(s.fd, mode) != 0) {
      const int err = errno;
      s.discard();
      throw_io(path, option, "cannot set permissions of the temporary file for", err);
    }
  }
  s.buf = std::make_unique<FdStreambuf>(s.fd);
  s.stream = std::make_unique<std::ostream>(s.buf.get());
}

OutputFile::~OutputFile() {
  if (state_ && !state_->committed) state_->discard();
}

std::ostream& OutputFile::stream() { return *state_->stream; }

void OutputFile::commit() {
  State& s = *state_;
  const bool is_stdout = s.temp.empty();
  const auto fail = [&](const std::string& what, int err) {
    s.discard();
    s.committed = true;  // nothing left to clean up
    if (is_stdout) {
      std::string message = "cannot write to standard output";
      if (err != 0) message += ": " + std::string(std::strerror(err));
      throw Error(Errc::IoError, message, {.field = s.option});
    }
    throw_io(s.path, s.option, what, err);
  };
  s.stream->flush();
  if (s.buf->error() != 0 || !*s.stream) fail("cannot write", s.buf->error());
  if (is_stdout) {
    s.committed = true;
    return;
  }
  if (::fsync(s.fd) != 0) fail("cannot flush", errno);
  const int fd = s.fd;
  s.fd = -1;
  if (::close(fd) != 0) fail("cannot close the temporary file for", errno);
  // The target may have changed since the constructor checked it: check again
  // so a symlink or device planted meanwhile is not replaced.
  struct stat st {};
  if (::lstat(s.path.c_str(), &st) == 0 && !S_ISREG(st.st_mode))
    fail(std::string("refusing to replace ") + file_kind(st.st_mode) + ":", 0);
  if (::rename(s.temp.c_str(), s.path.c_str()) != 0) fail("cannot replace", errno);
  s.committed = true;
  // Make the rename itself durable. A failure here leaves the new file in
  // place (the replacement has happened), so it is not reported.
  const int dir_fd = ::open(directory_of(s.path).c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir_fd >= 0) {
    (void)::fsync(dir_fd);
    ::close(dir_fd);
  }
}

void write_file_atomically(const std::filesystem::path& path, std::string_view contents, std::string_view option) {
  OutputFile out(path, option);
  out.stream().write(contents.data(), static_cast<std::streamsize>(contents.size()));
  out.commit();
}

void write_stdout(std::string_view contents) { write_file_atomically(std::filesystem::path("-"), contents, "stdout"); }

}  // namespace hula::io
