// SPDX-License-Identifier: MIT
// Parametric (C0–C3) and geometric (G1–G3) continuity at the knots of a NURBS
// curve and at the join of two curves, with the left/right derivative table of
// thesis Table 3 (7.1.2): C^(k) from below and from above for k = 0 … 3.
//
// Tests (all scale-relative, see ContinuityOptions):
//   Ck:  |C_L^(k) − C_R^(k)| ≤ ε · max(|C_L^(k)|, |C_R^(k)|, size / Δt^k) for every j ≤ k;
//   G1:  C0 and the unit tangents agree: |T_L − T_R| ≤ ε;
//   G2:  G1 and the curvature vectors κN agree: |κ_L N_L − κ_R N_R| ≤ ε · max(κ_L, κ_R, 1/size);
//   G3:  G2 and τ and dκ/ds agree to the same relative ε (Frenet-frame continuity).
#pragma once
#include <array>
#include <vector>

#include "hula/diffgeom/frenet.hpp"

namespace hula::diffgeom {

/// Options of the continuity tests.
struct ContinuityOptions {
  /// Relative tolerance ε of every comparison (see the file comment). Default 1e-9: far above the
  /// rounding of derivatives of a cubic (≈ 1e-13), far below any visible kink. Valid: (0, 1).
  double relative_tolerance = 1e-9;
  /// Resolutions for the Frenet quantities (zero speed, zero curvature). Default Tolerance{}.
  Tolerance tolerance{};
  /// Throws hula::Error(Errc::InvalidOption) naming the bad field.
  void validate() const;
};

/// The continuity at one knot or join, with the derivative table.
struct Continuity {
  double t = 0.0;                ///< the knot value (for a join: the end parameter of the first curve)
  int multiplicity = 0;          ///< knot multiplicity (0 for a join)
  std::array<Vec3, 4> left{};    ///< C, C', C'', C''' from below (Table 3 "left")
  std::array<Vec3, 4> right{};   ///< C, C', C'', C''' from above (Table 3 "right")
  int parametric = -1;           ///< largest k ≤ 3 with Ck (−1: not even C0)
  int geometric = -1;            ///< largest k ≤ 3 with Gk (G0 = C0; −1: not even C0)
  double tangent_angle = 0.0;    ///< angle between the one-sided tangents (radians; NaN if a side has zero speed)
  double curvature_left = 0.0;   ///< κ from below (NaN at zero speed)
  double curvature_right = 0.0;  ///< κ from above
};

/// Continuity at every interior breakpoint of the curve, in increasing order.
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] std::vector<Continuity> knot_continuity(const nurbs::NurbsCurve& curve,
                                                      const ContinuityOptions& options = {});

/// Continuity at the join of `first`'s end with `second`'s start (the two curves' own parameters).
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] Continuity join_continuity(const nurbs::NurbsCurve& first, const nurbs::NurbsCurve& second,
                                         const ContinuityOptions& options = {});

/// Continuity between two derivative tables (the kernel of the functions above).
/// @param size model size for the relative tests; @param step parameter scale Δt (domain length)
[[nodiscard]] Continuity compare_sides(double t, const std::array<Vec3, 4>& left, const std::array<Vec3, 4>& right,
                                       double size, double step, const ContinuityOptions& options);

}  // namespace hula::diffgeom
