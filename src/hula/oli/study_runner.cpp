// SPDX-License-Identifier: MIT
// The one study runner (study_runner.hpp).
#include "hula/oli/study_runner.hpp"

#include <chrono>
#include <optional>
#include <type_traits>
#include <utility>
#include <variant>

#include "hula/core/error.hpp"
#include "hula/io/fair_knots_study_file.hpp"
#include "hula/studies/curvature_torsion_match.hpp"
#include "hula/studies/match_study.hpp"

namespace hula::oli {

namespace {

// The run's limits and progress as every optimiser of a study takes them: the caller's callback, counted into
// the report (generations and evaluations across the study's optimiser runs).
struct Progress {
  const StudyRunOptions& options;
  studies::StudyReport& report;
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  // One deadline for the whole run, whatever optimisers and rounds it makes.
  optim::Deadline deadline = optim::deadline_after(options.wall_time_seconds);
  std::size_t evaluations_before = 0;

  optim::GenerationCallback callback() {
    return [this](const optim::GenerationLog& g) {
      if (g.generation == 0) evaluations_before = report.evaluations;
      report.evaluations = evaluations_before + g.evaluations;
      ++report.generations;
      report.seconds = seconds();
      if (options.on_generation) options.on_generation(g);
      if (options.on_progress) options.on_progress(g, report);
    };
  }
  [[nodiscard]] double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  void apply(optim::StopCriteria& stop) const {
    stop.deadline = deadline;
    stop.cancel = options.cancel;
  }
  void apply(studies::StudyHeader& header) {
    header.deadline = deadline;
    header.cancel = options.cancel;
    header.on_generation = callback();
  }
};

void run_match(const io::StudyDocument& doc, const io::PathResolver& resolver, Progress& progress, StudyOutcome& out) {
  io::MatchStudyFile file = io::match_study_from_json(doc, resolver);
  progress.apply(file.study.header);
  auto match = std::make_shared<const studies::CurvatureMatch>(file.study.setup);
  studies::MatchResult result = studies::run_curvature_match(*match, file.study, progress.options.keep_log);
  out.result = io::match_result_to_json(*match, file, result);
  out.log = std::move(result.log);
  if (std::optional<nurbs::NurbsCurve> c = studies::match_result_curve(*match, result))
    out.curves.push_back({std::move(*c), out.kind + " result"});
  file.study.header.on_generation = nullptr;  // it refers to this run's counters
  out.values = MatchValues{std::move(file), std::move(match), std::move(result)};
}

void run_match_torsion(const io::StudyDocument& doc, const io::PathResolver& resolver, Progress& progress,
                       StudyOutcome& out) {
  io::TorsionMatchStudyFile file = io::torsion_match_study_from_json(doc, resolver);
  studies::TorsionMatchStudy& study = file.study;
  study.settings.deadline = progress.deadline;
  study.settings.cancel = progress.options.cancel;
  study.settings.on_generation = progress.callback();
  auto match = std::make_shared<const studies::CurvatureMatch>(study.setup);
  studies::TorsionMatchResult result = studies::run_curvature_torsion_match(
      *match, study.settings, study.header.seed, study.header.threads, progress.options.keep_log);
  out.result = io::torsion_match_result_to_json(*match, file, result);
  out.log = std::move(result.log);
  if (!result.front.empty()) {
    std::vector<Vec3> pts(match->setup().points.size());
    match->points_from(result.front[result.compromise].variables, pts);
    out.curves.push_back({match->sampler().curve(pts), out.kind + " compromise"});
  }
  study.settings.on_generation = nullptr;
  out.values = TorsionMatchValues{std::move(file), std::move(match), std::move(result)};
}

// The chord-length start, the given parameters, the energy map and its sections, and the GA and/or
// deterministic optimum, each optimum a result curve.
void run_fair_knots(const io::StudyDocument& doc, Progress& progress, StudyOutcome& out) {
  studies::FairKnotsStudy study = io::fair_knots_study_from_json(doc);
  for (optim::RunSettings* run : {&study.ga.binary.run, &study.ga.real.run}) {
    progress.apply(run->stop);
    run->on_generation = progress.callback();
  }
  study.deterministic.deadline = progress.deadline;
  study.deterministic.cancel = progress.options.cancel;
  study.deterministic.on_generation = progress.callback();
  studies::FairKnotsOutcome outcome =
      studies::run_fair_knots_study(study, progress.options.keep_log ? &out.log : nullptr);
  out.result = io::fair_knots_result_to_json(study, outcome);
  if (outcome.ga) out.curves.push_back({outcome.ga->best.curve, "fair-knots GA optimum"});
  if (outcome.deterministic)
    out.curves.push_back({outcome.deterministic->best.curve, "fair-knots deterministic optimum"});
  for (optim::RunSettings* run : {&study.ga.binary.run, &study.ga.real.run}) run->on_generation = nullptr;
  study.deterministic.on_generation = nullptr;
  out.values = FairKnotsValues{std::move(study), std::move(outcome)};
}

// The editing studies are deterministic: their results carry the header's seed and threads.
void add_run_identity(const studies::StudyHeader& header, io::Json& result) {
  result["seed"] = header.seed;
  result["threads"] = header.threads;
}

// Thesis 8.1: the rebuilt curve is the result.
void run_edit_projection(const io::StudyDocument& doc, StudyOutcome& out) {
  io::EditProjectionStudy study = io::read_edit_projection_study(doc);
  studies::ProjectionEditResult r = studies::edit_projection(study.curve.nurbs(), study.edited.nurbs(), study.plane);
  out.result = io::edit_projection_result_to_json(study, r);
  add_run_identity(study.header, out.result);
  out.curves.push_back({r.curve, "edit-projection result"});
  out.values = EditProjectionValues{std::move(study), std::move(r)};
}

// Thesis 8.3: the result curve is the rebuilt 3-D curve, the compound or the parent.
void run_fin_compound(const io::StudyDocument& doc, StudyOutcome& out) {
  io::FinCompoundStudy study = io::read_fin_compound_study(doc);
  io::FinCompoundRun run = io::run_fin_compound_study(study);
  out.result = io::fin_compound_result_to_json(study, run);
  add_run_identity(study.header, out.result);
  const char* what = run.edit ? "rebuilt curve" : (run.compound ? "compound" : "parent");
  out.curves.push_back({run.result_curve(), std::string("fin-compound ") + what});
  out.values = FinCompoundValues{std::move(study), std::move(run)};
}

// Thesis 7.5.2: the curve rebuilt from the edited handles.
void run_hermite(const io::StudyDocument& doc, StudyOutcome& out) {
  io::HermiteStudy study = io::read_hermite_study(doc);
  studies::HermiteEditResult r = studies::hermite_edit(study.spline.points, study.edits, study.options);
  out.result = io::hermite_result_to_json(study, r);
  add_run_identity(study.header, out.result);
  out.curves.push_back({r.curve, "hermite result"});
  out.values = HermiteValues{std::move(study), std::move(r)};
}

}  // namespace

const std::vector<std::string>& study_kinds() {
  static const std::vector<std::string> kinds{
      "match-curvature", "match-curvature-torsion", "fair-knots", "edit-projection", "fin-compound", "hermite"};
  return kinds;
}

StudyOutcome run_study(const io::StudyDocument& study, const io::PathResolver& resolver,
                       const StudyRunOptions& options) {
  StudyOutcome out;
  out.kind = study.header.kind;
  out.seed = study.header.seed;
  out.threads = study.header.threads;
  out.report.kind = out.kind;
  Progress progress{options, out.report};
  if (out.kind == "match-curvature")
    run_match(study, resolver, progress, out);
  else if (out.kind == "match-curvature-torsion")
    run_match_torsion(study, resolver, progress, out);
  else if (out.kind == "fair-knots")
    run_fair_knots(study, progress, out);
  else if (out.kind == "edit-projection")
    run_edit_projection(study, out);
  else if (out.kind == "fin-compound")
    run_fin_compound(study, out);
  else if (out.kind == "hermite")
    run_hermite(study, out);
  else {
    std::string supported;
    for (const std::string& k : study_kinds()) supported += (supported.empty() ? "" : ", ") + k;
    throw Error(Errc::InvalidArgument, "study kind \"" + out.kind + "\" is not run here (supported: " + supported + ")",
                {.field = "study"});
  }
  out.report.cancelled = options.cancel != nullptr && options.cancel->is_cancelled();
  out.report.seconds = progress.seconds();
  return out;
}

io::StudyFigures study_figures(const StudyOutcome& outcome) {
  return std::visit(
      [](const auto& v) -> io::StudyFigures {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, MatchValues>)
          return io::match_figures(*v.match, v.file.study, v.result);
        else if constexpr (std::is_same_v<T, TorsionMatchValues>)
          return io::torsion_match_figures(*v.match, v.file.study.settings, v.result);
        else if constexpr (std::is_same_v<T, FairKnotsValues>)
          return io::fair_knots_figures(v.study, v.outcome);
        else if constexpr (std::is_same_v<T, EditProjectionValues>)
          return io::edit_projection_figures(v.study, v.result);
        else if constexpr (std::is_same_v<T, FinCompoundValues>)
          return io::fin_compound_figures(v.study, v.run);
        else
          return io::hermite_figures(v.study, v.result);
      },
      outcome.values);
}

}  // namespace hula::oli
