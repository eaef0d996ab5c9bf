// SPDX-License-Identifier: MIT
// Sampled curvature, radius, torsion, speed and log-curvature plots; see plot.hpp.
#include "hula/diffgeom/plot.hpp"

#include <cmath>

#include "hula/core/error.hpp"
#include "hula/nurbs/arc_length.hpp"

namespace hula::diffgeom {

void PlotOptions::validate() const {
  frenet.validate();
  if (samples < 2 || samples > 1000000)
    throw Error(Errc::InvalidOption, "samples = " + std::to_string(samples) + " must be in [2, 1000000]",
                {.field = "samples"});
  if (!(radius_limit > 0.0))
    throw Error(Errc::InvalidOption, "radius_limit = " + format_number(radius_limit) + " must be > 0",
                {.field = "radius_limit"});
}

Plot plot(const nurbs::NurbsCurve& curve, const PlotOptions& options) {
  options.validate();
  const nurbs::Interval d = curve.domain();
  const auto n = static_cast<std::size_t>(options.samples);
  Plot out;
  out.t.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    out.t[i] = d.start + d.length() * static_cast<double>(i) / static_cast<double>(n - 1);
  out.t.back() = d.end;
  std::vector<FrenetPoint> pts(n);
  frenet(curve, out.t, pts, options.frenet);
  out.x.resize(n);
  out.y.resize(n);
  out.defined.assign(n, 0);
  const double nan = std::nan("");
  double s = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const FrenetPoint& p = pts[i];
    if (i > 0 && options.abscissa == PlotAbscissa::ArcLength) s += nurbs::arc_length(curve, out.t[i - 1], out.t[i]);
    out.x[i] = options.abscissa == PlotAbscissa::ArcLength ? s : p.t;
    double y = nan;
    switch (options.quantity) {
      case PlotQuantity::Curvature:
        y = p.tangent_defined ? p.curvature : nan;
        break;
      case PlotQuantity::SignedCurvature:
        y = p.tangent_defined ? p.signed_curvature : nan;
        break;
      case PlotQuantity::Radius: {
        const double r = p.frame_defined ? 1.0 / p.curvature : nan;
        y = r <= options.radius_limit ? r : nan;
        break;
      }
      case PlotQuantity::Torsion:
        y = p.torsion_defined ? p.torsion : nan;
        break;
      case PlotQuantity::Speed:
        y = p.speed;
        break;
      case PlotQuantity::LogCurvatureGraph: {
        // x = log10 ρ, y = log10(κ / |dκ/ds|); undefined where κ = 0 or dκ/ds = 0.
        const bool ok = p.frame_defined && p.curvature_derivative != 0.0;
        out.x[i] = ok ? -std::log10(p.curvature) : nan;
        y = ok ? std::log10(p.curvature / std::fabs(p.curvature_derivative)) : nan;
        break;
      }
    }
    if (options.log_scale && options.quantity != PlotQuantity::LogCurvatureGraph)
      y = std::isfinite(y) && y != 0.0 ? std::log10(std::fabs(y)) : nan;
    out.y[i] = y;
    out.defined[i] = std::isfinite(y) && std::isfinite(out.x[i]) ? 1 : 0;
  }
  return out;
}

}  // namespace hula::diffgeom
