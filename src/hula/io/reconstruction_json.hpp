// SPDX-License-Identifier: MIT
// JSON summaries of a curve reconstructed from its natural equations and of its
// NURBS fit (intrinsic::reconstruct, intrinsic::fit_nurbs), one codec for
// `hula reconstruct` and POST /api/reconstruct (docs/cli.md, docs/server.md);
// and the request and report of design by curvature on an existing curve
// (studies::edit_curvature: `hula reconstruct --curve`, POST
// .../entities/{label}/curvature-edit).
#pragma once

#include <nlohmann/json.hpp>

#include "hula/intrinsic/natural_equations.hpp"
#include "hula/studies/curvature_edit.hpp"

namespace hula::io {

/// How a curve was integrated: {"method": "planar-exact-angle" | "planar-numeric-angle" |
/// "frenet-serret", "steps": integration nodes after the start, "rejected_steps", "breakpoints":
/// the kinks of κ, τ the integration stepped onto}.
[[nodiscard]] nlohmann::json integration_summary(const intrinsic::IntrinsicCurve& curve);

/// A NURBS fit of a reconstructed curve: {"control_points": count, "segments", "tolerance": the
/// absolute tolerance applied, "max_deviation"}.
[[nodiscard]] nlohmann::json fit_summary(const intrinsic::NurbsFitResult& fit);

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
