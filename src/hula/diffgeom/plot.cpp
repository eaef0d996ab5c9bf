// SPDX-License-Identifier: MIT
// Sampled curvature, radius, torsion, speed, log-curvature and log-torsion plots; see plot.hpp.
#include "hula/diffgeom/plot.hpp"

#include <array>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>

#include "hula/core/error.hpp"
#include "hula/core/nan.hpp"
#include "hula/nurbs/arc_length.hpp"

namespace hula::diffgeom {

namespace {
// dτ/ds from r' … r'''' (d[1] … d[4]) at a point with a defined frame; 0 where the numerator of
// dτ/dt = [(a' · r''' + a · r'''') |a|² − 2 (a · r''') (a · a')] / |a|⁴ (a = r' × r'', a' = r' × r''')
// is below its rounding noise, so a constant torsion gives exactly 0.
double torsion_derivative(const FrenetPoint& p, std::span<const Vec3, 5> d) {
  const Vec3 a = cross(d[1], d[2]);
  const Vec3 a1 = cross(d[1], d[3]);
  const double a2 = dot(a, a);
  const double first = (dot(a1, d[3]) + dot(a, d[4])) * a2;
  const double second = 2.0 * dot(a, d[3]) * dot(a, a1);
  const double noise =
      64.0 * 2.220446049250313e-16 * ((norm(a1) * norm(d[3]) + std::sqrt(a2) * norm(d[4])) * a2 + std::fabs(second));
  const double num = first - second;
  if (!(std::fabs(num) > noise)) return 0.0;
  return num / (a2 * a2) / p.speed;
}

// Fills x and y from the Frenet points, the arc lengths s and (LogTorsionGraph only) the derivatives
// r … r'''' of each sample (5 per point).
void assemble(const std::vector<FrenetPoint>& pts, const std::vector<double>& s, std::span<const Vec3> d5,
              const PlotOptions& options, Plot& out) {
  const std::size_t n = pts.size();
  out.x.resize(n);
  out.y.resize(n);
  out.defined.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const FrenetPoint& p = pts[i];
    out.x[i] = options.abscissa == PlotAbscissa::ArcLength ? s[i] : p.t;
    double y = kNaN;
    switch (options.quantity) {
      case PlotQuantity::Curvature:
        y = p.tangent_defined ? p.curvature : kNaN;
        break;
      case PlotQuantity::SignedCurvature:
        y = p.tangent_defined ? p.signed_curvature : kNaN;
        break;
      case PlotQuantity::Radius: {
        const double r = p.frame_defined ? 1.0 / p.curvature : kNaN;
        y = r <= options.radius_limit ? r : kNaN;
        break;
      }
      case PlotQuantity::Torsion:
        y = p.torsion_defined ? p.torsion : kNaN;
        break;
      case PlotQuantity::Speed:
        y = p.speed;
        break;
      case PlotQuantity::LogCurvatureGraph: {
        // x = log10 ρ, y = log10(κ / |dκ/ds|); undefined where κ = 0 or dκ/ds = 0.
        const bool ok = p.frame_defined && p.curvature_derivative != 0.0;
        out.x[i] = ok ? -std::log10(p.curvature) : kNaN;
        y = ok ? std::log10(p.curvature / std::fabs(p.curvature_derivative)) : kNaN;
        break;
      }
      case PlotQuantity::LogTorsionGraph: {
        // x = log10(1/|τ|), y = log10(|τ| / |dτ/ds|); undefined where τ = 0 or dτ/ds = 0.
        const double dtau = p.torsion_defined ? torsion_derivative(p, d5.subspan(5 * i).first<5>()) : 0.0;
        const bool ok = p.torsion_defined && p.torsion != 0.0 && dtau != 0.0;
        out.x[i] = ok ? -std::log10(std::fabs(p.torsion)) : kNaN;
        y = ok ? std::log10(std::fabs(p.torsion) / std::fabs(dtau)) : kNaN;
        break;
      }
    }
    if (options.log_scale && options.quantity != PlotQuantity::LogCurvatureGraph &&
        options.quantity != PlotQuantity::LogTorsionGraph)
      y = std::isfinite(y) && y != 0.0 ? std::log10(std::fabs(y)) : kNaN;
    out.y[i] = y;
    out.defined[i] = std::isfinite(y) && std::isfinite(out.x[i]) ? 1 : 0;
  }
}

std::vector<double> sample_parameters(nurbs::Interval d, int samples) {
  const auto n = static_cast<std::size_t>(samples);
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) t[i] = d.start + d.length() * static_cast<double>(i) / static_cast<double>(n - 1);
  t.back() = d.end;
  return t;
}
}  // namespace

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
  Plot out;
  out.t = sample_parameters(curve.domain(), options.samples);
  const std::size_t n = out.t.size();
  std::vector<FrenetPoint> pts(n);
  frenet(curve, out.t, pts, options.frenet);
  std::vector<double> s(n, 0.0);
  if (options.abscissa == PlotAbscissa::ArcLength)
    for (std::size_t i = 1; i < n; ++i) s[i] = s[i - 1] + nurbs::arc_length(curve, out.t[i - 1], out.t[i]);
  std::vector<Vec3> d5;
  if (options.quantity == PlotQuantity::LogTorsionGraph) {
    d5.resize(5 * n);
    curve.derivatives(out.t, 4, d5, options.frenet.eval);
  }
  assemble(pts, s, d5, options, out);
  return out;
}

Plot plot(const law::Law& curve, std::string_view parameter, nurbs::Interval domain, const PlotOptions& options) {
  options.validate();
  if (!curve.valid() || (curve.dimension() != 2 && curve.dimension() != 3))
    throw Error(Errc::InvalidArgument, "the curve law must be a 2- or 3-vector", {.field = "law"});
  const std::string name(parameter);
  const LawFrenet frenet(curve, name, domain, options.frenet);  // checks the domain
  const law::CurveEvaluator eval(curve, name, 4);
  Plot out;
  out.t = sample_parameters(domain, options.samples);
  const std::size_t n = out.t.size();
  std::vector<FrenetPoint> pts(n);
  std::vector<Vec3> d5(5 * n);
  eval.derivatives(out.t, d5);
  for (std::size_t i = 0; i < n; ++i)
    pts[i] = frenet_from_derivatives(out.t[i], std::span<const Vec3, 4>(d5.data() + 5 * i, 4), frenet.scale(),
                                     options.frenet);
  std::vector<double> s(n, 0.0);
  if (options.abscissa == PlotAbscissa::ArcLength) {
    // ∫ |r'| dt between samples by 8-point Gauss–Legendre (smooth laws: rounding-level per step), Boost.Math's
    // positive nodes and their weights.
    using Gauss8 = boost::math::quadrature::gauss<double, 8>;
    const auto& nodes = Gauss8::abscissa();
    const auto& weights = Gauss8::weights();
    std::array<Vec3, 5> d;
    auto speed = [&](double t) {
      eval.derivatives(t, d);
      return norm(d[1]);
    };
    for (std::size_t i = 1; i < n; ++i) {
      const double mid = 0.5 * (out.t[i - 1] + out.t[i]), half = 0.5 * (out.t[i] - out.t[i - 1]);
      double sum = 0.0;
      for (std::size_t k = 0; k < nodes.size(); ++k)
        sum += weights[k] * (speed(mid - half * nodes[k]) + speed(mid + half * nodes[k]));
      s[i] = s[i - 1] + half * sum;
    }
  }
  assemble(pts, s, d5, options, out);
  return out;
}

Plot plot(const curve::Curve& curve, const PlotOptions& options) {
  if (const law::Law* l = curve.law()) return plot(*l, curve.law_parameter(), curve.domain(), options);
  if (curve.natural_evaluator() == nullptr) return plot(curve.nurbs(), options);
  options.validate();
  const CurveFrenet frenet(curve, options.frenet);
  Plot out;
  out.t = sample_parameters(curve.domain(), options.samples);
  const std::size_t n = out.t.size();
  std::vector<FrenetPoint> pts(n);
  std::vector<Vec3> d5(5 * n);
  curve.derivatives(out.t, 4, d5, options.frenet.eval);
  for (std::size_t i = 0; i < n; ++i)
    pts[i] = frenet_from_derivatives(out.t[i], std::span<const Vec3, 4>(d5.data() + 5 * i, 4), frenet.scale(),
                                     options.frenet);
  // The parameter is the arc length from the start.
  std::vector<double> s(n);
  for (std::size_t i = 0; i < n; ++i) s[i] = out.t[i] - out.t.front();
  assemble(pts, s, d5, options, out);
  return out;
}

}  // namespace hula::diffgeom
