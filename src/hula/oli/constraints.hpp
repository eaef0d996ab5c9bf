// SPDX-License-Identifier: MIT
// Geometric constraints stored with a curve entity (thesis 9.5.4
// "Constraints": data points, tangency conditions, curvature, length are
// geometric constraints whose representation is defined at the API level).
// A constraint is data; check_constraints reports each one's residual for any
// curve, and the optimisation over document variables (variables.hpp) adds
// them as penalties (docs/modules/oli.md "Constraints" gives the policy).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/io/json_read.hpp"

namespace hula::curve {
class Curve;
}  // namespace hula::curve

namespace hula::oli {

/// What a constraint holds the curve to.
enum class ConstraintKind : std::uint8_t {
  PassThrough,   ///< the curve passes through `point` (residual: distance from the point to the curve)
  EndTangent,    ///< the tangent at `end` points along `direction` (residual: angle in radians)
  EndCurvature,  ///< the curvature at `end` is `value` (residual: |κ − value|, 1/model units)
  FixedLength,   ///< the arc length is `value` (residual: |L − value|, model units)
};

/// "pass-through", "end-tangent", "end-curvature" or "fixed-length".
[[nodiscard]] std::string_view constraint_kind_name(ConstraintKind kind) noexcept;

/// Which end of the curve (its domain's start or end).
enum class CurveEnd : std::uint8_t { Start, End };

/// One constraint. Members a kind does not use are ignored and written as their defaults.
struct Constraint {
  ConstraintKind kind = ConstraintKind::PassThrough;
  /// PassThrough: the point, model units.
  Vec3 point{};
  /// EndTangent, EndCurvature: the end.
  CurveEnd end = CurveEnd::Start;
  /// EndTangent: the direction (any non-zero length; only its direction counts).
  Vec3 direction{};
  /// EndCurvature: κ ≥ 0; FixedLength: L > 0.
  double value = 0.0;
  /// The residual at or below which the constraint counts as met, > 0 (same
  /// units as the residual). Default 1e-6 (resabs; an angle of 1e-6 rad).
  double tolerance = 1e-6;

  /// @throws hula::Error(Errc::NonFiniteInput) for a NaN or infinity, naming the member
  /// @throws hula::Error(Errc::InvalidArgument) for a zero direction, a negative curvature,
  ///   a length ≤ 0 or a tolerance ≤ 0, naming the member and the value
  void validate() const;
  friend bool operator==(const Constraint&, const Constraint&) = default;
};

/// The residual of one constraint on one curve.
struct ConstraintResidual {
  /// The constraint's index in the list checked.
  std::size_t index = 0;
  ConstraintKind kind = ConstraintKind::PassThrough;
  /// The residual (units of the kind); NaN when undefined (curvature of a
  /// curve with zero speed at the end, a tangent of zero length).
  double residual = 0.0;
  /// residual ≤ tolerance (false when the residual is NaN).
  bool satisfied = false;
};

/// The residual of each constraint on `curve`, in order.
/// Complexity: O(1) evaluations per end constraint; a closest-point search per
/// pass-through point; an arc-length integration per length constraint.
/// @throws hula::Error from Constraint::validate (with the constraint's index in `where`)
[[nodiscard]] std::vector<ConstraintResidual> check_constraints(const curve::Curve& curve,
                                                                std::span<const Constraint> constraints);

/// Constraints as JSON: [{"kind": "pass-through", "point": [x, y, z], "tolerance": 1e-6},
/// {"kind": "end-tangent", "end": "start"|"end", "direction": [x, y, z], "tolerance"},
/// {"kind": "end-curvature", "end", "value", "tolerance"}, {"kind": "fixed-length", "value", "tolerance"}].
[[nodiscard]] io::json::Json constraints_to_json(std::span<const Constraint> constraints);
/// Parses constraints_to_json's form ("tolerance" optional) and validates each.
/// @throws hula::Error(Errc::ParseError) naming the member (constraints[i].kind, ...); Constraint::validate's errors
[[nodiscard]] std::vector<Constraint> constraints_from_json(const io::json::Json& json);

}  // namespace hula::oli
