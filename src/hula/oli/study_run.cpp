// SPDX-License-Identifier: MIT
// Study runs stored in the document (study_run.hpp).
#include "hula/oli/study_run.hpp"

#include <set>
#include <sstream>

#include "hula/core/error.hpp"
#include "hula/curve/curve.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/oli/detail/entity_codec.hpp"
#include "hula/io/match_study_file.hpp"
#include "hula/io/path_resolver.hpp"
#include "hula/io/study_file.hpp"
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

// Runs one study; returns the run and its result curve.
struct Ran {
  StudyRun run;
  std::optional<curve::Curve> curve;
  std::string kind;
};

Ran run_once(const Json& setup, const Document& document, const std::filesystem::path& base,
             std::optional<std::uint64_t> seed, std::set<Label>& read) {
  Json resolved = setup;
  resolve_entities(resolved, document, read);
  if (seed) resolved["seed"] = *seed;
  const std::string kind = resolved.contains("study") && resolved["study"].is_string()
                               ? resolved["study"].get<std::string>()
                               : std::string();
  Ran out;
  out.kind = kind;
  if (kind == "match-curvature") {
    // Files a study names stay inside the document's folder (io::confined_to), as on a server.
    const io::StudyDocument doc = io::parse_study_json(resolved.dump(), kind);
    const io::MatchStudyFile file = io::match_study_from_json(doc, io::confined_to(base));
    const studies::CurvatureMatch match(file.study.setup);
    const studies::MatchResult result = studies::run_curvature_match(match, file.study, true);
    out.run.seed = file.study.header.seed;
    out.run.result = io::match_result_to_json(match, file, result);
    std::ostringstream log;
    result.log.write_json(log);
    out.run.log = Json::parse(log.str());
    out.curve = io::curve_from_json(out.run.result.at("curve"));
    return out;
  }
  throw Error(Errc::InvalidArgument,
              "study kind \"" + kind + "\" cannot run inside a document (supported: match-curvature)",
              {.field = "study"});
}

StudyRunResult record(Edit& edit, Label study, Ran ran, const std::set<Label>& read) {
  StudyRunResult out;
  out.study = study;
  Provenance p;
  p.operation = "study:" + ran.kind;
  p.inputs.push_back(study);
  p.inputs.insert(p.inputs.end(), read.begin(), read.end());
  p.seed = ran.run.seed;
  p.tool_version = HULA_VERSION;
  Study stored = edit.get(study).study();
  p.details["run"] = stored.runs.size();
  if (ran.curve) out.curves.push_back(edit.add_curve(*ran.curve, {.name = ran.kind + " result"}, p));
  ran.run.result_curves = out.curves;
  out.result = ran.run.result;
  stored.runs.push_back(std::move(ran.run));
  edit.set_study(study, std::move(stored));
  return out;
}

}  // namespace

StudyRunResult run_study(Edit& edit, const Json& study_file, const std::filesystem::path& base) {
  if (!study_file.is_object()) throw Error(Errc::ParseError, "a study file must be a JSON object", {.field = "study"});
  std::set<Label> read;
  Ran ran = run_once(study_file, edit.document(), base, std::nullopt, read);
  Provenance p;
  p.operation = "study";
  p.inputs.assign(read.begin(), read.end());
  p.tool_version = HULA_VERSION;
  const Label study = edit.add_study({study_file, {}}, {.name = ran.kind}, p);
  return record(edit, study, std::move(ran), read);
}

StudyRunResult rerun_study(Edit& edit, Label study, const std::filesystem::path& base,
                           std::optional<std::uint64_t> seed) {
  const Json setup = edit.get(study).study().setup;
  std::set<Label> read;
  Ran ran = run_once(setup, edit.document(), base, seed, read);
  return record(edit, study, std::move(ran), read);
}

}  // namespace hula::oli
