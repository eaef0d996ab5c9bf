// SPDX-License-Identifier: MIT
// Design variables over a document (thesis 9.5.4 "Variables", 10.1.2 "GA
// translators", 10.1.3 "Parameter bounds"): parameters selected from the
// entities' construction data — control point coordinates (all, some, some
// axes), weights, interior knots, data points, end tangents, law constants —
// gathered into one named vector with bounds, read from the document and
// written back in a transaction. A Flexo problem can be stated over them
// (make_problem), with the curves' stored constraints as its inequality
// constraints, so the GA penalises violations (e = f + penalty × violation,
// optim/ga.hpp): the constraint policy is *penalty*, never repair.
//
// Example (the thesis's oli_create_bounds_from_positions: every control point
// of curve 1 free within ±0.5 of where it is):
//
//   oli::VariableSet set{"shape", {{.label = l, .kind = oli::VariableKind::ControlPoints,
//                                   .bounds = {oli::BoundMode::Relative, -0.5, 0.5}}}};
//   oli::VariableValues v = oli::read_variables(doc, set);
//   v.values[0] += 0.1;
//   doc.transact("nudge", [&](oli::Edit& e) { oli::write_variables(e, set, v.values); });
#pragma once

#include <functional>
#include <map>
#include <span>
#include <string>
#include <vector>

#include "hula/oli/document.hpp"
#include "hula/optim/problem.hpp"

namespace hula::oli {

/// Which parameters of an entity a selection takes.
enum class VariableKind : std::uint8_t {
  ControlPoints,  ///< control point coordinates of a NURBS or Bézier curve (point sets: their points)
  Weights,        ///< weights of a rational NURBS or Bézier curve
  InteriorKnots,  ///< the knots strictly inside the domain of a NURBS curve, in order
  DataPoints,     ///< the data points of an interpolated or Hermite curve
  EndTangents,    ///< the start and end tangents: of an interpolated curve with tangent end
                  ///< conditions, or the first and last Hermite tangents (index 0 = start, 1 = end)
  LawConstants,   ///< the numeric literals of a law's expression (natural curves: of κ, then τ), in text order
};

/// "control-points", "weights", "interior-knots", "data-points", "end-tangents" or "law-constants".
[[nodiscard]] std::string_view variable_kind_name(VariableKind kind) noexcept;

/// How bounds are read.
enum class BoundMode : std::uint8_t {
  Absolute,  ///< [lower, upper] as given
  Relative,  ///< [value + lower, value + upper] around each variable's current value (thesis 10.1.2)
};

/// The bounds of every variable of one selection.
struct Bounds {
  BoundMode mode = BoundMode::Relative;
  /// Finite; ≤ upper. Relative mode: ≤ 0.
  double lower = -1.0;
  /// Finite. Relative mode: ≥ 0.
  double upper = 1.0;
};

/// One entity's share of the variables.
struct VariableSelection {
  Label label{};
  VariableKind kind = VariableKind::ControlPoints;
  /// The points / weights / knots / tangents / constants taken, by index; empty = all.
  std::vector<std::size_t> indices{};
  /// For point and tangent kinds: the coordinates taken, a subset of "xyz" in order
  /// (a planar entity has no z). Default "xyz".
  std::string axes = "xyz";
  Bounds bounds{};
};

/// A named vector of variables: the selections in order, each contributing its
/// indices × axes in index-major order.
struct VariableSet {
  std::string name{};
  std::vector<VariableSelection> selections{};
};

/// The variables' current values and bounds.
struct VariableValues {
  /// "label.kind[index].axis", e.g. "3.control-points[2].y", one per variable.
  std::vector<std::string> names{};
  std::vector<double> values{};
  std::vector<double> lower{};
  std::vector<double> upper{};

  /// As Flexo variables (name and bounds; `precision` for binary coding, 0 = real-coded).
  [[nodiscard]] std::vector<optim::Variable> to_optim(double precision = 0.0) const;
};

/// Reads the variables' values from the document and resolves their bounds.
/// @throws hula::Error(Errc::InvalidArgument) naming the selection (selections[i]) for a missing
///   label, a kind the entity does not have (e.g. weights of a non-rational curve), an index out
///   of range, bad axes or bad bounds
[[nodiscard]] VariableValues read_variables(const Document& document, const VariableSet& set);

/// The selected entities' curves (and point sets) with `values` written into
/// them, without changing the document (fitness evaluation may run on many threads).
/// @throws as read_variables; hula::Error(Errc::InvalidArgument) if values has the wrong size;
///   the curve's own errors when the values make it invalid (knots out of order, weight ≤ 0)
[[nodiscard]] std::map<Label, curve::Curve> apply_variables(const Document& document, const VariableSet& set,
                                                            std::span<const double> values);

/// Writes `values` into the document (inside a transaction): set_curve / set_point_set per entity.
/// @throws as apply_variables, plus the errors of Edit (a locked entity)
void write_variables(Edit& edit, const VariableSet& set, std::span<const double> values);

/// The objective of a problem over document variables: reads the candidate curves (by label)
/// and writes the objectives. Called concurrently: must not change shared state.
using CurveObjective = std::function<void(const std::map<Label, curve::Curve>& curves, std::span<double> objectives)>;

/// A Flexo problem over document variables: the variables' bounds, `objectives` objectives from
/// `objective`, and one inequality constraint per stored constraint of the selected curves
/// (g = residual − tolerance ≤ 0; an undefined residual counts as violated).
/// The problem keeps copies of the entities, so the document may change afterwards.
/// @throws as read_variables
[[nodiscard]] optim::Problem make_problem(const Document& document, const VariableSet& set, CurveObjective objective,
                                          std::size_t objectives = 1);

}  // namespace hula::oli
