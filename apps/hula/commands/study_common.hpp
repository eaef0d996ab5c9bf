// SPDX-License-Identifier: MIT
// What the study commands (`hula fair-knots`, `match-curvature`,
// `match-curvature-torsion`, `fin-compound`, `edit-projection`, `hermite`)
// share: the study file argument, the --seed / --threads overrides of the
// file's own values, --log FILE (.csv or .json run log), --svg DIR (before /
// after figures and convergence graphs) and the JSON envelope of the output.
#pragma once

#include <signal.h>

#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "commands/common.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/study_file.hpp"
#include "hula/io/svg.hpp"
#include "hula/optim/run_log.hpp"

namespace hula::cli {

/// Command-line arguments common to the study commands.
struct StudyArgs {
  /// The study file (docs/formats.md "Study files").
  std::string study{};
  /// Overrides the file's "seed".
  std::optional<std::uint64_t> seed{};
  /// Overrides the file's "threads" (0 = all cores).
  std::optional<std::size_t> threads{};
  /// Run log path: CSV when it ends in .csv, JSON otherwise.
  std::optional<std::string> log{};
  /// Directory for the SVG figures (created if missing).
  std::optional<std::string> svg{};
  /// Wall-clock limit of the study's optimiser in seconds (> 0); absent = none.
  std::optional<double> time{};
};

/// The token set by Ctrl-C (SIGINT) while an InterruptGuard is alive.
[[nodiscard]] const optim::CancellationToken& interrupt_token();

/// Installs the SIGINT handler that sets interrupt_token() for the lifetime of
/// a run (an async-signal-safe lock-free store) and restores the previous
/// disposition afterwards. The handler is installed with SA_RESETHAND, so a
/// second Ctrl-C ends the process at once. Optimisers notice the token between
/// generations and end with their best so far (termination "Cancelled").
class InterruptGuard {
 public:
  InterruptGuard();
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

 private:
  struct sigaction previous_ {};
  bool installed_ = false;
};

/// Adds STUDY (positional, required), --seed, --threads, --time, --log and --svg to `sub`.
/// @param has_optimiser false for the editing studies (no iterations): they take no --time
void add_study_options(CLI::App* sub, StudyArgs& args, bool has_optimiser = true);

/// Checks the outputs (--log, --svg), reads the study file and applies the
/// --seed / --threads overrides, --time and the SIGINT token to its header.
/// @throws hula::Error as io::read_study_file
[[nodiscard]] io::StudyDocument load_study(const StudyArgs& args, std::string_view kind);

/// Writes `figure` as `<dir>/<name>.svg` atomically, creating `dir` first.
/// @throws hula::Error(Errc::IoError) naming the path if it cannot be written
void write_svg(const std::filesystem::path& dir, std::string_view name, const io::SvgFigure& figure);

/// Refuses an --svg path that exists and is not a directory, or that cannot be created, and an
/// existing directory holding a *.svg or *.csv entry that io::check_output_path refuses (a
/// symbolic link, FIFO, device or directory where a figure would be written).
/// @throws hula::Error(Errc::IoError) naming --svg
void check_svg_directory(const std::filesystem::path& dir);

/// A run log streamed to its file generation by generation (bounded memory:
/// nothing is kept), CSV when the path ends in .csv, else JSON. The file
/// appears, atomically, only on commit(); a run that fails or is killed
/// leaves the previous file as it was.
class RunLogFile {
 public:
  /// @throws hula::Error(Errc::IoError) naming --log if the path cannot be written
  explicit RunLogFile(const std::filesystem::path& path);
  /// Writes one generation (a write error is reported by commit()).
  void append(const optim::GenerationLog& generation);
  /// Ends the document and replaces the file.
  /// @throws hula::Error(Errc::IoError) on any write error (a full disk, a file-size limit)
  void commit();

 private:
  io::OutputFile file_;
  optim::RunLogWriter writer_;
};

/// Writes a run log as CSV (path ends in .csv) or JSON, atomically.
/// @throws hula::Error(Errc::IoError) naming the path if it cannot be written
void write_run_log(const optim::RunLog& log, const std::filesystem::path& path);

}  // namespace hula::cli
