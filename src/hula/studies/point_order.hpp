// SPDX-License-Identifier: MIT
// Ordering an unorganised cloud of points along the curve it samples (thesis
// chapter 3: digitised points arrive in scan order, which is not curve order).
// The method is the minimum-spanning-tree skeleton of Lee ("Curve
// reconstruction from unorganized points", CAGD 17, 2000): the Euclidean MST of
// the k-nearest-neighbour graph, whose longest path (tree diameter) runs from one
// end of the curve to the other; every point gets the arc length, along that
// path, of the path node its tree branch hangs from. Isolated points (strays)
// are left out of the tree so that they cannot lengthen the path, and take the
// key of their nearest tree point.
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
