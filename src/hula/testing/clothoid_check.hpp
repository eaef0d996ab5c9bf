// SPDX-License-Identifier: MIT
// Header-only test and benchmark support for intrinsic/clothoid.hpp: the end of a clothoid segment by
// closed forms (Fresnel integrals, circle, line), independent of ClothoidSegment::point()'s quadrature,
// and the largest G2 violation of a three-arc G2 Hermite result (joins and end conditions).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>

#include "hula/intrinsic/clothoid.hpp"

namespace hula::testing {

using intrinsic::ClothoidG2Result;
using intrinsic::ClothoidSegment;
using intrinsic::fresnel;
using intrinsic::FresnelValues;

/// The end of a segment by closed forms, independent of point()'s quadrature: completing the square,
/// x + i y = z0 + sqrt(π/κ′) e^{iω} [(C(u1) − C(u0)) + i (S(u1) − S(u0))], ω = θ0 − κ0²/(2κ′),
/// u = sqrt(κ′/π)(s + κ0/κ′) (mirrored in y for κ′ < 0), when |κ′| L² ≥ 1e-3 (its cancellation error,
/// about 1e-14 sqrt(π / |κ′|), is then below 1e-12 L), the circle or line when |κ′| L³ ≤ 1e-13 (the
/// neglected term κ′ L³ / 6); in between, the exact-angle natural-equation integrator (to_intrinsic).
inline Vec3 closed_form_end(const ClothoidSegment& c) {
  const double len = c.length, rate = std::abs(c.dkappa);
  if (rate * len * len >= 1e-3) {
    const double mirror = c.dkappa < 0.0 ? -1.0 : 1.0;
    const double th0 = mirror * c.theta0, k0 = mirror * c.kappa0;
    const double w = th0 - k0 * k0 / (2 * rate), k = std::sqrt(rate / std::numbers::pi),
                 scale = std::sqrt(std::numbers::pi / rate);
    const FresnelValues f0 = fresnel(k * k0 / rate), f1 = fresnel(k * (len + k0 / rate));
    const double dc = f1.c - f0.c, ds = f1.s - f0.s;
    return {c.start.x + scale * (std::cos(w) * dc - std::sin(w) * ds),
            c.start.y + mirror * scale * (std::sin(w) * dc + std::cos(w) * ds), c.start.z};
  }
  if (rate * len * len * len <= 1e-13) {
    if (c.kappa0 == 0.0) return c.start + len * Vec3{std::cos(c.theta0), std::sin(c.theta0), 0.0};
    const double t1 = c.theta0 + c.kappa0 * len;
    return c.start +
           Vec3{(std::sin(t1) - std::sin(c.theta0)) / c.kappa0, (std::cos(c.theta0) - std::cos(t1)) / c.kappa0, 0.0};
  }
  return c.to_intrinsic().evaluate(len).position;
}

/// The largest violation of G2 continuity at the joins and of the end conditions, with positions by
/// closed_form_end() and differences of angles taken modulo 2π at p1 only; curvatures times the chord
/// so that every term is scale-free, positions divided by the chord.
inline double g2_violation(const ClothoidG2Result& r, const Vec3& p0, double theta0, double kappa0, const Vec3& p1,
                           double theta1, double kappa1) {
  const double chord = distance(p0, p1);
  const auto& s = r.segments;
  double e = std::max(
      {distance(s[0].start, p0) / chord, std::abs(s[0].theta0 - theta0), std::abs(s[0].kappa0 - kappa0) * chord});
  for (std::size_t j = 0; j < 2; ++j) {
    e = std::max({e, distance(closed_form_end(s[j]), s[j + 1].start) / chord,
                  std::abs(s[j].angle(s[j].length) - s[j + 1].theta0),
                  std::abs(s[j].curvature(s[j].length) - s[j + 1].kappa0) * chord});
  }
  const ClothoidSegment& last = s[2];
  return std::max({e, distance(closed_form_end(last), p1) / chord,
                   std::abs(std::remainder(last.angle(last.length) - theta1, 2 * std::numbers::pi)),
                   std::abs(last.curvature(last.length) - kappa1) * chord});
}

}  // namespace hula::testing
