// SPDX-License-Identifier: MIT
// Validity of a design curve (thesis chapter 10, further work: "a curve that
// doubles back on itself is a solution, but not a valid solution"): the
// requirements a study may add — no self-intersection
// (nurbs::self_intersect), no cusp (the parameter speed |C'| nowhere below a
// fraction of its mean, so the curve neither stops nor turns back), and
// optionally monotone curvature (diffgeom::curvature_monotonicity) — checked
// on a curve, turned into inequality constraints g ≤ 0 for Flexo (the GA then
// prefers valid designs by Deb's feasibility rules, or ranks by objective +
// penalty × violation), and reported with their reasons.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "hula/nurbs/nurbs_curve.hpp"
#include "hula/optim/solution.hpp"

namespace hula::studies {

/// What a valid design must satisfy. The default requires nothing.
struct ValidityRequirements {
  /// The curve must not meet itself (no crossing, touch or doubled-back stretch). Default false.
  bool no_self_intersection = false;
  /// No cusp: min |C'(t)| ≥ min_speed × mean |C'| (the mean being the arc length over the domain length).
  /// 0 = not required (default); valid [0, 1). 0.05 forbids a speed below 5 % of the mean: the speed of a
  /// cubic vanishes at a cusp, and a near-cusp shows as a speed far below the mean where the curve turns.
  double min_speed = 0.0;
  /// The curvature (signed for planar curves) must be monotone: no curvature extremum inside. Default false.
  bool monotone_curvature = false;
  /// How the optimiser treats invalid designs: Deb's feasibility rules (default: a valid design beats every
  /// invalid one, fewer violations beat more) or a static penalty (objective + penalty × violation).
  optim::ConstraintHandling handling = optim::ConstraintHandling::FeasibilityRules;
  /// The penalty factor of ConstraintHandling::Penalty (objective units per violation); finite, ≥ 0. Default 1000.
  double penalty = 1000.0;

  /// Whether anything is required.
  [[nodiscard]] bool any() const noexcept { return no_self_intersection || min_speed > 0.0 || monotone_curvature; }
  /// The number of constraint values validity_constraints writes: one per requirement.
  [[nodiscard]] std::size_t count() const noexcept;
  /// @throws hula::Error(Errc::InvalidArgument) naming `validity.min_speed` outside [0, 1) or `validity.penalty`
  ///   negative or not finite
  void validate() const;
  /// The handling and penalty written into a Flexo run.
  void apply(optim::RunSettings& run) const;
};

/// The measures of one curve and what they break.
struct ValidityCheck {
  /// Self-intersection points plus doubled-back stretches (0 unless required).
  std::size_t self_intersections = 0;
  /// min |C'| / mean |C'| over 32 samples per knot span (both sides of every knot); computed when min_speed > 0.
  double speed_ratio = 1.0;
  /// Parameter where the speed is lowest.
  double slowest_at = 0.0;
  /// Curvature extrema inside the domain (0 unless monotone curvature is required).
  std::size_t curvature_extrema = 0;
  /// One sentence per broken requirement, naming where ("meets itself at (x, y) (t = 0.2 and 0.7)").
  std::vector<std::string> reasons{};
  /// True when no requirement is broken.
  [[nodiscard]] bool valid() const noexcept { return reasons.empty(); }
};

/// Checks a curve against the requirements (only those asked are measured).
/// @throws hula::Error(Errc::InvalidArgument) from requirements.validate()
[[nodiscard]] ValidityCheck check_validity(const nurbs::NurbsCurve& curve, const ValidityRequirements& requirements);

/// The requirements as Flexo inequality constraints g_k ≤ 0, in the order self-intersection, cusp,
/// monotone curvature (those asked): the number of meetings, min_speed − speed ratio, the number of
/// curvature extrema.
/// @param out requirements.count() values
void validity_constraints(const ValidityCheck& check, const ValidityRequirements& requirements, std::span<double> out);

}  // namespace hula::studies
