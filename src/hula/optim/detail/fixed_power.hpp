// SPDX-License-Identifier: MIT
// x^p for one exponent p in [-1, 1] used many times: the roots x^(1/(eta+1)) of
// SBX's spread factor and polynomial mutation's step (Deb's distributions), and
// x^(-1/(eta+1)) for SBX's spread beyond the parents. For
// x = 2^k m with k in [-127, 128] and m in [1/2, 1), with m_j the centre of m's
// bin of width 1/128 and r = (m - m_j) / m_j (|r| <= 1/128):
//
//   x^p = 2^(k p) * m_j^p * (1 + r)^p,
//
// the first two factors from tables built once per p with std::pow on exact
// arguments, the third from its binomial series to r^7 (the first term left
// out is below 2^-59 for p in (0, 1], below 2^-56 for p in [-1, 0)). The error of r itself counts only
// p |r| times. Every other x (0, subnormal, outside the table, inf, NaN) goes to
// std::pow. Within a few ulp of std::pow (tests/optim/operators_test.cpp
// measures it over seeded inputs); about a fifth of its cost.
#pragma once

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

namespace hula::optim::detail {

class FixedPower {
 public:
  static constexpr int kMinExponent = -127;  // x = 2^k m, m in [1/2, 1)
  static constexpr int kExponents = 256;
  static constexpr int kBinBits = 6;
  static constexpr int kBins = 1 << kBinBits;
  static constexpr int kDegree = 7;

  FixedPower() = default;
  /// Tables for x^p; p = 0, p outside [-1, 1] or NaN makes every call std::pow.
  explicit FixedPower(double p);

  [[nodiscard]] double exponent() const noexcept { return p_; }

  /// x^p for x >= 0.
  [[nodiscard]] double operator()(double x) const noexcept {
    const auto bits = std::bit_cast<std::uint64_t>(x);
    // Biased exponent minus the table's first: out-of-range, zero, subnormal, inf, NaN and negative x
    // all land >= kExponents as unsigned.
    const std::uint64_t e = (bits >> 52) - static_cast<std::uint64_t>(1022 + kMinExponent);
    if (e >= static_cast<std::uint64_t>(kExponents) || !tabled_) return std::pow(x, p_);
    const auto j = static_cast<std::size_t>((bits >> (52 - kBinBits)) & (kBins - 1));
    // m in [1/2, 1): factors below 1 round on the finer grid.
    const double m = std::bit_cast<double>((bits & 0x000f'ffff'ffff'ffffULL) | 0x3fe0'0000'0000'0000ULL);
    const double r = (m - centre_[j]) * inv_centre_[j];  // m - centre is exact (same binade, Sterbenz)
    const double r2 = r * r;
    const double* c = c_.data();
    // (1 + r)^p - 1 = r (c1 + c2 r + ... + c7 r^6), by Estrin's scheme (a shorter dependency chain than
    // Horner's); kept apart from the 1 so that its rounding is relative to a number below 2^-6.
    const double lo = (c[1] + c[2] * r) + r2 * (c[3] + c[4] * r);
    const double hi = (c[5] + c[6] * r) + r2 * c[7];
    const double s = r * (lo + (r2 * r2) * hi);
    const double t = scale_[e] * bin_[j];
    return t + t * s;
  }

 private:
  double p_ = std::numeric_limits<double>::quiet_NaN();
  bool tabled_ = false;
  std::array<double, kExponents> scale_{};  // 2^(k p)
  std::array<double, kBins> bin_{};         // m_j^p
  std::array<double, kBins> centre_{};      // m_j = (1 + (j + 1/2) / 64) / 2
  std::array<double, kBins> inv_centre_{};  // 1 / m_j
  std::array<double, kDegree + 1> c_{};     // binomial coefficients C(p, i)
};

/// The calling thread's FixedPower for p (a small cache of recent exponents: SBX and mutation
/// may use different ones); valid until the thread calls this with four other exponents.
[[nodiscard]] const FixedPower& fixed_power(double p);

}  // namespace hula::optim::detail
