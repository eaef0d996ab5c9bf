// SPDX-License-Identifier: MIT
// All roots and all extrema of a scalar law of one parameter on an interval.
// Roots use the exact symbolic derivatives: the critical points of f (roots
// of f', found the same way, recursively down to `derivative_levels`) cut the
// interval into pieces on which f is monotone, so each piece holds at most
// one root, bracketed and refined by TOMS 748 (Boost.Math; Alefeld, Potra
// and Shi's bracketing interpolation with bisection steps). Roots of even
// multiplicity are the critical points where |f| is below the value
// tolerance. The lowest level is found by dense sampling of the derivative.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

#include "hula/law/expr.hpp"

namespace hula::law {

/// Options of roots() and extrema().
struct RootOptions {
  /// Samples of the lowest derivative level over [a, b]. Default 512; valid ≥ 2. Raise it only for
  /// laws whose derivatives oscillate faster than the sampling (more than ~100 sign changes).
  std::size_t samples = 512;
  /// Levels of derivatives used to split the interval into monotone pieces. Default 2; valid 0 … 6.
  int derivative_levels = 2;
  /// Relative parameter tolerance: a root is located to tolerance × max(1, |t|). Default 1e-14;
  /// valid (0, 1e-3].
  double tolerance = 1e-14;
  /// A critical point c is a root of even multiplicity when |f(c)| ≤ value_tolerance × (max |f| sampled).
  /// Default 1e-12; valid [0, 1e-3].
  double value_tolerance = 1e-12;

  /// @throws hula::Error(Errc::InvalidOption) naming the field out of range
  void validate() const;
};

/// Result of find_roots().
struct RootReport {
  /// Converged roots, increasing, without duplicates (roots closer than tolerance are merged).
  std::vector<double> roots;
  /// Sign changes that did not converge to a root: the bracket shrank to the tolerance but
  /// |f| did not vanish there (a pole such as 1/(t − 1), a jump such as sign(t − 1), or an
  /// undefined point inside the bracket). Increasing. f has no root there.
  std::vector<double> unresolved;
  /// True when every sign change converged to a root.
  [[nodiscard]] bool converged() const { return unresolved.empty(); }
};

/// All roots of the scalar law f(parameter) in [a, b], with the sign changes that are not roots.
/// A refined sign change is a root when |f(x)| ≤ value_tolerance × (max |f| sampled) or
/// |f(x)| ≤ 1e-3 × min(|f|) at the two ends of its bracket (f fell towards zero); otherwise it is
/// unresolved. Points where f is undefined are skipped.
/// @throws hula::Error(Errc::InvalidArgument) if f is not a scalar or depends on another parameter,
///   or unless a < b, both finite
/// @throws hula::Error(Errc::InvalidOption) if options are invalid
[[nodiscard]] RootReport find_roots(const Law& f, std::string_view parameter, double a, double b,
                                    const RootOptions& options = {});

/// The converged roots of find_roots() (poles and jumps, which are no roots, left out).
/// @throws as find_roots()
[[nodiscard]] std::vector<double> roots(const Law& f, std::string_view parameter, double a, double b,
                                        const RootOptions& options = {});

/// Kind of an extremum.
enum class ExtremumKind {
  Minimum,     ///< local minimum (interior or at an end)
  Maximum,     ///< local maximum (interior or at an end)
  Stationary,  ///< f' = 0 without a change of sign (inflection with horizontal tangent)
};

/// One extremum.
struct Extremum {
  double t = 0.0;
  double value = 0.0;
  ExtremumKind kind = ExtremumKind::Minimum;
};

/// Result of extrema().
struct ExtremaResult {
  /// Interior critical points and both ends, increasing in t.
  std::vector<Extremum> points;
  /// The smallest and the largest value among points (global on [a, b] where f is defined).
  Extremum minimum;
  Extremum maximum;
};

/// Extrema of the scalar law f on [a, b]: roots of f' (roots()) classified by the sign of f' on
/// each side, plus both ends.
/// @throws as roots()
[[nodiscard]] ExtremaResult extrema(const Law& f, std::string_view parameter, double a, double b,
                                    const RootOptions& options = {});

}  // namespace hula::law
