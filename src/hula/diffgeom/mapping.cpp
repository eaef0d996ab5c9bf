// SPDX-License-Identifier: MIT
// K-orthotomics and polar maps; see mapping.hpp.
#include "hula/diffgeom/mapping.hpp"

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/diffgeom/detail/derived_curve.hpp"
#include "hula/law/derive.hpp"

namespace hula::diffgeom {

namespace {

void check_finite(const Vec3& v, const char* field) {
  if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)))
    throw Error(Errc::InvalidArgument, std::string(field) + " must be finite", {.field = field});
}

MappedCurve mapped(const law::Law& l, const detail::ParentLaw& p, const curve::Curve& c, double tolerance,
                   const char* field, const std::string& what, const std::string& why) {
  try {
    // Both maps take the first derivative of a NURBS: fit span by span where that leaves less than C2.
    detail::DerivedCurve d =
        detail::derived_curve(l, p, true, c.domain(), tolerance,
                              p.printable ? std::vector<double>{} : detail::low_continuity_knots(c.nurbs(), 1));
    return {std::move(d.curve), d.exact, d.deviation};
  } catch (const Error&) {
    detail::rethrow_undefined(field, what, why);
  }
}

}  // namespace

void MappingOptions::validate() const {
  if (!(tolerance >= 1e-12 && tolerance <= 1e-2))
    throw Error(Errc::InvalidOption, "tolerance = " + format_number(tolerance) + " must lie in [1e-12, 1e-2]",
                {.field = "tolerance"});
}

law::Law orthotomic_law(const law::Law& curve, std::string_view parameter, const Vec3& pole, double k) {
  if (!curve.valid() || curve.dimension() == 1)
    throw Error(Errc::InvalidArgument, "an orthotomic needs a 2- or 3-vector law, got a scalar", {.field = "law"});
  const law::Law P = curve.context().constant(pole, curve.dimension());
  const law::Law w = curve - P;
  const law::Law t = law::normalize(law::derivative(curve, parameter));
  return P + k * (w - law::dot(w, t) * t);
}

law::Law polar_law(const law::Law& curve, std::string_view parameter, const Vec3& centre, double radius) {
  if (!curve.valid() || curve.dimension() == 1)
    throw Error(Errc::InvalidArgument, "a polar map needs a 2- or 3-vector law, got a scalar", {.field = "law"});
  const law::Law x = law::term(curve, 1) - centre.x;
  const law::Law y = law::term(curve, 2) - centre.y;
  const law::Law dx = law::derivative(law::term(curve, 1), parameter);
  const law::Law dy = law::derivative(law::term(curve, 2), parameter);
  // n = (−y', x') / |C'|, h = (C − P)·n; Q = P + ρ² n / h = P + ρ² (−y', x') / (x'(y − Py) − y'(x − Px)):
  // the speeds cancel, so Q is rational in the derivatives.
  const law::Law h = dx * y - dy * x;
  const double r2 = radius * radius;
  // A 3-D curve at constant z maps into its own plane.
  if (curve.dimension() == 3) return law::vec(centre.x + r2 * (-dy) / h, centre.y + r2 * dx / h, law::term(curve, 3));
  return law::vec(centre.x + r2 * (-dy) / h, centre.y + r2 * dx / h);
}

MappedCurve orthotomic(const curve::Curve& curve, const Vec3& pole, double k, const MappingOptions& options) {
  options.validate();
  check_finite(pole, "pole");
  if (!(std::isfinite(k) && k != 0.0))
    throw Error(Errc::InvalidArgument, "k = " + format_number(k) + " must be finite and non-zero", {.field = "k"});
  const detail::ParentLaw p = detail::parent_law(curve);
  const law::Law r = detail::plane_law(p, curve);
  const Vec3 P = curve.dimension() == 2 ? Vec3{pole.x, pole.y, 0.0} : pole;
  return mapped(orthotomic_law(r, p.parameter, P, k), p, curve, options.tolerance, "curve", "the orthotomic",
                " (C' = 0 there)");
}

MappedCurve polar_map(const curve::Curve& curve, const Vec3& centre, double radius, const MappingOptions& options) {
  options.validate();
  detail::require_xy_plane(curve, "a polar map");
  check_finite(centre, "centre");
  if (!(std::isfinite(radius) && radius > 0.0))
    throw Error(Errc::InvalidArgument, "radius = " + format_number(radius) + " must be positive and finite",
                {.field = "radius"});
  const detail::ParentLaw p = detail::parent_law(curve);
  return mapped(polar_law(detail::plane_law(p, curve), p.parameter, centre, radius), p, curve, options.tolerance,
                "centre", "the polar map", " (a tangent line passes through the centre there)");
}

}  // namespace hula::diffgeom
