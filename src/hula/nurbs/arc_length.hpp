// SPDX-License-Identifier: MIT
// Arc length s(t) = ∫ |C'(u)| du to a tolerance (adaptive Gauss–Legendre per
// span, so the integrand is smooth on every piece) and its inverse t(s) by
// safeguarded Newton iteration.
#pragma once

#include <cstddef>

#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::nurbs {

/// Options for arc-length computations.
struct ArcLengthOptions {
  /// Relative tolerance on the length: |error| ≤ tolerance × length. Default 1e-12.
  /// Valid range [1e-15, 1e-2].
  double tolerance = 1e-12;
  /// Worker threads for a curve of many spans (16,384 or more in the interval): 0 = all cores, 1 = this
  /// thread only. The result, and any error, is the same on any number of threads. Default 0.
  std::size_t threads = 0;
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// Length of the curve between parameters a ≤ b inside the domain.
/// @throws hula::Error(Errc::OutOfDomain) if a or b is outside the domain, InvalidArgument if a > b
/// @throws hula::Error(Errc::NumericalFailure) if the tolerance cannot be met
[[nodiscard]] double arc_length(const NurbsCurve& curve, double a, double b, const ArcLengthOptions& options = {});
/// Length of the whole curve.
[[nodiscard]] double arc_length(const NurbsCurve& curve, const ArcLengthOptions& options = {});
/// Parameter t with arc_length(curve, t0, t) = s, for 0 ≤ s ≤ length.
/// @throws hula::Error(Errc::OutOfDomain) if s < 0 or s > length (beyond tolerance)
[[nodiscard]] double parameter_at_length(const NurbsCurve& curve, double s, const ArcLengthOptions& options = {});

}  // namespace hula::nurbs
