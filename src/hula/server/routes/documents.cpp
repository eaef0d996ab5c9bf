// SPDX-License-Identifier: MIT
// Documents: GET /api/documents (the workspace's *.hula files),
// POST /api/documents {"name", "backend"?} (201), GET /api/documents/{name}
// (revision and entities: label, kind, name, attributes), DELETE (moved to
// the workspace's .trash folder, never unlinked), undo, redo, history, and
// GET /api/documents/{name}/events: every change set of the document, by any
// client, as Server-Sent Events ("change" events), from the subscription on.
// POST /api/documents/{name}/import {"file"} | {"filename", "content"}: the
// curves of a STEP, IGES or JSON file, or the points of a point file (.csv,
// .txt, .dat, .xyz: io::parse_points), a plain name in the workspace or the
// file's text in the body, as new entities, in one "import" step.
// POST /api/documents/{name}/export {"labels", "format"} (json, dxf, step…, iges): the entities
// written as a JSON, STEP or IGES file, its text in the reply (the document is
// only read). Import and export run on the server's request workers (Runs::Worker): the exchange helper
// can take seconds.
#include "hula/server/documents.hpp"

#include <stdlib.h>  // mkstemps, mkdtemp
#include <unistd.h>  // close

#include <cctype>
#include <fstream>
#include <limits>

#include "hula/io/atomic_file.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/json_read.hpp"
#include "hula/io/points_file.hpp"
#include "hula/oli/file_convert.hpp"
#include "hula/oli/json_exchange.hpp"
#include "hula/server/security.hpp"
#ifdef HULA_WITH_OCCT
#include "hula/oli/cad_exchange.hpp"
#endif
#include "hula/server/routes/routes.hpp"

namespace hula::server::routes {

namespace {

namespace json = io::json;

Json summary(const oli::Document& doc, const std::string& name) {
  Json out = Json::object();
  out["name"] = name;
  out["revision"] = doc.revision();
  out["backend"] = doc.options().backend;
  Json entities = Json::array();
  for (const oli::Label label : doc.labels()) {
    const oli::Entity e = doc.get(label);
    Json j = Json::object();
    j["label"] = label.value;
    j["kind"] = std::string(oli::entity_kind_name(e.kind()));
    j["name"] = e.attributes().name;
    j["attributes"] = oli::attributes_to_json(e.attributes());
    entities.push_back(std::move(j));
  }
  out["entities"] = std::move(entities);
  return out;
}

Json history_json(const std::vector<oli::HistoryEntry>& history) {
  Json out = Json::array();
  for (const oli::HistoryEntry& h : history) {
    Json j = Json::object();
    j["revision"] = h.revision;
    j["name"] = h.name;
    j["time"] = h.time;
    Json labels = Json::array();
    for (const oli::Label l : h.changed) labels.push_back(l.value);
    j["changed"] = std::move(labels);
    j["applied"] = h.applied;
    out.push_back(std::move(j));
  }
  return out;
}

bool is_points_extension(const std::string& ext) {
  return ext == "csv" || ext == "txt" || ext == "dat" || ext == "xyz";
}

// The lower-case extension of an import file name: step, stp, iges, igs, dxf, json or a point file's (else 400).
std::string import_extension(const std::string& name, const char* field) {
  std::string ext = std::filesystem::path(name).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (ext != ".step" && ext != ".stp" && ext != ".iges" && ext != ".igs" && ext != ".dxf" && ext != ".json" &&
      !is_points_extension(ext.empty() ? ext : ext.substr(1)))
    throw Error(
        Errc::InvalidArgument,
        "import file '" + name + "' must end in .step, .stp, .iges, .igs, .dxf, .json, .csv, .txt, .dat or .xyz",
        ErrorWhere{.field = field});
  return ext.substr(1);
}

// The labels of an export request: a non-empty array of positive integers.
std::vector<oli::Label> export_labels(const Json& body) {
  const json::JsonPath path = json::root_path("labels");
  const Json& array = json::get_array(json::require_member(body, json::JsonPath(), "labels"), path);
  if (array.empty()) throw Error(Errc::InvalidArgument, "labels: name at least one entity to export", path.where);
  std::vector<oli::Label> labels;
  for (std::size_t i = 0; i < array.size(); ++i) {
    const long long v = json::get_integer(array[i], path.element(i), 1, std::numeric_limits<long long>::max());
    labels.push_back(oli::Label{static_cast<std::uint64_t>(v)});
  }
  return labels;
}

#ifdef HULA_WITH_OCCT
// A private temporary directory removed when done: the exchange helper writes files, not text.
class ExportDirectory {
 public:
  ExportDirectory() {
    std::string pattern = (std::filesystem::temp_directory_path() / "hula-export-XXXXXX").string();
    if (mkdtemp(pattern.data()) == nullptr)
      throw Error(Errc::IoError, "cannot create a temporary directory for the export", ErrorWhere{.field = "format"});
    path_ = pattern;
  }
  ExportDirectory(const ExportDirectory&) = delete;
  ExportDirectory& operator=(const ExportDirectory&) = delete;
  ~ExportDirectory() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};
#endif

// A file the import route reads: a workspace file, or the uploaded text in a temporary file
// removed when done (the exchange helper reads files, not text).
class ImportFile {
 public:
  ImportFile(const std::filesystem::path& workspace, const Json& body) {
    if (const Json* f = json::optional_member(body, "file")) {
      name_ = json::get_string(*f, json::root_path("file"));
      extension_ = import_extension(name_, "file");
      path_ = workspace_file_path(workspace, name_, "file");
      if (!std::filesystem::is_regular_file(path_))
        throw HttpError(404, "NotFound", "the workspace has no file '" + name_ + "'");
      return;
    }
    name_ = json::get_string(json::require_member(body, json::JsonPath(), "filename"), json::root_path("filename"));
    extension_ = import_extension(name_, "filename");
    content_ = json::get_string(json::require_member(body, json::JsonPath(), "content"), json::root_path("content"));
    if (extension_ == "json" || extension_ == "dxf" || is_points_extension(extension_)) return;
    std::string pattern = (std::filesystem::temp_directory_path() / "hula-import-XXXXXX.").string() + extension_;
    const int fd = mkstemps(pattern.data(), static_cast<int>(extension_.size() + 1));
    if (fd < 0)
      throw Error(Errc::IoError, "cannot create a temporary file for the upload of '" + name_ + "'",
                  ErrorWhere{.field = "filename"});
    ::close(fd);
    path_ = pattern;
    temporary_ = true;
    std::ofstream out(path_, std::ios::binary);
    out << content_;
    if (!out.flush())
      throw Error(Errc::IoError, "cannot write the upload of '" + name_ + "' to " + path_.string(),
                  ErrorWhere{.field = "filename"});
  }
  ImportFile(const ImportFile&) = delete;
  ImportFile& operator=(const ImportFile&) = delete;
  ~ImportFile() {
    std::error_code ec;
    if (temporary_) std::filesystem::remove(path_, ec);
  }

  [[nodiscard]] bool json() const { return extension_ == "json"; }
  [[nodiscard]] bool dxf() const { return extension_ == "dxf"; }
  [[nodiscard]] bool points() const { return is_points_extension(extension_); }
  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  /// The JSON text: the upload's, or the workspace file's.
  [[nodiscard]] std::string text() const { return path_.empty() ? content_ : io::read_text_file(path_); }

 private:
  std::string name_;
  std::string extension_;
  std::string content_;
  std::filesystem::path path_;
  bool temporary_ = false;
};

}  // namespace

Json change_json(const Change& change) {
  const oli::Outcome& outcome = change.outcome;
  if (!outcome.committed) {
    try {
      outcome.throw_if_failed();
    } catch (const Error&) {
      throw;
    } catch (const std::bad_alloc& e) {
      throw out_of_memory_error(e);
    } catch (const std::exception& e) {
      throw HttpError(500, "InternalError", e.what());
    }
    throw HttpError(500, "InternalError", "the change was not applied: " + outcome.error_message);
  }
  Json out = Json::object();
  out["revision"] = outcome.revision;
  out["changes"] = change_set_to_json(outcome.changes);
  Json entities = Json::array();
  for (const oli::Entity& e : change.entities) entities.push_back(oli::entity_to_json(e));
  out["changes"]["entities"] = std::move(entities);
  return out;
}

Response change_response(const Change& change, unsigned status) { return json_response(status, change_json(change)); }

void add_documents(Router& router, const Context& context) {
  DocumentRegistry& docs = context.documents;
  router.add("GET", "/api/documents", [&docs](const Request&) {
    Json out = Json::object();
    out["documents"] = docs.list();
    return json_response(200, out);
  });
  router.add("POST", "/api/documents", [&docs](const Request& request) {
    const Json body = request.json();
    const json::JsonPath root;
    json::reject_unknown_members(body, root, {"name", "backend"});
    const std::string name = json::get_string(json::require_member(body, root, "name"), json::root_path("name"));
    std::string backend = "native";
    if (const Json* b = json::optional_member(body, "backend"))
      backend = json::get_string(*b, json::root_path("backend"));
    const auto doc = docs.create(name, backend);
    return json_response(201, doc->read([&](const oli::Document& d) { return summary(d, name); }));
  });
  router.add("GET", "/api/documents/{name}", [&docs](const Request& request) {
    const auto doc = docs.get(request.params.at(0));
    return json_response(200, doc->read([&](const oli::Document& d) { return summary(d, doc->name()); }));
  });
  router.add("DELETE", "/api/documents/{name}", [&docs](const Request& request) {
    const std::filesystem::path trash = docs.trash(request.params.at(0));
    Json out = Json::object();
    out["name"] = request.params.at(0);
    out["trash"] = trash.filename().string();
    return json_response(200, out);
  });
  router.add(
      "POST", "/api/documents/{name}/import",
      [&docs, workspace = context.workspace](const Request& request) {
        const Json body = request.json();
        json::reject_unknown_members(body, json::JsonPath(), {"file", "filename", "content"});
        const auto doc = docs.get(request.params.at(0));
        const ImportFile file(workspace, body);
        std::vector<oli::Label> labels;
        Change outcome;
        Json cad = Json::object();  // a CAD file's "skipped" and "warnings" (what the reader could not read)
        if (file.points()) {
          io::PointSet points;
          try {
            points = io::parse_points(file.text());
          } catch (const Error& e) {
            throw Error(e.code(), file.name() + ": " + e.message(), e.where());
          }
          outcome = doc->change([&](oli::Document& d) {
            return d.transact("import",
                              [&](oli::Edit& e) { labels = {oli::import_points(e, std::move(points), file.name())}; });
          });
        } else if (file.dxf()) {
          // DXF SPLINE entities (io/dxf_file.hpp, dxflib): read here, no helper process.
          const io::DxfReadReport report = io::parse_dxf(file.text(), file.name());
          outcome = doc->change([&](oli::Document& d) {
            return d.transact("import", [&](oli::Edit& e) { labels = oli::add_dxf_imported(e, report, file.name()); });
          });
          cad["skipped"] = report.skipped;
          cad["warnings"] = report.warnings;
        } else if (file.json()) {
          const Json input = io::json::parse_json_text(file.text(), file.name());
          outcome = doc->change([&](oli::Document& d) {
            return d.transact("import", [&](oli::Edit& e) { labels = oli::import_json(e, input, file.name()); });
          });
        } else {
#ifdef HULA_WITH_OCCT
          // Read in the isolated helper process before taking the document: a crash or hang of the
          // reader is an error naming the file, and the document is untouched.
          const oli::ImportReport report = oli::import_curves(file.path());
          outcome = doc->change([&](oli::Document& d) {
            return d.transact("import", [&](oli::Edit& e) { labels = oli::add_imported(e, report, file.name()); });
          });
          cad["skipped"] = report.skipped;
          cad["warnings"] = report.warnings;
#else
          throw Error(Errc::Unsupported,
                      "importing '" + file.name() + "' needs Open CASCADE, and this hula was built without it",
                      ErrorWhere{.field = "file"});
#endif
        }
        Json out = change_json(outcome);
        Json list = Json::array();
        for (const oli::Label l : labels) list.push_back(l.value);
        out["labels"] = std::move(list);
        for (auto& [key, value] : cad.items()) out[key] = std::move(value);
        return json_response(201, out);
      },
      Runs::Worker);
  router.add(
      "POST", "/api/documents/{name}/export",
      [&docs](const Request& request) {
        const Json body = request.json();
        json::reject_unknown_members(body, json::JsonPath(), {"labels", "format"});
        const std::vector<oli::Label> labels = export_labels(body);
        const std::string format =
            json::get_string(json::require_member(body, json::JsonPath(), "format"), json::root_path("format"));
        const auto doc = docs.get(request.params.at(0));
        Json out = Json::object();
        Json list = Json::array();
        for (const oli::Label l : labels) list.push_back(l.value);
        out["labels"] = std::move(list);
        if (format == "json") {
          out["format"] = format;
          out["content"] =
              io::to_file_text(doc->read([&](const oli::Document& d) { return oli::export_json(d, labels); }));
          return json_response(200, out);
        }
        if (format == "dxf") {  // dxflib, in this process: no helper, no temporary file
          oli::DxfExport dxf = doc->read([&](const oli::Document& d) { return oli::dxf_export(d, labels); });
          out["format"] = format;
          out["content"] = std::move(dxf.text);
          out["max_deviation"] = dxf.max_deviation;
          return json_response(200, out);
        }
#ifdef HULA_WITH_OCCT
        const oli::ExchangeFormat exchange = oli::exchange_format_from_name(format);
        // The curves are read under the document's lock; the helper process runs after it is released.
        const auto items = doc->read([&](const oli::Document& d) { return oli::export_items(d, labels); });
        const ExportDirectory dir;
        const auto report = oli::export_curves(
            dir.path() / (exchange == oli::ExchangeFormat::Iges ? "out.igs" : "out.step"), items, exchange);
        out["format"] = std::string(oli::exchange_format_name(report.format));
        out["content"] = io::read_text_file(report.path);
        out["max_deviation"] = report.max_deviation;
        return json_response(200, out);
#else
        throw Error(Errc::Unsupported,
                    "exporting " + format + " needs Open CASCADE, and this hula was built without it",
                    ErrorWhere{.field = "format"});
#endif
      },
      Runs::Worker);
  router.add("POST", "/api/documents/{name}/undo", [&docs](const Request& request) {
    const auto doc = docs.get(request.params.at(0));
    return change_response(doc->change([](oli::Document& d) { return d.undo(); }), 200);
  });
  router.add("POST", "/api/documents/{name}/redo", [&docs](const Request& request) {
    const auto doc = docs.get(request.params.at(0));
    return change_response(doc->change([](oli::Document& d) { return d.redo(); }), 200);
  });
  router.add("GET", "/api/documents/{name}/history", [&docs](const Request& request) {
    const auto doc = docs.get(request.params.at(0));
    Json out = Json::object();
    doc->read([&](const oli::Document& d) {
      out["revision"] = d.revision();
      out["history"] = history_json(d.history());
      return 0;
    });
    return json_response(200, out);
  });
  router.add("GET", "/api/documents/{name}/events", [&docs](const Request& request) {
    const auto doc = docs.get(request.params.at(0));
    Response r;
    r.events = doc->events();
    r.events_from = r.events->size();
    return r;
  });
}

}  // namespace hula::server::routes
