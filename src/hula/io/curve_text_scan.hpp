// SPDX-License-Identifier: MIT
// The fast path of the curve-file reader: a NURBS or Bézier curve file in the
// plain shape hula writes it (the members of json_curve.hpp and nothing else,
// plain ASCII strings, numbers in JSON's grammar) read straight from its text
// into the kernel's arrays, without a JSON value of a node per number. A
// million-pole file is read about ten times faster this way (docs/benchmarks.md).
//
// It only ever accepts what the general reader accepts, with the same values
// bit for bit (integers as nlohmann reads them, -0 included; other numbers
// correctly rounded, as strtod): anything else — another kind, an unknown or
// repeated member, an escape or a non-ASCII byte in a string, a malformed,
// overflowing or underflowing number, an empty array, mixed 2-D and 3-D points,
// a curve the kernel refuses — gives nullopt, and the general reader reads the
// text again and names what is wrong.
#pragma once

#include <optional>
#include <string_view>

#include "hula/curve/curve.hpp"

namespace hula::io {

/// The curve of a plain NURBS or Bézier curve-file text, or nullopt when the text is anything else.
[[nodiscard]] std::optional<curve::Curve> scan_plain_curve_text(std::string_view text);

}  // namespace hula::io
