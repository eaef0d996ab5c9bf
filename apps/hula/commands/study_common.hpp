// SPDX-License-Identifier: MIT
// What the study commands (`hula fair-knots`, `match-curvature`,
// `match-curvature-torsion`, `fin-compound`, `edit-projection`, `hermite`)
// share: the study file argument, the --seed / --threads overrides of the
// file's own values, --log FILE (.csv or .json run log), --svg DIR (before /
// after figures and convergence graphs) and the JSON envelope of the output.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "commands/common.hpp"
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
};

/// Adds STUDY (positional, required), --seed, --threads, --log and --svg to `sub`.
void add_study_options(CLI::App* sub, StudyArgs& args);

/// Reads the study file and applies the --seed / --threads overrides.
/// @throws hula::Error as io::read_study_file
[[nodiscard]] io::StudyDocument load_study(const StudyArgs& args, std::string_view kind);

/// Writes `figure` as `<dir>/<name>.svg` atomically, creating `dir` first.
/// @throws hula::Error(Errc::IoError) naming the path if it cannot be written
void write_svg(const std::filesystem::path& dir, std::string_view name, const io::SvgFigure& figure);

/// Writes a run log as CSV (path ends in .csv) or JSON, atomically.
/// @throws hula::Error(Errc::IoError) naming the path if it cannot be written
void write_run_log(const optim::RunLog& log, const std::filesystem::path& path);

}  // namespace hula::cli
