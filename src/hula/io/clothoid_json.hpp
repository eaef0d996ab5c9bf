// SPDX-License-Identifier: MIT
// JSON form of clothoid segments and clothoid splines (intrinsic/clothoid.hpp), the codec of
// `hula clothoid` (docs/cli.md, docs/formats.md "Clothoid result").
#pragma once

#include <span>

#include "hula/intrinsic/clothoid.hpp"
#include "hula/io/json_curve.hpp"

namespace hula::io {

/// One segment: {"start": [x, y], "theta0", "kappa0", "dkappa", "length", "end": [x, y], "theta1",
/// "kappa1"}, angles in radians, curvature in 1 / model units, dkappa in 1 / model units²; the end
/// values are the segment's own (point() at s = L, θ(L), κ(L)), so that a reader sees the joins.
[[nodiscard]] Json clothoid_segment_to_json(const intrinsic::ClothoidSegment& segment);

/// Segments in order: {"segments": [clothoid_segment_to_json ...], "length": the total length}.
[[nodiscard]] Json clothoid_spline_to_json(std::span<const intrinsic::ClothoidSegment> segments);

}  // namespace hula::io
