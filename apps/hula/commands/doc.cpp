// SPDX-License-Identifier: MIT
// `hula doc`: the curve document from the command line (docs/cli.md "hula
// doc"). Each subcommand opens the .hula file, runs at most one transaction
// (or one undo / redo) and prints JSON; inputs are read and checked before
// the file is opened, and a failed transaction rolls back, so a failing
// subcommand leaves the file unchanged. Thin: every operation is an oli call.
#include "commands/doc.hpp"

#include <cctype>
#include <charconv>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>

#include "commands/study_common.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/dxf_file.hpp"
#include "hula/io/json_read.hpp"
#include "hula/oli/document.hpp"
#include "hula/oli/file_convert.hpp"
#include "hula/oli/json_exchange.hpp"
#include "hula/oli/study_run.hpp"
#ifdef HULA_WITH_OCCT
#include "hula/oli/cad_exchange.hpp"
#endif

namespace hula::cli {

namespace {

oli::Label parse_label(const std::string& text) {
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size() || value == 0)
    throw Error(Errc::ParseError, "LABEL \"" + text + "\" must be a positive integer", {.field = "label"});
  return oli::Label{value};
}

Json revision_json(const oli::Document& doc) {
  Json out = Json::object();
  out["revision"] = doc.revision();
  return out;
}

// Runs one transaction and rethrows its error (main turns it into the exit code).
void commit(oli::Document& doc, std::string_view name, const std::function<void(oli::Edit&)>& body) {
  doc.transact(name, body).throw_if_failed();
}

Json labels_json(const std::vector<oli::Label>& labels) {
  Json out = Json::array();
  for (oli::Label l : labels) out.push_back(l.value);
  return out;
}

struct Options {
  std::string file, backend = "native", curve, points, name, attribute, to, study, format = "json", output, input;
  std::vector<std::string> labels;
  std::string label;
  std::optional<std::size_t> move_point;
  bool force = false;
};

int run_new(const Options& o) {
  oli::DocumentOptions options;
  options.backend = o.backend;
  const oli::Document doc = oli::Document::create(o.file, options, o.force);
  Json out = Json::object();
  out["file"] = o.file;
  out["revision"] = doc.revision();
  out["backend"] = doc.options().backend;
  print_json(out);
  return kExitOk;
}

int run_add(const Options& o) {
  oli::Attributes attributes;
  attributes.name = o.name;
  std::optional<curve::Curve> curve;
  std::optional<io::PointSet> points;
  if (!o.curve.empty())
    curve = io::read_curve_file(o.curve);
  else
    points = io::read_points_file(o.points);
  oli::Document doc = oli::Document::open(o.file);
  oli::Label label;
  commit(doc, curve ? "add curve" : "add points",
         [&](oli::Edit& e) { label = curve ? e.add_curve(*curve, attributes) : e.add_point_set(*points, attributes); });
  Json out = Json::object();
  out["label"] = label.value;
  out["revision"] = doc.revision();
  print_json(out);
  return kExitOk;
}

int run_list(const Options& o) {
  const oli::Document doc = oli::Document::open(o.file, oli::OpenMode::ReadOnly);
  Json entities = Json::array();
  for (oli::Label l : doc.labels()) {
    const oli::Entity e = doc.get(l);
    Json item = Json::object();
    item["label"] = l.value;
    item["kind"] = oli::entity_display_kind(e);
    item["name"] = e.attributes().name;
    item["attributes"] = oli::attributes_to_json(e.attributes());
    entities.push_back(std::move(item));
  }
  Json out = Json::object();
  out["revision"] = doc.revision();
  out["entities"] = std::move(entities);
  print_json(out);
  return kExitOk;
}

int run_show(const Options& o) {
  const oli::Document doc = oli::Document::open(o.file, oli::OpenMode::ReadOnly);
  print_json(oli::entity_to_json(doc.get(parse_label(o.label))));
  return kExitOk;
}

int run_set(const Options& o) {
  const oli::Label label = parse_label(o.label);
  const int given = (!o.curve.empty() ? 1 : 0) + (!o.attribute.empty() ? 1 : 0) + (o.move_point ? 1 : 0);
  if (given != 1)
    throw Error(Errc::InvalidArgument,
                "give exactly one of --curve, --attribute, --move-point (got " + std::to_string(given) + ")",
                {.field = "set"});
  std::function<void(oli::Edit&)> body;
  std::string name;
  if (!o.curve.empty()) {
    const curve::Curve curve = io::read_curve_file(o.curve);
    name = "set curve";
    body = [label, curve](oli::Edit& e) { e.set_curve(label, curve); };
  } else if (!o.attribute.empty()) {
    const auto eq = o.attribute.find('=');
    if (eq == std::string::npos || eq == 0)
      throw Error(Errc::ParseError, "--attribute \"" + o.attribute + "\" must be KEY=JSON", {.field = "attribute"});
    const std::string key = o.attribute.substr(0, eq);
    const Json value = io::json::parse_json_text(o.attribute.substr(eq + 1), "--attribute value");
    name = "set " + key;
    body = [label, key, value](oli::Edit& e) { e.set_attribute(label, key, value); };
  } else {
    if (o.to.empty()) throw Error(Errc::InvalidArgument, "--move-point needs --to x,y[,z]", {.field = "to"});
    const std::vector<double> to = parse_number_list(o.to, "to");
    if (to.size() != 2 && to.size() != 3)
      throw Error(Errc::ParseError, "--to takes 2 or 3 numbers, got " + std::to_string(to.size()), {.field = "to"});
    const Vec3 p{to[0], to[1], to.size() == 3 ? to[2] : 0.0};
    const std::size_t index = *o.move_point;
    name = "move point";
    body = [label, index, p](oli::Edit& e) { e.move_point(label, index, p); };
  }
  oli::Document doc = oli::Document::open(o.file);
  commit(doc, name, body);
  Json out = Json::object();
  out["label"] = label.value;
  out["revision"] = doc.revision();
  print_json(out);
  return kExitOk;
}

int run_remove(const Options& o) {
  const oli::Label label = parse_label(o.label);
  oli::Document doc = oli::Document::open(o.file);
  commit(doc, "remove", [&](oli::Edit& e) { e.remove(label); });
  print_json(revision_json(doc));
  return kExitOk;
}

int run_undo_redo(const Options& o, bool undo) {
  oli::Document doc = oli::Document::open(o.file);
  (undo ? doc.undo() : doc.redo()).throw_if_failed();
  print_json(revision_json(doc));
  return kExitOk;
}

int run_history(const Options& o) {
  const oli::Document doc = oli::Document::open(o.file, oli::OpenMode::ReadOnly);
  Json applied = Json::array();
  Json redo = Json::array();
  for (const oli::HistoryEntry& h : doc.history()) {
    Json item = Json::object();
    item["revision"] = h.revision;
    item["name"] = h.name;
    item["time"] = h.time;
    item["changed"] = labels_json(h.changed);
    (h.applied ? applied : redo).push_back(std::move(item));
  }
  Json out = Json::object();
  out["transactions"] = std::move(applied);
  out["redo"] = std::move(redo);
  print_json(out);
  return kExitOk;
}

// True for the STEP and IGES names of --format and the .step/.stp/.iges/.igs extensions.
bool is_cad_format(const std::string& format) { return format != "json" && format != "dxf"; }

std::string lower_extension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (auto& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

bool is_cad_file(const std::string& path) {
  const std::string ext = lower_extension(path);
  return ext == ".step" || ext == ".stp" || ext == ".iges" || ext == ".igs";
}

#ifndef HULA_WITH_OCCT
[[noreturn]] void no_occt(const std::string& what) {
  throw Error(Errc::Unsupported, what + " needs Open CASCADE, and this hula was built without it (HULA_WITH_OCCT=OFF)",
              {.field = "format"});
}
#endif

int run_export(const Options& o) {
  // The output-path policy (a regular file or -, never a link, FIFO, device or directory), checked
  // before the document is opened and before the STEP/IGES helper starts.
  io::check_output_path(o.output, "--output");
  std::vector<oli::Label> labels;
  for (const std::string& l : o.labels) labels.push_back(parse_label(l));
  const oli::Document doc = oli::Document::open(o.file, oli::OpenMode::ReadOnly);
  Json out = Json::object();
  out["file"] = o.output;
  out["format"] = o.format;
  out["labels"] = labels_json(labels);
  if (o.format == "dxf") {  // dxflib, in this process (the server's export writes the same text)
    out["max_deviation"] = oli::export_dxf(doc, labels, o.output);
  } else if (!is_cad_format(o.format)) {
    io::write_file_atomically(o.output, io::to_file_text(oli::export_json(doc, labels)));
  } else {
#ifdef HULA_WITH_OCCT
    // STEP and IGES are written by the isolated Open CASCADE helper (oli/exchange).
    const auto report = oli::export_entities(doc, labels, o.output, oli::exchange_format_from_name(o.format));
    out["format"] = std::string(oli::exchange_format_name(report.format));
    out["max_deviation"] = report.max_deviation;
#else
    no_occt("--format " + o.format);
#endif
  }
  print_result(out, o.output);
  return kExitOk;
}

// The JSON of a file `doc import` reads as JSON: any name that is not a STEP/IGES name. Text that is
// not JSON is refused naming the formats import reads, not only "not valid JSON" (a.dxf, a.csv).
Json parse_import_json(const std::string& path) {
  const std::string text = io::read_text_file(path);
  try {
    return io::json::parse_json_text(text, "import file");
  } catch (const Error& e) {
    if (e.code() != Errc::ParseError) throw;
    const std::string ext = std::filesystem::path(path).extension().string();
    ErrorWhere where = e.where();
    if (where.field.empty()) where.field = "input";
    throw Error(Errc::ParseError,
                "cannot import '" + path + "': doc import reads a curve file, a points array or a hula-document " +
                    "(JSON), a STEP or IGES file (.step, .stp, .iges, .igs) or a DXF file (.dxf)" +
                    (ext.empty() || ext == ".json" ? std::string() : "; '" + ext + "' is none of these") +
                    " — as JSON: " + e.message(),
                where);
  }
}

int run_import(const Options& o) {
  std::vector<oli::Label> labels;
  std::optional<oli::Document> doc;
  Json cad = Json::object();  // a CAD file's "skipped" and "warnings" (what the reader could not read)
  if (lower_extension(o.input) == ".dxf") {
    // DXF SPLINE entities, read in this process (dxflib) as the server's import reads them.
    const io::DxfReadReport report = io::read_dxf_file(o.input);
    doc.emplace(oli::Document::open(o.file));
    commit(*doc, "import", [&](oli::Edit& e) { labels = oli::add_dxf_imported(e, report, o.input); });
  } else if (is_cad_file(o.input)) {
#ifdef HULA_WITH_OCCT
    // Read in the helper process first: a reader crash or hang leaves the document unopened.
    const oli::ImportReport report = oli::import_curves(o.input);
    doc.emplace(oli::Document::open(o.file));
    commit(*doc, "import", [&](oli::Edit& e) { labels = oli::add_imported(e, report, o.input); });
    cad["skipped"] = report.skipped;
    cad["warnings"] = report.warnings;
    for (const std::string& w : report.warnings) std::cerr << "hula: warning: " << o.input << ": " << w << "\n";
#else
    no_occt("importing " + o.input);
#endif
  } else {
    const Json input = parse_import_json(o.input);
    doc.emplace(oli::Document::open(o.file));
    commit(*doc, "import", [&](oli::Edit& e) { labels = oli::import_json(e, input, o.input); });
  }
  Json out = Json::object();
  out["labels"] = labels_json(labels);
  out["revision"] = doc->revision();
  for (auto& [key, value] : cad.items()) out[key] = std::move(value);
  print_json(out);
  return kExitOk;
}

int run_study(const Options& o) {
  const Json study = io::json::parse_json_text(io::read_text_file(o.study), "study file");
  const std::filesystem::path base = std::filesystem::path(o.study).parent_path();
  oli::Document doc = oli::Document::open(o.file);
  oli::StudyRunResult ran;
  const InterruptGuard guard;  // Ctrl-C ends the optimiser with its best so far, which is stored
  oli::StudyRunOptions options;
  options.cancel = &interrupt_token();
  TerminalProgress progress;
  if (progress.active()) options.on_generation = [&progress](const optim::GenerationLog& g) { progress.show(g); };
  commit(doc, "run study", [&](oli::Edit& e) { ran = oli::run_study(e, study, base, options); });
  progress.finish();
  Json out = ran.result;
  out["cancelled"] = ran.cancelled;
  out["study_label"] = ran.study.value;
  out["result_labels"] = labels_json(ran.curves);
  out["revision"] = doc.revision();
  print_json(out);
  return kExitOk;
}

int run_check(const Options& o) {
  const oli::CheckReport report = oli::Document::check_file(o.file);
  Json out = Json::object();
  out["ok"] = report.ok;
  out["schema_version"] = report.schema_version;
  out["revision"] = report.revision;
  out["entities"] = report.entities;
  out["steps"] = report.steps;
  out["problems"] = report.problems;
  print_json(out);
  return report.ok ? kExitOk : kExitInvalidInput;
}

}  // namespace

Command add_doc(CLI::App& app) {
  auto o = std::make_shared<Options>();
  CLI::App* doc = app.add_subcommand("doc", "The curve document (.hula): add, edit, undo, history, check");
  doc->require_subcommand(1);
  auto file = [&](CLI::App* sub) { sub->add_option("file", o->file, "Document file (.hula)")->required(); };
  auto label = [&](CLI::App* sub) { sub->add_option("label", o->label, "Entity label")->required(); };

  CLI::App* make = doc->add_subcommand("new", "Create an empty document (refuses to overwrite unless --force)");
  file(make);
  make->add_option("--backend", o->backend, "Geometry kernel recorded in the document")
      ->check(CLI::IsMember({"native", "occt"}));
  make->add_flag("--force", o->force, "Replace an existing file");

  CLI::App* add = doc->add_subcommand("add", "Add a curve (or a point set) as a new entity");
  file(add);
  auto* curve_opt = add->add_option("--curve", o->curve, "Curve file (JSON)");
  auto* points_opt = add->add_option("--points", o->points,
                                     "Points file (JSON, or lines x y [z]: whitespace, comma or semicolon separated)");
  curve_opt->excludes(points_opt);
  add->add_option("--name", o->name, "The entity's name");

  CLI::App* list = doc->add_subcommand("list", "List the entities");
  file(list);
  CLI::App* show = doc->add_subcommand("show", "Print one entity as its curve file plus label, attributes, provenance");
  file(show);
  label(show);

  CLI::App* set = doc->add_subcommand("set", "Change an entity: its curve, one attribute, or one point");
  file(set);
  label(set);
  set->add_option("--curve", o->curve, "Replace the curve with this curve file");
  set->add_option("--attribute", o->attribute,
                  "KEY=JSON: a system attribute (name, colour, visible, layer, locked) "
                  "or a user attribute (null removes it)");
  set->add_option("--move-point", o->move_point, "Index of the point to move (control point or data point)");
  set->add_option("--to", o->to, "x,y[,z]: where --move-point moves it");

  CLI::App* remove = doc->add_subcommand("remove", "Remove an entity (its label is never reused)");
  file(remove);
  label(remove);
  CLI::App* undo = doc->add_subcommand("undo", "Undo the latest transaction");
  file(undo);
  CLI::App* redo = doc->add_subcommand("redo", "Redo the latest undone transaction");
  file(redo);
  CLI::App* history = doc->add_subcommand("history", "List the transactions");
  file(history);

  CLI::App* exp = doc->add_subcommand("export", "Write entities to a file");
  file(exp);
  exp->add_option("labels", o->labels, "Entity labels")->required();
  exp->add_option("--format", o->format, "json | dxf | step (= step-ap214) | step-ap242 | iges")
      ->check(CLI::IsMember({"json", "dxf", "step", "step-ap214", "step-ap242", "iges"}));
  exp->add_option("-o,--output", o->output, "Output file")->required();
  CLI::App* imp = doc->add_subcommand(
      "import", "Add the curves of a JSON curve or document file, or of a STEP, IGES or DXF file, as new entities");
  file(imp);
  imp->add_option("input", o->input, "Curve file, hula-document JSON, or .step/.stp/.iges/.igs/.dxf file")->required();

  CLI::App* run = doc->add_subcommand("run", "Run a study file (values {\"entity\": L} name entities) and store it");
  file(run);
  run->add_option("study", o->study, "Study file (JSON)")->required();

  CLI::App* check = doc->add_subcommand("check", "Check a document: schema, every entity loads, undo log consistent");
  file(check);

  return {doc, [=] {
            if (make->parsed()) return run_new(*o);
            if (add->parsed()) {
              if (o->curve.empty() && o->points.empty())
                throw Error(Errc::InvalidArgument, "give --curve or --points", {.field = "curve"});
              return run_add(*o);
            }
            if (list->parsed()) return run_list(*o);
            if (show->parsed()) return run_show(*o);
            if (set->parsed()) return run_set(*o);
            if (remove->parsed()) return run_remove(*o);
            if (undo->parsed()) return run_undo_redo(*o, true);
            if (redo->parsed()) return run_undo_redo(*o, false);
            if (history->parsed()) return run_history(*o);
            if (exp->parsed()) return run_export(*o);
            if (imp->parsed()) return run_import(*o);
            if (run->parsed()) return run_study(*o);
            return run_check(*o);
          }};
}

}  // namespace hula::cli
