// SPDX-License-Identifier: MIT
// The analysis of one curve (thesis 6.1–6.4, 7.1): the one entry every door
// asks — `hula analyse`, POST …/analysis, hulahoops.analyse, the study
// figures and the page (through the server) — so the same question gets the
// same answer everywhere (DESIGN.md, "One engine, one answer").
//
// It samples the curve by parameter or arc length (Frenet frame, κ, τ, dκ/ds,
// speed; optionally arc length and the Bishop frame), draws fins of any kind
// with one automatic scale rule (auto_fin_scale), and, when asked, finds the
// features:
//  - the plane, found once from the control points (planarity.hpp); the
//    signed curvature and the inflections are measured about it;
//  - inflections only where they are defined: on planar curves;
//  - curvature and torsion extrema by the one significance rule of
//    features.hpp (none on a constant-κ curve, never one twice);
//  - continuity at the interior knots only for curves that have knots (the
//    exact NURBS kinds: nurbs, bezier, interpolated, hermite — not the
//    stand-in NURBS of a law or natural curve);
//  - the pieces of monotone curvature and the largest curvature;
//  - the self-intersections (nurbs::self_intersect of the curve's NURBS).
// Law curves are analysed exactly from their law, natural curves' features
// from their natural equations κ(s), τ(s).
#pragma once

#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "hula/curve/curve.hpp"
#include "hula/diffgeom/bishop.hpp"
#include "hula/diffgeom/continuity.hpp"
#include "hula/diffgeom/features.hpp"
#include "hula/diffgeom/fins.hpp"
#include "hula/diffgeom/frenet.hpp"
#include "hula/diffgeom/monotonicity.hpp"
#include "hula/diffgeom/planarity.hpp"
#include "hula/nurbs/intersect.hpp"

namespace hula::diffgeom {

/// The abscissa of the samples.
enum class SampleBy {
  Parameter,  ///< equal steps in t (or the given parameters)
  ArcLength,  ///< equal steps in arc length s (or the given arc lengths)
};

/// "parameter" or "arclength".
[[nodiscard]] std::string_view sample_by_name(SampleBy by) noexcept;
/// The abscissa named `name` (sample_by_name's spelling), or nullopt.
[[nodiscard]] std::optional<SampleBy> sample_by_from_name(std::string_view name) noexcept;

/// Largest number of samples or fins of one analysis.
inline constexpr int kMaxAnalysisSamples = 1'000'000;

/// Options of analyse_curve().
struct AnalysisOptions {
  /// Number of samples, ends included, equally spaced in the abscissa `by`; 1 gives the start alone.
  /// Ignored when `at` is given. Default 100. Valid 1 … kMaxAnalysisSamples.
  int samples = 100;
  /// The abscissae to sample instead (parameters, or arc lengths from the start with
  /// SampleBy::ArcLength), in any order. Default none. At most kMaxAnalysisSamples.
  std::vector<double> at{};
  /// Abscissa of `samples` and `at`. Default Parameter.
  SampleBy by = SampleBy::Parameter;
  /// Arc length at every sample also when sampling by parameter (one integration per sample).
  /// Default false (by arc length the arc lengths are always there).
  bool arc_lengths = false;
  /// Bishop frame {U, V} at every sample, propagated from the domain start on a grid of 4096 steps
  /// plus the samples (double reflection, error O(h⁴): ~1e-12 rad on curves of moderate turning).
  /// Default false.
  bool bishop = false;
  /// Fin combs, in this order (duplicates are drawn once each as given). Default none.
  std::vector<FinKind> fins{};
  /// Fin scale s for every kind (FinOptions::scale: finite and non-zero); absent: auto_fin_scale per
  /// kind. Default absent.
  std::optional<double> fin_scale{};
  /// Fins per comb, equally spaced in t (parameter_grid); 0: as many as `samples` (then, sampling by
  /// parameter, the fins stand at the samples). Default 0. Valid 0 or 2 … kMaxAnalysisSamples.
  int fin_density = 0;
  /// Find the features (planarity is always there). Default false.
  bool features = false;
  /// Sampling and significance of the feature searches. Default {} (its plane normal is replaced by
  /// the curve's plane).
  FeatureOptions feature{};
  /// @throws hula::Error(Errc::InvalidOption) naming the field out of range
  void validate() const;
};

/// One comb as drawn: its kind, the scale used (given or automatic) and the fins.
struct AnalysedFins {
  FinKind kind = FinKind::Curvature;
  double scale = 1.0;
  Fins fins;
};

/// The largest curvature of a curve: over the domain ends, the curvature maxima and both sides of
/// every interior knot. NaN (value and t) where the curvature is nowhere defined.
struct MaximumCurvature {
  double value = std::numeric_limits<double>::quiet_NaN();  ///< κ max (1 / model units)
  double t = std::numeric_limits<double>::quiet_NaN();      ///< where
};

/// The features of a curve (AnalysisOptions::features).
struct CurveFeatures {
  /// Sign changes of the signed curvature about the curve's plane; empty for space curves.
  std::vector<Feature> inflections;
  /// Curvature maxima and minima (significance rule of features.hpp), increasing t.
  std::vector<Feature> curvature_extrema;
  /// Torsion maxima and minima (same rule), increasing t.
  std::vector<Feature> torsion_extrema;
  /// Continuity at every interior knot of the exact NURBS kinds; empty for law and natural curves.
  std::vector<Continuity> knots;
  /// Pieces of monotone curvature (signed for planar curves) between the extrema.
  CurvatureMonotonicity monotonicity;
  /// The largest curvature.
  MaximumCurvature maximum_curvature;
  /// Where the curve meets itself (nurbs::self_intersect of its NURBS; thesis ch. 10: a curve that
  /// doubles back on itself is not a valid design).
  nurbs::IntersectionResult self_intersections;
};

/// The analysis of a curve.
struct CurveAnalysis {
  /// The abscissa the samples were asked in.
  SampleBy by = SampleBy::Parameter;
  /// One Frenet point per sample, in the order asked (FrenetPoint's rules for undefined values).
  std::vector<FrenetPoint> samples;
  /// Arc length from the start at every sample (SampleBy::ArcLength or arc_lengths), else empty.
  std::vector<double> s;
  /// Bishop frame at every sample when asked, else empty.
  std::vector<BishopFrame> bishop;
  /// The combs, in AnalysisOptions::fins order.
  std::vector<AnalysedFins> fins;
  /// The curve's plane.
  Planarity planarity;
  /// The features, when asked.
  std::optional<CurveFeatures> features;
};

/// The automatic fin scale of one kind (the one rule of every door and figure): the longest fin is
/// a fifth of the box diagonal of the sampled points, divided by turns / 2 beyond two turns of the
/// tangent (so neighbouring coils' fins do not cover each other), and at most half the smallest
/// non-zero box extent (a slender helix's fins keep to its diameter). The quantity is κ, |τ|,
/// √(1 + (τ/κ)²) (Combescure) or 1 (unit-vector fins); 1 where it is zero everywhere.
/// @param frames the curve sampled in increasing t (the fins' own samples)
[[nodiscard]] double auto_fin_scale(std::span<const FrenetPoint> frames, FinKind kind);

/// Analyses a curve.
/// Example:
///   AnalysisOptions o;
///   o.samples = 50;
///   o.features = true;
///   const CurveAnalysis a = analyse_curve(curve, o);  // a.features->inflections, a.samples[i].curvature
/// @throws hula::Error(Errc::InvalidOption) for bad options
/// @throws hula::Error(Errc::OutOfDomain) naming "t" (or "s") and the index of an abscissa of `at`
///   outside the domain (length)
/// @throws hula::Error as frenet, fins, the feature searches and knot_continuity
[[nodiscard]] CurveAnalysis analyse_curve(const curve::Curve& curve, const AnalysisOptions& options = {});

}  // namespace hula::diffgeom
