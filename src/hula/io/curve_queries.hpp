// SPDX-License-Identifier: MIT
// The answers of the one-shot questions asked about curve values — what a
// curve is (`hula info`, `hula demo`), its nearest points (`hula closest`),
// the distance between two curves (`hula deviation`), the continuity of a
// join (`hula continuity`) and its fairness energies (`hula energy`) — each
// one function from values to its JSON document, so that every door that
// asks the question gets the same answer (docs/cli.md gives the shapes).
// The options types of the answers (nurbs::DeviationOptions) come with this
// header.
#pragma once

#include <span>
#include <string_view>

#include "hula/curve/curve.hpp"
#include "hula/diffgeom/match_blend.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/json_text.hpp"
#include "hula/nurbs/deviation.hpp"

namespace hula::io {

/// What a NURBS curve is: {"degree", "dimension", "rational", "domain", "knots", "control_points", "weights"
/// (null when not rational), "length" (nurbs::arc_length, relative tolerance 1e-12), "end_derivatives"
/// {"start", "end"}, "end_tangents" {"start", "end"} (null where |C'| is rounding noise), "planarity"}.
/// @throws hula::Error(Errc::NumericalFailure) if the arc length does not converge
[[nodiscard]] Json curve_description_json(const nurbs::NurbsCurve& curve);

/// curve_description_json streamed: the constructor computes everything that can fail (the arc length,
/// the planarity), write_members then writes the same members into an open object of a JsonText, the
/// same bytes as format_json of the value, without a JSON value of a node per number (`hula info` of a
/// million-pole curve). The curve must outlive the writer.
class DescriptionWriter {
 public:
  /// @throws as curve_description_json
  explicit DescriptionWriter(const nurbs::NurbsCurve& curve);
  /// The members "degree" … "planarity", after the caller's own, in the object `w` has open.
  void write_members(JsonText& w) const;

  /// What the description adds to the curve's own arrays.
  struct Computed {
    double length = 0.0;
    Vec3 start_derivative, end_derivative;
    bool start_unit = false, end_unit = false;  ///< whether |C'| is above rounding noise there
    Json planarity;
  };

 private:
  const nurbs::NurbsCurve& curve_;
  Computed computed_;
};

/// As curve_description_json, with "maximum_curvature" (diffgeom::analyse_curve's feature) added.
[[nodiscard]] Json curve_description_with_maximum_curvature_json(const nurbs::NurbsCurve& curve);

/// The points of `curve` nearest to `points` (nurbs::closest_point on its NURBS): {"law_stand_in_deviation"?
/// (a law curve, answered through its stand-in), "results": [{"point" (as given: `dimensions[i]` 2 or 3
/// coordinates), "t", "closest", "distance"}]}.
[[nodiscard]] Json closest_answer(const curve::Curve& curve, std::span<const Vec3> points,
                                  std::span<const int> dimensions);

/// The sampled distance between a and b (nurbs::deviation on their NURBS): {"mode" (`mode_name`), "samples",
/// "max", "max_at", "mean", "rms", "mean_axis", "max_axis"} (per-axis members always [x, y, z]).
/// @throws as nurbs::deviation
[[nodiscard]] Json deviation_answer(const curve::Curve& a, const curve::Curve& b,
                                    const nurbs::DeviationOptions& options, std::string_view mode_name);

/// The continuity of the join of a's end with b's start (diffgeom::join_continuity): {"parametric": "C<k>" or
/// null, "geometric": "G<k>" or null, "tangent_angle", "curvature_left", "curvature_right" (null where
/// undefined), "left", "right" (C, C', C'', C''' on each side)}.
/// @throws as diffgeom::join_continuity
[[nodiscard]] Json join_continuity_answer(const curve::Curve& a, const curve::Curve& b);

/// The fairness energies of a curve (diffgeom::bending_energy and curvature_variation_energy of its NURBS):
/// {"bending": {"value", "error_estimate", "converged"}, "curvature_variation": {...}}.
[[nodiscard]] Json energy_answer(const curve::Curve& curve);

/// A curve made from two curves (`hula match`, `hula blend`) and the members that report it.
struct CurveJoinAnswer {
  nurbs::NurbsCurve curve;
  Json report = Json::object();
};

/// "G0" … "G3" (or "0" … "3") as k, for a --continuity option between `lowest` and G3.
/// @throws hula::Error(Errc::InvalidOption) naming `field` for any other text
[[nodiscard]] int continuity_order_from_name(std::string_view text, int lowest, std::string_view field);

/// "start" or "end" as a curve end, for the end options of match and blend (`field` as the door names it:
/// "to-end" for the command line's --to-end, "to_end" in a request body).
/// @throws hula::Error(Errc::InvalidOption) naming `field` for any other text
[[nodiscard]] diffgeom::CurveEnd curve_end_from_name(std::string_view text, std::string_view field);

/// A's end matched to B (diffgeom::match_end): the new A and {"requested": "G<k>", "geometric": "G<k>" or null
/// (the continuity reached, diffgeom::compare_sides), "parametric", "tangent_angle", "curvature_left",
/// "curvature_right", "moved" (pole indices), "inserted_knots", "degree_elevation", "target_parameter" (on B),
/// "degree", "control_points" (count)}.
/// @throws as diffgeom::match_end
[[nodiscard]] CurveJoinAnswer match_answer(const curve::Curve& a, const curve::Curve& b,
                                           const diffgeom::MatchOptions& options);

/// The blend from A's end to B's start (diffgeom::blend): the curve and {"requested": "G<k>", "start", "end"
/// (each {"geometric", "parametric"} reached), "scale", "curvature_variation" {"value", "error_estimate",
/// "converged"} (∫(dκ/ds)² ds), "curvature_extrema" (count), "degree", "control_points" (count)}.
/// @throws as diffgeom::blend
[[nodiscard]] CurveJoinAnswer blend_answer(const curve::Curve& a, const curve::Curve& b,
                                           const diffgeom::BlendOptions& options);

/// The thesis's example curves of `hula demo` (7.1.2, Table 3) and their descriptions.
[[nodiscard]] Json thesis_examples_json();

}  // namespace hula::io
