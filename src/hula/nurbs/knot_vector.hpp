// SPDX-License-Identifier: MIT
// KnotVector: a validated, immutable B-spline knot vector in the full
// Piegl–Tiller form (m + 1 = n + p + 2 knots for n + 1 control points of
// degree p), with span search (The NURBS Book A2.1, exact comparisons only),
// multiplicities, normalisation, and the ACIS/openNURBS form of n + p - 1
// knots that the thesis's code uses (thesis eq. 28, 7.1.2).
//
// Notation: p = degree, U = knots, n + 1 = number of control points.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "hula/core/interval.hpp"

namespace hula::nurbs {

/// Which one-sided limit to take at a knot where the curve may be discontinuous.
enum class Side {
  Right,  ///< limit from above (t → u⁺); at the domain end, the only side there is
  Left,   ///< limit from below (t → u⁻); at the domain start, the only side there is
};

/// The parameter interval of core (hula::Interval), also reachable by its former name.
using hula::Interval;

/// Largest degree accepted by the kernel. Higher degrees lose accuracy in
/// double precision long before they become useful in design.
inline constexpr int kMaxDegree = 64;

namespace detail {
struct CurveAccess;  // detail/curve_access.hpp
}  // namespace detail

/// A non-decreasing sequence of knots valid for a given degree.
///
/// Invariants (checked at construction): degree in [1, kMaxDegree]; at least
/// 2(p + 1) knots; every knot finite; non-decreasing; multiplicity ≤ p + 1
/// everywhere and ≤ p strictly inside the domain (the curve stays C0);
/// domain [U[p], U[m - p]] non-empty.
class KnotVector {
 public:
  /// @param knots full (Piegl–Tiller) knot vector, m + 1 = n + p + 2 values
  /// @param degree p ≥ 1
  /// @throws hula::Error(Errc::InvalidDegree) if degree < 1 or > kMaxDegree
  /// @throws hula::Error(Errc::InvalidKnots) if too few knots, a decreasing
  ///   pair (names both indices and values), a multiplicity above the limit,
  ///   or an empty domain
  /// @throws hula::Error(Errc::NonFiniteInput) if a knot is NaN or infinite
  KnotVector(std::vector<double> knots, int degree);

  /// Imports the ACIS/openNURBS form (n + p - 1 knots: the full vector without
  /// its first and last knot). The missing end knots are set equal to their
  /// neighbours, which does not change the curve on its domain.
  /// @throws as the constructor, with indices referring to the ACIS array
  [[nodiscard]] static KnotVector from_acis(std::span<const double> knots, int degree);
  /// Exports the ACIS/openNURBS form (drops the first and last knot).
  [[nodiscard]] std::vector<double> to_acis() const;

  /// Clamped, uniformly spaced knot vector on [start, end] for `control_points` ≥ degree + 1.
  [[nodiscard]] static KnotVector uniform_clamped(std::size_t control_points, int degree, Interval domain = {});

  [[nodiscard]] int degree() const noexcept { return degree_; }
  [[nodiscard]] std::span<const double> values() const noexcept { return knots_; }
  [[nodiscard]] std::size_t size() const noexcept { return knots_.size(); }
  [[nodiscard]] double operator[](std::size_t i) const { return knots_[i]; }
  /// Number of control points this knot vector supports: m - p.
  [[nodiscard]] std::size_t control_point_count() const noexcept {
    return knots_.size() - static_cast<std::size_t>(degree_) - 1;
  }
  /// Parameter domain [U[p], U[m - p]].
  [[nodiscard]] Interval domain() const noexcept;
  /// True when the first and last p + 1 knots coincide (the curve interpolates its end control points).
  [[nodiscard]] bool is_clamped() const noexcept;

  /// Span index i with U[i] ≤ t < U[i+1] (Right) or U[i] < t ≤ U[i+1] (Left),
  /// restricted to p ≤ i ≤ n so that the span is non-empty; t outside the
  /// domain maps to the first or last span. Exact comparisons (A2.1).
  [[nodiscard]] std::size_t find_span(double t, Side side = Side::Right) const noexcept;
  /// As find_span, starting from a hint (the span of a nearby parameter): O(1)
  /// for sorted batches, falling back to binary search.
  [[nodiscard]] std::size_t find_span(double t, std::size_t hint, Side side) const noexcept;

  /// Number of knots equal to u (exact comparison).
  [[nodiscard]] int multiplicity(double u) const noexcept;
  /// Distinct knot values inside the closed domain, in increasing order
  /// (the breakpoints between polynomial pieces, both domain ends included).
  [[nodiscard]] std::vector<double> breakpoints() const;
  /// The knot vector mapped affinely so that the domain becomes [start, end].
  /// @throws hula::Error(Errc::InvalidArgument) unless start < end, both finite
  [[nodiscard]] KnotVector reparameterised(Interval domain) const;

  friend bool operator==(const KnotVector&, const KnotVector&) = default;

 private:
  struct Unchecked {};
  KnotVector(Unchecked, std::vector<double> knots, int degree) : knots_(std::move(knots)), degree_(degree) {}
  friend class NurbsCurve;
  friend struct detail::CurveAccess;

  std::vector<double> knots_;
  int degree_;
};

}  // namespace hula::nurbs
