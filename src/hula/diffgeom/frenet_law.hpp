// SPDX-License-Identifier: MIT
// The Frenet frame and curvatures of a law curve as laws (continuous, exact;
// thesis 6.1 eq. 5, 11, 17 built symbolically), for later symbolic work
// (differentiation, roots, integration) and compiled evaluation. Where a
// quantity is undefined (κ = 0, r' = 0) its law evaluates to NaN, the law
// engine's "undefined".
#pragma once
#include <string_view>

#include "hula/law/expr.hpp"

namespace hula::diffgeom {

/// Frenet quantities as laws of the curve parameter.
struct FrenetLaws {
  law::Law tangent;               ///< T = normalize(r')
  law::Law normal;                ///< N = B × T
  law::Law binormal;              ///< B = normalize(r' × r'')
  law::Law speed;                 ///< |r'|
  law::Law curvature;             ///< κ = |r' × r''| / |r'|³
  law::Law torsion;               ///< τ = (r' × r'') · r''' / |r' × r''|²
  law::Law curvature_derivative;  ///< dκ/ds = (dκ/dt) / |r'|
};

/// Builds the Frenet laws of a 3-vector law curve (in the curve's context).
/// @param curve a 3-vector law (a 2-vector law: embed it with vec(x, y, 0) first)
/// @param parameter the curve parameter
/// @throws hula::Error(Errc::InvalidArgument) if the law is not a 3-vector
[[nodiscard]] FrenetLaws frenet_laws(const law::Law& curve, std::string_view parameter);

}  // namespace hula::diffgeom
