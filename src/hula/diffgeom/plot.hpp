// SPDX-License-Identifier: MIT
// Curvature plots (thesis 6.3.1): κ, signed κ, radius of curvature (range
// limited), τ and speed |r'(t)| sampled against the parameter or the arc
// length, optionally as log10|q|, and the logarithmic curvature graph of
// log-aesthetic analysis (Yoshida & Saito 2006): x = log10 ρ,
// y = log10 |ρ ds/dρ| = log10 (κ / |dκ/ds|), a straight line for a
// log-aesthetic curve (slope α).
#pragma once
#include <cstdint>
#include <limits>
#include <string_view>
#include <vector>

#include "hula/diffgeom/frenet.hpp"

namespace hula::diffgeom {

/// What is plotted.
enum class PlotQuantity {
  Curvature,          ///< κ ≥ 0
  SignedCurvature,    ///< κ_s about FrenetOptions::plane_normal
  Radius,             ///< ρ = 1/κ, undefined (NaN) where ρ > PlotOptions::radius_limit or κ = 0
  Torsion,            ///< τ
  Speed,              ///< |r'(t)|
  LogCurvatureGraph,  ///< x = log10 ρ, y = log10(κ/|dκ/ds|) (abscissa option ignored)
  /// Logarithmic torsion graph: x = log10(1/|τ|), y = log10(|τ|/|dτ/ds|) (abscissa option ignored);
  /// undefined where τ = 0 or dτ/ds = 0 (a helix: everywhere)
  LogTorsionGraph,
};

/// Against what.
enum class PlotAbscissa {
  Parameter,  ///< t
  ArcLength,  ///< s from the domain start (nurbs::arc_length between samples)
};

/// Options of plot().
struct PlotOptions {
  PlotQuantity quantity = PlotQuantity::Curvature;  ///< default κ
  PlotAbscissa abscissa = PlotAbscissa::Parameter;  ///< default t
  /// Samples, equally spaced in t, ends included. Default 400. Valid: 2 … 1000000.
  int samples = 400;
  /// Largest radius shown; larger radii (nearly straight pieces) are NaN. Default +inf. Valid: > 0.
  double radius_limit = std::numeric_limits<double>::infinity();
  /// Plot log10|q| instead of q (q = 0 becomes NaN). Ignored by LogCurvatureGraph. Default false.
  bool log_scale = false;
  /// Frenet options. Default {}.
  FrenetOptions frenet{};
  /// Throws hula::Error(Errc::InvalidOption) naming the bad field.
  void validate() const;
};

/// Sampled graph; NaN y (defined[i] = 0) where the quantity is undefined.
struct Plot {
  std::vector<double> t;              ///< parameters of the samples
  std::vector<double> x;              ///< abscissae
  std::vector<double> y;              ///< values
  std::vector<std::uint8_t> defined;  ///< 1 where y is a number
};

/// Samples a plot of a NURBS curve.
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] Plot plot(const nurbs::NurbsCurve& curve, const PlotOptions& options = {});

/// Samples a plot of a law curve on [domain.start, domain.end] (arc length by Gauss–Legendre
/// quadrature of |r'| between samples).
/// @param curve a 2- or 3-vector law of `parameter`
/// @throws hula::Error(Errc::InvalidArgument) naming "law" for a scalar law or "domain" for a bad domain
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] Plot plot(const law::Law& curve, std::string_view parameter, nurbs::Interval domain,
                        const PlotOptions& options = {});

/// Samples a plot of a curve value on its domain from its exact form: the law of a law curve (as the
/// law overload), the natural evaluator of a natural curve (the arc length is the parameter; κ, κ', τ
/// and τ' are the laws' values, so a log-aesthetic curve's LogCurvatureGraph is a straight line of its
/// slope α to rounding), else its NURBS.
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] Plot plot(const curve::Curve& curve, const PlotOptions& options = {});
}  // namespace hula::diffgeom
