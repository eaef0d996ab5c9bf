// SPDX-License-Identifier: MIT
// Run log files (the `--log FILE` of `hula optimise` and the study commands):
// the run log (optim::RunLog) written as CSV when the path ends in .csv, JSON
// otherwise (the formats optim::RunLogWriter writes, docs/formats.md "Run
// logs"), atomically — whole, or streamed generation by generation with
// bounded memory, the file appearing only when the run is done.
#pragma once

#include <filesystem>
#include <string_view>

#include "hula/io/atomic_file.hpp"
#include "hula/optim/run_log.hpp"

namespace hula::io {

/// CSV for a path ending in .csv, else JSON.
[[nodiscard]] optim::RunLogFormat run_log_format(const std::filesystem::path& path);

/// A run log streamed to its file generation by generation (nothing is kept). The file appears,
/// atomically, only on commit(); a run that fails or is killed leaves the previous file as it was.
class RunLogFile {
 public:
  /// @param option how the user gave the path, for messages ("--log")
  /// @throws hula::Error(Errc::IoError) naming `option` if the path cannot be written
  explicit RunLogFile(const std::filesystem::path& path, std::string_view option = "--log");
  /// Writes one generation (a write error is reported by commit()).
  void append(const optim::GenerationLog& generation);
  /// Ends the document and replaces the file.
  /// @throws hula::Error(Errc::IoError) on any write error (a full disk, a file-size limit)
  void commit();

 private:
  OutputFile file_;
  optim::RunLogWriter writer_;
};

/// Writes a whole run log, atomically.
/// @throws hula::Error(Errc::IoError) naming `option` and the path if it cannot be written
void write_run_log_file(const optim::RunLog& log, const std::filesystem::path& path, std::string_view option = "--log");

}  // namespace hula::io
