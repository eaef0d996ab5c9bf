// SPDX-License-Identifier: MIT
// fit_scan: ordering, noise estimate, the tolerance fit with stray rejection and
// fairing (see scan_fit.hpp for the method).
#include "hula/studies/scan_fit.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "hula/core/error.hpp"
#include "hula/diffgeom/energy.hpp"
#include "hula/diffgeom/features.hpp"
#include "hula/studies/tolerance_fit.hpp"

namespace hula::studies {

void ScanFitOptions::validate() const {
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
    throw Error(Errc::InvalidOption, "tolerance must be > 0 and finite, got " + std::to_string(tolerance),
                ErrorWhere{.field = "tolerance"});
  if (degree < 3 || degree > 9)
    throw Error(Errc::InvalidOption, "degree must be in [3, 9], got " + std::to_string(degree),
                ErrorWhere{.field = "degree"});
  if (min_degree < 3 || min_degree > degree)
    throw Error(Errc::InvalidOption,
                "min_degree must be in [3, degree = " + std::to_string(degree) + "], got " + std::to_string(min_degree),
                ErrorWhere{.field = "min_degree"});
  if (max_control_points < static_cast<std::size_t>(degree) + 1)
    throw Error(Errc::InvalidOption,
                "max_control_points must be at least degree + 1, got " + std::to_string(max_control_points),
                ErrorWhere{.field = "max_control_points"});
  ToleranceFitOptions{.tolerance = tolerance, .end_check = end_check}.validate();
  order.validate();
}

namespace {

// Where the points are dense, the curve follows them to max(kBiasNoise σ̂, kBiasFloor tol) (no
// systematic deviation beyond the noise: the curve is the scanned shape, not merely a curve within
// the tolerance), and the fairing moves it by at most max(kShiftNoise σ̂, kShiftFloor tol): beyond
// the noise the points say where the curve is, and smoothness may not overrule them. Together
// with the fit's own error (σ̂ / √15 over a window) this keeps the curve within 3 σ of the scanned
// shape. The floors are for exact data (σ̂ ≈ 0: an airfoil's design points); they are low enough that a
// quiet scan (σ = 0.01 × tolerance) stays within 3 σ too: 0.05 and 0.03 let it stray to 3.7 σ.
constexpr double kBiasNoise = 1.5;
constexpr double kBiasFloor = 0.015;
constexpr double kShiftNoise = 1.0;
constexpr double kShiftFloor = 0.01;

ScanCurveReport report(const nurbs::NurbsCurve& curve, std::span<const double> dist,
                       std::span<const std::size_t> kept) {
  ScanCurveReport r;
  double sum = 0.0;
  for (const std::size_t i : kept) {
    r.max_deviation = std::max(r.max_deviation, dist[i]);
    sum += dist[i];
  }
  r.mean_deviation = kept.empty() ? 0.0 : sum / static_cast<double>(kept.size());
  r.control_points = curve.control_points().size();
  r.inflections = diffgeom::inflections(curve).size();
  r.curvature_extrema = diffgeom::curvature_extrema(curve).size();
  r.curvature_variation = diffgeom::curvature_variation_energy(curve).value;
  r.bending = diffgeom::bending_energy(curve).value;
  return r;
}

}  // namespace

ScanFitResult fit_scan(std::span<const Vec3> points, const ScanFitOptions& options) {
  options.validate();
  const std::size_t m = points.size();
  if (m < 10)
    throw Error(Errc::TooFewPoints, "a scan fit needs at least 10 points, got " + std::to_string(m),
                ErrorWhere{.field = "points"});
  for (std::size_t i = 0; i < m; ++i)
    if (!is_finite(points[i]))
      throw Error(Errc::NonFiniteInput, "point " + std::to_string(i) + " is not finite",
                  ErrorWhere{.field = "points", .index = i});

  // Stages 1 and 2: order, starting parameters, closedness, noise.
  const CurveOrder order = order_points(points, options.ordered, options.order);
  std::vector<std::uint8_t> left_out(m, 0);
  for (const std::size_t i : order.suspects) left_out[i] = 1;

  // Stage 3: the tolerance fit with strays left out, then fairing.
  ToleranceFitOptions o;
  o.tolerance = options.tolerance;
  o.degree = options.degree;
  o.min_degree = options.min_degree;
  o.closed = order.closed;
  o.max_control_points = options.max_control_points;
  o.reject_outliers = true;
  o.noise = order.noise;
  o.end_check = options.end_check;
  o.fair = options.fair;
  o.bias_limit = std::max(kBiasNoise * order.noise, kBiasFloor * options.tolerance);
  o.fairing_shift = std::min(options.tolerance, std::max(kShiftNoise * order.noise, kShiftFloor * options.tolerance));
  std::size_t generations = 0;  // the candidates reported, so that the result comes after them
  if (options.on_generation)
    o.on_generation = [&](const optim::GenerationLog& g) {
      generations = g.generation + 1;
      options.on_generation(g);
    };
  ToleranceFit fit = fit_within_tolerance(points, order.parameters, left_out, o);

  nurbs::NurbsCurve faired = fit.faired;
  double smoothing = fit.smoothing;
  std::vector<double> deviations = fit.deviations, parameters = fit.parameters;
  // The penalty is ∫|C‴|² dt, not ∫κ'² ds itself: when the faired curve's ∫κ'² ds is not below the
  // tolerance fit's, the tolerance fit is returned as faired.
  const double fit_variation = diffgeom::curvature_variation_energy(fit.fit).value;
  if (diffgeom::curvature_variation_energy(fit.faired).value > fit_variation) {
    faired = fit.fit;
    smoothing = 0.0;
    deviations = fit.fit_deviations;
    parameters = fit.fit_parameters;
  }
  // A stray is a point farther than the tolerance from the curve returned: one left out during the fit
  // that the faired curve passes within the tolerance is kept (the tolerance fit before fairing may
  // pass it a little farther: its figures in `before` are over the same kept points).
  std::vector<std::size_t> kept, strays;
  for (std::size_t i = 0, k = 0; i < m; ++i) {
    if (k < fit.outliers.size() && fit.outliers[k] == i) {
      ++k;
      if (deviations[i] > options.tolerance) {
        strays.push_back(i);
        continue;
      }
    }
    kept.push_back(i);
  }
  const ScanCurveReport before = report(fit.fit, fit.fit_deviations, kept);
  const ScanCurveReport after = smoothing == 0.0 && faired == fit.fit ? before : report(faired, deviations, kept);
  std::vector<std::size_t> along = kept;
  std::stable_sort(along.begin(), along.end(),
                   [&](std::size_t a, std::size_t b) { return parameters[a] < parameters[b]; });
  ScanFitResult result{.fit = fit.fit,
                       .faired = std::move(faired),
                       .strays = std::move(strays),
                       .order = std::move(along),
                       .parameters = std::move(parameters),
                       .deviations = std::move(deviations),
                       .noise_scale = order.noise,
                       .biweight_scale = options.tolerance,
                       .ordering = order.source,
                       .closed = order.closed,
                       .smoothing = smoothing,
                       .fits = fit.fits,
                       .before = before,
                       .after = after};
  if (options.on_generation) options.on_generation(fit_progress(generations, result.fits, after.max_deviation));
  return result;
}

}  // namespace hula::studies
