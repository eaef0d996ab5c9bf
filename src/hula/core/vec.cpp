// SPDX-License-Identifier: MIT
// Scaled norms: divide by the largest component before squaring so neither
// overflow (|a| ~ 1e200) nor underflow (|a| ~ 1e-200) can happen.
#include "hula/core/vec.hpp"

#include <limits>

namespace hula {

double detail::norm_scaled(const Vec3& a) {
  const double m = max_abs(a);
  // Squares of components in [1e-150, 1e150] neither overflow nor lose
  // precision to underflow: the plain formula is exact enough and cheaper.
  if (m > 1e-150 && m < 1e150) return std::sqrt(dot(a, a));
  if (m == 0.0 || !std::isfinite(m)) return m;
  const Vec3 b = a / m;
  return m * std::sqrt(dot(b, b));
}

Vec3 normalized(const Vec3& a) {
  const double m = max_abs(a);
  if (m == 0.0 || !std::isfinite(m)) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    return {nan, nan, nan};
  }
  const Vec3 b = a / m;
  return b / std::sqrt(dot(b, b));
}

}  // namespace hula
