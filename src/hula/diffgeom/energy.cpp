// SPDX-License-Identifier: MIT
// Energies by per-span adaptive Gauss–Kronrod; see energy.hpp.
#include "hula/diffgeom/energy.hpp"

#include <array>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>

#include "hula/core/error.hpp"

namespace hula::diffgeom {

namespace {
template <class F>
EnergyResult integrate_over_spans(const nurbs::NurbsCurve& curve, const EnergyOptions& options, F integrand) {
  options.validate();
  const FrenetScale scale = frenet_scale(curve, options.frenet.tolerance);
  nurbs::EvalOptions inside;  // quadrature nodes are interior to the span; Right side is harmless
  auto g = [&](double t) {
    std::array<Vec3, 4> d;
    curve.derivatives(t, 3, d, inside);
    const FrenetPoint p = frenet_from_derivatives(t, d, scale, options.frenet);
    const double f = integrand(p);
    return std::isfinite(f) ? f * p.speed : 0.0;
  };
  using Rule = boost::math::quadrature::gauss_kronrod<double, 15>;
  const std::vector<double> bp = curve.knots().breakpoints();
  EnergyResult r;
  double l1 = 0.0;
  for (std::size_t i = 0; i + 1 < bp.size(); ++i) {
    double err = 0.0, abs = 0.0;
    r.value += Rule::integrate(g, bp[i], bp[i + 1], static_cast<unsigned>(options.max_depth),
                               options.relative_tolerance, &err, &abs);
    r.error_estimate += err;
    l1 += abs;
  }
  r.converged = r.error_estimate <= options.relative_tolerance * l1 || l1 == 0.0;
  return r;
}
}  // namespace

void EnergyOptions::validate() const {
  frenet.validate();
  if (!(relative_tolerance >= 1e-15 && relative_tolerance <= 1e-1))
    throw Error(Errc::InvalidOption,
                "relative_tolerance = " + format_number(relative_tolerance) + " must be in [1e-15, 0.1]",
                {.field = "relative_tolerance"});
  if (max_depth < 1 || max_depth > 30)
    throw Error(Errc::InvalidOption, "max_depth = " + std::to_string(max_depth) + " must be in [1, 30]",
                {.field = "max_depth"});
}

EnergyResult bending_energy(const nurbs::NurbsCurve& curve, const EnergyOptions& options) {
  return integrate_over_spans(curve, options, [](const FrenetPoint& p) { return p.curvature * p.curvature; });
}

EnergyResult curvature_variation_energy(const nurbs::NurbsCurve& curve, const EnergyOptions& options) {
  return integrate_over_spans(curve, options, [](const FrenetPoint& p) {
    return p.frame_defined ? p.curvature_derivative * p.curvature_derivative : 0.0;
  });
}

}  // namespace hula::diffgeom
