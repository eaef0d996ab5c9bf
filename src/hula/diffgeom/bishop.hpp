// SPDX-License-Identifier: MIT
// The Bishop (rotation-minimising) frame of a curve, thesis 6.4, by the
// double-reflection method of Wang, Jüttler, Zheng and Liu, "Computation of
// rotation minimizing frames", ACM TOG 27(1), 2008, Algorithm 1. Unlike the
// Frenet frame it needs only the tangent, so it is defined through inflections
// and straight spans. The global error is O(h⁴) in the step h.
//
// Notation (Wang et al.): x_i sample points, t_i unit tangents, r_i the
// reference vector U; v1 = x_{i+1} − x_i, r_i^L and t_i^L the reflections in
// the plane normal to v1, v2 = t_{i+1} − t_i^L, r_{i+1} the reflection of r_i^L
// in the plane normal to v2.
#pragma once
#include <optional>
#include <span>
#include <vector>

#include "hula/diffgeom/frenet.hpp"

namespace hula::diffgeom {

/// Options of bishop_frame.
struct BishopOptions {
  /// Initial reference vector U at the first sample, projected onto the plane normal to T and
  /// normalised. Default: none, meaning Frenet N at the first sample where it is defined, else the
  /// signed normal plane_normal × T, else the coordinate axis least aligned with T made normal to T.
  /// Must be finite and not parallel to T.
  std::optional<Vec3> initial_u{};
  /// Close the frame on a closed curve: the angle between the propagated U at the last sample and
  /// U at the first is distributed linearly in (chord) arc length, so the frame is periodic. The
  /// first and last samples must coincide with parallel tangents. Default false.
  bool close = false;
  /// Options of the Frenet evaluation that supplies positions and tangents. Default {}.
  FrenetOptions frenet{};
  /// Throws hula::Error(Errc::InvalidOption) naming the bad field.
  void validate() const;
};

/// One Bishop frame {T, U, V}: right-handed (T × U = V) and orthonormal where defined.
struct BishopFrame {
  double t = 0.0;        ///< the parameter
  double s = 0.0;        ///< chord-length arc length from the first sample (model units)
  Vec3 position{};       ///< r(t)
  Vec3 tangent{};        ///< T (NaN where undefined)
  Vec3 u{};              ///< U, rotation-minimising normal (NaN where undefined)
  Vec3 v{};              ///< V = T × U (NaN where undefined)
  bool defined = false;  ///< false only at zero speed or non-finite derivatives (FrenetPoint::reason)
};

/// Frames at sorted samples and what the closing step did.
struct BishopResult {
  std::vector<BishopFrame> frames;  ///< one per sample
  /// Angle (radians) of the closing rotation applied at the last sample (0 when close is false).
  double closing_angle = 0.0;
};

/// Bishop frame from Frenet samples (positions and tangents) at increasing parameters.
/// @param samples ≥ 2 points in increasing t; those without a tangent get an undefined frame and are skipped
/// @returns the frames; every frame undefined if no sample has a tangent
/// @throws hula::Error(Errc::InvalidArgument) if fewer than 2 samples, t does not increase (names the
///   index), or close is requested and the ends do not meet
/// @throws hula::Error(Errc::InvalidOption) for bad options (e.g. initial_u parallel to T)
[[nodiscard]] BishopResult bishop_frame(std::span<const FrenetPoint> samples, const BishopOptions& options = {});

/// Bishop frame of a NURBS curve at increasing parameters `ts` (Frenet batch + double reflection).
/// Complexity O(n). @throws as above and as frenet(curve, ts)
[[nodiscard]] BishopResult bishop_frame(const nurbs::NurbsCurve& curve, std::span<const double> ts,
                                        const BishopOptions& options = {});

/// Bishop frame of a law curve at increasing parameters `ts`. @throws as above
[[nodiscard]] BishopResult bishop_frame(const LawFrenet& curve, std::span<const double> ts,
                                        const BishopOptions& options = {});

}  // namespace hula::diffgeom
