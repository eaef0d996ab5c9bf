// SPDX-License-Identifier: MIT
// Fairness energies of a curve (thesis eq. 30 and the curvature-variation
// energy): the bending energy ∫κ² ds and ∫(dκ/ds)² ds, integrated per knot span
// (where the integrand is smooth) with adaptive 15-point Gauss–Kronrod
// quadrature (Boost.Math) in the parameter: ∫ f(t) |r'(t)| dt.
#pragma once
#include "hula/diffgeom/frenet.hpp"

namespace hula::diffgeom {

/// Options of the energy integrals.
struct EnergyOptions {
  /// Relative tolerance of the quadrature (error estimate ≤ tolerance × ∫|f| ds). Default 1e-10.
  /// Valid: [1e-15, 1e-1].
  double relative_tolerance = 1e-10;
  /// Maximum bisection depth per knot span. Default 15. Valid: 1 … 30.
  int max_depth = 15;
  /// Frenet options (tolerances for the undefined tests). Default {}.
  FrenetOptions frenet{};
  /// Throws hula::Error(Errc::InvalidOption) naming the bad field.
  void validate() const;
};

/// An integral and how well it is known.
struct EnergyResult {
  double value = 0.0;           ///< the energy (1/model units for ∫κ² ds, 1/model units³ for ∫κ'² ds)
  double error_estimate = 0.0;  ///< summed Gauss–Kronrod error estimates
  bool converged = false;       ///< error_estimate ≤ relative_tolerance × value (or value = 0)
};

/// Bending energy ∫κ² ds over the whole curve. Points where κ is undefined (zero speed) contribute 0
/// (they have measure zero on a regular curve).
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] EnergyResult bending_energy(const nurbs::NurbsCurve& curve, const EnergyOptions& options = {});

/// Curvature-variation energy ∫(dκ/ds)² ds. Where the frame is undefined (κ = 0 on a straight span,
/// a single inflection point) the integrand is taken as 0.
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] EnergyResult curvature_variation_energy(const nurbs::NurbsCurve& curve,
                                                      const EnergyOptions& options = {});

}  // namespace hula::diffgeom
