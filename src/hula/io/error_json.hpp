// SPDX-License-Identifier: MIT
// The JSON form of hula::Error shared by the CLI (stderr) and the HTTP API
// (every error body of `hula serve`):
// {"error": {"code": "InvalidKnots", "message": "...", "where": {...}}}.
// `code` is the stable errc_name; `where` holds only the ErrorWhere members
// that are set (field, index, component, line, column).
#pragma once

#include <nlohmann/json.hpp>

#include "hula/core/error.hpp"

namespace hula::io {

/// Converts an error to its JSON form.
/// @param error any hula::Error
/// @returns {"error": {"code": name, "message": message without the code
///   prefix, "where": {present members only; {} when none}}}
[[nodiscard]] nlohmann::ordered_json error_to_json(const Error& error);

}  // namespace hula::io
