// SPDX-License-Identifier: MIT
// Symbolic Frenet quantities; see frenet_law.hpp.
#include "hula/diffgeom/frenet_law.hpp"

#include "hula/core/error.hpp"
#include "hula/law/derive.hpp"

namespace hula::diffgeom {

FrenetLaws frenet_laws(const law::Law& curve, std::string_view parameter) {
  if (curve.dimension() != 3)
    throw Error(Errc::InvalidArgument,
                "frenet_laws needs a 3-vector law, got dimension " + std::to_string(curve.dimension()),
                {.field = "law"});
  const law::Law d1 = law::derivative(curve, parameter, 1);
  const law::Law d2 = law::derivative(curve, parameter, 2);
  const law::Law d3 = law::derivative(curve, parameter, 3);
  const law::Law a = law::cross(d1, d2);
  FrenetLaws f;
  f.speed = law::norm(d1);
  f.tangent = law::normalize(d1);
  f.binormal = law::normalize(a);
  f.normal = law::cross(f.binormal, f.tangent);
  f.curvature = law::norm(a) / law::pow(f.speed, 3.0);
  f.torsion = law::dot(a, d3) / law::dot(a, a);
  f.curvature_derivative = law::derivative(f.curvature, parameter) / f.speed;
  return f;
}

}  // namespace hula::diffgeom
