// SPDX-License-Identifier: MIT
// JSON text for people and for diffs: 2-space indentation,
// arrays of scalars on one line ("pretty but compact": a control point or a
// knot vector reads as one line, not one number per line), no negative zero,
// and invalid UTF-8 replaced rather than thrown on. Every JSON document the
// CLI prints or writes goes through format_json.
#pragma once

#include <string>

#include "hula/io/json_read.hpp"

namespace hula::io {

/// The text of `value`: objects and arrays of containers one member per line
/// with 2-space indentation, arrays whose elements are all scalars on one line
/// ("[0.0, 0.5, 1.0]"), numbers in nlohmann's shortest round-trip form with
/// -0.0 written as 0.0, and a final newline.
[[nodiscard]] std::string format_json(const json::Json& value);

/// One line of JSON (no newline inside, final newline): the `jsonl` form.
[[nodiscard]] std::string format_json_line(const json::Json& value);

/// Appends a double as format_json writes it: "0.0" for ±0, "null" when not finite, else the
/// shortest round-trip digits in nlohmann's layout (fixed for decimal exponents in (-4, 15]).
void append_json_number(std::string& out, double v);

}  // namespace hula::io
