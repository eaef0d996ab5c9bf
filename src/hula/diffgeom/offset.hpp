// SPDX-License-Identifier: MIT
// Offset curves. The planar offset O(t) = C(t) + d n(t) of a plane curve, n the
// left unit normal (T turned by +90°), with its cusps and loops found and
// trimmed away; the offset of a law curve is itself a law curve, so its
// curvature and their derivatives come exactly from the law engine.
//
// With T' = κ N for the signed curvature κ, dO/ds = (1 − dκ) T: the offset
// runs parallel to the curve where dκ < 1, backwards where dκ > 1, and has a
// cusp where dκ = 1 (Farouki and Neff, "Analytic properties of plane offset
// curves", CAGD 7, 1990). Its curvature is κ / (1 − dκ). Trimming keeps the
// points of the raw offset whose distance to the curve is |d| (the others are
// nearer to some other part of the curve): the raw offset is split at its
// cusps, its self-intersections and (open curves) its crossings of the circles
// of radius |d| about the end points, and each piece is kept or dropped by the
// distance of its midpoint to the curve.
//
// The helical offset (thesis 6.5.2) H(t) = C(t) + d(t) (cos θ(t) U(t) +
// sin θ(t) V(t)) of a plane or space curve winds around it at the distance
// d(t) with the twist θ(t), both laws of the curve parameter; {U, V} is the
// Frenet pair {N, B} or the Bishop (rotation-minimising) pair. A circle gives
// the thesis's toroidal round helix, a straight line (Bishop frame) the
// circular helix. The Bishop pair of a plane curve is {n × T, n} for the
// plane's normal n, a law; that of a space curve is {cos φ N + sin φ B,
// −sin φ N + cos φ B} with φ' = −τ |C'| (Bishop, "There is more than one way
// to frame a curve", Amer. Math. Monthly 82, 1975), φ integrated and held as
// a quintic NURBS leaf of the law.
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "hula/core/interval.hpp"
#include "hula/curve/curve.hpp"
#include "hula/law/expr.hpp"
#include "hula/nurbs/intersect.hpp"

namespace hula::diffgeom {

/// The planar offset law C + d n of a plane curve law, n = (−y', x') / |C'|.
/// @param curve a 2-vector law, or a 3-vector law offset in its x and y with its z carried over
/// @param parameter the curve parameter
/// @param distance d, model units; positive to the left of the direction of travel
/// @returns a law of the curve's dimension, undefined (NaN) where C' = 0
/// @throws hula::Error(Errc::InvalidArgument) naming "law" for a scalar law
[[nodiscard]] law::Law planar_offset_law(const law::Law& curve, std::string_view parameter, double distance);

/// Options of planar_offset.
struct OffsetOptions {
  /// Largest distance between the offset's NURBS and the exact offset, model units. Default 1e-6 (resabs);
  /// valid [1e-12, 1e-2]. Self-intersections are resolved to 4 × tolerance.
  double tolerance = 1e-6;
  /// Find and trim cusps and loops. Default true; false returns the raw offset only (trimmed empty).
  bool trim = true;
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// One connected piece of the trimmed offset.
struct OffsetPiece {
  /// Parameter intervals of the raw offset, in the order the piece runs through them: consecutive spans
  /// meet at a self-intersection of the raw offset (a corner); a piece of a closed curve's offset may run
  /// on from the end of the domain to its start.
  std::vector<Interval> spans;
  /// The piece as one NURBS, C0 at its corners; each span keeps its parameter length and the parameter runs
  /// on from the first span's start.
  nurbs::NurbsCurve curve;
  /// True when the piece ends where it starts (the whole offset of a closed curve, trimmed or not).
  bool closed = false;
};

/// Result of planar_offset.
struct PlanarOffset {
  /// The raw (untrimmed) offset on the curve's domain and parameter: a law curve when the input is one
  /// (exact; its nurbs() the stand-in), else a NURBS curve within the tolerance.
  curve::Curve raw;
  /// True when raw is a law curve, evaluated exactly.
  bool exact = false;
  /// max |raw.nurbs()(t) − (C(t) + d n(t))| at 1,000 samples, C' from the input's exact derivatives.
  double deviation = 0.0;
  /// Parameters where dκ = 1: the raw offset stops and turns back (a cusp), increasing.
  std::vector<double> cusps{};
  /// Self-intersections of the raw offset (s < t), as nurbs::self_intersect reports them.
  std::vector<nurbs::CurveIntersection> loops{};
  /// The trimmed offset: the pieces of the raw offset at distance |d| from the curve. Empty when every
  /// point of the raw offset is nearer than |d| to the curve (a circle offset inwards by more than its
  /// radius) or when trimming was not asked for.
  std::vector<OffsetPiece> trimmed{};
};

/// The planar offset of a plane curve by a distance, with cusps and loops trimmed.
/// @param curve a plane curve in the XY plane (2-D, or 3-D with constant z; the offset is then 3-D at that z) with
///   C' ≠ 0 on its domain; a law curve gives an exact law curve,
///   any other kind is offset through its own NURBS (a natural curve through its stand-in, so the reported
///   deviation includes the stand-in's)
/// @param distance d, model units, finite; positive to the left of the direction of travel
/// @throws hula::Error(Errc::InvalidArgument) naming "curve" for a curve not in a plane z = constant, naming
///   "distance" if it is not finite
/// @throws hula::Error(Errc::NumericalFailure) naming the parameter where C' = 0 (the offset is undefined)
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
/// Example: a circle of radius 2 run anticlockwise offset by d = 0.5 is the concentric circle of radius 1.5.
[[nodiscard]] PlanarOffset planar_offset(const curve::Curve& curve, double distance, const OffsetOptions& options = {});

/// The frame a helical offset winds in.
enum class OffsetFrame {
  Frenet,  ///< {N, B}: undefined where κ = 0
  Bishop,  ///< {U, V}, rotation-minimising, U(start) = N(start) (a plane curve: U = n × T, V = n)
};

/// "frenet" or "bishop".
[[nodiscard]] std::string_view offset_frame_name(OffsetFrame frame) noexcept;
/// The frame of that name, or nothing.
[[nodiscard]] std::optional<OffsetFrame> offset_frame_from_name(std::string_view name) noexcept;

/// H = C + d (cos θ u + sin θ v) of 3-vector laws C, u, v and scalar laws d, θ (one context).
/// @throws hula::Error(Errc::InvalidArgument) naming "law" for operands of the wrong dimension
[[nodiscard]] law::Law helical_offset_law(const law::Law& curve, const law::Law& distance, const law::Law& twist,
                                          const law::Law& u, const law::Law& v);

/// Options of helical_offset.
struct HelicalOffsetOptions {
  /// Which frame. Default Frenet (the thesis's); Bishop where the curve has straight stretches or inflections.
  OffsetFrame frame = OffsetFrame::Frenet;
  /// Largest distance between the offset's NURBS and the offset, model units. Default 1e-6; valid
  /// [1e-12, 1e-2]. The Bishop angle of a space curve is integrated to 0.1 × tolerance / max(1, max |d|).
  double tolerance = 1e-6;
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// Result of helical_offset.
struct HelicalOffset {
  /// The offset, 3-D, on the curve's domain and parameter: a law curve (exact) when the input is a law curve and
  /// the frame is Frenet or the curve is planar; else a NURBS curve within the tolerance.
  curve::Curve curve;
  /// True when curve is a law curve.
  bool exact = false;
  /// Bound on the distance between curve.nurbs() and the offset: the measured fit deviation plus, for the
  /// Bishop frame of a space curve, max |d| times the error of the integrated angle φ.
  double deviation = 0.0;
  /// The plane normal n of a plane curve's Bishop frame, else empty.
  std::optional<Vec3> plane_normal{};
};

/// The helical offset of a curve (thesis 6.5.2).
/// @param curve any curve with C' ≠ 0 (Frenet: also κ ≠ 0; Bishop of a space curve: κ ≠ 0 where τ is
///   integrated); a 2-D curve lies in z = 0
/// @param distance d as a law text of the curve's parameter (e.g. "0.5", "0.2 + 0.1*t")
/// @param twist θ in radians as a law text of the curve's parameter (e.g. "8*t")
/// @throws hula::Error(Errc::ParseError) naming "distance" or "twist" for a bad or non-scalar law
/// @throws hula::Error(Errc::NumericalFailure) naming "frame" where the frame is undefined (a straight stretch
///   or an inflection under Frenet), or where the offset cannot be fitted
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
/// Example: the circle (2 cos t, 2 sin t) with d = 0.5, θ = 8t (Frenet) is the toroidal helix
///   ((2 − 0.5 cos 8t) cos t, (2 − 0.5 cos 8t) sin t, 0.5 sin 8t).
[[nodiscard]] HelicalOffset helical_offset(const curve::Curve& curve, std::string_view distance, std::string_view twist,
                                           const HelicalOffsetOptions& options = {});

}  // namespace hula::diffgeom
