// SPDX-License-Identifier: MIT
// The Combescure transform (thesis 8.3, eq. 38–44): the compound curve
// Q = P + C (τ/κ T + B) moves each point of P in its rectifying plane; Q has the
// same T, N, B directions as P and the same ratio τ/κ, so the inverse is
// P = Q − C (τ_Q/κ_Q T_Q + B_Q) computed from Q's own Frenet frame (assuming
// the transform preserves the orientation, ds_Q/ds = 1 + a' > 0 with a = Cτ/κ).
// Undefined where κ = 0 (the fraction of eq. 44) and on planar pieces (τ = 0:
// Q is only P shifted along ±B, and B flips at inflections).
#pragma once
#include <string_view>

#include "hula/diffgeom/frenet.hpp"
#include "hula/law/expr.hpp"

namespace hula::diffgeom {

/// One transformed point.
struct CombescurePoint {
  Vec3 point{};                        ///< Q (forward) or P (inverse); NaN where undefined
  bool defined = false;                ///< false where κ = 0, at zero speed, or where the curve is planar
  Undefined reason = Undefined::None;  ///< the FrenetPoint reason, or ZeroCurvature for a planar point
};

/// Q = P + C (τ/κ T + B) at one Frenet point.
/// @param p the Frenet quantities of P at t
/// @param c the constant C (model units), finite
/// @param angular a point is planar (undefined) when |τ| ≤ angular · κ; default Tolerance{}.angular
/// @returns the point, undefined (NaN) where the frame is undefined or the point is planar
/// @throws hula::Error(Errc::InvalidArgument) if c or angular is not finite
[[nodiscard]] CombescurePoint combescure(const FrenetPoint& p, double c, double angular = Tolerance{}.angular);

/// The inverse P = Q − C (τ_Q/κ_Q T_Q + B_Q) from the Frenet quantities of Q. Same rules as combescure.
[[nodiscard]] CombescurePoint combescure_inverse(const FrenetPoint& q, double c, double angular = Tolerance{}.angular);

/// The transform as an exact law of the same parameter (built in the curve's context):
/// P + c · ((r' × r'') · r''' |r'|³ / |r' × r''|³ · normalize(r') + normalize(r' × r'')), which
/// evaluates to NaN where κ = 0.
/// @throws hula::Error(Errc::InvalidArgument) if the law is not a 3-vector or c is not finite
[[nodiscard]] law::Law combescure_law(const law::Law& curve, std::string_view parameter, double c);

}  // namespace hula::diffgeom
