// SPDX-License-Identifier: MIT
// The JSON form of Frenet Hermite handles (nurbs::FrenetHandle), read by `hula
// hermite-frenet` and hulahoops.hermite_frenet alike (docs/formats.md "Frenet
// handle files").
#pragma once

#include <vector>

#include "hula/io/json_curve.hpp"
#include "hula/nurbs/interpolate.hpp"

namespace hula::io {

/// Frenet handles and how to place them.
struct FrenetHandles {
  std::vector<nurbs::FrenetHandle> handles;
  std::vector<double> parameters;  ///< empty: chord length
  int dimension = 3;               ///< 2 when every point is [x, y]
};

/// {"handles": [{"point", "tangent", "normal"?, "curvature"?, "torsion"?}], "parameters"?: [t0, …]}.
/// @throws hula::Error(Errc::ParseError) naming the member at fault ("handles[2].tangent"), unknown members too
[[nodiscard]] FrenetHandles frenet_handles_from_json(const Json& document);

/// The one answer of `hula hermite-frenet` and hulahoops.hermite_frenet: nurbs::hermite_frenet of the handles.
/// @throws as frenet_handles_from_json and nurbs::hermite_frenet
[[nodiscard]] nurbs::NurbsCurve hermite_frenet_curve(const Json& document);

}  // namespace hula::io
