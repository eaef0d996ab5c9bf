// SPDX-License-Identifier: MIT
// Ordering an unorganised cloud of points along the curve it samples (thesis
// chapter 3: digitised points arrive in scan order, which is not curve order).
// The method is the minimum-spanning-tree skeleton of Lee ("Curve
// reconstruction from unorganized points", CAGD 17, 2000): the Euclidean MST of
// the k-nearest-neighbour graph, whose longest path (tree diameter) runs from one
// end of the curve to the other; every point gets the arc length, along that
// path, of the path node its tree branch hangs from. Isolated points (strays)
// are left out of the tree so that they cannot lengthen the path, and take the
// key of their nearest tree point. Where a gap in the sampling is wider than the
// k neighbours reach, the k-NN forest's pieces (of four points or more) are joined
// by their shortest edges, as the Euclidean MST would join them.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "hula/core/vec.hpp"

namespace hula::studies {

/// Options of order_along_curve.
struct PointOrderOptions {
  /// Neighbours k of the k-nearest-neighbour graph the tree is built on. Default 8; valid [2, 64].
  /// Raise it when the cloud has gaps wider than k point spacings.
  int neighbours = 8;
  /// A point is isolated (kept out of the tree) when its mean distance to its k neighbours exceeds
  /// `isolation_factor` × the median of that mean over the cloud. Default 5; valid > 1.
  double isolation_factor = 5.0;
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// Where each point lies along the curve.
struct PointOrder {
  /// key[i] ∈ [0, 1]: normalised arc length, along the tree's longest path, of point i's attachment.
  std::vector<double> key;
  /// Point indices sorted by key (ties by index).
  std::vector<std::size_t> order;
  /// Indices of the isolated points left out of the tree, increasing.
  std::vector<std::size_t> isolated;
  /// Length of the tree's longest path (model units).
  double path_length = 0.0;
};

/// Where the order of a cloud came from.
enum class OrderSource {
  Given,         ///< the caller said the points are in order along the curve
  File,          ///< the file order was found consistent (each point beside the next) and taken
  SpanningTree,  ///< the points were ordered by order_along_curve's tree
};

/// "given", "file" or "spanning-tree".
[[nodiscard]] const char* order_source_name(OrderSource source) noexcept;

/// Starting foot parameters of a cloud along the curve it samples.
struct CurveOrder {
  /// Per point: its parameter in [0, 1], increasing along the curve (closed: the curve returns to 0 at 1).
  std::vector<double> parameters;
  /// Points that break the order: far from all others (order_along_curve's isolated points) or, in a
  /// consistent file order, a detour of one to three points between two neighbours. Increasing.
  std::vector<std::size_t> suspects;
  OrderSource source = OrderSource::SpanningTree;
  /// The points close on themselves smoothly (no corner where the last meets the first).
  bool closed = false;
  /// Noise scale σ̂ of the points across the curve (see estimate_noise), model units.
  double noise = 0.0;
};

/// Orders a cloud and gives it starting parameters. The file order is taken when `given` says so, or
/// when it is consistent: every point (other than isolated ones) lies within twice its k-th
/// neighbour distance of the next (a local step), except detours of at most three points that the
/// sequence skips (at either end too), and gaps in the sampling: a longer step that continues the
/// directions of the points before and after it (each within 45°) over an empty stretch (at most three
/// points near it); detours skip at most a tenth of the points and gaps number at most 1 + n / 100, so
/// shuffled files, swapped halves or a stretch out of place are refused;
/// otherwise order_along_curve's tree orders the points and each takes the arc length of its
/// projection on the tree's longest path (smoothed over five nodes, extended along its end
/// segments). In file order the parameters are chord lengths (of a five-point running mean when the
/// noise exceeds 0.3 of the median spacing). The curve is closed when its two ends lie within a
/// neighbour distance of each other and the directions there differ by less than 60°.
/// @param points n ≥ 3 finite points
/// @throws as order_along_curve
[[nodiscard]] CurveOrder order_points(std::span<const Vec3> points, bool given, const PointOrderOptions& options = {});

/// Noise scale σ̂ across the curve from local polynomial residuals: for each point, the 7 points around
/// it in `order` (wrapping when `closed`), a cubic in their local chord length fitted to each
/// coordinate, and the point's residual across the fitted tangent divided by √(1 − hᵢᵢ) (hᵢᵢ its
/// leverage); σ̂ is 1.4826 × the median of these (planar) or the median / 1.1774 (space: the Rayleigh
/// median), so neither strays nor a few high-curvature windows move it. When σ̂ exceeds a fifth of the
/// median spacing (the chord lengths of neighbours are then noise), wider windows of about 20 σ̂
/// along the curve in their principal-axis frame, a quadratic across, give the estimate (twice).
/// @param order every index of points once, along the curve
[[nodiscard]] double estimate_noise(std::span<const Vec3> points, std::span<const std::size_t> order, bool closed);

/// Orders an unorganised cloud along the open curve it samples.
/// @param points n ≥ 3 finite points in model units
/// @returns keys in [0, 1]; which end is 0 is the end farther from points[0]'s side of the tree
///   (reverse the order when the orientation matters)
/// @throws hula::Error(Errc::TooFewPoints) if n < 3
/// @throws hula::Error(Errc::NonFiniteInput) naming the first non-finite point
/// @throws hula::Error(Errc::CoincidentPoints) if all points coincide
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
/// Complexity O(n k log n): kd-tree queries, Kruskal on n k edges, two tree traversals.
[[nodiscard]] PointOrder order_along_curve(std::span<const Vec3> points, const PointOrderOptions& options = {});

}  // namespace hula::studies
