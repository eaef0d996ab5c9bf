// SPDX-License-Identifier: MIT
// Documents: GET /api/documents (the workspace's *.hula files),
// POST /api/documents {"name", "backend"?} (201), GET /api/documents/{name}
// (revision and entities: label, kind, name, attributes), DELETE (moved to
// the workspace's .trash folder, never unlinked), undo, redo, history, and
// GET /api/documents/{name}/events: every change set of the document, by any
// client, as Server-Sent Events ("change" events), from the subscription on.
#include "hula/server/documents.hpp"

#include "hula/io/json_read.hpp"
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

}  // namespace

Response outcome_response(const oli::Outcome& outcome, unsigned status) {
  if (!outcome.committed) {
    try {
      outcome.throw_if_failed();
    } catch (const Error&) {
      throw;
    } catch (const std::exception& e) {
      throw HttpError(500, "InternalError", e.what());
    }
    throw HttpError(500, "InternalError", "the change was not applied: " + outcome.error_message);
  }
  Json out = Json::object();
  out["revision"] = outcome.revision;
  out["changes"] = change_set_to_json(outcome.changes);
  return json_response(status, out);
}

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
  router.add("POST", "/api/documents/{name}/undo", [&docs](const Request& request) {
    const auto doc = docs.get(request.params.at(0));
    return outcome_response(doc->write([](oli::Document& d) { return d.undo(); }), 200);
  });
  router.add("POST", "/api/documents/{name}/redo", [&docs](const Request& request) {
    const auto doc = docs.get(request.params.at(0));
    return outcome_response(doc->write([](oli::Document& d) { return d.redo(); }), 200);
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
