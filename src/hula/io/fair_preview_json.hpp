// SPDX-License-Identifier: MIT
// The codec of the fairing assistant's preview (studies::fair_within_tolerance,
// POST /api/documents/{name}/entities/{label}/fair-preview, docs/server.md):
// the request {"tolerance", "method"?: "min-variation"|"knots", "budget"?,
// "hold"?: "free"|"points"|"tangents", "analysis"?, "curve"?} ("curve": the page's edit in flight, faired instead of
// the stored entity) and the ghost it answers {"revision", "method", "tolerance",
// "curve", "energy_before", "energy_after", "max_deviation", "data_points",
// "faired_points", "iterations", "stopped", "seconds", "hold"} (then "analysis" when
// asked, written by the server). Member names and order are a contract
// (src/hula/server/openapi.json): extend, never rename.
#pragma once

#include <cstdint>
#include <optional>

#include "hula/io/json_curve.hpp"
#include "hula/studies/fairing_assistant.hpp"

namespace hula::io {

/// A fairing-preview request.
struct FairPreviewRequest {
  /// "tolerance" (required), "method" (default min-variation), "budget" → time_budget_seconds, "hold"
  /// (default free); validated.
  studies::AssistantOptions options{};
  /// The "analysis" member as given (the viewport analysis options of the ghost), when present.
  std::optional<Json> analysis{};
  /// The "curve" member (docs/formats.md curve JSON), when present: a drag's latest position, sent beside the
  /// PATCH that stores it rather than after its answer, faired instead of the stored entity.
  std::optional<curve::Curve> curve{};
};

/// Reads a fairing-preview request body.
/// @throws hula::Error(Errc::ParseError) for an unknown, missing or mistyped member, naming it;
///   hula::Error(Errc::InvalidOption) for an unknown method or an option out of range
///   (studies::AssistantOptions::validate), naming the field
[[nodiscard]] FairPreviewRequest fair_preview_request_from_json(const Json& body);

/// The ghost as JSON, in the member order of the file comment (without "analysis").
/// @param revision the document revision the faired entity was read at
[[nodiscard]] Json fair_preview_to_json(const studies::AssistantResult& result,
                                        const studies::AssistantOptions& options, std::uint64_t revision);

}  // namespace hula::io
