// SPDX-License-Identifier: MIT
// The short text forms of values that command lines and query strings carry:
// comma-separated number lists ("0,0.5,1") and spline end conditions
// ("natural", "clamped:1,0,0", ...), read with a hula::Error that names the
// field, the entry and what was typed.
#pragma once

#include <string_view>
#include <vector>

#include "hula/nurbs/interpolate.hpp"

namespace hula::io {

/// Parses a comma-separated list of numbers ("0,0.5,1").
/// @param text the option's value
/// @param field name used in messages and ErrorWhere.field (e.g. "t", "knots")
/// @throws hula::Error(Errc::ParseError) naming `field[i]` and the text of the bad entry
/// @throws hula::Error(Errc::NonFiniteInput) for nan/inf or a value outside the range of a double
[[nodiscard]] std::vector<double> parse_number_list(std::string_view text, std::string_view field);

/// Parses an end condition: natural | bessel | not-a-knot | occt | direction:x,y[,z] | clamped:x,y[,z].
/// @throws hula::Error(Errc::ParseError) naming `field` ("start" or "end") and the value
[[nodiscard]] nurbs::EndCondition parse_end_condition(std::string_view text, std::string_view field);

}  // namespace hula::io
