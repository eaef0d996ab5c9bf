// SPDX-License-Identifier: MIT
// Tolerances are explicit parameters with documented defaults (DESIGN.md,
// STYLE.md "Tolerance policy"); there is no global precision constant.
#pragma once

#include <string>

namespace hula {

/// Geometric tolerances passed to the operations that need them.
struct Tolerance {
  /// Absolute positional resolution in model units: two points closer than
  /// this are the same point. Default 1e-6 (ACIS's resabs). Valid: > 0, finite.
  /// Scale-aware operations use max(resabs, kRelativeResolution × model size).
  double resabs = 1e-6;
  /// Angular resolution in radians: directions closer than this are parallel.
  /// Default 1e-10. Valid: > 0, finite.
  double angular = 1e-10;

  /// Throws hula::Error(Errc::InvalidOption) naming the bad field.
  void validate() const;
};

/// Relative resolution of a model: a distance below kRelativeResolution times
/// the model size cannot be told from rounding noise (about 50 ulps).
inline constexpr double kRelativeResolution = 1e-14;

/// The positional resolution for a model of the given size:
/// max(tol.resabs scaled down for tiny models, kRelativeResolution × size).
/// A model at 1e-200 scale compares against 1e-214, not against 1e-6.
[[nodiscard]] double resolution_for_size(const Tolerance& tol, double model_size);

}  // namespace hula
