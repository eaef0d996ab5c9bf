// SPDX-License-Identifier: MIT
// The scalar semantics of every law operation, shared by constant folding
// (detail::apply) and the evaluation tape so that both give the same bits.
// Undefined results are a quiet NaN produced without raising FE_INVALID
// (quiet comparisons std::isless & co. are used where an argument may be NaN).
#pragma once

#include <cmath>
#include <limits>

namespace hula::law::detail {

inline constexpr double kUndefined = std::numeric_limits<double>::quiet_NaN();

inline double op_div(double a, double b) { return b == 0.0 ? kUndefined : a / b; }
inline double op_pow(double a, double b) {
  if (std::isnan(a) || std::isnan(b)) return kUndefined;
  if (a == 0.0 && b < 0.0) return kUndefined;
  if (a < 0.0 && b != std::floor(b)) return kUndefined;
  return std::pow(a, b);
}
/// a^k for a small integer k by repeated multiplication (within a few ulps of pow).
inline double op_powi(double a, int k) {
  if (k == 0) return std::isnan(a) ? kUndefined : 1.0;
  const int m = k < 0 ? -k : k;
  double r = a;
  for (int i = 1; i < m; ++i) r *= a;
  return k < 0 ? op_div(1.0, r) : r;
}
inline double op_sqrt(double a) { return std::isless(a, 0.0) ? kUndefined : std::sqrt(a); }
inline double op_log(double a) { return std::islessequal(a, 0.0) ? kUndefined : std::log(a); }
inline double op_asin(double a) { return std::isgreater(std::fabs(a), 1.0) ? kUndefined : std::asin(a); }
inline double op_acos(double a) { return std::isgreater(std::fabs(a), 1.0) ? kUndefined : std::acos(a); }
inline double op_atan2(double y, double x) { return (y == 0.0 && x == 0.0) ? kUndefined : std::atan2(y, x); }
inline double op_sign(double a) { return std::isnan(a) ? kUndefined : (a > 0.0 ? 1.0 : (a < 0.0 ? -1.0 : 0.0)); }
inline double op_min(double a, double b) { return (std::isnan(a) || std::isnan(b)) ? kUndefined : (b < a ? b : a); }
inline double op_max(double a, double b) { return (std::isnan(a) || std::isnan(b)) ? kUndefined : (a < b ? b : a); }
inline double op_less(double a, double b) {
  return (std::isnan(a) || std::isnan(b)) ? kUndefined : (a < b ? 1.0 : 0.0);
}
inline double op_less_equal(double a, double b) {
  return (std::isnan(a) || std::isnan(b)) ? kUndefined : (a <= b ? 1.0 : 0.0);
}
/// piecewise: an undefined condition makes the result undefined; otherwise only the chosen
/// branch's value is taken.
inline double op_select(double c, double a, double b) { return std::isnan(c) ? kUndefined : (c != 0.0 ? a : b); }

}  // namespace hula::law::detail
