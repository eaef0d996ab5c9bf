// SPDX-License-Identifier: MIT
// The JSON shape of curve–curve intersections, self-intersections and curve
// distances (nurbs/intersect.hpp), written by `hula intersect`, `hula
// distance`, POST /api/intersect, POST /api/distance and the Python
// binding alike (docs/formats.md "Intersection results").
#pragma once

#include "hula/io/json_curve.hpp"
#include "hula/nurbs/intersect.hpp"

namespace hula::io {

/// {"tolerance", "points": [{"s", "t", "point", "distance", "angle", "kind"}], "overlaps": [{"s": [s0, s1],
/// "t": [t0, t1], "start", "end"}]}; points as [x, y] when dimension is 2. With `stand_in_deviation` ≥ 0 (a law
/// or natural-equation curve answered through its NURBS stand-in) a member "stand_in_deviation" is added.
[[nodiscard]] Json intersection_to_json(const nurbs::IntersectionResult& result, int dimension,
                                        double stand_in_deviation = -1.0);

/// {"distance", "s", "t", "point_a", "point_b", "lower_bound"} (and "stand_in_deviation" as above).
[[nodiscard]] Json curve_distance_to_json(const nurbs::CurveDistanceResult& result, int dimension,
                                          double stand_in_deviation = -1.0);

}  // namespace hula::io
