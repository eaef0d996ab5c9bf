// SPDX-License-Identifier: MIT
// Vec3: the point and vector type of HulaHoops. Planar curves are 3-D curves
// with z = 0 (DESIGN.md). Norms are overflow- and underflow-safe (scaled by the
// largest component, as LAPACK's dnrm2 does), so a model at 1e-200 or 1e200
// has the lengths it should instead of 0 or infinity.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

namespace hula {

/// A 3-component vector of doubles: a point or a vector in model units.
struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;

  constexpr Vec3() = default;
  constexpr Vec3(double x_, double y_, double z_) : x(x_), y(y_), z(z_) {}

  [[nodiscard]] constexpr double operator[](std::size_t i) const { return i == 0 ? x : (i == 1 ? y : z); }
  [[nodiscard]] constexpr double& operator[](std::size_t i) { return i == 0 ? x : (i == 1 ? y : z); }

  constexpr Vec3& operator+=(const Vec3& o) {
    x += o.x;
    y += o.y;
    z += o.z;
    return *this;
  }
  constexpr Vec3& operator-=(const Vec3& o) {
    x -= o.x;
    y -= o.y;
    z -= o.z;
    return *this;
  }
  constexpr Vec3& operator*=(double s) {
    x *= s;
    y *= s;
    z *= s;
    return *this;
  }
  constexpr Vec3& operator/=(double s) {
    x /= s;
    y /= s;
    z /= s;
    return *this;
  }

  friend constexpr Vec3 operator+(Vec3 a, const Vec3& b) { return a += b; }
  friend constexpr Vec3 operator-(Vec3 a, const Vec3& b) { return a -= b; }
  friend constexpr Vec3 operator-(const Vec3& a) { return {-a.x, -a.y, -a.z}; }
  friend constexpr Vec3 operator*(Vec3 a, double s) { return a *= s; }
  friend constexpr Vec3 operator*(double s, Vec3 a) { return a *= s; }
  friend constexpr Vec3 operator/(Vec3 a, double s) { return a /= s; }
  friend constexpr bool operator==(const Vec3&, const Vec3&) = default;
};

[[nodiscard]] constexpr double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
[[nodiscard]] constexpr Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
/// Largest absolute component (the infinity norm).
[[nodiscard]] inline double max_abs(const Vec3& a) {
  return std::fmax(std::fabs(a.x), std::fmax(std::fabs(a.y), std::fabs(a.z)));
}
namespace detail {
/// norm() outside the range where the plain formula is exact enough (scaled by the largest component).
[[nodiscard]] double norm_scaled(const Vec3& a);
}  // namespace detail
/// Euclidean length without intermediate overflow or underflow.
[[nodiscard]] inline double norm(const Vec3& a) {
  // |a|² in (1e-290, 1e290) means the largest component m has m² ≤ |a|² < 1e290 and 3 m² ≥ |a|² > 1e-290,
  // so m lies in (1e-150, 1e150), where squaring loses nothing: the plain formula, inline (the
  // out-of-line call and its libm fmax were 12 % of a 10-point interpolation). Else the scaled form.
  const double s = a.x * a.x + a.y * a.y + a.z * a.z;
  if (s > 1e-290 && s < 1e290) return std::sqrt(s);
  return detail::norm_scaled(a);
}
/// Squared length; may overflow for |a| > 1e154: use norm() for lengths.
[[nodiscard]] constexpr double norm_squared(const Vec3& a) { return dot(a, a); }
/// Distance between two points, overflow-safe.
[[nodiscard]] inline double distance(const Vec3& a, const Vec3& b) { return norm(a - b); }
/// True when every component is finite.
[[nodiscard]] inline bool is_finite(const Vec3& a) {
  return std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(a.z);
}
/// Unit vector along a. Returns a NaN vector when a is zero (callers test
/// the length against their tolerance first; see docs/numerics.md).
[[nodiscard]] Vec3 normalized(const Vec3& a);

/// Axis-aligned box. Empty when min > max in any coordinate.
struct Box3 {
  Vec3 min{HUGE_VAL, HUGE_VAL, HUGE_VAL};
  Vec3 max{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};

  /// Grows the box to contain p (p must be finite).
  void add(const Vec3& p) {
    min = {p.x < min.x ? p.x : min.x, p.y < min.y ? p.y : min.y, p.z < min.z ? p.z : min.z};
    max = {p.x > max.x ? p.x : max.x, p.y > max.y ? p.y : max.y, p.z > max.z ? p.z : max.z};
  }
  [[nodiscard]] bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  /// Length of the diagonal (overflow-safe): the model size used by relative tolerances.
  [[nodiscard]] double diagonal() const { return empty() ? 0.0 : norm(max - min); }
  /// Largest absolute coordinate in the box.
  [[nodiscard]] double extent() const { return empty() ? 0.0 : std::fmax(max_abs(min), max_abs(max)); }
};

}  // namespace hula
