// SPDX-License-Identifier: MIT
// JSON summaries of a curve reconstructed from its natural equations and of its
// NURBS fit (intrinsic::reconstruct, intrinsic::fit_nurbs), one codec for
// `hula reconstruct` and POST /api/reconstruct (docs/cli.md, docs/server.md).
#pragma once

#include <nlohmann/json.hpp>
#include <span>
#include <string>

#include "hula/intrinsic/natural_equations.hpp"
#include "hula/law/expr.hpp"

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

}  // namespace hula::io
