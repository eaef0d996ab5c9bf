// SPDX-License-Identifier: MIT
// Combescure transform (thesis 8.3, eq. 44); see combescure.hpp.
#include "hula/diffgeom/combescure.hpp"

#include <cmath>
#include <limits>

#include "hula/core/error.hpp"
#include "hula/law/derive.hpp"

namespace hula::diffgeom {

namespace {
CombescurePoint shift(const FrenetPoint& p, double c, double angular, double sign) {
  if (!std::isfinite(c))
    throw Error(Errc::InvalidArgument, "C = " + format_number(c) + " must be finite", {.field = "c"});
  if (!(std::isfinite(angular) && angular > 0.0))
    throw Error(Errc::InvalidArgument, "angular = " + format_number(angular) + " must be finite and > 0",
                {.field = "angular"});
  CombescurePoint r;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  r.point = Vec3{nan, nan, nan};
  if (!p.frame_defined) {
    r.reason = p.reason;
    return r;
  }
  if (!(std::fabs(p.torsion) > angular * p.curvature)) {
    r.reason = Undefined::ZeroCurvature;  // planar point: see the file comment
    return r;
  }
  r.point = p.position + (p.tangent * (p.torsion / p.curvature) + p.binormal) * (sign * c);
  r.defined = true;
  return r;
}
}  // namespace

CombescurePoint combescure(const FrenetPoint& p, double c, double angular) { return shift(p, c, angular, 1.0); }

CombescurePoint combescure_inverse(const FrenetPoint& q, double c, double angular) {
  return shift(q, c, angular, -1.0);
}

law::Law combescure_law(const law::Law& curve, std::string_view parameter, double c) {
  if (curve.dimension() != 3)
    throw Error(Errc::InvalidArgument, "the Combescure transform needs a 3-vector law", {.field = "law"});
  if (!std::isfinite(c))
    throw Error(Errc::InvalidArgument, "C = " + format_number(c) + " must be finite", {.field = "c"});
  const law::Law d1 = law::derivative(curve, parameter, 1);
  const law::Law d2 = law::derivative(curve, parameter, 2);
  const law::Law d3 = law::derivative(curve, parameter, 3);
  const law::Law a = law::cross(d1, d2);
  // τ/κ = [(a · r''')/|a|²] / [|a|/|r'|³] = (a · r''') |r'|³ / |a|³.
  const law::Law ratio = law::dot(a, d3) * law::pow(law::norm(d1), 3.0) / law::pow(law::norm(a), 3.0);
  return curve + c * (ratio * law::normalize(d1) + law::normalize(a));
}

}  // namespace hula::diffgeom
