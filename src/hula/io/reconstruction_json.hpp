// SPDX-License-Identifier: MIT
// JSON summaries of a curve reconstructed from its natural equations and of its
// NURBS fit (intrinsic::reconstruct, intrinsic::fit_nurbs), one codec for
// `hula reconstruct` and POST /api/reconstruct (docs/cli.md, docs/server.md).
#pragma once

#include <nlohmann/json.hpp>

#include "hula/intrinsic/natural_equations.hpp"

namespace hula::io {

/// How a curve was integrated: {"method": "planar-exact-angle" | "planar-numeric-angle" |
/// "frenet-serret", "steps": integration nodes after the start, "rejected_steps", "breakpoints":
/// the kinks of κ, τ the integration stepped onto}.
[[nodiscard]] nlohmann::json integration_summary(const intrinsic::IntrinsicCurve& curve);

/// A NURBS fit of a reconstructed curve: {"control_points": count, "segments", "tolerance": the
/// absolute tolerance applied, "max_deviation"}.
[[nodiscard]] nlohmann::json fit_summary(const intrinsic::NurbsFitResult& fit);

}  // namespace hula::io
