// SPDX-License-Identifier: MIT
// The answers of the commands that make a new curve from a curve or from
// points: the kernel's edits of a NURBS (`hula edit insert-knot|refine|
// remove-knots|elevate|split|reverse|reparam|to-nurbs`), Lagrange
// interpolation (`hula interpolate --lagrange`) and least-squares
// approximation within a tolerance (`hula approximate`). Each returns the
// curves and the JSON members that describe them, so the caller only names
// the files. The request types (nurbs::Interval, io::PointSet) come with this
// header.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "hula/curve/curve.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/points_file.hpp"

namespace hula::io {

/// The edits of `hula edit`.
enum class CurveEdit {
  InsertKnot,
  Refine,
  RemoveKnot,
  RemoveKnots,
  Elevate,
  ReduceDegree,
  Rebuild,
  Split,
  Reverse,
  Reparam,
  ToNurbs
};

/// What an edit needs; each edit reads its own members.
struct CurveEditRequest {
  CurveEdit edit = CurveEdit::Reverse;
  double at = 0.0;                 ///< InsertKnot, RemoveKnot, Split
  int times = 1;                   ///< InsertKnot, RemoveKnot, Elevate
  double tolerance = 0.0;          ///< RemoveKnot, RemoveKnots, ReduceDegree, ToNurbs
  std::vector<double> knots{};     ///< Refine
  nurbs::Interval domain{0, 1};    ///< Reparam
  int degree = 3;                  ///< Rebuild
  std::size_t control_points = 0;  ///< Rebuild (required)
  std::size_t samples = 0;         ///< Rebuild (0: automatic, nurbs::RebuildOptions::samples)
};

/// The curves an edit made (two for Split, one otherwise) and its report members: {"removed", "error_bound",
/// "tolerance"} (remove-knots), {"error_bound", "bezier_bound", "tolerance"} (reduce-degree), {"degree",
/// "control_points", "samples", "max_deviation", "mean_deviation", "at"} (rebuild: nurbs::rebuild's measured
/// deviation from the original), {"at"} (split), {"from", "tolerance", "max_deviation"} (to-nurbs), none else.
struct CurveEditAnswer {
  std::vector<nurbs::NurbsCurve> curves;
  Json report = Json::object();
};

/// Applies the edit to `curve` (read from `path`, named in errors). Every edit but ToNurbs needs the NURBS
/// itself: a law or natural curve is refused with the advice to convert it first.
/// @throws hula::Error(Errc::InvalidArgument) naming "curve" for an exact curve; as the nurbs edits and
///   intrinsic::to_nurbs
[[nodiscard]] CurveEditAnswer edit_curve(const curve::Curve& curve, const std::string& path,
                                         const CurveEditRequest& request);

/// NURBS → law (`hula edit to-law`, hulahoops.NurbsCurve.to_law): the curve written out as a law of t
/// (law::explicit_from_nurbs, printed) and that law as a law curve on the curve's domain.
struct LawConversionAnswer {
  curve::Curve curve;      ///< the law curve (its stand-in NURBS within curve::kApproximationTolerance)
  std::string expression;  ///< its law text, of parameter "t"
  /// {"spans" (rational polynomial pieces), "degree", "max_difference" (max |law(t) − C(t)| over 1,001 samples of
  /// the domain, the law evaluated exactly), "expression_length"}.
  Json report = Json::object();
};

/// @param path the curve's file, named in errors
/// @throws hula::Error(Errc::InvalidArgument) naming "curve" for a law or natural curve (already exact); as
///   curve::Curve::from_law (ParseError naming "expression" when the text passes the parser's 64 KiB limit)
[[nodiscard]] LawConversionAnswer law_from_nurbs(const curve::Curve& curve, const std::string& path);

/// {"output": path, "degree", "control_points" (count), "knots", "domain"}: a written curve as `hula edit`
/// reports it.
[[nodiscard]] Json edited_curve_summary(const std::string& path, const nurbs::NurbsCurve& curve);

/// {"dimension", "degree", "control_points" (count), "domain"}: the shape of a made curve.
[[nodiscard]] Json curve_shape_summary(const nurbs::NurbsCurve& curve);

/// The Lagrange polynomial through the points (nurbs::interpolate_lagrange, a Bézier curve of degree N - 1)
/// at `parameters`, or when empty at the parameters of `rule`.
/// @throws as nurbs::interpolate_lagrange
[[nodiscard]] nurbs::NurbsCurve lagrange_curve(const PointSet& points, std::span<const double> parameters,
                                               nurbs::Parameterisation rule);

/// A made curve and the members that describe it.
struct MadeCurveAnswer {
  nurbs::NurbsCurve curve;
  Json report = Json::object();
};

/// `hula interpolate --closed`'s curve and summary (without the file name), POST /api/interpolate-closed's answer:
/// closed_cubic_curve with {"kind": "nurbs", "method": "closed", "points" (count), "dimension", "degree",
/// "control_points" (count), "domain", "parameterisation" (the rule's name, or "given" with parameters)}.
/// @param parameterisation the rule's name (io::parameterisation_from_name), used when `parameters` is empty
/// @throws hula::Error(Errc::ParseError) naming "parameterisation" for an unknown name; as closed_cubic_curve
[[nodiscard]] MadeCurveAnswer closed_interpolation_answer(const PointSet& points, std::span<const double> parameters,
                                                          std::string_view parameterisation);

/// `hula hermite-frenet`'s curve and summary (without the file names), POST /api/hermite-frenet's answer:
/// hermite_frenet_curve with {"degree", "control_points" (count), "domain"}.
/// @throws as hermite_frenet_curve
[[nodiscard]] MadeCurveAnswer hermite_frenet_answer(const Json& handles);

/// The closed (periodic, C2) cubic spline through the points and back to the first
/// (nurbs::interpolate_closed_cubic) at `parameters`, or when empty at the parameters of `rule`.
/// @throws as nurbs::interpolate_closed_cubic
[[nodiscard]] nurbs::NurbsCurve closed_cubic_curve(const PointSet& points, std::span<const double> parameters,
                                                   nurbs::Parameterisation rule);

/// A least-squares approximation of points: within `tolerance` (the fewest control points, a compact fair
/// B-spline through the first and last point: studies::fit_within_tolerance without stray rejection), or
/// with a given count of control points (nurbs::approximate).
struct ApproximationRequest {
  std::optional<double> tolerance{};
  std::optional<std::size_t> control_points{};
  int degree = 3;
  nurbs::Parameterisation parameterisation = nurbs::Parameterisation::ChordLength;
};

/// The approximating curve and its report: {"degree", "control_points" (count), "tolerance"?, "max_deviation",
/// "max_deviation_index", "fits", "fit_max_deviation"?, "smoothing"?} (the members marked ? with a tolerance).
struct ApproximationAnswer {
  nurbs::NurbsCurve curve;
  Json report = Json::object();
};

/// @throws hula::Error(Errc::InvalidArgument) naming "tolerance" unless exactly one of tolerance and
///   control_points is given; as the fits
[[nodiscard]] ApproximationAnswer approximation_answer(const PointSet& points, const ApproximationRequest& request);

}  // namespace hula::io
