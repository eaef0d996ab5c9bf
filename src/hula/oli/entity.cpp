// SPDX-License-Identifier: MIT
// Entity views, attributes and provenance: their schema checks and JSON forms
// (docs/modules/oli.md "Attributes", docs/formats.md "Document files").
#include <cctype>
#include <string>

#include "hula/core/error.hpp"
#include "hula/io/json_read.hpp"
#include "hula/oli/detail/entity_codec.hpp"
#include "hula/oli/detail/entity_state.hpp"
#include "hula/oli/document.hpp"

namespace hula::oli {

std::string_view entity_kind_name(EntityKind kind) noexcept {
  switch (kind) {
    case EntityKind::Curve:
      return "curve";
    case EntityKind::PointSet:
      return "point-set";
    case EntityKind::Study:
      return "study";
  }
  return "curve";
}

void Attributes::validate() const {
  const bool hex = colour.size() == 7 && colour[0] == '#' && [&] {
    for (std::size_t i = 1; i < 7; ++i) {
      const char c = colour[i];
      if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
    }
    return true;
  }();
  if (!hex)
    throw Error(Errc::InvalidArgument, "colour \"" + colour + "\" must be \"#rrggbb\" in lower-case hex",
                {.field = "colour"});
  if (layer.empty()) throw Error(Errc::InvalidArgument, "layer must not be empty", {.field = "layer"});
  for (const auto& [key, value] : user) {
    if (key.empty()) throw Error(Errc::InvalidArgument, "a user attribute key must not be empty", {.field = "user"});
    if (key[0] == '$')
      throw Error(Errc::InvalidArgument, "user attribute key \"" + key + "\" starts with '$' (reserved)",
                  {.field = "user"});
  }
}

void DocumentOptions::validate() const {
  if (undo_limit && *undo_limit == 0)
    throw Error(Errc::InvalidOption, "undo_limit = 0: give at least 1, or none for unbounded", {.field = "undo_limit"});
  if (backend != "native" && backend != "occt")
    throw Error(Errc::InvalidOption, "backend \"" + backend + "\" is unknown (expected native or occt)",
                {.field = "backend"});
}

void Outcome::throw_if_failed() const {
  if (!committed && error) std::rethrow_exception(error);
}

Entity::Entity(Label label, std::shared_ptr<const detail::EntityState> state)
    : label_(label), state_(std::move(state)) {}

EntityKind Entity::kind() const { return state_->kind; }
const Attributes& Entity::attributes() const { return state_->attributes; }
const std::optional<Provenance>& Entity::provenance() const { return state_->provenance; }
const std::vector<Constraint>& Entity::constraints() const { return state_->constraints; }

namespace {
[[noreturn]] void wrong_kind(Label label, EntityKind have, std::string_view want) {
  throw Error(Errc::InvalidArgument,
              "entity " + std::to_string(label.value) + " is a " + std::string(entity_kind_name(have)) + ", not a " +
                  std::string(want),
              {.field = "label"});
}
}  // namespace

const curve::Curve& Entity::curve() const {
  if (state_->kind != EntityKind::Curve) wrong_kind(label_, state_->kind, "curve");
  return *state_->curve;
}
const PointSet& Entity::point_set() const {
  if (state_->kind != EntityKind::PointSet) wrong_kind(label_, state_->kind, "point set");
  return *state_->points;
}
const Study& Entity::study() const {
  if (state_->kind != EntityKind::Study) wrong_kind(label_, state_->kind, "study");
  return *state_->study;
}

Json attributes_to_json(const Attributes& a) {
  Json out = Json::object();
  out["name"] = a.name;
  out["colour"] = a.colour;
  out["visible"] = a.visible;
  out["layer"] = a.layer;
  out["locked"] = a.locked;
  Json user = Json::object();
  for (const auto& [key, value] : a.user) user[key] = value;
  out["user"] = std::move(user);
  return out;
}

Attributes attributes_from_json(const Json& json) {
  const io::json::JsonPath root = io::json::root_path("attributes");
  io::json::reject_unknown_members(json, root, {"name", "colour", "visible", "layer", "locked", "user"});
  Attributes a;
  auto boolean = [&](const char* name, bool& out) {
    if (const Json* v = io::json::optional_member(json, name)) {
      if (!v->is_boolean()) io::json::type_error(*v, root.member(name), "true or false");
      out = v->get<bool>();
    }
  };
  if (const Json* v = io::json::optional_member(json, "name")) a.name = io::json::get_string(*v, root.member("name"));
  if (const Json* v = io::json::optional_member(json, "colour"))
    a.colour = io::json::get_string(*v, root.member("colour"));
  if (const Json* v = io::json::optional_member(json, "layer"))
    a.layer = io::json::get_string(*v, root.member("layer"));
  boolean("visible", a.visible);
  boolean("locked", a.locked);
  if (const Json* v = io::json::optional_member(json, "user")) {
    if (!v->is_object()) io::json::type_error(*v, root.member("user"), "an object");
    for (const auto& [key, value] : v->items()) a.user[key] = value;
  }
  return a;
}

Json provenance_to_json(const Provenance& p) {
  Json out = Json::object();
  out["operation"] = p.operation;
  Json inputs = Json::array();
  for (Label l : p.inputs) inputs.push_back(l.value);
  out["inputs"] = std::move(inputs);
  out["seed"] = p.seed ? Json(*p.seed) : Json(nullptr);
  out["tool_version"] = p.tool_version;
  out["details"] = p.details;
  return out;
}

Provenance provenance_from_json(const Json& json) {
  const io::json::JsonPath root = io::json::root_path("provenance");
  io::json::reject_unknown_members(json, root, {"operation", "inputs", "seed", "tool_version", "details"});
  Provenance p;
  p.operation = io::json::get_string(io::json::require_member(json, root, "operation"), root.member("operation"));
  if (const Json* v = io::json::optional_member(json, "inputs")) {
    const Json& array = io::json::get_array(*v, root.member("inputs"));
    for (std::size_t i = 0; i < array.size(); ++i)
      p.inputs.push_back(Label{
          static_cast<std::uint64_t>(io::json::get_integer(array[i], root.member("inputs").element(i), 1, INT64_MAX))});
  }
  if (const Json* v = io::json::optional_member(json, "seed"))
    p.seed = static_cast<std::uint64_t>(io::json::get_integer(*v, root.member("seed"), 0, INT64_MAX));
  if (const Json* v = io::json::optional_member(json, "tool_version"))
    p.tool_version = io::json::get_string(*v, root.member("tool_version"));
  if (const Json* v = io::json::optional_member(json, "details")) p.details = *v;
  return p;
}

Json entity_to_json(const Entity& entity) {
  Json out = detail::entity_data_to_json(*entity.state());
  out["label"] = entity.label().value;
  out["attributes"] = attributes_to_json(entity.attributes());
  out["provenance"] = entity.provenance() ? provenance_to_json(*entity.provenance()) : Json(nullptr);
  if (entity.kind() == EntityKind::Curve) out["constraints"] = constraints_to_json(entity.constraints());
  return out;
}

}  // namespace hula::oli
