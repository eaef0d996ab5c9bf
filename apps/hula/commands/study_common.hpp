// SPDX-License-Identifier: MIT
// What the study commands (`hula fair-knots`, `match-curvature`,
// `match-curvature-torsion`, `fin-compound`, `edit-projection`, `hermite`)
// share: the study file argument, the --seed / --threads overrides of the
// file's own values, --time and Ctrl-C, the run itself (oli::run_study, the
// runner of every door), --log FILE (.csv or .json run log) and --svg DIR
// (the run's figures, oli::study_figures).
#pragma once

#include <signal.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "commands/common.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/run_log_file.hpp"
#include "hula/io/study_file.hpp"
#include "hula/io/svg.hpp"
#include "hula/oli/study_runner.hpp"

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

/// The progress line of a long run on a terminal: when standard error is a terminal, each generation's
/// io::generation_progress_line (generation, evaluations, best; with several objectives the front size
/// and hypervolume), or a line of the caller's (`hula batch`'s item counts), redraws one line of stderr,
/// at most every 0.1 s, and the last line stays, ended by a newline, when the run ends. When stderr is
/// not a terminal (a pipe, a file, a CI log) nothing is drawn.
class TerminalProgress {
 public:
  /// `reference`: the hypervolume reference (empty: none); `enabled` false: never active.
  explicit TerminalProgress(std::vector<double> reference = {}, bool enabled = true);
  ~TerminalProgress();
  TerminalProgress(const TerminalProgress&) = delete;
  TerminalProgress& operator=(const TerminalProgress&) = delete;
  /// True when stderr is a terminal.
  [[nodiscard]] bool active() const noexcept { return active_; }
  /// Shows `g` (or keeps it for the final line when the last redraw is too recent).
  void show(const optim::GenerationLog& g);
  /// Shows `line` (or keeps it for the final line when the last redraw is too recent).
  void show(std::string line);
  /// Writes `text` and a newline on stderr, terminal or not; on a terminal above the progress line, which
  /// is drawn again below it.
  void print(const std::string& text);
  /// Draws the last line kept and ends the line (before the result is printed); idempotent.
  void finish();

 private:
  [[nodiscard]] bool too_soon() const;
  void draw(const std::string& line);
  bool active_ = false;
  std::vector<double> reference_;
  std::chrono::steady_clock::time_point last_{};
  bool drawn_ = false;
  std::string line_;  // the line on screen
  // What came too soon after the last redraw: a generation (formatted only if drawn) or a line.
  std::optional<optim::GenerationLog> pending_;
  std::optional<std::string> pending_line_;
};

/// Adds STUDY (positional, required), --seed, --threads, --time, --log and --svg to `sub`.
/// @param has_optimiser false for the editing studies (no iterations): they take no --time
void add_study_options(CLI::App* sub, StudyArgs& args, bool has_optimiser = true);

/// A member of the study file that a command-line option replaces (--method replaces "method"), applied
/// before the file is read, so the value is checked as the file's own would be.
struct StudyOverride {
  /// The study file's member.
  std::string member{};
  /// The option, named in an error about the member ("--method").
  std::string flag{};
  /// The value.
  Json value{};
};

/// Checks the outputs (--log, --svg), reads the study file and applies the --seed / --threads overrides.
/// @throws hula::Error as io::read_study_file
[[nodiscard]] io::StudyDocument load_study(const StudyArgs& args, std::string_view kind);

/// Runs the study of `args` through oli::run_study, the runner of every door: the file read (load_study)
/// with `overrides` applied, the files it names read relative to its folder, --time and Ctrl-C
/// (InterruptGuard) ending the optimisers with their best so far, every generation kept when --log asks;
/// then writes the --svg figures and tables (oli::study_figures). The caller writes --log.
/// @throws hula::Error as oli::run_study; an error in an overridden member names its option
[[nodiscard]] oli::StudyOutcome run_study_command(const StudyArgs& args, std::string_view kind,
                                                  const std::vector<StudyOverride>& overrides = {});

/// `--occt`: Open CASCADE's fairing baselines of a fair-knots or planar match-curvature run
/// (oli::fairing_baselines), with baselines.svg under --svg.
/// @throws hula::Error as oli::fairing_baselines, naming --occt
[[nodiscard]] Json occt_baselines(const oli::StudyOutcome& run, const StudyArgs& args);

/// Writes `figure` as `<dir>/<name>.svg` atomically, creating `dir` first.
/// @throws hula::Error(Errc::IoError) naming the path if it cannot be written
void write_svg(const std::filesystem::path& dir, std::string_view name, const io::SvgFigure& figure);

/// Refuses an --svg path that exists and is not a directory, or that cannot be created, and an
/// existing directory holding a *.svg or *.csv entry that io::check_output_path refuses (a
/// symbolic link, FIFO, device or directory where a figure would be written).
/// @throws hula::Error(Errc::IoError) naming --svg
void check_svg_directory(const std::filesystem::path& dir);

/// Adds "log" (the --log path or null) to the output document of a study without generations and, with
/// --log, writes the output document there too (it has no generations to log).
void record_run(Json& output, const StudyArgs& args);

}  // namespace hula::cli
