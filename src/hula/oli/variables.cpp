// SPDX-License-Identifier: MIT
// Design variables over a document (variables.hpp). Each selection is turned
// into a list of "slots" — (parameter array, index, axis) — over a mutable
// copy of the entity's construction data; reading gathers the slots' values,
// writing scatters new values into a copy and rebuilds the curve through its
// validating factory, so variables can never produce an invalid curve.
//
// Law constants are the numeric literals of the expression text (a literal
// written back negative is wrapped as "(-v)" and read back as one literal),
// printed as the shortest decimal that reads back to the same double.
#include "hula/oli/variables.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <variant>

#include "hula/core/error.hpp"
#include "hula/curve/curve.hpp"
#include "hula/intrinsic/natural_curve.hpp"
#include "hula/oli/constraints.hpp"
#include "hula/oli/detail/entity_state.hpp"

namespace hula::oli {

std::string_view variable_kind_name(VariableKind kind) noexcept {
  switch (kind) {
    case VariableKind::ControlPoints:
      return "control-points";
    case VariableKind::Weights:
      return "weights";
    case VariableKind::InteriorKnots:
      return "interior-knots";
    case VariableKind::DataPoints:
      return "data-points";
    case VariableKind::EndTangents:
      return "end-tangents";
    case VariableKind::LawConstants:
      return "law-constants";
  }
  return "control-points";
}

std::vector<optim::Variable> VariableValues::to_optim(double precision) const {
  std::vector<optim::Variable> out;
  for (std::size_t i = 0; i < values.size(); ++i) out.push_back({names[i], lower[i], upper[i], precision});
  return out;
}

namespace {

// A numeric literal of an expression: its byte range and value.
struct Literal {
  std::size_t begin = 0, end = 0;
  double value = 0.0;
};

std::vector<Literal> literals(const std::string& text) {
  std::vector<Literal> out;
  std::size_t i = 0;
  auto ident = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; };
  while (i < text.size()) {
    const char c = text[i];
    const bool starts = std::isdigit(static_cast<unsigned char>(c)) != 0 ||
                        (c == '.' && i + 1 < text.size() && std::isdigit(static_cast<unsigned char>(text[i + 1])) != 0);
    if (!starts || (i > 0 && ident(text[i - 1]))) {
      ++i;
      continue;
    }
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(text.data() + i, text.data() + text.size(), value);
    std::size_t end = static_cast<std::size_t>(ptr - text.data());
    if (ec != std::errc() || end == i) {
      ++i;
      continue;
    }
    std::size_t begin = i;
    // "(-v)" as written by write-back: one negative literal.
    if (begin >= 2 && text[begin - 1] == '-' && text[begin - 2] == '(' && end < text.size() && text[end] == ')') {
      begin -= 2;
      value = -value;
      ++end;
    }
    out.push_back({begin, end, value});
    i = end;
  }
  return out;
}

std::string literal_text(double v) {
  char buffer[64];
  const auto [ptr, ec] = std::to_chars(buffer, buffer + sizeof buffer, std::abs(v));
  std::string text(buffer, ptr);
  if (text.find_first_of(".e") == std::string::npos && text.find("inf") == std::string::npos) text += ".0";
  return std::signbit(v) ? "(-" + text + ")" : text;
}

std::string replace_literals(const std::string& text, const std::vector<Literal>& found,
                             std::span<const double> values) {
  std::string out;
  std::size_t at = 0;
  for (std::size_t k = 0; k < found.size(); ++k) {
    out.append(text, at, found[k].begin - at);
    out += literal_text(values[k]);
    at = found[k].end;
  }
  out.append(text, at);
  return out;
}

[[noreturn]] void selection_error(std::size_t s, const std::string& what) {
  throw Error(Errc::InvalidArgument, "selections[" + std::to_string(s) + "]: " + what,
              {.field = "selections", .index = s});
}

// The editable parameters of one entity: arrays of scalars or of points, taken from a copy of
// its construction data, and a function rebuilding the entity from the edited copy.
struct Editable {
  // Scalar arrays (weights, knots, constants) and point arrays (control points, data, tangents).
  std::vector<double> scalars;
  std::vector<Vec3> points;
  bool is_points = false;
  int dimension = 3;
  // For knots: the positions in the full knot vector of the interior knots.
  std::vector<std::size_t> positions;
};

// A rebuilt entity's data.
using Rebuilt = std::variant<curve::Curve, PointSet>;

// The data a selection works on and how to put it back.
struct Slots {
  Editable e;
  std::function<Rebuilt(const Editable&)> rebuild;
};

Slots slots_for(const detail::EntityState& state, const VariableSelection& sel, std::size_t s) {
  Slots slots;
  const VariableKind kind = sel.kind;
  auto wrong = [&](const std::string& have) {
    selection_error(s, "entity " + std::to_string(sel.label.value) + " (" + have + ") has no " +
                           std::string(variable_kind_name(kind)));
  };
  if (state.kind == EntityKind::PointSet) {
    if (kind != VariableKind::ControlPoints && kind != VariableKind::DataPoints) wrong("a point set");
    slots.e.points = state.points->points;
    slots.e.is_points = true;
    slots.e.dimension = state.points->dimension;
    const int dimension = state.points->dimension;
    slots.rebuild = [dimension](const Editable& e) -> Rebuilt { return PointSet{e.points, dimension}; };
    return slots;
  }
  if (state.kind != EntityKind::Curve) wrong("a study");
  const curve::Curve& c = *state.curve;
  slots.e.dimension = c.dimension();
  std::visit(
      [&](const auto& data) {
        using T = std::decay_t<decltype(data)>;
        if constexpr (std::is_same_v<T, curve::NurbsData>) {
          const nurbs::NurbsCurve& n = data.curve;
          std::vector<Vec3> cps(n.control_points().begin(), n.control_points().end());
          std::vector<double> weights(n.weights().begin(), n.weights().end());
          std::vector<double> knots(n.knots().values().begin(), n.knots().values().end());
          const int degree = n.degree();
          const int dimension = n.dimension();
          if (kind == VariableKind::ControlPoints) {
            slots.e.points = cps;
            slots.e.is_points = true;
          } else if (kind == VariableKind::Weights) {
            if (weights.empty()) wrong("a non-rational NURBS");
            slots.e.scalars = weights;
          } else if (kind == VariableKind::InteriorKnots) {
            const Interval d = n.domain();
            for (std::size_t k = 0; k < knots.size(); ++k)
              if (knots[k] > d.start && knots[k] < d.end) {
                slots.e.scalars.push_back(knots[k]);
                slots.e.positions.push_back(k);
              }
          } else {
            wrong("a NURBS curve");
          }
          slots.rebuild = [kind, cps, weights, knots, degree, dimension](const Editable& e) -> Rebuilt {
            std::vector<Vec3> p = cps;
            std::vector<double> w = weights, u = knots;
            if (kind == VariableKind::ControlPoints) p = e.points;
            if (kind == VariableKind::Weights) w = e.scalars;
            if (kind == VariableKind::InteriorKnots)
              for (std::size_t k = 0; k < e.positions.size(); ++k) u[e.positions[k]] = e.scalars[k];
            return curve::Curve(nurbs::NurbsCurve(degree, std::move(u), std::move(p), std::move(w), dimension));
          };
        } else if constexpr (std::is_same_v<T, curve::BezierData>) {
          if (kind == VariableKind::ControlPoints) {
            slots.e.points = data.control_points;
            slots.e.is_points = true;
          } else if (kind == VariableKind::Weights) {
            if (data.weights.empty()) wrong("a non-rational Bézier curve");
            slots.e.scalars = data.weights;
          } else {
            wrong("a Bézier curve");
          }
          slots.rebuild = [kind, data](const Editable& e) -> Rebuilt {
            curve::BezierData next = data;
            if (kind == VariableKind::ControlPoints) next.control_points = e.points;
            if (kind == VariableKind::Weights) next.weights = e.scalars;
            return curve::Curve::bezier(std::move(next));
          };
        } else if constexpr (std::is_same_v<T, curve::InterpolatedData>) {
          if (kind == VariableKind::DataPoints) {
            slots.e.points = data.points;
          } else if (kind == VariableKind::EndTangents) {
            using K = nurbs::EndCondition::Kind;
            if (data.start.kind != K::Clamped || data.end.kind != K::Clamped)
              wrong("an interpolated curve without tangent conditions at both ends");
            slots.e.points = {data.start.derivative, data.end.derivative};
          } else {
            wrong("an interpolated curve");
          }
          slots.e.is_points = true;
          slots.rebuild = [kind, data](const Editable& e) -> Rebuilt {
            curve::InterpolatedData next = data;
            if (kind == VariableKind::DataPoints) next.points = e.points;
            if (kind == VariableKind::EndTangents) {
              next.start = nurbs::EndCondition::clamped(e.points[0]);
              next.end = nurbs::EndCondition::clamped(e.points[1]);
            }
            return curve::Curve::interpolated(std::move(next));
          };
        } else if constexpr (std::is_same_v<T, curve::HermiteData>) {
          if (kind == VariableKind::DataPoints)
            slots.e.points = data.points;
          else if (kind == VariableKind::EndTangents)
            slots.e.points = {data.tangents.front(), data.tangents.back()};
          else
            wrong("a Hermite curve");
          slots.e.is_points = true;
          slots.rebuild = [kind, data](const Editable& e) -> Rebuilt {
            curve::HermiteData next = data;
            if (kind == VariableKind::DataPoints) next.points = e.points;
            if (kind == VariableKind::EndTangents) {
              next.tangents.front() = e.points[0];
              next.tangents.back() = e.points[1];
            }
            return curve::Curve::hermite(std::move(next));
          };
        } else if constexpr (std::is_same_v<T, curve::LawData>) {
          if (kind != VariableKind::LawConstants) wrong("a law curve");
          const std::vector<Literal> found = literals(data.expression);
          for (const Literal& l : found) slots.e.scalars.push_back(l.value);
          slots.rebuild = [data, found](const Editable& e) -> Rebuilt {
            return curve::Curve::from_law(replace_literals(data.expression, found, e.scalars), data.parameter,
                                          data.domain);
          };
        } else {
          if (kind != VariableKind::LawConstants) wrong("a natural-equation curve");
          const std::vector<Literal> k = literals(data.curvature);
          const std::vector<Literal> t = literals(data.torsion);
          for (const Literal& l : k) slots.e.scalars.push_back(l.value);
          for (const Literal& l : t) slots.e.scalars.push_back(l.value);
          slots.rebuild = [data, k, t](const Editable& e) -> Rebuilt {
            curve::NaturalData next = data;
            const std::span<const double> all(e.scalars);
            next.curvature = replace_literals(data.curvature, k, all.subspan(0, k.size()));
            next.torsion = replace_literals(data.torsion, t, all.subspan(k.size()));
            return intrinsic::natural_curve(next, curve::kApproximationTolerance);
          };
        }
      },
      c.data());
  return slots;
}

// One resolved variable: which element and axis of the selection's array.
struct Var {
  std::size_t element = 0;
  int axis = -1;  // -1 for scalars
};

std::vector<Var> resolve(const Slots& slots, const VariableSelection& sel, std::size_t s) {
  const std::size_t count = slots.e.is_points ? slots.e.points.size() : slots.e.scalars.size();
  std::vector<std::size_t> indices = sel.indices;
  if (indices.empty())
    for (std::size_t i = 0; i < count; ++i) indices.push_back(i);
  std::vector<int> axes;
  if (slots.e.is_points) {
    for (char a : sel.axes) {
      const int axis = a == 'x' ? 0 : a == 'y' ? 1 : a == 'z' ? 2 : -1;
      if (axis < 0 || (!axes.empty() && axis <= axes.back()))
        selection_error(s, "axes \"" + sel.axes + "\" must be a subset of \"xyz\" in order");
      if (axis == 2 && slots.e.dimension == 2) selection_error(s, "axis z of a planar (2-D) entity");
      axes.push_back(axis);
    }
    if (axes.empty()) selection_error(s, "no axes");
  }
  std::vector<Var> out;
  for (std::size_t i : indices) {
    if (i >= count)
      selection_error(s, "index " + std::to_string(i) + " is out of range (" + std::to_string(count) + " " +
                             std::string(variable_kind_name(sel.kind)) + ")");
    if (slots.e.is_points)
      for (int a : axes) out.push_back({i, a});
    else
      out.push_back({i, -1});
  }
  return out;
}

double get(const Editable& e, const Var& v) {
  return v.axis < 0 ? e.scalars[v.element] : e.points[v.element][static_cast<std::size_t>(v.axis)];
}
void set(Editable& e, const Var& v, double value) {
  if (v.axis < 0)
    e.scalars[v.element] = value;
  else
    e.points[v.element][static_cast<std::size_t>(v.axis)] = value;
}

void check_bounds(const Bounds& b, std::size_t s) {
  if (!std::isfinite(b.lower) || !std::isfinite(b.upper) || b.lower > b.upper)
    selection_error(s, "bounds [" + format_number(b.lower) + ", " + format_number(b.upper) +
                           "] must be finite with lower <= upper");
  if (b.mode == BoundMode::Relative && (b.lower > 0.0 || b.upper < 0.0))
    selection_error(s, "relative bounds [" + format_number(b.lower) + ", " + format_number(b.upper) +
                           "] must contain 0 (the current value)");
}

// The entity states the variables read, by label.
using States = std::map<Label, detail::StatePtr>;

States states_of(const Document& document, const VariableSet& set) {
  States out;
  for (std::size_t s = 0; s < set.selections.size(); ++s) {
    const std::optional<Entity> e = document.find(set.selections[s].label);
    if (!e) selection_error(s, "no entity with label " + std::to_string(set.selections[s].label.value));
    out.emplace(e->label(), e->state());
  }
  return out;
}

}  // namespace

VariableValues read_variables(const Document& document, const VariableSet& set) {
  const States states = states_of(document, set);
  VariableValues out;
  for (std::size_t s = 0; s < set.selections.size(); ++s) {
    const VariableSelection& sel = set.selections[s];
    check_bounds(sel.bounds, s);
    Slots slots = slots_for(*states.at(sel.label), sel, s);
    for (const Var& v : resolve(slots, sel, s)) {
      const double value = get(slots.e, v);
      std::string name = std::to_string(sel.label.value) + "." + std::string(variable_kind_name(sel.kind)) + "[" +
                         std::to_string(v.element) + "]";
      if (v.axis >= 0) name += std::string(".") + "xyz"[v.axis];
      out.names.push_back(std::move(name));
      out.values.push_back(value);
      const bool rel = sel.bounds.mode == BoundMode::Relative;
      out.lower.push_back(rel ? value + sel.bounds.lower : sel.bounds.lower);
      out.upper.push_back(rel ? value + sel.bounds.upper : sel.bounds.upper);
    }
  }
  return out;
}

namespace {

// Applies the values entity by entity; selections of one label act on the same copy in order.
struct Applied {
  std::map<Label, curve::Curve> curves;
  std::map<Label, PointSet> points;
};

Applied apply(const States& states, const VariableSet& set, std::span<const double> values) {
  // Group the selections by label, keeping their order and their offset in `values`.
  std::map<Label, std::vector<std::pair<std::size_t, std::size_t>>> by_label;  // (selection, offset)
  std::size_t offset = 0;
  std::vector<std::size_t> counts;
  for (std::size_t s = 0; s < set.selections.size(); ++s) {
    const VariableSelection& sel = set.selections[s];
    Slots slots = slots_for(*states.at(sel.label), sel, s);
    const std::size_t n = resolve(slots, sel, s).size();
    by_label[sel.label].emplace_back(s, offset);
    offset += n;
  }
  if (values.size() != offset)
    throw Error(Errc::InvalidArgument,
                "values has " + std::to_string(values.size()) + " entries; the variables are " + std::to_string(offset),
                {.field = "values"});
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      throw Error(Errc::NonFiniteInput, "values[" + std::to_string(i) + "] = " + format_number(values[i]),
                  {.field = "values", .index = i});
  Applied out;
  for (const auto& [label, list] : by_label) {
    auto state = std::make_shared<detail::EntityState>(*states.at(label));
    for (const auto& [s, at] : list) {
      const VariableSelection& sel = set.selections[s];
      Slots slots = slots_for(*state, sel, s);
      const std::vector<Var> vars = resolve(slots, sel, s);
      for (std::size_t k = 0; k < vars.size(); ++k) oli::set(slots.e, vars[k], values[at + k]);
      Rebuilt rebuilt = slots.rebuild(slots.e);
      if (auto* c = std::get_if<curve::Curve>(&rebuilt)) state->curve = std::make_shared<const curve::Curve>(*c);
      if (auto* p = std::get_if<PointSet>(&rebuilt)) state->points = std::make_shared<const PointSet>(std::move(*p));
    }
    if (state->kind == EntityKind::Curve)
      out.curves.emplace(label, *state->curve);
    else
      out.points.emplace(label, *state->points);
  }
  return out;
}

}  // namespace

std::map<Label, curve::Curve> apply_variables(const Document& document, const VariableSet& set,
                                              std::span<const double> values) {
  return apply(states_of(document, set), set, values).curves;
}

void write_variables(Edit& edit, const VariableSet& set, std::span<const double> values) {
  Applied applied = apply(states_of(edit.document(), set), set, values);
  for (auto& [label, c] : applied.curves) edit.set_curve(label, c);
  for (auto& [label, p] : applied.points) edit.set_point_set(label, std::move(p));
}

optim::Problem make_problem(const Document& document, const VariableSet& set, CurveObjective objective,
                            std::size_t objectives) {
  const VariableValues v = read_variables(document, set);
  // The evaluation reads immutable copies of the states (shared, not copied), so later
  // edits of the document do not reach a run, and threads may read them concurrently.
  const States states = states_of(document, set);
  std::vector<std::pair<Label, std::vector<Constraint>>> constraints;
  for (const auto& [label, state] : states)
    if (state->kind == EntityKind::Curve && !state->constraints.empty())
      constraints.emplace_back(label, state->constraints);
  std::size_t inequalities = 0;
  for (const auto& [label, list] : constraints) inequalities += list.size();
  optim::Problem problem;
  problem.name = set.name;
  problem.variables = v.to_optim();
  problem.objectives = objectives;
  problem.inequality_constraints = inequalities;
  problem.evaluate = [states, set, objective, constraints, objectives](std::span<const double> x,
                                                                       std::span<double> out) {
    const std::map<Label, curve::Curve> curves = apply(states, set, x).curves;
    objective(curves, out.subspan(0, objectives));
    std::size_t at = objectives;
    for (const auto& [label, list] : constraints) {
      const auto it = curves.find(label);
      for (const ConstraintResidual& r : check_constraints(it->second, list)) {
        // An undefined residual is a violation of size 1 (never feasible, never NaN for the GA).
        out[at++] = std::isnan(r.residual) ? 1.0 : r.residual - list[r.index].tolerance;
      }
    }
  };
  return problem;
}

}  // namespace hula::oli
