// SPDX-License-Identifier: MIT
// Entities of a document: POST /api/documents/{name}/entities {"curve": curve
// file, "name"?, "attributes"?} (201), GET|PUT|PATCH|DELETE
// /api/documents/{name}/entities/{label}, and POST .../{label}/analysis
// (io::analyse_curve_json, read-only), POST .../{label}/fair-preview (the fairing
// assistant's ghost of the entity or of a "curve" sent with it, oli::fair_preview with
// io/fair_preview_json.hpp, read-only: accepted by a PUT of its curve), POST .../{label}/insert-knot {"u",
// "times"?},
// .../{label}/elevate {"times"?}, .../{label}/reverse and .../{label}/split {"t"}
// (oli::Edit through the document's kernel; split answers the two pieces'
// labels, first [a, t] then [t, b]). A PATCH {"move": [{"index", "to"}],
// "continue": true} continues the previous "move points" step, so a drag is
// one undo step (oli::TransactMode::Continue). Every change answers
// {"revision", "changes"} (the change set, also pushed to the document's
// event stream).
#include <algorithm>
#include <optional>

#include "hula/curve/curve.hpp"
#include "hula/io/curve_analysis_json.hpp"
#include "hula/io/fair_preview_json.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/json_read.hpp"
#include "hula/io/json_text.hpp"
#include "hula/oli/fair_preview.hpp"
#include "hula/server/documents.hpp"
#include "hula/server/routes/routes.hpp"

namespace hula::server::routes {

namespace {

namespace json = io::json;

constexpr std::string_view kMoveStep = "move points";

oli::Attributes read_attributes(const Json& body, oli::Attributes attributes) {
  if (const Json* a = json::optional_member(body, "attributes")) attributes = oli::attributes_from_json(*a);
  if (const Json* n = json::optional_member(body, "name"))
    attributes.name = json::get_string(*n, json::root_path("name"));
  return attributes;
}

struct Move {
  std::size_t index;
  Vec3 to;
};

std::vector<Move> read_moves(const Json& list) {
  const json::JsonPath path = json::root_path("move");
  const Json& moves = json::get_array(list, path);
  std::vector<Move> out;
  for (std::size_t i = 0; i < moves.size(); ++i) {
    const json::JsonPath p = path.element(i);
    json::reject_unknown_members(moves[i], p, {"index", "to"});
    const auto index = static_cast<std::size_t>(
        json::get_integer(json::require_member(moves[i], p, "index"), p.member("index"), 0, 1ll << 40));
    out.push_back({index, json::get_point(json::require_member(moves[i], p, "to"), p.member("to")).first});
  }
  return out;
}

// The optional "times" of a knot insertion or degree elevation (default 1).
int read_times(const Json& body) {
  const Json* t = json::optional_member(body, "times");
  return t ? static_cast<int>(json::get_integer(*t, json::root_path("times"), 1, 64)) : 1;
}

}  // namespace

oli::Label parse_label(const std::string& text) {
  std::uint64_t value = 0;
  bool ok = !text.empty() && text.size() <= 19;
  for (const char c : text) {
    if (c < '0' || c > '9') ok = false;
    if (ok) value = value * 10 + static_cast<std::uint64_t>(c - '0');
  }
  if (!ok || value == 0)
    throw Error(Errc::InvalidArgument, "entity label '" + text + "' is not a positive integer",
                ErrorWhere{.field = "label"});
  return oli::Label{value};
}

std::pair<std::shared_ptr<OpenDocument>, oli::Label> entity_of(DocumentRegistry& docs, const Request& request) {
  auto doc = docs.get(request.params.at(0));
  const oli::Label label = parse_label(request.params.at(1));
  if (!doc->read([&](const oli::Document& d) { return d.contains(label); }))
    throw HttpError(404, "NotFound", "document '" + doc->name() + "' has no entity " + request.params.at(1));
  return {std::move(doc), label};
}

void add_entities(Router& router, const Context& context) {
  DocumentRegistry& docs = context.documents;
  router.add("POST", "/api/documents/{name}/entities", [&docs](const Request& request) {
    const Json body = request.json();
    json::reject_unknown_members(body, json::JsonPath(), {"curve", "name", "attributes"});
    const curve::Curve c = io::curve_from_json(json::require_member(body, json::JsonPath(), "curve"));
    const oli::Attributes attributes = read_attributes(body, {});
    const auto doc = docs.get(request.params.at(0));
    oli::Label label;
    const Change o = doc->change([&](oli::Document& d) {
      return d.transact("add curve", [&](oli::Edit& e) { label = e.add_curve(c, attributes); });
    });
    const Json out = change_json(o);
    Json with_label = Json::object();
    with_label["label"] = label.value;
    with_label.update(out);
    return json_response(201, with_label);
  });
  router.add("GET", "/api/documents/{name}/entities/{label}", [&docs](const Request& request) {
    const auto [doc, label] = entity_of(docs, request);
    const oli::Entity e = doc->read([&](const oli::Document& d) { return d.get(label); });
    return json_response(200, oli::entity_to_json(e));  // encoded outside the lock: the entity is a snapshot
  });
  router.add("PUT", "/api/documents/{name}/entities/{label}", [&docs](const Request& request) {
    const Json body = request.json();
    json::reject_unknown_members(body, json::JsonPath(), {"curve", "name", "attributes"});
    const curve::Curve c = io::curve_from_json(json::require_member(body, json::JsonPath(), "curve"));
    const auto [doc, label] = entity_of(docs, request);
    const bool has_attributes = body.contains("attributes") || body.contains("name");
    return change_response(doc->change([&](oli::Document& d) {
      return d.transact("replace curve", [&](oli::Edit& e) {
        e.set_curve(label, c);
        if (has_attributes) e.set_attributes(label, read_attributes(body, e.get(label).attributes()));
      });
    }),
                           200);
  });
  router.add("PATCH", "/api/documents/{name}/entities/{label}", [&docs](const Request& request) {
    const Json body = request.json();
    const json::JsonPath root;
    json::reject_unknown_members(body, root, {"move", "continue", "attributes", "analysis"});
    std::vector<Move> moves;
    if (const Json* m = json::optional_member(body, "move")) moves = read_moves(*m);
    bool continue_step = false;
    if (const Json* c = json::optional_member(body, "continue")) {
      if (!c->is_boolean()) json::type_error(*c, json::root_path("continue"), "true or false");
      continue_step = c->get<bool>();
    }
    const Json* attributes = json::optional_member(body, "attributes");
    if (attributes && !attributes->is_object())
      json::type_error(*attributes, json::root_path("attributes"), "an object");
    if (moves.empty() && !attributes)
      throw Error(Errc::InvalidArgument, "a PATCH needs \"move\" or \"attributes\"", ErrorWhere{.field = "move"});
    // The moved curve's analysis in the same reply when asked: a drag is one request and one reply.
    std::optional<diffgeom::AnalysisOptions> analysis;
    if (const Json* a = json::optional_member(body, "analysis"))
      analysis = io::analysis_options_from_json(*a, io::analysis_request_defaults());
    const auto [doc, label] = entity_of(docs, request);
    const std::string step = moves.empty() ? std::string("edit attributes") : std::string(kMoveStep);
    const Change change = doc->change([&](oli::Document& d) {
      return d.transact(
          step,
          [&](oli::Edit& e) {
            for (const Move& m : moves) e.move_point(label, m.index, m.to);
            if (attributes)
              for (const auto& [key, value] : attributes->items()) e.set_attribute(label, key, value);
          },
          continue_step ? oli::TransactMode::Continue : oli::TransactMode::New);
    });
    const Json out = change_json(change);
    if (!analysis) return json_response(200, out);
    // Computed outside the lock from the snapshot the change took.
    const auto moved = std::find_if(change.entities.begin(), change.entities.end(),
                                    [&](const oli::Entity& e) { return e.label() == label; });
    if (moved == change.entities.end() || moved->kind() != oli::EntityKind::Curve) return json_response(200, out);
    Response reply;
    reply.body = io::object_with_encoded_member(
        out, "analysis", io::analyse_curve_json(moved->curve(), *analysis, false, change.outcome.revision));
    return reply;
  });
  router.add("DELETE", "/api/documents/{name}/entities/{label}", [&docs](const Request& request) {
    const auto [doc, label] = entity_of(docs, request);
    return change_response(
        doc->change([&](oli::Document& d) { return d.transact("remove", [&](oli::Edit& e) { e.remove(label); }); }),
        200);
  });
  router.add("POST", "/api/documents/{name}/entities/{label}/insert-knot", [&docs](const Request& request) {
    const Json body = request.json();
    json::reject_unknown_members(body, json::JsonPath(), {"u", "times"});
    const double u = json::get_number(json::require_member(body, json::JsonPath(), "u"), json::root_path("u"));
    const int times = read_times(body);
    const auto [doc, label] = entity_of(docs, request);
    return change_response(doc->change([&](oli::Document& d) {
      return d.transact("insert knot", [&](oli::Edit& e) { e.insert_knot(label, u, times); });
    }),
                           200);
  });
  router.add("POST", "/api/documents/{name}/entities/{label}/elevate", [&docs](const Request& request) {
    const Json body = request.body.empty() ? Json::object() : request.json();
    json::reject_unknown_members(body, json::JsonPath(), {"times"});
    const int times = read_times(body);
    const auto [doc, label] = entity_of(docs, request);
    return change_response(doc->change([&](oli::Document& d) {
      return d.transact("elevate degree", [&](oli::Edit& e) { e.elevate_degree(label, times); });
    }),
                           200);
  });
  router.add("POST", "/api/documents/{name}/entities/{label}/reverse", [&docs](const Request& request) {
    const Json body = request.body.empty() ? Json::object() : request.json();
    json::reject_unknown_members(body, json::JsonPath(), std::span<const std::string_view>());  // no members
    const auto [doc, label] = entity_of(docs, request);
    return change_response(
        doc->change([&](oli::Document& d) { return d.transact("reverse", [&](oli::Edit& e) { e.reverse(label); }); }),
        200);
  });
  router.add("POST", "/api/documents/{name}/entities/{label}/split", [&docs](const Request& request) {
    const Json body = request.json();
    json::reject_unknown_members(body, json::JsonPath(), {"t"});
    const double t = json::get_number(json::require_member(body, json::JsonPath(), "t"), json::root_path("t"));
    const auto [doc, label] = entity_of(docs, request);
    std::pair<oli::Label, oli::Label> pieces;
    const Change o = doc->change(
        [&](oli::Document& d) { return d.transact("split", [&](oli::Edit& e) { pieces = e.split(label, t); }); });
    Json out = change_json(o);  // throws the error of a refused split
    out["labels"] = Json::array({pieces.first.value, pieces.second.value});
    return json_response(201, out);
  });
  router.add("POST", "/api/documents/{name}/entities/{label}/fair-preview", [&docs](const Request& request) {
    const io::FairPreviewRequest preview = io::fair_preview_request_from_json(request.json());
    const auto analysis =
        preview.analysis
            ? std::optional(io::analysis_options_from_json(*preview.analysis, io::analysis_request_defaults()))
            : std::nullopt;
    const auto [doc, label] = entity_of(docs, request);
    const auto [e, revision] = doc->read([&](const oli::Document& d) { return std::pair(d.get(label), d.revision()); });
    // Computed outside the lock from the immutable snapshot; the document is not changed.
    const studies::AssistantResult r = oli::fair_preview(e, preview.options, preview.curve ? &*preview.curve : nullptr);
    const Json out = io::fair_preview_to_json(r, preview.options, revision);
    if (!analysis) return json_response(200, out);
    Response reply;
    reply.body =
        io::object_with_encoded_member(out, "analysis", io::analyse_curve_json(r.curve, *analysis, false, revision));
    return reply;
  });
  router.add("POST", "/api/documents/{name}/entities/{label}/analysis", [&docs](const Request& request) {
    const auto options = io::analysis_options_from_json(request.body.empty() ? Json::object() : request.json(),
                                                        io::analysis_request_defaults());
    const auto [doc, label] = entity_of(docs, request);
    const auto [e, revision] = doc->read([&](const oli::Document& d) { return std::pair(d.get(label), d.revision()); });
    // Computed outside the lock from the immutable snapshot: edits go on meanwhile.
    Response r;
    r.body = io::analyse_curve_json(e.curve(), options, false, revision);
    return r;
  });
}

}  // namespace hula::server::routes
