// SPDX-License-Identifier: MIT
// The second scan generator (see scan_simulator.hpp). Deliberately independent of
// point_clouds.cpp: other curves, other random engine, other noise and orders.
#include "hula/testing/scan_simulator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>

namespace hula::testing {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Position and first two derivatives (d/du) of a shape before scaling.
struct Jet {
  Vec3 c, d1, d2;
};

// Cubic Bézier jet.
Jet bezier(const std::array<Vec3, 4>& p, double u) {
  const double v = 1.0 - u;
  Jet j;
  j.c = v * v * v * p[0] + 3.0 * v * v * u * p[1] + 3.0 * v * u * u * p[2] + u * u * u * p[3];
  j.d1 = 3.0 * (v * v * (p[1] - p[0]) + 2.0 * v * u * (p[2] - p[1]) + u * u * (p[3] - p[2]));
  j.d2 = 6.0 * (v * (p[2] - 2.0 * p[1] + p[0]) + u * (p[3] - 2.0 * p[2] + p[1]));
  return j;
}

Jet shape_jet(ScanShape shape, double u) {
  switch (shape) {
    case ScanShape::SCubic:
      return bezier({Vec3{0, 0, 0}, Vec3{0.3, 0.3, 0}, Vec3{0.7, -0.3, 0}, Vec3{1, 0, 0}}, u);
    case ScanShape::Convex:
      return bezier({Vec3{0, 0, 0}, Vec3{0.25, 0.35, 0}, Vec3{0.75, 0.35, 0}, Vec3{1, 0, 0}}, u);
    case ScanShape::Quartic: {
      // y = x⁴ − 1.2 x², x = −1.15 + 2.3 u, divided by 2.3 (chord about 1).
      constexpr double kS = 2.3;
      const double x = -1.15 + kS * u;
      const double y = x * x * x * x - 1.2 * x * x, y1 = 4 * x * x * x - 2.4 * x, y2 = 12 * x * x - 2.4;
      return {Vec3{x / kS, y / kS, 0}, Vec3{1.0, y1, 0}, Vec3{0.0, y2 * kS, 0}};
    }
    case ScanShape::TwistedCubic:
      return {Vec3{u, 0.6 * u * u, 0.4 * u * u * u}, Vec3{1.0, 1.2 * u, 1.2 * u * u}, Vec3{0.0, 1.2, 2.4 * u}};
    case ScanShape::Helix: {
      constexpr double kR = 0.3, kH = 0.8, kTurns = 1.25;
      const double w = kTwoPi * kTurns, a = w * u;
      return {Vec3{kR * std::cos(a), kR * std::sin(a), kH * u}, Vec3{-kR * w * std::sin(a), kR * w * std::cos(a), kH},
              Vec3{-kR * w * w * std::cos(a), -kR * w * w * std::sin(a), 0.0}};
    }
    case ScanShape::Ellipse: {
      const double a = kTwoPi * u;
      return {Vec3{0.5 * std::cos(a), 0.3 * std::sin(a), 0},
              Vec3{-0.5 * kTwoPi * std::sin(a), 0.3 * kTwoPi * std::cos(a), 0},
              Vec3{-0.5 * kTwoPi * kTwoPi * std::cos(a), -0.3 * kTwoPi * kTwoPi * std::sin(a), 0}};
    }
    case ScanShape::ClosedSpace: {
      const double a = kTwoPi * u, w = kTwoPi;
      return {Vec3{0.5 * std::cos(a), 0.35 * std::sin(a), 0.15 * std::sin(2 * a)},
              Vec3{-0.5 * w * std::sin(a), 0.35 * w * std::cos(a), 0.3 * w * std::cos(2 * a)},
              Vec3{-0.5 * w * w * std::cos(a), -0.35 * w * w * std::sin(a), -0.6 * w * w * std::sin(2 * a)}};
    }
  }
  return {};
}

Jet scaled_jet(const ScanSpec& spec, double u) {
  Jet j = shape_jet(spec.shape, u);
  j.c *= spec.size;
  j.d1 *= spec.size;
  j.d2 *= spec.size;
  return j;
}

// Unit tangent, normal and binormal of a jet (planar: the normal is the tangent turned +90°).
struct Frame {
  Vec3 t, n, b;
};
Frame frame_of(const Jet& j, bool planar) {
  const Vec3 t = normalized(j.d1);
  if (planar) return {t, Vec3{-t.y, t.x, 0.0}, Vec3{0, 0, 1}};
  Vec3 n = j.d2 - dot(j.d2, t) * t;
  n = norm(n) > 0.0 ? normalized(n) : normalized(cross(t, Vec3{0.3, 0.5, 0.8}));
  return {t, n, cross(t, n)};
}

}  // namespace

std::string scan_shape_name(ScanShape shape) {
  switch (shape) {
    case ScanShape::SCubic:
      return "s-cubic";
    case ScanShape::Convex:
      return "convex";
    case ScanShape::Quartic:
      return "quartic";
    case ScanShape::TwistedCubic:
      return "twisted-cubic";
    case ScanShape::Helix:
      return "helix";
    case ScanShape::Ellipse:
      return "ellipse";
    case ScanShape::ClosedSpace:
      return "closed-space";
  }
  return "?";
}

bool scan_shape_closed(ScanShape shape) { return shape == ScanShape::Ellipse || shape == ScanShape::ClosedSpace; }

bool scan_shape_planar(ScanShape shape) {
  return shape == ScanShape::SCubic || shape == ScanShape::Convex || shape == ScanShape::Quartic ||
         shape == ScanShape::Ellipse;
}

std::size_t scan_shape_inflections(ScanShape shape) {
  switch (shape) {
    case ScanShape::SCubic:
      return 1;
    case ScanShape::Quartic:
      return 2;
    default:
      return 0;
  }
}

Vec3 scan_curve_point(const ScanSpec& spec, double u) { return scaled_jet(spec, u).c; }

double distance_to_scan_curve(const ScanSpec& spec, const Vec3& point) {
  return foot_on_scan_curve(spec, point).distance;
}

ScanFoot foot_on_scan_curve(const ScanSpec& spec, const Vec3& point) {
  constexpr int kSeeds = 4000;
  const bool closed = scan_shape_closed(spec.shape);
  // The three best seeds, each polished by Newton on f(u) = (C − q)·C'.
  std::array<std::pair<double, double>, 3> best;
  best.fill({std::numeric_limits<double>::infinity(), 0.0});
  for (int i = 0; i <= kSeeds; ++i) {
    const double u = static_cast<double>(i) / kSeeds;
    const double d = norm_squared(scaled_jet(spec, u).c - point);
    if (d < best.back().first) {
      best.back() = {d, u};
      std::sort(best.begin(), best.end());
    }
  }
  ScanFoot result{best.front().second, std::sqrt(best.front().first)};
  for (const auto& [d0, u0] : best) {
    double u = u0;
    for (int it = 0; it < 30; ++it) {
      const Jet j = scaled_jet(spec, u);
      const Vec3 r = j.c - point;
      const double f = dot(r, j.d1), df = dot(j.d1, j.d1) + dot(r, j.d2);
      if (!(df > 0.0)) break;
      double next = u - f / df;
      if (closed)
        next -= std::floor(next);
      else
        next = std::clamp(next, 0.0, 1.0);
      if (std::abs(next - u) < 1e-15) break;
      u = next;
    }
    const double d = norm(scaled_jet(spec, u).c - point);
    if (d < result.distance) result = {u, d};
  }
  return result;
}

Scan simulate_scan(const ScanSpec& spec) {
  std::mt19937_64 engine(spec.seed * 0x9E3779B97F4A7C15ULL + 12345);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::student_t_distribution<double> student(4.0);
  const bool planar = scan_shape_planar(spec.shape);
  const bool closed = scan_shape_closed(spec.shape);

  // Arc-length table of the known curve, for sampling at uniform or varying spacing.
  constexpr int kTable = 20000;
  std::vector<double> s(kTable + 1, 0.0);
  Vec3 prev = scaled_jet(spec, 0.0).c;
  for (int i = 1; i <= kTable; ++i) {
    const Vec3 c = scaled_jet(spec, static_cast<double>(i) / kTable).c;
    s[static_cast<std::size_t>(i)] = s[static_cast<std::size_t>(i) - 1] + norm(c - prev);
    prev = c;
  }
  auto u_at_length = [&](double target) {
    const auto it = std::lower_bound(s.begin(), s.end(), target);
    if (it == s.begin()) return 0.0;
    if (it == s.end()) return 1.0;
    const auto k = static_cast<std::size_t>(it - s.begin());
    const double f = (target - s[k - 1]) / std::max(s[k] - s[k - 1], 1e-300);
    return (static_cast<double>(k - 1) + f) / kTable;
  };

  Scan scan;
  const std::size_t n = spec.points;
  // Inliers, in curve order.
  std::vector<Vec3> inliers;
  std::vector<double> inlier_u;
  const double spread = std::sqrt(3.0) * spec.sigma;
  const double t_scale = spec.sigma / std::sqrt(2.0);  // Student t(4) has variance 2
  const Vec3 view = planar ? normalized(Vec3{0.6, 0.8, 0.0}) : normalized(Vec3{0.48, 0.6, 0.64});
  for (std::size_t i = 0; i < n; ++i) {
    const double v =
        closed ? static_cast<double>(i) / static_cast<double>(n) : static_cast<double>(i) / static_cast<double>(n - 1);
    const double g = spec.varying_density ? v + 0.6 * std::sin(kTwoPi * v) / kTwoPi : v;
    const double u = u_at_length(g * s.back());
    const Jet j = scaled_jet(spec, u);
    Vec3 e{0, 0, 0};
    switch (spec.noise) {
      case ScanNoise::None:
        break;
      case ScanNoise::Uniform:
        e = {spread * (2 * unit(engine) - 1), spread * (2 * unit(engine) - 1),
             planar ? 0.0 : spread * (2 * unit(engine) - 1)};
        break;
      case ScanNoise::StudentT:
        e = {t_scale * student(engine), t_scale * student(engine), planar ? 0.0 : t_scale * student(engine)};
        break;
      case ScanNoise::Anisotropic: {
        const Frame f = frame_of(j, planar);
        e = spec.sigma * gauss(engine) * f.n + 4.0 * spec.sigma * gauss(engine) * f.t;
        if (!planar) e += spec.sigma * gauss(engine) * f.b;
        break;
      }
      case ScanNoise::Depth:
        e = spec.sigma * gauss(engine) * view;
        break;
    }
    inliers.push_back(j.c + e);
    inlier_u.push_back(u);
  }
  // Strays: a random foot, a random direction across the curve, a distance in [stray_min, stray_max];
  // redrawn while the curve comes nearer than stray_min elsewhere.
  std::vector<Vec3> strays;
  std::vector<double> stray_u;
  for (std::size_t k = 0; k < spec.strays; ++k) {
    for (;;) {
      const double u = unit(engine);
      const Jet j = scaled_jet(spec, u);
      const Frame f = frame_of(j, planar);
      const double phi = kTwoPi * unit(engine);
      const Vec3 dir = planar ? (unit(engine) < 0.5 ? -1.0 : 1.0) * f.n : std::cos(phi) * f.n + std::sin(phi) * f.b;
      const double d = spec.stray_min + (spec.stray_max - spec.stray_min) * unit(engine);
      const Vec3 q = j.c + d * dir;
      if (distance_to_scan_curve(spec, q) >= spec.stray_min) {
        strays.push_back(q);
        stray_u.push_back(u);
        break;
      }
    }
  }

  // The order: a sequence of (is stray, index) entries.
  std::vector<std::pair<bool, std::size_t>> seq;
  auto random_index = [&](std::size_t size) {
    return std::min(size - 1, static_cast<std::size_t>(unit(engine) * static_cast<double>(size)));
  };
  auto insert_strays = [&]() {
    for (std::size_t k = 0; k < strays.size(); ++k)
      seq.insert(seq.begin() + static_cast<std::ptrdiff_t>(random_index(seq.size() + 1)), {true, k});
  };
  switch (spec.order) {
    case ScanOrder::InOrder:
    case ScanOrder::Reversed:
    case ScanOrder::PartlyShuffled:
      for (std::size_t i = 0; i < n; ++i) seq.push_back({false, i});
      insert_strays();
      if (spec.order == ScanOrder::Reversed) std::reverse(seq.begin(), seq.end());
      if (spec.order == ScanOrder::PartlyShuffled) {
        const std::size_t moves = (seq.size() * 15) / 100;
        for (std::size_t m = 0; m < moves; ++m) {
          const std::size_t from = random_index(seq.size());
          const auto item = seq[from];
          seq.erase(seq.begin() + static_cast<std::ptrdiff_t>(from));
          seq.insert(seq.begin() + static_cast<std::ptrdiff_t>(random_index(seq.size() + 1)), item);
        }
      }
      break;
    case ScanOrder::Shuffled:
      for (std::size_t i = 0; i < n; ++i) seq.push_back({false, i});
      for (std::size_t k = 0; k < strays.size(); ++k) seq.push_back({true, k});
      for (std::size_t i = seq.size(); i > 1; --i) std::swap(seq[i - 1], seq[random_index(i)]);
      break;
    case ScanOrder::Passes: {
      // Four passes over overlapping quarters, alternately forwards and backwards; a point in an
      // overlap belongs to either pass at random.
      constexpr int kPasses = 4;
      std::array<std::vector<std::size_t>, kPasses> pass;
      for (std::size_t i = 0; i < n; ++i) {
        const double v = static_cast<double>(i) / static_cast<double>(n);
        int k = std::min(kPasses - 1, static_cast<int>(v * kPasses));
        const double local = v * kPasses - k;
        if (local < 0.1 && k > 0 && unit(engine) < 0.5) --k;
        if (local > 0.9 && k < kPasses - 1 && unit(engine) < 0.5) ++k;
        pass[static_cast<std::size_t>(k)].push_back(i);
      }
      for (int k = 0; k < kPasses; ++k) {
        auto& p = pass[static_cast<std::size_t>(k)];
        if (k % 2 == 1) std::reverse(p.begin(), p.end());
        for (const std::size_t i : p) seq.push_back({false, i});
      }
      insert_strays();
      break;
    }
  }
  for (std::size_t i = 0; i < seq.size(); ++i) {
    const auto [is_stray, k] = seq[i];
    scan.points.push_back(is_stray ? strays[k] : inliers[k]);
    scan.truth.push_back(is_stray ? stray_u[k] : inlier_u[k]);
    if (is_stray) scan.strays.push_back(i);
  }
  return scan;
}

}  // namespace hula::testing
