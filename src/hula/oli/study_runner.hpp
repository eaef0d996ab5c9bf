// SPDX-License-Identifier: MIT
// The one study runner (thesis ch. 7 and 8, docs/formats.md "Study files"):
// a study setup run without a document, giving a typed outcome — the result
// document every door returns (one io codec per kind), the result curves as
// curve values, the run report and log, and the typed values the figures and
// Open CASCADE baselines are drawn from. `hula <study kind> STUDY`, the
// document's study runs (study_run.hpp: `hula doc run-study`, the server's
// study jobs, Document.run_study in Python) and hulahoops' study functions all
// run a study through run_study; none runs one its own way.
//
// Kinds: "match-curvature" (result curve: the direct method's NURBS, else the
// spline through the best points), "match-curvature-torsion" (the best
// compromise), "fair-knots" (the GA's and/or the deterministic optimum; the
// energy map and its sections when the setup asks), "edit-projection" (the
// rebuilt curve), "fin-compound" (the rebuilt 3-D curve, the compound or the
// parent) and "hermite" (the curve rebuilt from the edited handles). The
// results of the last three are deterministic and carry the run's "seed" and
// "threads" (the header's) for uniformity with the others, whose resolved
// "study" holds them.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include "hula/curve/curve.hpp"
#include "hula/io/editing_study_file.hpp"
#include "hula/io/match_study_file.hpp"
#include "hula/io/path_resolver.hpp"
#include "hula/io/study_figures.hpp"
#include "hula/io/study_file.hpp"
#include "hula/optim/run_log.hpp"
#include "hula/studies/fair_knots_study.hpp"

namespace hula::oli {

/// The study kinds run_study runs, in the order of the file comment.
[[nodiscard]] const std::vector<std::string>& study_kinds();

/// How a study runs.
struct StudyRunOptions {
  /// Called on the running thread with each generation of every optimiser run the study makes, in
  /// order (re-centred rounds and the two fair-knots optimisers each start again at generation 0).
  /// Default none.
  optim::GenerationCallback on_generation{};
  /// Called after on_generation with the same generation and the report so far: generations (this one
  /// included) and evaluations counted across the study's optimiser runs, seconds since the start (a
  /// server job's progress events). Default none.
  std::function<void(const optim::GenerationLog&, const studies::StudyReport&)> on_progress{};
  /// Checked between generations (and simplex iterations); once set the optimisers stop with their best
  /// so far, which is the result. Not owned; must outlive the run. Default none.
  const optim::CancellationToken* cancel = nullptr;
  /// Wall-clock limit of the whole run in seconds, from the start of run_study: every optimiser and every
  /// re-centred round shares this one deadline and ends with its best so far once it passes (a `--time`
  /// of 0.3 s on a study of 11 rounds is 0.3 s, not 11 × 0.3 s). 0 = none (default). The run then depends
  /// on the machine: leave it at 0 when reproducibility matters.
  double wall_time_seconds = 0.0;
  /// Collect every individual of every generation into StudyOutcome::log. Default true (a document stores
  /// it).
  bool keep_log = true;
};

/// A "match-curvature" run's values.
struct MatchValues {
  io::MatchStudyFile file{};
  std::shared_ptr<const studies::CurvatureMatch> match{};
  studies::MatchResult result{};
};
/// A "match-curvature-torsion" run's values.
struct TorsionMatchValues {
  io::TorsionMatchStudyFile file{};
  std::shared_ptr<const studies::CurvatureMatch> match{};
  studies::TorsionMatchResult result{};
};
/// A "fair-knots" run's values.
struct FairKnotsValues {
  studies::FairKnotsStudy study{};
  studies::FairKnotsOutcome outcome{};
};
/// An "edit-projection" run's values.
struct EditProjectionValues {
  io::EditProjectionStudy study;
  studies::ProjectionEditResult result;
};
/// A "fin-compound" run's values.
struct FinCompoundValues {
  io::FinCompoundStudy study{};
  io::FinCompoundRun run{};
};
/// A "hermite" run's values.
struct HermiteValues {
  io::HermiteStudy study;
  studies::HermiteEditResult result;
};
/// The typed values of a run, by kind.
using StudyValues = std::variant<MatchValues, TorsionMatchValues, FairKnotsValues, EditProjectionValues,
                                 FinCompoundValues, HermiteValues>;

/// A result curve with the name it gets in a document ("match-curvature result", ...).
struct NamedCurve {
  curve::Curve curve;
  std::string name{};
};

/// What a run gives.
struct StudyOutcome {
  /// The study kind.
  std::string kind{};
  /// The run's seed and threads (the study's header).
  std::uint64_t seed = 1;
  std::size_t threads = 1;
  /// The result document every door returns (the kind's io codec: docs/formats.md).
  io::Json result = io::Json::object();
  /// The result curves, as values.
  std::vector<NamedCurve> curves{};
  /// Every generation of every optimiser run (StudyRunOptions::keep_log; empty for the editing studies).
  optim::RunLog log{};
  /// How the run went (io::study_report_to_json).
  studies::StudyReport report{};
  /// The typed values (figures, baselines, Python's arrays).
  StudyValues values;
  /// True when the cancellation token was set when the run ended: the result is the best so far.
  [[nodiscard]] bool cancelled() const noexcept { return report.cancelled; }
};

/// Runs a study setup.
/// @param study the parsed study document (io::study_from_json / io::read_study_file) of a kind of
///   study_kinds()
/// @param resolver opens the files the setup names (io::relative_to the study file's folder on the CLI,
///   io::confined_to a document's folder)
/// @throws hula::Error(Errc::InvalidArgument) naming "study" for a kind run_study does not run; the kind's
///   reader's errors (ParseError naming the member, InvalidOption, ...) before any run; the study's own
///   errors (NumericalFailure)
[[nodiscard]] StudyOutcome run_study(const io::StudyDocument& study, const io::PathResolver& resolver,
                                     const StudyRunOptions& options = {});

/// The figures of a run (io/study_figures.hpp: the kind's figures).
[[nodiscard]] io::StudyFigures study_figures(const StudyOutcome& outcome);

}  // namespace hula::oli
