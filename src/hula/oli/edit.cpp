// SPDX-License-Identifier: MIT
// Edit: the changes a transaction body can make. Each method validates its
// input before writing anything, builds the entity's next immutable state and
// hands it to the document's journal (so a later failure in the body undoes it).
#include <cmath>
#include <type_traits>
#include <variant>

#include "hula/core/error.hpp"
#include "hula/curve/curve.hpp"
#include "hula/oli/detail/document_impl.hpp"
#include "hula/oli/detail/entity_codec.hpp"
#include "hula/oli/kernel/kernel.hpp"

#ifndef HULA_VERSION
#define HULA_VERSION "unknown"
#endif

namespace hula::oli {

using detail::EntityState;
using detail::StatePtr;

namespace {

std::string label_text(Label label) { return "entity " + std::to_string(label.value); }

// A copy of an existing entity's state to modify, refusing a locked entity.
std::shared_ptr<EntityState> editable(const StatePtr& state, Label label, std::string_view what) {
  if (state->attributes.locked)
    throw Error(Errc::InvalidArgument,
                label_text(label) + " is locked: unlock it (attribute locked = false) to " + std::string(what),
                {.field = "label"});
  return std::make_shared<EntityState>(*state);
}

void require_kind(const EntityState& state, Label label, EntityKind kind) {
  if (state.kind != kind)
    throw Error(Errc::InvalidArgument,
                label_text(label) + " is a " + std::string(entity_kind_name(state.kind)) + ", not a " +
                    std::string(entity_kind_name(kind)),
                {.field = "label"});
}

void check_point(const Vec3& to, int dimension) {
  for (std::size_t c = 0; c < 3; ++c)
    if (!std::isfinite(to[c]))
      throw Error(Errc::NonFiniteInput, "to[" + std::to_string(c) + "] = " + format_number(to[c]) + " is not finite",
                  {.field = "to", .component = c});
  if (dimension == 2 && to.z != 0.0)
    throw Error(Errc::InvalidArgument, "to has z = " + format_number(to.z) + " for a planar (2-D) entity",
                {.field = "to", .component = 2});
}

void check_index(std::size_t index, std::size_t count, std::string_view what) {
  if (index >= count)
    throw Error(Errc::InvalidArgument,
                "point index " + std::to_string(index) + " is out of range (" + std::string(what) + " has " +
                    std::to_string(count) + " points)",
                {.field = "index", .index = index});
}

// The curve with point `index` of its construction data moved to `to`.
curve::Curve moved(const curve::Curve& c, std::size_t index, Vec3 to) {
  check_point(to, c.dimension());
  return std::visit(
      [&](const auto& data) -> curve::Curve {
        using T = std::decay_t<decltype(data)>;
        if constexpr (std::is_same_v<T, curve::NurbsData>) {
          const nurbs::NurbsCurve& n = data.curve;
          check_index(index, n.control_points().size(), "the control polygon");
          std::vector<Vec3> points(n.control_points().begin(), n.control_points().end());
          points[index] = to;
          return curve::Curve(nurbs::NurbsCurve(n.knots(), std::move(points),
                                                std::vector<double>(n.weights().begin(), n.weights().end()),
                                                n.dimension()));
        } else if constexpr (std::is_same_v<T, curve::BezierData>) {
          check_index(index, data.control_points.size(), "the control polygon");
          curve::BezierData next = data;
          next.control_points[index] = to;
          return curve::Curve::bezier(std::move(next));
        } else if constexpr (std::is_same_v<T, curve::InterpolatedData>) {
          check_index(index, data.points.size(), "the data");
          curve::InterpolatedData next = data;
          next.points[index] = to;
          return curve::Curve::interpolated(std::move(next));
        } else if constexpr (std::is_same_v<T, curve::HermiteData>) {
          check_index(index, data.points.size(), "the data");
          curve::HermiteData next = data;
          next.points[index] = to;
          return curve::Curve::hermite(std::move(next));
        } else {
          throw Error(Errc::InvalidArgument,
                      "a " + std::string(c.kind_name()) +
                          " curve has no points to move (change its expression or equations instead)",
                      {.field = "index"});
        }
      },
      c.data());
}

// The exact NURBS of a curve entity, for an operation of the document's kernel.
const nurbs::NurbsCurve& exact_nurbs(const EntityState& state, Label label, std::string_view operation) {
  require_kind(state, label, EntityKind::Curve);
  const curve::Curve& c = *state.curve;
  if (c.kind() == curve::Kind::Law || c.kind() == curve::Kind::Natural)
    throw Error(Errc::InvalidArgument,
                "cannot " + std::string(operation) + " " + label_text(label) + ": a " + std::string(c.kind_name()) +
                    " curve is held exactly, its NURBS is an approximation (add its NURBS as a curve first)",
                {.field = "label"});
  return c.nurbs();
}

// Runs a kernel operation; its errors keep code and field and gain the entity and operation.
template <class Operation>
auto through_kernel(const Document& document, Label label, std::string_view operation, Operation&& op) {
  const std::shared_ptr<const Kernel> kernel = make_kernel(document.options().backend);
  try {
    return op(*kernel);
  } catch (const Error& e) {
    throw Error(e.code(),
                std::string(operation) + " of " + label_text(label) + " (" + std::string(kernel->name()) +
                    " backend): " + e.message(),
                e.where());
  }
}

}  // namespace

Label Edit::add_curve(const curve::Curve& curve, Attributes attributes, std::optional<Provenance> provenance) {
  attributes.validate();
  auto state = std::make_shared<EntityState>();
  state->kind = EntityKind::Curve;
  state->attributes = std::move(attributes);
  state->provenance = std::move(provenance);
  state->curve = std::make_shared<const curve::Curve>(curve);
  Document::Impl& m = *document_->impl_;
  const Label label{m.next_label++};
  m.put(label, std::move(state));
  return label;
}

Label Edit::add_point_set(PointSet points, Attributes attributes, std::optional<Provenance> provenance) {
  attributes.validate();
  detail::validate_point_set(points);
  auto state = std::make_shared<EntityState>();
  state->kind = EntityKind::PointSet;
  state->attributes = std::move(attributes);
  state->provenance = std::move(provenance);
  state->points = std::make_shared<const PointSet>(std::move(points));
  Document::Impl& m = *document_->impl_;
  const Label label{m.next_label++};
  m.put(label, std::move(state));
  return label;
}

Label Edit::add_study(Study study, Attributes attributes, std::optional<Provenance> provenance) {
  attributes.validate();
  if (!study.setup.is_object())
    throw Error(Errc::InvalidArgument, "a study's setup must be a JSON object", {.field = "setup"});
  auto state = std::make_shared<EntityState>();
  state->kind = EntityKind::Study;
  state->attributes = std::move(attributes);
  state->provenance = std::move(provenance);
  state->study = std::make_shared<const Study>(std::move(study));
  Document::Impl& m = *document_->impl_;
  const Label label{m.next_label++};
  m.put(label, std::move(state));
  return label;
}

void Edit::set_curve(Label label, const curve::Curve& curve) {
  Document::Impl& m = *document_->impl_;
  const StatePtr& current = m.existing(label);
  require_kind(*current, label, EntityKind::Curve);
  auto next = editable(current, label, "change its curve");
  next->curve = std::make_shared<const curve::Curve>(curve);
  m.put(label, std::move(next));
}

void Edit::set_point_set(Label label, PointSet points) {
  Document::Impl& m = *document_->impl_;
  const StatePtr& current = m.existing(label);
  require_kind(*current, label, EntityKind::PointSet);
  detail::validate_point_set(points);
  auto next = editable(current, label, "change its points");
  next->points = std::make_shared<const PointSet>(std::move(points));
  m.put(label, std::move(next));
}

void Edit::set_study(Label label, Study study) {
  Document::Impl& m = *document_->impl_;
  const StatePtr& current = m.existing(label);
  require_kind(*current, label, EntityKind::Study);
  if (!study.setup.is_object())
    throw Error(Errc::InvalidArgument, "a study's setup must be a JSON object", {.field = "setup"});
  auto next = editable(current, label, "change its study");
  next->study = std::make_shared<const Study>(std::move(study));
  m.put(label, std::move(next));
}

void Edit::move_point(Label label, std::size_t index, Vec3 to) {
  Document::Impl& m = *document_->impl_;
  const StatePtr& current = m.existing(label);
  if (current->kind == EntityKind::Study)
    throw Error(Errc::InvalidArgument, label_text(label) + " is a study: it has no points to move", {.field = "label"});
  auto next = editable(current, label, "move its points");
  if (current->kind == EntityKind::Curve) {
    next->curve = std::make_shared<const curve::Curve>(moved(*current->curve, index, to));
  } else {
    check_index(index, current->points->points.size(), "the point set");
    check_point(to, current->points->dimension);
    PointSet points = *current->points;
    points.points[index] = to;
    next->points = std::make_shared<const PointSet>(std::move(points));
  }
  m.put(label, std::move(next));
}

void Edit::set_attributes(Label label, Attributes attributes) {
  Document::Impl& m = *document_->impl_;
  const StatePtr& current = m.existing(label);
  attributes.validate();
  auto next = std::make_shared<EntityState>(*current);
  next->attributes = std::move(attributes);
  m.put(label, std::move(next));
}

void Edit::set_attribute(Label label, std::string_view key, const Json& value) {
  Document::Impl& m = *document_->impl_;
  const StatePtr& current = m.existing(label);
  Attributes a = current->attributes;
  auto wrong = [&](const char* expected) {
    throw Error(Errc::InvalidArgument, "attribute " + std::string(key) + " = " + value.dump() + " must be " + expected,
                {.field = std::string(key)});
  };
  if (key == "name" || key == "colour" || key == "layer") {
    if (!value.is_string()) wrong("a string");
    (key == "name" ? a.name : key == "colour" ? a.colour : a.layer) = value.get<std::string>();
  } else if (key == "visible" || key == "locked") {
    if (!value.is_boolean()) wrong("true or false");
    (key == "visible" ? a.visible : a.locked) = value.get<bool>();
  } else if (value.is_null()) {
    a.user.erase(std::string(key));
  } else {
    a.user[std::string(key)] = value;
  }
  a.validate();
  auto next = std::make_shared<EntityState>(*current);
  next->attributes = std::move(a);
  m.put(label, std::move(next));
}

void Edit::set_constraints(Label label, std::vector<Constraint> constraints) {
  Document::Impl& m = *document_->impl_;
  const StatePtr& current = m.existing(label);
  require_kind(*current, label, EntityKind::Curve);
  for (std::size_t i = 0; i < constraints.size(); ++i) {
    try {
      constraints[i].validate();
    } catch (const Error& e) {
      ErrorWhere where = e.where();
      where.index = i;
      throw Error(e.code(), "constraints[" + std::to_string(i) + "]: " + e.message(), where);
    }
  }
  auto next = editable(current, label, "change its constraints");
  next->constraints = std::move(constraints);
  m.put(label, std::move(next));
}

void Edit::remove(Label label) {
  Document::Impl& m = *document_->impl_;
  const StatePtr& current = m.existing(label);
  (void)editable(current, label, "remove it");
  m.put(label, nullptr);
}

void Edit::insert_knot(Label label, double u, int times) {
  Document::Impl& m = *document_->impl_;
  const StatePtr& current = m.existing(label);
  const nurbs::NurbsCurve& n = exact_nurbs(*current, label, "insert a knot into");
  auto next = editable(current, label, "insert a knot");
  next->curve = std::make_shared<const curve::Curve>(
      through_kernel(*document_, label, "knot insertion", [&](const Kernel& k) { return k.insert_knot(n, u, times); }));
  m.put(label, std::move(next));
}

void Edit::elevate_degree(Label label, int times) {
  Document::Impl& m = *document_->impl_;
  const StatePtr& current = m.existing(label);
  const nurbs::NurbsCurve& n = exact_nurbs(*current, label, "elevate the degree of");
  auto next = editable(current, label, "elevate its degree");
  next->curve = std::make_shared<const curve::Curve>(through_kernel(
      *document_, label, "degree elevation", [&](const Kernel& k) { return k.elevate_degree(n, times); }));
  m.put(label, std::move(next));
}

void Edit::reverse(Label label) {
  Document::Impl& m = *document_->impl_;
  const StatePtr& current = m.existing(label);
  const nurbs::NurbsCurve& n = exact_nurbs(*current, label, "reverse");
  auto next = editable(current, label, "reverse it");
  next->curve = std::make_shared<const curve::Curve>(
      through_kernel(*document_, label, "reversal", [&](const Kernel& k) { return k.reverse(n); }));
  m.put(label, std::move(next));
}

std::pair<Label, Label> Edit::split(Label label, double t) {
  Document::Impl& m = *document_->impl_;
  const StatePtr current = m.existing(label);  // a copy: remove() below replaces the map's entry
  const nurbs::NurbsCurve& n = exact_nurbs(*current, label, "split");
  (void)editable(current, label, "split it");
  nurbs::SplitResult pieces =
      through_kernel(*document_, label, "split", [&](const Kernel& k) { return k.split(n, t); });
  Provenance provenance{.operation = "split", .inputs = {label}, .tool_version = HULA_VERSION};
  provenance.details["t"] = t;
  provenance.details["backend"] = document_->options().backend;
  Attributes first = current->attributes;
  Attributes second = current->attributes;
  first.name += " (1)";
  second.name += " (2)";
  remove(label);
  const Label a = add_curve(curve::Curve(std::move(pieces.before)), std::move(first), provenance);
  const Label b = add_curve(curve::Curve(std::move(pieces.after)), std::move(second), std::move(provenance));
  return {a, b};
}

}  // namespace hula::oli
