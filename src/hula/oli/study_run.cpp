// SPDX-License-Identifier: MIT
// Study runs stored in the document (study_run.hpp).
#include "hula/oli/study_run.hpp"

#include <algorithm>
#include <iterator>
#include <memory>
#include <optional>
#include <set>
#include <variant>

#include "hula/core/error.hpp"
#include "hula/curve/curve.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/path_resolver.hpp"
#include "hula/io/study_file.hpp"
#include "hula/oli/detail/entity_codec.hpp"

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
  const std::vector<std::string>& kinds = study_kinds();
  if (std::find(kinds.begin(), kinds.end(), out.kind) == kinds.end()) {
    std::string supported;
    for (const std::string& k : kinds) supported += (supported.empty() ? "" : ", ") + k;
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
  out.cancelled = ran.report.cancelled;
  out.report = ran.report;
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
  for (const NamedCurve& c : ran.curves) out.curves.push_back(edit.add_curve(c.curve, {.name = c.name}, p));
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
  // Files a study names stay inside the document's folder (io::confined_to), as on a server.
  StudyOutcome ran =
      run_study(io::study_from_json(out.prepared.resolved, out.prepared.kind), io::confined_to(base), options);
  out.run.seed = ran.seed;
  out.run.result = std::move(ran.result);
  // The editing studies have no generations: their stored log stays the empty array.
  if (std::holds_alternative<MatchValues>(ran.values) || std::holds_alternative<TorsionMatchValues>(ran.values) ||
      std::holds_alternative<FairKnotsValues>(ran.values))
    out.run.log = std::make_shared<const optim::RunLog>(std::move(ran.log));
  out.curves = std::move(ran.curves);
  out.report = ran.report;
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
