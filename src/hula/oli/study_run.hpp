// SPDX-License-Identifier: MIT
// Study runs stored in the document (thesis 9.5.4): a study
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
// The run itself is oli::run_study of the resolved setup (study_runner.hpp: the
// one runner of every door, with its kinds and result documents), its files
// read inside the document's folder (io::confined_to); the run stores its
// result document, its log and its result curves, not its figures.
//
// Phases (so a server need not hold the document's writer lock while a study
// computes): prepare_study / prepare_rerun resolve the entity references
// against the document as it is then (a reader is enough), compute_study runs
// the study without touching the document, and commit_study stores the study
// entity, the run and its result curves in the caller's transaction.
// run_study and rerun_study are the three in a row inside one transaction.
// When the document changes between prepare and commit, the run is still
// stored: it is the run of the setup on the entities as read at prepare (the
// revision and their data then), its result curves' provenance lists the
// entities read (a removed one stays named; labels are never reused) and, under
// details "inputs_changed", the labels whose data changed or which were removed
// since; a study entity removed meanwhile (rerun) fails the commit.
//
// Progress and cancellation (StudyRunOptions): the caller's callback sees
// every generation of the study's optimiser(s); a cancellation token stops
// them at the next generation, and the best so far is stored like a finished
// run (StudyRunResult::cancelled says so).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hula/curve/curve.hpp"
#include "hula/oli/document.hpp"
#include "hula/oli/study_runner.hpp"

namespace hula::oli {

/// What a run added.
struct StudyRunResult {
  /// The study entity.
  Label study{};
  /// The run's result curves (new entities).
  std::vector<Label> curves{};
  /// The study's result document.
  Json result = Json::object();
  /// The study kind ("match-curvature", ...).
  std::string kind{};
  /// True when the cancellation token was set before the run ended: the stored result is the best so far.
  bool cancelled = false;
  /// How the run went (generations and evaluations across the study's optimiser runs, seconds).
  studies::StudyReport report{};
};

/// A study file with its entity references resolved against one revision of a document (phase 1).
struct PreparedStudy {
  /// The setup as given (stored in the study entity, references kept).
  Json setup = Json::object();
  /// The setup with every {"entity": L} replaced by L's data (and the seed of a rerun).
  Json resolved = Json::object();
  /// The study kind ("match-curvature", ...), checked to be one run here.
  std::string kind{};
  /// The entities the setup read, in label order, as they were at `revision`.
  std::vector<Entity> inputs{};
  /// The document's revision when the references were resolved.
  std::uint64_t revision = 0;
  /// The stored study a rerun appends to; none for a new study.
  std::optional<Label> study{};
};

/// A computed run not yet stored (phase 2).
struct ComputedStudy {
  PreparedStudy prepared{};
  /// The run (seed, result, log); its result curves are set when committed.
  StudyRun run{};
  /// The result curves with the names they get in the document.
  std::vector<NamedCurve> curves{};
  /// How the run went; report.cancelled when the cancellation token was set when the computation ended.
  studies::StudyReport report{};
};

/// Resolves `study_file`'s entity references against `document` (phase 1; reads only).
/// @throws hula::Error(Errc::ParseError) when `study_file` is not an object or a reference is not a
///   label; hula::Error(Errc::InvalidArgument) naming the kind when it is not supported, or an
///   entity reference to a missing label or a study
PreparedStudy prepare_study(const Document& document, const Json& study_file);

/// Resolves the stored setup of `study` (with `seed` in place of its own, if given) against `document`.
/// @throws as prepare_study; hula::Error(Errc::InvalidArgument) when `study` is not a study
PreparedStudy prepare_rerun(const Document& document, Label study, std::optional<std::uint64_t> seed = std::nullopt);

/// Runs a prepared study (phase 2); reads no document, so it needs no lock.
/// @param base the directory relative paths of the study file are read from
/// @throws the study's own errors (ParseError naming the member, InvalidOption, NumericalFailure)
ComputedStudy compute_study(PreparedStudy prepared, const std::filesystem::path& base,
                            const StudyRunOptions& options = {});

/// Stores a computed run (phase 3, inside the caller's transaction): a new study entity for a
/// prepare_study, then the run and its result curves (see the header comment for inputs changed meanwhile).
/// @throws hula::Error(Errc::InvalidArgument) when a rerun's study entity is gone
StudyRunResult commit_study(Edit& edit, ComputedStudy computed);

/// Adds a study entity for `study_file` and runs it once (inside the caller's transaction).
/// @param base the directory relative paths of the study file are read from
/// @throws hula::Error(Errc::InvalidArgument) naming the kind when it is not supported, or an
///   entity reference to a missing label or a study; the study's own errors (ParseError naming the
///   member, InvalidOption, NumericalFailure) — the transaction then rolls back
StudyRunResult run_study(Edit& edit, const Json& study_file, const std::filesystem::path& base,
                         const StudyRunOptions& options = {});

/// Runs a stored study again from its stored setup and seed (or `seed`), appending a run.
/// @throws as run_study; hula::Error(Errc::InvalidArgument) when `study` is not a study
StudyRunResult rerun_study(Edit& edit, Label study, const std::filesystem::path& base,
                           std::optional<std::uint64_t> seed = std::nullopt, const StudyRunOptions& options = {});

}  // namespace hula::oli
