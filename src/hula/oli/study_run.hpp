// SPDX-License-Identifier: MIT
// Study runs stored in the document (issue 11 item 5, thesis 9.5.4): a study
// file is added as a study entity holding its setup; each run records its
// seed, its result (champion, distances, termination — the study's own result
// document), its run log, and adds its result curve as a new curve entity
// whose provenance names the study, the entities the setup read and the seed.
// A run repeats bit-exactly from what the document stored: rerun_study runs
// the stored setup again, with its stored seed.
//
// In a study file given to run_study, any value written {"entity": L} is
// replaced by entity L's data before the study reads it: a curve by its curve
// file, a point set by its points array (so "points": {"entity": 3} takes the
// data points from point set 3). The setup is stored with the references, so
// a rerun reads the entities as they are then; the run records their labels.
//
// Supported study kinds: "match-curvature" (docs/studies.md).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include "hula/oli/document.hpp"

namespace hula::oli {

/// What a run added.
struct StudyRunResult {
  /// The study entity.
  Label study{};
  /// The run's result curves (new entities).
  std::vector<Label> curves{};
  /// The study's result document.
  Json result = Json::object();
};

/// Adds a study entity for `study_file` and runs it once (inside the caller's transaction).
/// @param base the directory relative paths of the study file are read from
/// @throws hula::Error(Errc::InvalidArgument) naming the kind when it is not supported, or an
///   entity reference to a missing label or a study; the study's own errors (ParseError naming the
///   member, InvalidOption, NumericalFailure) — the transaction then rolls back
StudyRunResult run_study(Edit& edit, const Json& study_file, const std::filesystem::path& base);

/// Runs a stored study again from its stored setup and seed (or `seed`), appending a run.
/// @throws as run_study; hula::Error(Errc::InvalidArgument) when `study` is not a study
StudyRunResult rerun_study(Edit& edit, Label study, const std::filesystem::path& base,
                           std::optional<std::uint64_t> seed = std::nullopt);

}  // namespace hula::oli
