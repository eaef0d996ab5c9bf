// SPDX-License-Identifier: MIT
// Pareto tools for NSGA-II (Deb, Pratap, Agarwal & Meyarivan 2002): fast
// non-dominated sort under Deb's constrained domination, with a specialised
// O(n log n) sweep for two objectives (Jensen 2003 / ENS-BS), crowding
// distance, and the hypervolume indicator (exact sweep in 2-D, HSO slicing
// (While et al. 2006) for more objectives).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

namespace hula::optim {

/// Deb's constrained domination of a over b (both minimised): a feasible point
/// beats an infeasible one; of two infeasible points the smaller violation
/// wins; of two feasible points the Pareto-dominating one wins.
/// @param a, b m objective values each.
/// @param violation_a, violation_b constraint violations (0 = feasible).
/// @returns true when a constrained-dominates b.
[[nodiscard]] bool constrained_dominates(std::span<const double> a, double violation_a, std::span<const double> b,
                                         double violation_b) noexcept;

/// Reusable workspace for non-dominated sorting: after the first call of a
/// given size, sorting does not allocate.
class NonDominatedSorter {
 public:
  /// Ranks n points: rank 0 is the first front. Feasible points (violation 0)
  /// are sorted into Pareto fronts; infeasible points follow, ordered by
  /// violation (equal violations share a rank); points with NaN/infinite
  /// violation or NaN objectives (failed evaluations) share the last rank.
  /// @param objectives n x m values, row-major.
  /// @param m number of objectives >= 1.
  /// @param violation n violations, or empty when every point is feasible.
  /// @returns n ranks, valid until the next call.
  /// Complexity: O(n log n) for m <= 2, O(m n^2) otherwise.
  std::span<const std::size_t> sort(std::span<const double> objectives, std::size_t m,
                                    std::span<const double> violation);
  /// Number of distinct ranks of the last sort.
  [[nodiscard]] std::size_t fronts() const noexcept { return fronts_; }
  /// The feasible points of the last sort; for m <= 2 in lexicographic order of their objectives (ties
  /// by index), so that each front read in this order is sorted by its first objective.
  [[nodiscard]] std::span<const std::size_t> feasible() const noexcept { return order_; }

 private:
  struct Key2 {
    double f0, f1;
    std::size_t index;
  };
  std::vector<std::size_t> rank_, order_, dominated_, count_, start_, current_, next_, last_, next_front_;
  std::vector<Key2> keys_;
  std::size_t fronts_ = 0;
};

/// Ranks of a non-dominated sort (see NonDominatedSorter::sort).
struct ParetoRanking {
  /// rank[i] of point i, 0 = first front.
  std::vector<std::size_t> rank{};
  /// Number of distinct ranks.
  std::size_t fronts = 0;
};

/// One-shot non-dominated sort. @see NonDominatedSorter::sort.
[[nodiscard]] ParetoRanking non_dominated_sort(std::span<const double> objectives, std::size_t m,
                                               std::span<const double> violation = {});

/// Crowding distance of the members of one front (Deb 2002): for each
/// objective, members sorted by that objective get the normalised distance
/// between their neighbours; the extremes get +infinity.
/// @param objectives n x m values, row-major (all points of the population).
/// @param m number of objectives.
/// @param front indices of the front's members.
/// @param distance output indexed by point (size n); only front members are written.
///   (A caller-owned buffer so NSGA-II does not allocate per generation.)
/// @param scratch caller-owned buffer of front.size() indices, reordered.
void crowding_distance(std::span<const double> objectives, std::size_t m, std::span<const std::size_t> front,
                       std::span<double> distance, std::span<std::size_t> scratch) noexcept;

/// Thins a set of mutually non-dominated points to `keep` of them by removing,
/// one at a time, the member with the smallest crowding distance and
/// recomputing its neighbours' distances (Kukkonen & Deb 2006): a more even
/// spread than NSGA-II's one-shot truncation. The extremes of each objective
/// (infinite distance) are kept. Ties remove the lowest index.
/// @param objectives n x m values, row-major, finite.
/// @param m number of objectives >= 1.
/// @param keep number of points to keep (all when keep >= n).
/// @returns the indices kept, increasing.
/// Complexity: O((n - keep) m n log n).
[[nodiscard]] std::vector<std::size_t> thin_by_crowding(std::span<const double> objectives, std::size_t m,
                                                        std::size_t keep);

/// Hypervolume dominated by a point set and bounded by a reference point
/// (minimisation). Points that do not strictly dominate the reference in every
/// objective contribute nothing.
/// @param points n x m values, row-major, finite.
/// @param m number of objectives >= 1.
/// @param reference m finite values.
/// @returns the Lebesgue measure of the dominated region, >= 0.
/// @throws hula::Error(Errc::InvalidArgument) if m == 0, reference.size() != m
///   or points.size() is not a multiple of m.
/// @throws hula::Error(Errc::NonFiniteInput) if a point or the reference is not finite.
/// Complexity: O(n log n) for m = 2; O(n^(m-1) log n) (HSO) for m >= 3:
/// intended for m <= 5 and a few hundred points.
[[nodiscard]] double hypervolume(std::span<const double> points, std::size_t m, std::span<const double> reference);

}  // namespace hula::optim
