// SPDX-License-Identifier: MIT
// Whole-file I/O for the io module and the CLI, safe against hostile paths and
// faults:
// - reading: a regular file or `-` (standard input), never a device,
//   directory or FIFO (a pipe, when set_pipe_inputs allows it: a named FIFO
//   or a process substitution such as `<(cat pts.csv)`, read once), and
//   never more than a stated number of bytes;
// - writing: a regular file replaced atomically (a temporary file in the same
//   directory, fsync, rename over the target, directory fsync), or `-`
//   (standard output). Symlinks, devices, FIFOs and directories are refused by
//   name; the target is checked before any computation (check_output_path) and
//   again just before the rename. Every write, flush and close is checked: a
//   short write is an error, never a truncated file. A reader or a crash never
//   sees a half-written file, and a failed write leaves the previous file
//   byte-identical (DESIGN.md "Errors").
// Temporary files are named `.<name>.tmp-<pid>-XXXXXX`; a write removes the
// temporaries of the same target left by processes that no longer exist (a
// killed write). POSIX only.
#pragma once

#include <cstddef>
#include <filesystem>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>

namespace hula::io {

/// The file name that means standard input (for reading) or standard output (for writing).
inline constexpr std::string_view kStdStreamName = "-";

/// True when `path` is `-`.
[[nodiscard]] bool is_std_stream(const std::filesystem::path& path);

/// Largest input read into memory by default (64 MiB): a 300,000-point curve
/// file is ~20 MB. Larger inputs are refused before they exhaust memory.
inline constexpr std::size_t kMaxInputBytes = std::size_t{64} << 20;

/// Whether read_text_file reads pipes (named FIFOs, process substitutions such as /dev/fd/63), once,
/// to their end, under the same cap; a named FIFO waits for its writer, as `cat` would. Off by default:
/// a server must never block on a path it is given. The command line turns it on for the commands a
/// user runs from a shell (not `hula serve`).
void set_pipe_inputs(bool on) noexcept;

/// Reads a whole regular file (or pipe, see set_pipe_inputs), or standard input for `-`, as bytes.
/// @param path file to read, or `-`
/// @param max_bytes refuse inputs longer than this
/// @returns the contents
/// @throws hula::Error(Errc::IoError) naming the path and the reason: missing,
///   permission denied, not a regular file (directory, device, FIFO unless set_pipe_inputs, socket),
///   longer than `max_bytes` (the cap is named), a read error; ErrorWhere.field is "path"
[[nodiscard]] std::string read_text_file(const std::filesystem::path& path, std::size_t max_bytes = kMaxInputBytes);

/// Largest curve or point file read (1 GiB): what `hula` writes, `hula` reads. An
/// interpolated curve of 1,000,000 points is a ~70 MB file, a NURBS of as many
/// poles ~100 MB. Writers of these files refuse (check_readable_size) rather than
/// write a file above this limit.
inline constexpr std::size_t kMaxGeometryInputBytes = std::size_t{1} << 30;

/// Checks, before a file is written, that readers will take it back.
/// @param bytes the size of the text about to be written
/// @param path the output path, for the message
/// @param option how the user gave the path ("--output")
/// @param max_bytes the readers' limit for this kind of file
/// @throws hula::Error(Errc::InvalidArgument) naming the path, the size and the limit when
///   `bytes` > `max_bytes`; ErrorWhere.field is `option`. Nothing is written.
void check_readable_size(std::size_t bytes, const std::filesystem::path& path, std::string_view option,
                         std::size_t max_bytes = kMaxGeometryInputBytes);

/// Checks that `path` can be written before a computation starts: `-`, or a
/// name in an existing, writable directory that is either absent or a regular
/// file (not a symlink, directory, device, FIFO or socket).
/// @param path the output path
/// @param option how the user gave it, for the message ("--output", "--log")
/// @throws hula::Error(Errc::IoError) naming `option` and the path; ErrorWhere.field is `option`
void check_output_path(const std::filesystem::path& path, std::string_view option);

/// An output being written: a temporary file renamed over the target on
/// commit(), or standard output for `-`. Memory stays bounded whatever is
/// written (the stream is buffered in 64 KiB). Destroying an uncommitted
/// OutputFile removes its temporary file and leaves the target untouched.
class OutputFile {
 public:
  /// Checks the target (check_output_path), removes stale temporaries of the
  /// same target and opens a new temporary file next to it.
  /// @throws hula::Error(Errc::IoError) naming `option` and the path
  explicit OutputFile(const std::filesystem::path& path, std::string_view option = "path");
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;

  /// The stream to write to. A failed write sets its badbit; commit() reports it.
  [[nodiscard]] std::ostream& stream();
  /// Flushes, fsyncs and renames the temporary file over the target (or
  /// flushes standard output).
  /// @throws hula::Error(Errc::IoError) naming the path and the system's reason
  ///   (a short write, a full disk, a file-size limit); the temporary file is removed
  void commit();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// Replaces (or creates) `path` with `contents` atomically, or writes them to
/// standard output for `-`. An existing target keeps its permission bits; a
/// new one gets 0666 minus the process umask.
/// @param path destination; its directory must exist and be writable
/// @param contents bytes to write
/// @param option how the user gave the path, for messages
/// @throws hula::Error(Errc::IoError) naming the path and the system's reason;
///   ErrorWhere.field is `option`
void write_file_atomically(const std::filesystem::path& path, std::string_view contents,
                           std::string_view option = "path");

/// Writes `contents` to standard output and flushes it.
/// @throws hula::Error(Errc::IoError) "cannot write to standard output: <reason>"
///   when the write or the flush fails (a full disk, a closed descriptor, a closed pipe)
void write_stdout(std::string_view contents);

}  // namespace hula::io
