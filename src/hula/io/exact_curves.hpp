// SPDX-License-Identifier: MIT
// The answers of the commands that make exact curves (curves held by their
// laws, evaluated exactly: intrinsic/natural_curve.hpp) — the clothoid
// Hermite interpolants (`hula clothoid`), the log-aesthetic segments (`hula
// log-aesthetic`) — and the writing of an exact curve, by its laws or as its
// NURBS within a tolerance (their -o/--to-nurbs, `hula edit to-nurbs`).
// The request types of the answers (intrinsic::StartFrame,
// intrinsic::ClothoidSegment) come with this header.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hula/curve/curve.hpp"
#include "hula/intrinsic/clothoid.hpp"
#include "hula/intrinsic/natural_equations.hpp"
#include "hula/io/json_curve.hpp"

namespace hula::io {

/// Writes `curve` to `path` (atomically): by its construction data, or with `to_nurbs` as its NURBS within that
/// tolerance (intrinsic::to_nurbs). Returns the summary {"path", "kind" ("natural", "law" or "nurbs"),
/// "tolerance"?, "max_deviation"?, "control_points"? (the last three with `to_nurbs`)}.
/// @throws as intrinsic::to_nurbs and write_curve_file
[[nodiscard]] Json write_exact_curve(const std::string& path, const curve::Curve& curve,
                                     const std::optional<double>& to_nurbs);

/// The exact curve of natural equations given as text (a natural curve, its stand-in NURBS within
/// curve::kApproximationTolerance).
/// @throws as intrinsic::natural_curve
[[nodiscard]] curve::Curve natural_equation_curve(const curve::NaturalData& data);

/// A G1 or G2 clothoid Hermite interpolation: planar end points (z = 0) and tangent angles (radians from +x,
/// counter-clockwise), and with both end curvatures the G2 spline of three clothoids.
struct ClothoidRequest {
  Vec3 start_point{};
  double start_angle = 0.0;
  Vec3 end_point{};
  double end_angle = 0.0;
  /// Hermite problem: with end_curvature the G2 spline of three clothoids; spline: the curvature at the first /
  /// last point (open G2 splines, each optional, at an end without its angle).
  std::optional<double> start_curvature{};
  std::optional<double> end_curvature{};
  std::vector<double> at{};  ///< arc lengths along the whole result to sample (none: no "points")
  /// ≥ 2 points: a spline through them (intrinsic::fit_clothoid_spline or fit_biarc_spline) instead of the
  /// Hermite problem; start_point and end_point are then unused, and start_angle / end_angle are the end
  /// angles of an open spline only with `spline_start_angle` / `spline_end_angle`.
  std::vector<Vec3> points{};
  bool closed = false;              ///< spline: closed (G1 or G2 at the first point too)
  bool spline_start_angle = false;  ///< spline: start_angle is given
  bool spline_end_angle = false;    ///< spline: end_angle is given
  bool biarc = false;               ///< biarcs (two arcs per interval, G1) instead of clothoids
  std::optional<int> continuity{};  ///< spline: 1 or 2 (default 2); Hermite: 2 needs both curvatures
};

/// The segments of a clothoid interpolation and its JSON.
struct ClothoidAnswer {
  std::vector<intrinsic::ClothoidSegment> segments;
  /// {"kind": "g1" | "g2" | "biarc", "segments", "length" (clothoid_spline_to_json), "iterations", "points"?:
  /// [{"s", "point", "theta", "kappa"}] at `at`}, and for a spline through points "through": N, "closed".
  Json json;
};

/// intrinsic::fit_clothoid_g1, fit_clothoid_g2, fit_biarc, fit_clothoid_spline or fit_biarc_spline of the
/// request, sampled at its arc lengths.
/// @throws as the fits; hula::Error(Errc::OutOfDomain) naming at[i] outside [0, length];
///   hula::Error(Errc::InvalidArgument) naming "continuity" for a biarc with a continuity, or 2 for a Hermite
///   problem without curvatures (1 with them), naming "closed" for a closed Hermite problem, and naming the
///   missing one of a Hermite problem's curvatures given alone
[[nodiscard]] ClothoidAnswer clothoid_answer(const ClothoidRequest& request);

/// The request of POST /api/clothoid: {"points"?: [[x, y], ...], "closed"?, "fit"?: "g1" | "g2" | "biarc",
/// "start_point"?, "start_angle"?, "end_point"?, "end_angle"?, "start_curvature"?, "end_curvature"?,
/// "at"?: [s, ...]} — with "points" a spline (the end angles and curvatures optional), else the Hermite
/// problem (start and end point and angle required). Unknown members are refused by name.
/// @throws hula::Error(Errc::ParseError) naming the member at fault
[[nodiscard]] ClothoidRequest clothoid_request_from_json(const Json& body);

/// The exact curve of consecutive clothoid segments (a natural curve: its curvature law, position integrated
/// to `tolerance`).
[[nodiscard]] curve::Curve clothoid_curve(const std::vector<intrinsic::ClothoidSegment>& segments, double tolerance);

/// A log-aesthetic segment of slope alpha (intrinsic/log_aesthetic.hpp) from a planar start point and angle.
struct LogAestheticRequest {
  double alpha = 0.0;
  double rho0 = 1.0;
  double lambda = 0.0;
  double length = 1.0;
  Vec3 start_point{};
  double start_angle = 0.0;
  std::optional<std::vector<double>> at{};  ///< arc lengths to sample (default 0, L/2, L)
  double tolerance = curve::kNaturalTolerance;
};

/// The exact curve of a log-aesthetic segment and its JSON.
struct LogAestheticAnswer {
  curve::Curve curve;
  /// {"alpha", "rho0", "lambda", "length", "max_length" (null when unbounded), "curvature" (the law), "points":
  /// [{"s", "point", "tangent", "kappa", "kappa_prime"}]} with κ and dκ/ds as the analysis computes them
  /// (diffgeom::frenet of the curve value).
  Json json;
};

/// @throws hula::Error naming the field for parameters outside the family (intrinsic::LogAestheticCurve)
[[nodiscard]] LogAestheticAnswer log_aesthetic_answer(const LogAestheticRequest& request);

}  // namespace hula::io
