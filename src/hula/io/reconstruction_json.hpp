// SPDX-License-Identifier: MIT
// JSON summaries of a curve reconstructed from its natural equations and of its
// NURBS fit (intrinsic::reconstruct, intrinsic::fit_nurbs), one codec for
// `hula reconstruct` and POST /api/reconstruct (docs/cli.md, docs/server.md);
// and the request and report of design by curvature on an existing curve
// (studies::edit_curvature: `hula reconstruct --curve`, POST
// .../entities/{label}/curvature-edit).
#pragma once

#include <nlohmann/json.hpp>
#include <span>
#include <string>

#include "hula/intrinsic/natural_equations.hpp"
#include "hula/law/expr.hpp"
#include "hula/studies/curvature_edit.hpp"

namespace hula::io {

/// How a curve was integrated: {"method": "planar-exact-angle" | "planar-numeric-angle" |
/// "frenet-serret", "steps": integration nodes after the start, "rejected_steps", "breakpoints":
/// the kinks of κ, τ the integration stepped onto}.
[[nodiscard]] nlohmann::json integration_summary(const intrinsic::IntrinsicCurve& curve);

/// A NURBS fit of a reconstructed curve: {"control_points": count, "segments", "tolerance": the
/// absolute tolerance applied, "max_deviation"}.
[[nodiscard]] nlohmann::json fit_summary(const intrinsic::NurbsFitResult& fit);

/// A natural-equation law κ(s) or τ(s) (parameter "s") parsed from `text`; a parse error names `field` and
/// starts with `shown` and the text ("kappa 'x': ..." over HTTP, "--kappa 'x': ..." on the command line).
/// @throws hula::Error(Errc::ParseError) with where.field = `field`
[[nodiscard]] law::Law natural_equation_law(const std::string& text, law::Context& context, const std::string& field,
                                            const std::string& shown);

/// Frenet frames along a reconstructed curve: [{"s", "position", "T", "N", "B"}], vectors [x, y, z].
[[nodiscard]] nlohmann::ordered_json frame_points_json(std::span<const intrinsic::FramePoint> points);

/// Answers a reconstruction request {"kappa", "tau" (laws of s), "length", "start_point"?,
/// "start_frame"? {"tangent", "normal"}, "tolerance"?, "fit_tolerance"?, "at"?} (POST /api/reconstruct):
/// {"points": [{"s", "position", "T", "N", "B"}] at `at` (default 5 equal steps), "curve" (the fitted NURBS
/// as a curve file), "max_deviation", "integration", "fit"}, with the work bounded
/// (intrinsic::kFrontEndMaxSteps, kFrontEndMaxSegments) so a rough law is an error naming the limit.
/// @throws hula::Error naming the member at fault (ParseError for a bad law, with field "kappa" or "tau");
///   as intrinsic::reconstruct and intrinsic::fit_nurbs_converged
[[nodiscard]] nlohmann::ordered_json reconstruction_request_json(const nlohmann::ordered_json& body);

/// A design-by-curvature request: the laws (parsed in one new law::Context) and the options.
struct CurvatureEditRequest {
  studies::CurvatureEdit edit{};
  studies::CurvatureEditOptions options{};
};

/// Reads {"kappa": law of s, "target"?: "curvature" | "change" (default "curvature"), "tau"?: law of s,
/// "hold"?: "free" | "tangent" | "curvature" (default "tangent"), "max_handles_factor"?: 2}
/// (docs/server.md). The reconstruction's integration is bounded by intrinsic::kFrontEndMaxSteps.
/// @throws hula::Error(Errc::ParseError) naming the member for unknown members, wrong types and bad laws
///   (with the law's line and column); Errc::InvalidArgument naming "target" or "hold" for an unknown name;
///   Errc::InvalidOption naming the option out of range
[[nodiscard]] CurvatureEditRequest curvature_edit_request_from_json(const nlohmann::ordered_json& body);

/// The report of an edit: {"kind": the result's curve kind, "handles_before", "handles_after", "planar",
/// "length_before", "length_after", "reconstructed", "max_curvature_deviation", "mean_curvature_deviation",
/// "reconstruction_max_deviation", "reconstruction_mean_deviation", "iterations", "start_point_error",
/// "end_point_error", "start_tangent_error", "end_tangent_error", "start_curvature_error", "end_curvature_error",
/// "inflections_before", "inflections_after", "seconds"}.
[[nodiscard]] nlohmann::ordered_json curvature_edit_to_json(const studies::CurvatureEditResult& result);

}  // namespace hula::io
