// SPDX-License-Identifier: MIT
// Pieces of monotone curvature between curvature extrema (see the header).
#include "hula/diffgeom/monotonicity.hpp"

#include <algorithm>
#include <cmath>

namespace hula::diffgeom {

std::string_view curvature_trend_name(CurvatureTrend trend) noexcept {
  switch (trend) {
    case CurvatureTrend::Increasing:
      return "increasing";
    case CurvatureTrend::Decreasing:
      return "decreasing";
    case CurvatureTrend::Constant:
      return "constant";
  }
  return "constant";
}

CurvatureMonotonicity curvature_monotonicity(const curve::Curve& curve, bool planar, const FeatureOptions& options) {
  const std::vector<Feature> extrema = curvature_extrema(curve, options);
  const std::vector<Feature> zeros = planar ? inflections(curve, options) : std::vector<Feature>{};
  return curvature_monotonicity(curve, planar, extrema, zeros, options);
}

CurvatureMonotonicity curvature_monotonicity(const curve::Curve& curve, bool planar, std::span<const Feature> extrema,
                                             std::span<const Feature> zeros, const FeatureOptions& options) {
  const auto dom = curve.domain();
  // Extrema and inflections are each located to the parameter resolution of their own search: within a
  // sample step of the bracketing grid they are the same point.
  const double near = dom.length() / (64.0 * options.samples_per_span);
  CurvatureMonotonicity result;
  for (const Feature& f : extrema) {
    // An extremum of |κ| at an inflection is where the signed curvature of a planar curve passes through
    // zero: not a turn of the signed curvature.
    const bool at_inflection =
        f.kind == FeatureKind::CurvatureMinimum &&
        std::any_of(zeros.begin(), zeros.end(), [&](const Feature& z) { return std::abs(z.t - f.t) <= near; });
    if (!at_inflection) result.violations.push_back(f);
  }
  std::vector<double> cuts{dom.start};
  for (const Feature& f : result.violations) cuts.push_back(f.t);
  cuts.push_back(dom.end);
  std::vector<FrenetPoint> frames(cuts.size());
  frenet(curve, cuts, frames, options.frenet);
  const auto kappa = [&](std::size_t i) { return planar ? frames[i].signed_curvature : frames[i].curvature; };
  double scale = 0.0;
  for (std::size_t i = 0; i < cuts.size(); ++i)
    if (std::isfinite(kappa(i))) scale = std::max(scale, std::abs(kappa(i)));
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    MonotonePiece p{cuts[i], cuts[i + 1], kappa(i), kappa(i + 1), CurvatureTrend::Constant};
    const double change = p.kappa1 - p.kappa0;
    if (std::abs(change) > 1e-12 * scale)
      p.trend = change > 0.0 ? CurvatureTrend::Increasing : CurvatureTrend::Decreasing;
    result.pieces.push_back(p);
  }
  return result;
}

}  // namespace hula::diffgeom
