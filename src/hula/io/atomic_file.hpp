// SPDX-License-Identifier: MIT
// Whole-file text I/O for the io module and the CLI: reading a file into a
// string, and replacing a file atomically (write a temporary file in the same
// directory, fsync it, rename it over the target, fsync the directory), so a
// reader or a crash never sees a half-written curve file and a failed write
// leaves the previous file byte-identical (DESIGN.md "Errors": boundaries leave
// the state exactly as it was). POSIX only.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace hula::io {

/// Reads a whole file as bytes (no newline translation).
/// @param path file to read
/// @returns the file's contents
/// @throws hula::Error(Errc::IoError) naming the path and the system's reason
///   (missing file, permission denied, a directory, a read error);
///   ErrorWhere.field is "path"
[[nodiscard]] std::string read_text_file(const std::filesystem::path& path);

/// Replaces (or creates) `path` with `contents` atomically.
///
/// Writes a temporary file `.<name>.tmp-XXXXXX` next to the target, fsyncs
/// it, renames it over `path` and fsyncs the directory. An existing target
/// keeps its permission bits; a new one gets 0666 minus the process umask.
/// On any failure the temporary file is removed and the target is untouched.
/// @param path destination file; its directory must exist and be writable
/// @param contents bytes to write
/// @throws hula::Error(Errc::IoError) naming the path and the system's reason;
///   ErrorWhere.field is "path"
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

}  // namespace hula::io
