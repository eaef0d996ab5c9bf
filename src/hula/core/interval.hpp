// SPDX-License-Identifier: MIT
// Interval: a closed parameter interval [start, end], the domain of every
// curve (NURBS, law, natural equations) and of the searches on it. It lives in
// core because every layer from the kernel up speaks of domains.
#pragma once

namespace hula {

/// Parameter interval [start, end]. A plain value: whoever builds one for a
/// curve checks start < end (the curve factories do).
struct Interval {
  double start = 0.0;
  double end = 1.0;
  /// end − start.
  [[nodiscard]] double length() const { return end - start; }
  /// True when start ≤ t ≤ end (false for NaN).
  [[nodiscard]] bool contains(double t) const { return t >= start && t <= end; }
};

}  // namespace hula
