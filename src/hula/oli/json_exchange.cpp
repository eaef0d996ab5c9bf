// SPDX-License-Identifier: MIT
// JSON export and import of entities (json_exchange.hpp).
#include "hula/oli/json_exchange.hpp"

#include "hula/core/error.hpp"
#include "hula/curve/curve.hpp"
#include "hula/io/json_read.hpp"
#include "hula/oli/detail/entity_codec.hpp"
#include "hula/oli/detail/entity_state.hpp"

#ifndef HULA_VERSION
#define HULA_VERSION "unknown"
#endif

namespace hula::oli {

std::string entity_display_kind(const Entity& entity) {
  if (entity.kind() == EntityKind::Curve) return std::string(entity.curve().kind_name());
  return std::string(entity_kind_name(entity.kind()));
}

Json export_json(const Document& document, std::span<const Label> labels) {
  if (labels.empty()) throw Error(Errc::InvalidArgument, "no labels to export", {.field = "labels"});
  if (labels.size() == 1) {
    const Entity e = document.get(labels[0]);
    switch (e.kind()) {
      case EntityKind::Curve:
        return detail::entity_data_to_json(*e.state());
      case EntityKind::PointSet:
        return detail::entity_data_to_json(*e.state()).at("points");
      case EntityKind::Study:
        return e.study().setup;
    }
  }
  Json out = Json::object();
  out["format"] = "hula-document";
  out["version"] = kDocumentJsonVersion;
  Json entities = Json::array();
  for (Label l : labels) entities.push_back(entity_to_json(document.get(l)));
  out["entities"] = std::move(entities);
  return out;
}

namespace {

Provenance import_provenance(std::string_view source, std::optional<std::uint64_t> original,
                             std::string operation = "import:json") {
  Provenance p;
  p.operation = std::move(operation);
  p.tool_version = HULA_VERSION;
  p.details["file"] = std::string(source);
  if (original) p.details["label"] = *original;
  return p;
}

}  // namespace

Label import_points(Edit& edit, PointSet points, std::string_view source) {
  return edit.add_point_set(std::move(points), {}, import_provenance(source, {}, "import:points"));
}

std::vector<Label> import_json(Edit& edit, const Json& input, std::string_view source) {
  namespace j = io::json;
  std::vector<Label> out;
  if (input.is_array()) {
    const j::PointArray points = j::get_points(input, j::root_path("points"));
    out.push_back(edit.add_point_set(PointSet{points.points, points.dimension}, {}, import_provenance(source, {})));
    return out;
  }
  if (!input.is_object()) j::type_error(input, j::root_path(""), "a curve file, a points array or a hula-document");
  const Json* format = j::optional_member(input, "format");
  if (format == nullptr || *format != "hula-document") {
    out.push_back(edit.add_curve(io::curve_from_json(input), {}, import_provenance(source, {})));
    return out;
  }
  // A document of a later version (or with members this build does not know) is refused, as a curve
  // file of a later version is: importing it would silently drop what this build cannot read.
  if (const Json* v = j::optional_member(input, "version")) {
    if (!v->is_number_integer() || v->get<long long>() < 1 || v->get<long long>() > kDocumentJsonVersion)
      throw Error(Errc::ParseError,
                  std::string(source) + ": version = " + j::describe(*v) +
                      " is not a hula-document version this build reads (1 to " + std::to_string(kDocumentJsonVersion) +
                      ")",
                  {.field = "version"});
  }
  j::reject_unknown_members(input, j::root_path(""), {"format", "version", "entities"});
  const j::JsonPath root = j::root_path("entities");
  const Json& entities = j::get_array(j::require_member(input, j::root_path(""), "entities"), root);
  for (std::size_t i = 0; i < entities.size(); ++i) {
    const Json& item = entities[i];
    const j::JsonPath at = root.element(i);
    if (!item.is_object()) j::type_error(item, at, "an entity object");
    Json data = item;
    std::optional<std::uint64_t> original;
    if (const Json* l = j::optional_member(item, "label"))
      original = static_cast<std::uint64_t>(j::get_integer(*l, at.member("label"), 1, INT64_MAX));
    Attributes attributes;
    if (const Json* a = j::optional_member(item, "attributes")) attributes = attributes_from_json(*a);
    Provenance provenance = import_provenance(source, original);
    if (const Json* p = j::optional_member(item, "provenance")) provenance = provenance_from_json(*p);
    std::vector<Constraint> constraints;
    if (const Json* c = j::optional_member(item, "constraints")) constraints = constraints_from_json(*c);
    for (const char* member : {"label", "attributes", "provenance", "constraints"}) data.erase(member);
    const std::string kind = j::get_string(j::require_member(item, at, "kind"), at.member("kind"));
    detail::EntityState state;
    if (kind == "point-set") {
      detail::entity_data_from_json(EntityKind::PointSet, data, state);
      out.push_back(edit.add_point_set(*state.points, attributes, provenance));
    } else if (kind == "study") {
      detail::entity_data_from_json(EntityKind::Study, data, state);
      out.push_back(edit.add_study(*state.study, attributes, provenance));
    } else {
      // Constraints go in before a locked entity is locked.
      Attributes unlocked = attributes;
      unlocked.locked = false;
      out.push_back(edit.add_curve(io::curve_from_json(data), unlocked, provenance));
      if (!constraints.empty()) edit.set_constraints(out.back(), std::move(constraints));
      if (attributes.locked) edit.set_attributes(out.back(), attributes);
    }
  }
  return out;
}

}  // namespace hula::oli
