// SPDX-License-Identifier: MIT
// The JSON shape of curve–curve intersections, self-intersections and curve
// distances (nurbs/intersect.hpp), written by `hula intersect`, `hula
// distance`, POST /api/intersect, POST /api/distance and the Python
// binding alike (docs/formats.md "Intersection results").
#pragma once

#include "hula/curve/curve.hpp"
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

/// The one answer of `hula intersect`, POST /api/intersect and hulahoops.intersect: nurbs::intersect of a and b
/// (nurbs::self_intersect of a when b is null) on their NURBS, encoded by intersection_to_json, points as [x, y]
/// when both curves are planar; a law or natural-equation curve is answered through its NURBS stand-in, whose
/// deviation is added as "stand_in_deviation".
/// @throws hula::Error as nurbs::intersect / self_intersect
[[nodiscard]] Json intersection_answer(const curve::Curve& a, const curve::Curve* b,
                                       const nurbs::IntersectOptions& options = {});

/// The one answer of `hula distance`, POST /api/distance and hulahoops.distance: nurbs::curve_distance encoded by
/// curve_distance_to_json, with "stand_in_deviation" as intersection_answer.
/// @throws hula::Error as nurbs::curve_distance
[[nodiscard]] Json distance_answer(const curve::Curve& a, const curve::Curve& b,
                                   const nurbs::IntersectOptions& options = {});

}  // namespace hula::io
