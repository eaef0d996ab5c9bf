// SPDX-License-Identifier: MIT
// Study runs stored in the document (study_run.hpp).
#include "hula/oli/study_run.hpp"

#include <algorithm>
#include <iterator>
#include <optional>
#include <set>

#include "hula/core/error.hpp"
#include "hula/curve/curve.hpp"
#include "hula/io/editing_study_file.hpp"
#include "hula/io/fair_knots_study_file.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/match_study_file.hpp"
#include "hula/io/path_resolver.hpp"
#include "hula/io/run_report_json.hpp"
#include "hula/io/study_file.hpp"
#include "hula/oli/detail/entity_codec.hpp"
#include "hula/studies/curvature_torsion_match.hpp"
#include "hula/studies/match_study.hpp"

#ifndef HULA_VERSION
#define HULA_VERSION "unknown"
#endif

namespace hula::oli {
namespace {

// Replaces every {"entity": L} in `value` by entity L's data; collects the labels read.
void resolve_entities(Json& value, const Document& document, std::set<Label>& read) {
  if (value.is_object() && value.size() == 1 && value.contains("entity")) {
    const Json& ref = value["entity"];
    if (!ref.is_number_unsigned() || ref.get<std::uint64_t>() == 0)
      throw Error(Errc::ParseError, "{\"entity\": " + ref.dump() + "}: an entity reference must be a label",
                  {.field = "entity"});
    const Label label{ref.get<std::uint64_t>()};
    const Entity e = document.get(label);
    read.insert(label);
    switch (e.kind()) {
      case EntityKind::Curve:
        value = io::curve_to_json(e.curve());
        return;
      case EntityKind::PointSet:
        value = detail::entity_data_to_json(*e.state()).at("points");
        return;
      case EntityKind::Study:
        throw Error(
            Errc::InvalidArgument,
            "entity " + std::to_string(label.value) + " is a study; a study file may name curves and point sets",
            {.field = "entity"});
    }
  }
  if (value.is_object())
    for (auto& [key, member] : value.items()) resolve_entities(member, document, read);
  else if (value.is_array())
    for (Json& element : value) resolve_entities(element, document, read);
}

Json log_json(const optim::RunLog& log) { return io::run_log_to_json(log); }

void run_match(const io::StudyDocument& doc, const std::filesystem::path& base, const StudyRunOptions& options,
               ComputedStudy& out) {
  // Files a study names stay inside the document's folder (io::confined_to), as on a server.
  io::MatchStudyFile file = io::match_study_from_json(doc, io::confined_to(base));
  file.study.header.cancel = options.cancel;
  file.study.header.on_generation = options.on_generation;
  const studies::CurvatureMatch match(file.study.setup);
  const studies::MatchResult result = studies::run_curvature_match(match, file.study, true);
  out.run.seed = file.study.header.seed;
  out.run.result = io::match_result_to_json(match, file, result);
  out.run.log = log_json(result.log);
  if (std::optional<nurbs::NurbsCurve> c = studies::match_result_curve(match, result))
    out.curves.emplace_back(std::move(*c), out.prepared.kind + " result");
}

void run_match_torsion(const io::StudyDocument& doc, const std::filesystem::path& base, const StudyRunOptions& options,
                       ComputedStudy& out) {
  io::TorsionMatchStudyFile file = io::torsion_match_study_from_json(doc, io::confined_to(base));
  studies::TorsionMatchStudy& study = file.study;
  study.settings.cancel = options.cancel;
  study.settings.on_generation = options.on_generation;
  const studies::CurvatureMatch match(study.setup);
  const studies::TorsionMatchResult result =
      studies::run_curvature_torsion_match(match, study.settings, study.header.seed, study.header.threads, true);
  out.run.seed = study.header.seed;
  out.run.result = io::torsion_match_result_to_json(match, file, result);
  out.run.log = log_json(result.log);
  if (!result.front.empty()) {
    std::vector<Vec3> pts(match.setup().points.size());
    match.points_from(result.front[result.compromise].variables, pts);
    out.curves.emplace_back(match.sampler().curve(pts), out.prepared.kind + " compromise");
  }
}

// As `hula fair-knots` without the energy map and figures: the chord-length start, the given
// parameters, and the GA and/or deterministic optimum, each optimum a result curve.
void run_fair_knots(const io::StudyDocument& doc, const StudyRunOptions& options, ComputedStudy& out) {
  studies::FairKnotsStudy study = io::fair_knots_study_from_json(doc);
  for (optim::RunSettings* run : {&study.ga.binary.run, &study.ga.real.run}) {
    run->stop.cancel = options.cancel;
    run->on_generation = options.on_generation;
  }
  study.deterministic.cancel = options.cancel;
  const studies::KnotFairingSetup& setup = study.setup;
  const std::vector<double> chord = studies::chord_length_parameters(setup);
  const studies::ParameterEvaluation before = studies::evaluate_parameters(setup, chord);
  Json result = Json::object();
  result["study"] = io::fair_knots_study_to_json(study);
  result["energy"] = studies::fairing_energy_name(setup.energy);
  result["chord_length"] = io::fairing_evaluation_to_json(before);
  if (study.parameters)
    result["given"] = io::fairing_evaluation_to_json(studies::evaluate_parameters(setup, *study.parameters));
  optim::RunLog log;
  if (study.method != studies::FairingMethod::Deterministic) {
    const studies::FairingResult ga = studies::fair_knots_ga(setup, chord, study.ga, &log);
    result["ga"] = io::fairing_result_to_json(ga, before.energy);
    out.curves.emplace_back(ga.best.curve, "fair-knots GA optimum");
  }
  if (study.method != studies::FairingMethod::Ga) {
    const studies::FairingResult det = studies::fair_knots_deterministic(setup, chord, study.deterministic);
    result["deterministic"] = io::fairing_result_to_json(det, before.energy);
    out.curves.emplace_back(det.best.curve, "fair-knots deterministic optimum");
  }
  out.run.seed = study.header.seed;
  out.run.result = std::move(result);
  out.run.log = log_json(log);
}

// As `hula edit-projection` (thesis 8.1): deterministic, no generations; the rebuilt curve is the result.
void run_edit_projection(const io::StudyDocument& doc, ComputedStudy& out) {
  const io::EditProjectionStudy study = io::read_edit_projection_study(doc);
  const studies::ProjectionEditResult r =
      studies::edit_projection(study.curve.nurbs(), study.edited.nurbs(), study.plane);
  out.run.seed = study.header.seed;
  out.run.result = io::edit_projection_result_to_json(study, r);
  out.curves.emplace_back(r.curve, "edit-projection result");
}

// As `hula fin-compound` (thesis 8.3) without its figures; the result curve is the one `-o` writes (the
// rebuilt 3-D curve, the compound or the parent). Deterministic, no generations.
void run_fin_compound(const io::StudyDocument& doc, ComputedStudy& out) {
  const io::FinCompoundStudy study = io::read_fin_compound_study(doc);
  const io::FinCompoundRun run = io::run_fin_compound_study(study);
  out.run.seed = study.header.seed;
  out.run.result = io::fin_compound_result_to_json(study, run);
  const char* what = run.edit ? "rebuilt curve" : (run.compound ? "compound" : "parent");
  out.curves.emplace_back(run.result_curve(), std::string("fin-compound ") + what);
}

// As `hula hermite` (thesis 7.5.2) without its figures: the curve rebuilt from the edited handles.
void run_hermite(const io::StudyDocument& doc, ComputedStudy& out) {
  const io::HermiteStudy study = io::read_hermite_study(doc);
  const studies::HermiteEditResult r = studies::hermite_edit(study.spline.points, study.edits, study.options);
  out.run.seed = study.header.seed;
  out.run.result = io::hermite_result_to_json(study, r);
  out.curves.emplace_back(r.curve, "hermite result");
}

// The study kinds run inside a document (the header comment says what each stores).
constexpr const char* kKinds[] = {
    "match-curvature", "match-curvature-torsion", "fair-knots", "edit-projection", "fin-compound", "hermite"};

PreparedStudy prepare(const Json& setup, const Document& document, std::optional<std::uint64_t> seed,
                      std::optional<Label> study) {
  PreparedStudy out;
  out.setup = setup;
  out.resolved = setup;
  out.study = study;
  out.revision = document.revision();
  std::set<Label> read;
  resolve_entities(out.resolved, document, read);
  for (const Label l : read) out.inputs.push_back(document.get(l));
  if (seed) out.resolved["seed"] = *seed;
  out.kind = out.resolved.contains("study") && out.resolved["study"].is_string()
                 ? out.resolved["study"].get<std::string>()
                 : std::string();
  if (std::find(std::begin(kKinds), std::end(kKinds), out.kind) == std::end(kKinds)) {
    std::string supported;
    for (const char* k : kKinds) supported += (supported.empty() ? "" : ", ") + std::string(k);
    throw Error(Errc::InvalidArgument,
                "study kind \"" + out.kind + "\" cannot run inside a document (supported: " + supported + ")",
                {.field = "study"});
  }
  return out;
}

// The inputs whose data changed, or which were removed, since they were read (attributes do not count).
std::vector<Label> inputs_changed(const Document& document, const std::vector<Entity>& inputs) {
  std::vector<Label> changed;
  for (const Entity& was : inputs) {
    if (!document.contains(was.label())) {
      changed.push_back(was.label());
      continue;
    }
    const Entity now = document.get(was.label());
    if (now.kind() != was.kind() || now.state()->curve != was.state()->curve ||
        now.state()->points != was.state()->points)
      changed.push_back(was.label());
  }
  return changed;
}

// Stores the run and its result curves; a cancelled run (best so far) says so in the curves' provenance.
StudyRunResult record(Edit& edit, Label study, ComputedStudy ran) {
  StudyRunResult out;
  out.study = study;
  out.kind = ran.prepared.kind;
  out.cancelled = ran.cancelled;
  Provenance p;
  p.operation = "study:" + ran.prepared.kind;
  p.inputs.push_back(study);
  for (const Entity& e : ran.prepared.inputs) p.inputs.push_back(e.label());
  p.seed = ran.run.seed;
  p.tool_version = HULA_VERSION;
  Study stored = edit.get(study).study();
  p.details["run"] = stored.runs.size();
  if (out.cancelled) p.details["cancelled"] = true;
  if (const std::vector<Label> changed = inputs_changed(edit.document(), ran.prepared.inputs); !changed.empty()) {
    Json labels = Json::array();
    for (const Label l : changed) labels.push_back(l.value);
    p.details["inputs_changed"] = std::move(labels);
    p.details["read_at_revision"] = ran.prepared.revision;
  }
  for (const auto& [curve, name] : ran.curves) out.curves.push_back(edit.add_curve(curve, {.name = name}, p));
  ran.run.result_curves = out.curves;
  out.result = ran.run.result;
  stored.runs.push_back(std::move(ran.run));
  edit.set_study(study, std::move(stored));
  return out;
}

}  // namespace

PreparedStudy prepare_study(const Document& document, const Json& study_file) {
  if (!study_file.is_object()) throw Error(Errc::ParseError, "a study file must be a JSON object", {.field = "study"});
  return prepare(study_file, document, std::nullopt, std::nullopt);
}

PreparedStudy prepare_rerun(const Document& document, Label study, std::optional<std::uint64_t> seed) {
  return prepare(document.get(study).study().setup, document, seed, study);
}

ComputedStudy compute_study(PreparedStudy prepared, const std::filesystem::path& base, const StudyRunOptions& options) {
  ComputedStudy out;
  out.prepared = std::move(prepared);
  const std::string& kind = out.prepared.kind;
  const io::StudyDocument doc = io::study_from_json(out.prepared.resolved, kind);
  if (kind == "match-curvature")
    run_match(doc, base, options, out);
  else if (kind == "match-curvature-torsion")
    run_match_torsion(doc, base, options, out);
  else if (kind == "fair-knots")
    run_fair_knots(doc, options, out);
  else if (kind == "edit-projection")
    run_edit_projection(doc, out);
  else if (kind == "fin-compound")
    run_fin_compound(doc, out);
  else
    run_hermite(doc, out);
  out.cancelled = options.cancel != nullptr && options.cancel->is_cancelled();
  return out;
}

StudyRunResult commit_study(Edit& edit, ComputedStudy computed) {
  if (computed.prepared.study) return record(edit, *computed.prepared.study, std::move(computed));
  Provenance p;
  p.operation = "study";
  for (const Entity& e : computed.prepared.inputs) p.inputs.push_back(e.label());
  p.tool_version = HULA_VERSION;
  const Label study = edit.add_study({computed.prepared.setup, {}}, {.name = computed.prepared.kind}, p);
  return record(edit, study, std::move(computed));
}

StudyRunResult run_study(Edit& edit, const Json& study_file, const std::filesystem::path& base,
                         const StudyRunOptions& options) {
  return commit_study(edit, compute_study(prepare_study(edit.document(), study_file), base, options));
}

StudyRunResult rerun_study(Edit& edit, Label study, const std::filesystem::path& base,
                           std::optional<std::uint64_t> seed, const StudyRunOptions& options) {
  return commit_study(edit, compute_study(prepare_rerun(edit.document(), study, seed), base, options));
}

}  // namespace hula::oli
