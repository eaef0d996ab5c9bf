// SPDX-License-Identifier: MIT
// Log-aesthetic curves (Yoshida & Saito, "Interactive aesthetic curve segments",
// The Visual Computer 22, 2006): planar curves whose logarithmic curvature graph
// log(ρ ds/dρ) against log ρ is a straight line of slope α. Integrating
// ρ ds/dρ = ρ^α / λ from the radius ρ0 at s = 0 gives the radius of curvature in
// closed form,
//     ρ(s)^α = ρ0^α + α λ s   (α ≠ 0),      ρ(s) = ρ0 e^{λ s}   (α = 0),
// so κ(s) = 1/ρ(s) is an exact law of s: α = −1 is the clothoid (κ linear in s),
// α = 1 the logarithmic spiral (ρ linear in s), α = 2 the circle involute, α = 0
// the exponential-radius spiral. For λ ≠ 0 the radius, hence
// the curvature, is strictly monotone: the curves' defining aesthetic property,
// checked by curvature_monotonicity() in diffgeom and by the property tests.
#pragma once

#include <string_view>

#include "hula/curve/curve.hpp"
#include "hula/intrinsic/natural_equations.hpp"
#include "hula/law/expr.hpp"

namespace hula::intrinsic {

/// A log-aesthetic curve segment of slope α (see the file comment).
struct LogAestheticCurve {
  /// Slope α of the logarithmic curvature graph (any finite value).
  double alpha = -1.0;
  /// Radius of curvature ρ0 > 0 at s = 0, model units.
  double rho0 = 1.0;
  /// Rate λ (1 / model units^α): ρ grows with s for λ > 0, shrinks for λ < 0, and λ = 0 is the circle.
  double lambda = 0.1;
  /// Length L > 0, model units; ρ must stay positive and finite on [0, L] (see max_length()).
  double length = 1.0;

  /// ρ(s) in closed form; +∞ or NaN past the end of the family's domain (see max_length()).
  [[nodiscard]] double radius(double s) const noexcept;
  /// κ(s) = 1 / ρ(s).
  [[nodiscard]] double curvature(double s) const noexcept;
  /// dκ/ds = −λ ρ^{−1−α}: the sign of −λ everywhere (monotone curvature).
  [[nodiscard]] double curvature_rate(double s) const noexcept;
  /// The largest length for which ρ stays positive and finite: −ρ0^α / (α λ) when α λ < 0, else +∞.
  [[nodiscard]] double max_length() const noexcept;
  /// κ(s) as a law of `parameter`: pow(ρ0^α + α λ s, −1/α), or e^{−λ s} / ρ0 for α = 0.
  [[nodiscard]] law::Law curvature_law(const law::Context& context, std::string_view parameter = "s") const;
  /// The curve from `start` (κ > 0 turns towards start.normal), by reconstruct_planar.
  /// @throws hula::Error(Errc::InvalidArgument) naming "rho0", "length" or "alpha" when ρ0 ≤ 0,
  ///   L ≤ 0 or L ≥ max_length(); Errc::NonFiniteInput naming the field for NaN/inf
  [[nodiscard]] IntrinsicCurve to_intrinsic(const StartFrame& start = {},
                                            const ReconstructionOptions& options = {}) const;
  /// Checks the parameters as to_intrinsic() does.
  void validate() const;
  /// The curve as natural-equation data (a curve file stores it by its law): κ = curvature_law() printed
  /// exactly (17 significant digits), τ = 0, length L, the start frame, the integration tolerance.
  /// intrinsic::natural_curve() makes the exact curve value of it.
  /// @param tolerance position tolerance of the integration, model units (NaturalData::tolerance)
  /// @throws as validate()
  [[nodiscard]] curve::NaturalData natural_data(const StartFrame& start = {},
                                                double tolerance = curve::kNaturalTolerance) const;
};

}  // namespace hula::intrinsic
