// SPDX-License-Identifier: MIT
// Law → NURBS fitted span by span between given breakpoints (the knots of the
// NURBS curves inside the law), so that derivative jumps at the knots (a cubic's
// third derivative) do not force law::to_nurbs to crowd breakpoints there.
// The pieces are joined C0 with knots of multiplicity 5 at the breakpoints.
#pragma once
#include <span>
#include <string_view>
#include <vector>

#include "hula/law/convert.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::studies::detail {

/// The sorted distinct breakpoints of a curve: domain ends and interior knot values.
[[nodiscard]] std::vector<double> breakpoints(const nurbs::NurbsCurve& curve);

/// law::to_nurbs on each [breaks[i], breaks[i+1]], joined into one quintic.
/// @param field the input named in the error when the pieces do not meet
/// @throws as law::to_nurbs
/// @throws hula::Error(Errc::InvalidArgument) naming `field` and the breakpoint where the law jumps
///   (the two pieces' ends differ by more than 10 × the fit tolerance: e.g. the input's tangent jumps
///   there, so its compound is torn)
[[nodiscard]] law::ToNurbsResult fit_on_spans(const law::Law& law, std::string_view parameter,
                                              std::span<const double> breaks, const law::ToNurbsOptions& options,
                                              std::string_view field);

}  // namespace hula::studies::detail
