// SPDX-License-Identifier: MIT
// The "validity" member of study files (docs/formats.md "Validity
// requirements"): what a valid design must satisfy (studies/validity.hpp), and
// the report of a result's validity with the reasons it is refused.
#pragma once

#include "hula/io/json_curve.hpp"
#include "hula/io/json_read.hpp"
#include "hula/studies/validity.hpp"

namespace hula::io {

/// Reads {"no_self_intersection"?: bool, "min_speed"?: number in [0, 1), "monotone_curvature"?: bool,
/// "handling"?: "feasibility" | "penalty", "penalty"?: number ≥ 0}.
/// @throws hula::Error(Errc::ParseError) naming `validity.<member>` for an unknown member, a wrong type or name
/// @throws hula::Error(Errc::InvalidArgument) as studies::ValidityRequirements::validate
[[nodiscard]] studies::ValidityRequirements validity_from_json(const Json& value, const json::JsonPath& path);
/// Every member, defaults resolved.
[[nodiscard]] Json validity_to_json(const studies::ValidityRequirements& requirements);
/// {"valid", "reasons": [...], and the measures of what was required: "self_intersections", "min_speed_ratio",
/// "curvature_extrema"}.
[[nodiscard]] Json validity_check_to_json(const studies::ValidityCheck& check,
                                          const studies::ValidityRequirements& requirements);

}  // namespace hula::io
