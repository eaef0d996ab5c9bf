// SPDX-License-Identifier: MIT
// Seeded scanned-point clouds (see point_clouds.hpp).
#include "hula/testing/point_clouds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

#include "hula/core/rng.hpp"

namespace hula::testing {

std::string_view known_curve_name(KnownCurve curve) noexcept {
  switch (curve) {
    case KnownCurve::Arc:
      return "arc";
    case KnownCurve::SCurve:
      return "s-curve";
    case KnownCurve::Wave:
      return "wave";
  }
  return "arc";
}

std::size_t known_curve_inflections(KnownCurve curve) noexcept {
  switch (curve) {
    case KnownCurve::Arc:
      return 0;
    case KnownCurve::SCurve:
      return 1;
    case KnownCurve::Wave:
      return 2;
  }
  return 0;
}

Vec3 known_curve_point(KnownCurve curve, double u) noexcept {
  constexpr double kPi = std::numbers::pi;
  switch (curve) {
    case KnownCurve::Arc: {
      const double a = (-55.0 + 110.0 * u) * kPi / 180.0;
      return {60.0 * std::sin(a), 60.0 * std::cos(a), 0.0};
    }
    case KnownCurve::SCurve: {
      const double x = -60.0 + 120.0 * u;
      return {x, 12.0 * std::sin(2.0 * kPi * x / 150.0), 0.0};
    }
    case KnownCurve::Wave: {
      const double x = -30.0 + 110.0 * u;
      return {x, 8.0 * std::sin(2.0 * kPi * x / 90.0), 0.0};
    }
  }
  return {};
}

double distance_to_known_curve(KnownCurve curve, const Vec3& point) {
  constexpr int kSegments = 20000;
  double best = std::numeric_limits<double>::infinity();
  Vec3 a = known_curve_point(curve, 0.0);
  for (int i = 1; i <= kSegments; ++i) {
    const Vec3 b = known_curve_point(curve, static_cast<double>(i) / kSegments);
    const Vec3 ab = b - a;
    const double t = std::clamp(dot(point - a, ab) / std::max(dot(ab, ab), 1e-300), 0.0, 1.0);
    best = std::min(best, norm(a + t * ab - point));
    a = b;
  }
  return best;
}

namespace {

// A standard normal 2-vector redrawn while longer than kNoiseBound (see point_clouds.hpp).
Vec3 truncated_normal_2d(Rng& rng) {
  constexpr double kNoiseBound = 2.5;
  for (;;) {
    const double x = rng.normal();
    const double y = rng.normal();
    if (x * x + y * y <= kNoiseBound * kNoiseBound) return {x, y, 0.0};
  }
}

}  // namespace

Cloud scanned_cloud(const CloudSpec& spec) {
  Rng rng(spec.seed);
  const auto n_strays = static_cast<std::size_t>(std::llround(spec.stray_fraction * static_cast<double>(spec.points)));
  const std::size_t n_in = spec.points - n_strays;
  std::vector<Vec3> pts;
  pts.reserve(spec.points);
  Vec3 lo{1e300, 1e300, 0.0}, hi{-1e300, -1e300, 0.0};
  for (std::size_t i = 0; i < n_in; ++i) {
    const Vec3 c = known_curve_point(spec.curve, static_cast<double>(i) / static_cast<double>(n_in - 1));
    lo = {std::min(lo.x, c.x), std::min(lo.y, c.y), 0.0};
    hi = {std::max(hi.x, c.x), std::max(hi.y, c.y), 0.0};
    const Vec3 e = truncated_normal_2d(rng);
    pts.push_back({c.x + spec.noise * e.x, c.y + spec.noise * e.y, 0.0});
  }
  // Strays: uniform over the bounding box enlarged by 10 units, redrawn while too near the curve.
  constexpr double kMargin = 10.0;
  std::vector<char> is_stray(spec.points, 0);
  for (std::size_t s = 0; s < n_strays; ++s) {
    Vec3 q;
    do {
      q = {rng.uniform(lo.x - kMargin, hi.x + kMargin), rng.uniform(lo.y - kMargin, hi.y + kMargin), 0.0};
    } while (distance_to_known_curve(spec.curve, q) < spec.stray_min_distance);
    pts.push_back(q);
    is_stray[pts.size() - 1] = 1;
  }
  std::vector<std::size_t> perm(pts.size());
  std::iota(perm.begin(), perm.end(), std::size_t{0});
  if (spec.shuffle) {
    for (std::size_t i = perm.size(); i > 1; --i)
      std::swap(perm[i - 1], perm[static_cast<std::size_t>(rng.uniform() * static_cast<double>(i)) % i]);
  } else {
    // Scan order: the strays appear at random places among the inliers, which stay in curve order.
    perm.resize(n_in);
    for (std::size_t s = 0; s < n_strays; ++s) {
      const auto at =
          static_cast<std::size_t>(rng.uniform() * static_cast<double>(perm.size() + 1)) % (perm.size() + 1);
      perm.insert(perm.begin() + static_cast<std::ptrdiff_t>(at), n_in + s);
    }
  }
  Cloud cloud;
  cloud.points.reserve(pts.size());
  for (std::size_t i = 0; i < perm.size(); ++i) {
    cloud.points.push_back(pts[perm[i]]);
    if (is_stray[perm[i]]) cloud.strays.push_back(i);
  }
  return cloud;
}

}  // namespace hula::testing
