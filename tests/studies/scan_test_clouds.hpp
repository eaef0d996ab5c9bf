// SPDX-License-Identifier: MIT
// Test clouds for studies::fit_scan from generators independent of the code under test, shared by
// scan_fit_foreign_clouds_test.cpp, scan_fit_tail_clouds_test.cpp and the end-stray sweep
// (scan_fit_end_sweep.cpp). None of them uses the fit's code; distances to the known curves are measured
// here (sampling, then golden-section refinement) or by the generator's own analytic foot.
//
//  - Bézier clouds: a random cubic Bézier (a C or an S in the plane, or lifted into space), points at
//    equal parameter steps (dense where the curve is slow), Gaussian noise in every direction;
//  - wave clouds: a sine wave (planar) or a wavy helix (space) with random phase and frequency, points
//    at sorted uniform random parameters (clusters and gaps), Laplace (double-exponential) noise;
//  - tail clouds (make_tail_cloud): a logarithmic spiral arc, a tanh step (one inflection) or a conical
//    helix, points drawn from a density varying 1:3 along the curve with two or three empty gaps,
//    contaminated-normal noise (90 % of the draws at a scale s, 10 % at 3 s: heavy tails);
//  - adapters of hula::testing's scanned_cloud and simulate_scan to the same judged cloud (TestCloud),
//    with an optional end stray added here.
//
// judge() applies the judged criteria of issue 21: every generated stray found, no point within
// 0.25 / 0.3 of the tolerance of the known curve called a stray, the faired curve within 3 σ of the known
// curve (where its foot is inside the known curve's domain), and planar clouds keep the known inflections
// (those whose lobes stand out by more than 6 σ, which no curve within 3 σ of the known one can flatten,
// counted by one rule on both curves: significant_inflections).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <functional>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/diffgeom/features.hpp"
#include "hula/studies/scan_fit.hpp"
#include "hula/testing/point_clouds.hpp"
#include "hula/testing/scan_simulator.hpp"

namespace hula::studies::test_clouds {

inline constexpr double kPi = 3.14159265358979323846;

// A known curve on t ∈ [0, 1] with its first and second derivatives.
struct KnownCurve {
  std::function<Vec3(double)> at, d1, d2;
  bool planar = true;
};

// Foot of q on the known curve: the best of 2,001 samples, then golden section on the bracket.
struct Foot {
  double t = 0.0;
  double distance = 0.0;
};

inline Foot foot(const KnownCurve& c, const Vec3& q) {
  constexpr int kSamples = 2000;
  int best = 0;
  double best_d = norm(c.at(0.0) - q);
  for (int i = 1; i <= kSamples; ++i) {
    const double d = norm(c.at(static_cast<double>(i) / kSamples) - q);
    if (d < best_d) best_d = d, best = i;
  }
  double a = std::max(0.0, (best - 1.0) / kSamples), b = std::min(1.0, (best + 1.0) / kSamples);
  const double g = (std::sqrt(5.0) - 1.0) / 2.0;
  double x1 = b - g * (b - a), x2 = a + g * (b - a);
  double f1 = norm(c.at(x1) - q), f2 = norm(c.at(x2) - q);
  for (int k = 0; k < 80 && b - a > 1e-15; ++k) {
    if (f1 < f2) {
      b = x2, x2 = x1, f2 = f1, x1 = b - g * (b - a), f1 = norm(c.at(x1) - q);
    } else {
      a = x1, x1 = x2, f1 = f2, x2 = a + g * (b - a), f2 = norm(c.at(x2) - q);
    }
  }
  const double t = (a + b) / 2.0;
  return {t, std::min(best_d, norm(c.at(t) - q))};
}

// Sign changes of the planar curvature's numerator along the known curve.
inline std::size_t known_inflections(const KnownCurve& c) {
  std::size_t n = 0;
  int last = 0;
  for (int i = 0; i <= 100000; ++i) {
    const double t = i / 100000.0;
    const Vec3 a = c.d1(t), b = c.d2(t);
    const double z = a.x * b.y - a.y * b.x;
    const int s = z > 0 ? 1 : (z < 0 ? -1 : 0);
    if (s != 0 && last != 0 && s != last) ++n;
    if (s != 0) last = s;
  }
  return n;
}

// A cubic Bézier over the chord [0, size] along x: a C (both inner points on one side) or an S.
inline KnownCurve bezier_curve(double size, bool s_shape, bool planar, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double h1 = 0.2 + 0.2 * u(rng), h2 = (s_shape ? -1.0 : 1.0) * (0.2 + 0.2 * u(rng));
  std::array<Vec3, 4> p{Vec3{0.0, 0.0, 0.0}, Vec3{0.2 + 0.2 * u(rng), h1, 0.0}, Vec3{0.6 + 0.2 * u(rng), h2, 0.0},
                        Vec3{1.0, 0.0, 0.0}};
  if (!planar) p[1].z = 0.3, p[2].z = -0.15, p[3].z = 0.25;
  for (Vec3& q : p) q = q * size;
  KnownCurve c;
  c.planar = planar;
  c.at = [p](double t) {
    const double s = 1.0 - t;
    return p[0] * (s * s * s) + p[1] * (3.0 * s * s * t) + p[2] * (3.0 * s * t * t) + p[3] * (t * t * t);
  };
  c.d1 = [p](double t) {
    const double s = 1.0 - t;
    return (p[1] - p[0]) * (3.0 * s * s) + (p[2] - p[1]) * (6.0 * s * t) + (p[3] - p[2]) * (3.0 * t * t);
  };
  c.d2 = [p](double t) {
    return (p[2] - p[1] * 2.0 + p[0]) * (6.0 * (1.0 - t)) + (p[3] - p[2] * 2.0 + p[1]) * (6.0 * t);
  };
  return c;
}

// A sine wave over [0, size] (planar) or a wavy helix around the x axis (space), 0.6 to 1.4 periods.
inline KnownCurve wave_curve(double size, bool planar, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double w = 2.0 * kPi * (0.6 + 0.8 * u(rng)), phase = 2.0 * kPi * u(rng), a = 0.12 * size;
  KnownCurve c;
  c.planar = planar;
  const double zc = planar ? 0.0 : 1.0;
  c.at = [=](double t) { return Vec3{size * t, a * std::sin(w * t + phase), zc * a * std::cos(w * t + phase)}; };
  c.d1 = [=](double t) { return Vec3{size, a * w * std::cos(w * t + phase), -zc * a * w * std::sin(w * t + phase)}; };
  c.d2 = [=](double t) {
    return Vec3{0.0, -a * w * w * std::sin(w * t + phase), -zc * a * w * w * std::cos(w * t + phase)};
  };
  return c;
}

enum class Generator { BezierGaussian, WaveLaplace };
enum class Order { InOrder, Shuffled, Reversed };

struct Case {
  Generator generator;
  bool planar;
  bool s_shape;  // Bézier only
  Order order;
  double size;
  std::size_t points;
  double sigma_over_tolerance;
  // A stray at an end of the curve (sweep only): the first (or, when end_stray_last, the last) point in curve
  // order moved this many tolerances off the curve across it; 0: none.
  double end_stray = 0.0;
  bool end_stray_last = false;
};

struct Cloud {
  KnownCurve curve;
  std::vector<Vec3> points;
  std::vector<std::size_t> strays;  // indices, increasing
  double sigma = 0.0;
};

// One noise draw of standard deviation sigma per coordinate (planar clouds: z stays 0).
inline Vec3 noise(Generator g, bool planar, double sigma, std::mt19937_64& rng) {
  std::normal_distribution<double> gauss(0.0, sigma);
  std::exponential_distribution<double> expo(std::sqrt(2.0) / sigma);  // Laplace b = σ/√2 as a difference
  const auto draw = [&] { return g == Generator::BezierGaussian ? gauss(rng) : expo(rng) - expo(rng); };
  Vec3 e{draw(), draw(), 0.0};
  if (!planar) e.z = draw();
  return e;
}

// A point `off` from c(t) across the curve: along ± the normal (planar) or a random direction normal to the
// tangent (space).
inline Vec3 end_stray_point(const KnownCurve& c, double t, double off, bool planar, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Vec3 d1 = c.d1(t);
  const Vec3 tan = d1 * (1.0 / norm(d1));
  for (;;) {
    Vec3 dir{u(rng), u(rng), planar ? 0.0 : u(rng)};
    dir = dir - tan * dot(dir, tan);
    if (norm(dir) < 1e-3) continue;
    return c.at(t) + dir * (off / norm(dir));
  }
}

inline Cloud make_cloud(const Case& c, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  Cloud out;
  out.curve = c.generator == Generator::BezierGaussian ? bezier_curve(c.size, c.s_shape, c.planar, rng)
                                                       : wave_curve(c.size, c.planar, rng);
  const double tolerance = 0.003 * c.size;
  out.sigma = c.sigma_over_tolerance * tolerance;
  std::vector<double> ts(c.points);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (std::size_t i = 0; i < c.points; ++i)
    ts[i] = c.generator == Generator::BezierGaussian ? static_cast<double>(i) / (c.points - 1) : u(rng);
  if (c.generator == Generator::WaveLaplace) {
    std::sort(ts.begin(), ts.end());
    ts.front() = 0.0, ts.back() = 1.0;
  }
  for (const double t : ts) out.points.push_back(out.curve.at(t) + noise(c.generator, c.planar, out.sigma, rng));

  // 1 % strays, inner points moved off the curve until their own distance is 1.2–30 tolerances.
  std::vector<std::size_t> stray_at;
  const std::size_t count = std::max<std::size_t>(2, c.points / 100);
  for (std::size_t k = 0; k < count; ++k) stray_at.push_back(5 + (k * 7919 + seed) % (c.points - 10));
  std::sort(stray_at.begin(), stray_at.end());
  stray_at.erase(std::unique(stray_at.begin(), stray_at.end()), stray_at.end());
  for (const std::size_t i : stray_at) {
    for (;;) {
      Vec3 dir{u(rng) - 0.5, u(rng) - 0.5, c.planar ? 0.0 : u(rng) - 0.5};
      if (norm(dir) < 1e-3) continue;
      const Vec3 q = out.curve.at(ts[i]) + dir * ((1.2 + 28.8 * u(rng)) * tolerance / norm(dir));
      // A point beyond an end of the curve would extend it, not stray from it: the foot stays inside.
      const Foot f = foot(out.curve, q);
      if (f.distance < 1.2 * tolerance || f.t < 0.01 || f.t > 0.99) continue;
      out.points[i] = q;
      break;
    }
  }
  if (c.end_stray > 0.0) {
    const std::size_t i = c.end_stray_last ? c.points - 1 : 0;
    out.points[i] = end_stray_point(out.curve, ts[i], c.end_stray * tolerance, c.planar, rng);
    stray_at.insert(c.end_stray_last ? stray_at.end() : stray_at.begin(), i);
  }
  // The order: a permutation of the indices; strays are tracked through it.
  std::vector<std::size_t> perm(c.points);
  std::iota(perm.begin(), perm.end(), 0);
  if (c.order == Order::Shuffled) std::shuffle(perm.begin(), perm.end(), rng);
  if (c.order == Order::Reversed) std::reverse(perm.begin(), perm.end());
  std::vector<Vec3> ordered(c.points);
  for (std::size_t j = 0; j < c.points; ++j) {
    ordered[j] = out.points[perm[j]];
    if (std::binary_search(stray_at.begin(), stray_at.end(), perm[j])) out.strays.push_back(j);
  }
  std::sort(out.strays.begin(), out.strays.end());
  out.points = std::move(ordered);
  return out;
}

// ---- one judged cloud, whatever its generator ------------------------------------------------------

struct TestCloud {
  std::string name;
  std::vector<Vec3> points;         // as given to the fit
  std::vector<std::size_t> strays;  // generated strays, indices into points, increasing
  double tolerance = 0.0;
  double sigma = 0.0;
  bool planar = true;
  std::size_t inflections = 0;                  // of the known curve (planar): every sign change of its curvature
  std::function<Foot(const Vec3&)> known_foot;  // foot on the known curve, t in [0, 1]
  std::function<Vec3(double)> known_at;         // the known curve, t in [0, 1]
};

// ---- inflections the criteria can hold a curve to -------------------------------------------------

// The inflections of a planar curve whose lobes stand out by more than `height`, counted by one rule for the
// known curve and the fit. The curve, sampled at `samples` + 1 equal parameter steps, is cut at every sign change
// of its turning (the cross product of consecutive chords) into lobes of one-signed curvature; a lobe's height
// is the largest distance of its samples from its chord. While the lowest lobe is below `height`, it is merged
// with its neighbours (an end lobe with its one neighbour, losing one inflection; an inner lobe with both, losing
// two) and the merged lobe measured again (persistence simplification). A lobe a straight chord stays within
// `height` / 2 of can be flattened or raised by a curve that stays within `height` / 2 of the known one (the
// chord's ends and the crest each move by that much), so an inflection beside it is no feature such a criterion
// can require or forbid: the tanh step's nearly straight ends, a sine whose inflection falls near an end.
inline std::size_t significant_inflections(const std::function<Vec3(double)>& at, double t0, double t1, double height,
                                           int samples = 20000) {
  std::vector<Vec3> p(static_cast<std::size_t>(samples) + 1);
  for (int i = 0; i <= samples; ++i) p[static_cast<std::size_t>(i)] = at(t0 + (t1 - t0) * i / samples);
  // Lobe boundaries: sample indices where the turning changes sign (zero turns keep the last sign).
  std::vector<std::size_t> cuts{0};
  int last = 0;
  for (std::size_t i = 1; i + 1 < p.size(); ++i) {
    const Vec3 a = p[i] - p[i - 1], b = p[i + 1] - p[i];
    const double z = a.x * b.y - a.y * b.x;
    const double scale = norm(a) * norm(b);
    const int sign = z > 1e-12 * scale ? 1 : (z < -1e-12 * scale ? -1 : 0);
    if (sign != 0 && last != 0 && sign != last) cuts.push_back(i);
    if (sign != 0) last = sign;
  }
  cuts.push_back(p.size() - 1);
  const auto lobe_height = [&](std::size_t a, std::size_t b) {
    const Vec3 chord = p[b] - p[a];
    const double length = norm(chord);
    double h = 0.0;
    for (std::size_t i = a; i <= b; ++i) {
      const Vec3 r = p[i] - p[a];
      h = std::max(h, length > 0.0 ? std::abs(chord.x * r.y - chord.y * r.x) / length : norm(r));
    }
    return h;
  };
  // Lobe k runs from cuts[k] to cuts[k + 1].
  while (cuts.size() > 2) {
    std::size_t low = 0;
    double low_height = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k + 1 < cuts.size(); ++k) {
      const double h = lobe_height(cuts[k], cuts[k + 1]);
      if (h < low_height) low_height = h, low = k;
    }
    if (low_height >= height) break;
    const std::size_t lobes = cuts.size() - 1;
    if (low == 0) {
      cuts.erase(cuts.begin() + 1);
    } else if (low + 1 == lobes) {
      cuts.erase(cuts.end() - 2);
    } else {
      cuts.erase(cuts.begin() + static_cast<std::ptrdiff_t>(low), cuts.begin() + static_cast<std::ptrdiff_t>(low + 2));
    }
  }
  return cuts.size() - 2;
}

// Applies `order` to a cloud given in curve order (strays tracked through the permutation).
inline void arrange(TestCloud& cloud, Order order, std::mt19937_64& rng) {
  const std::size_t n = cloud.points.size();
  std::vector<std::size_t> perm(n);
  std::iota(perm.begin(), perm.end(), std::size_t{0});
  if (order == Order::Shuffled) std::shuffle(perm.begin(), perm.end(), rng);
  if (order == Order::Reversed) std::reverse(perm.begin(), perm.end());
  std::vector<Vec3> pts(n);
  std::vector<std::size_t> strays;
  for (std::size_t j = 0; j < n; ++j) {
    pts[j] = cloud.points[perm[j]];
    if (std::binary_search(cloud.strays.begin(), cloud.strays.end(), perm[j])) strays.push_back(j);
  }
  std::sort(strays.begin(), strays.end());
  cloud.points = std::move(pts);
  cloud.strays = std::move(strays);
}

inline const char* order_name(Order o) {
  static const char* names[] = {"in order", "shuffled", "reversed"};
  return names[static_cast<int>(o)];
}

// The Bézier/Gaussian and wave/Laplace clouds above as judged clouds.
inline TestCloud foreign_cloud(const Case& c, std::uint64_t seed) {
  Cloud cloud = make_cloud(c, seed);
  TestCloud out;
  out.name = std::string(c.generator == Generator::BezierGaussian ? "Bezier/Gaussian" : "wave/Laplace") +
             (c.planar ? " planar" : " space") +
             (c.generator == Generator::BezierGaussian ? (c.s_shape ? " S" : " C") : "");
  out.points = std::move(cloud.points);
  out.strays = std::move(cloud.strays);
  out.tolerance = 0.003 * c.size;
  out.sigma = cloud.sigma;
  out.planar = c.planar;
  out.inflections = c.planar ? known_inflections(cloud.curve) : 0;
  out.known_foot = [curve = cloud.curve](const Vec3& q) { return foot(curve, q); };
  out.known_at = cloud.curve.at;
  return out;
}

// ---- the tail generator ---------------------------------------------------------------------------

enum class TailShape { Spiral, Step, ConicalHelix };

// The known curve, chord (or height) about `size`.
inline KnownCurve tail_curve(TailShape shape, double size, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  KnownCurve c;
  c.planar = shape != TailShape::ConicalHelix;
  if (shape == TailShape::Spiral) {
    // r = a e^{bθ}, θ over 1.1π from a random start; a puts the chord near `size`.
    const double b = 0.2 + 0.1 * u(rng), th0 = 2.0 * kPi * u(rng), span = 1.1 * kPi;
    const double a = size / (std::exp(b * span) + 1.0);
    const auto r = [=](double t) { return a * std::exp(b * (span * t)); };
    c.at = [=](double t) {
      const double th = th0 + span * t;
      return Vec3{r(t) * std::cos(th), r(t) * std::sin(th), 0.0};
    };
    c.d1 = [=](double t) {
      const double th = th0 + span * t, rr = r(t) * span;
      return Vec3{rr * (b * std::cos(th) - std::sin(th)), rr * (b * std::sin(th) + std::cos(th)), 0.0};
    };
    c.d2 = [=](double t) {
      const double th = th0 + span * t, rr = r(t) * span * span;
      return Vec3{rr * ((b * b - 1.0) * std::cos(th) - 2.0 * b * std::sin(th)),
                  rr * ((b * b - 1.0) * std::sin(th) + 2.0 * b * std::cos(th)), 0.0};
    };
  } else if (shape == TailShape::Step) {
    // y = h tanh(k (t − t0)): one inflection at t0.
    const double t0 = 0.35 + 0.3 * u(rng), k = 5.0 + 2.0 * u(rng), h = 0.15 * size;
    c.at = [=](double t) { return Vec3{size * t, h * std::tanh(k * (t - t0)), 0.0}; };
    c.d1 = [=](double t) {
      const double th = std::tanh(k * (t - t0));
      return Vec3{size, h * k * (1.0 - th * th), 0.0};
    };
    c.d2 = [=](double t) {
      const double th = std::tanh(k * (t - t0));
      return Vec3{0.0, -2.0 * h * k * k * th * (1.0 - th * th), 0.0};
    };
  } else {
    // A helix of 1.2 turns whose radius grows from 0.08 to 0.2 of its height.
    const double w = 2.0 * kPi * 1.2, ph = 2.0 * kPi * u(rng);
    c.at = [=](double t) {
      const double r = size * (0.08 + 0.12 * t);
      return Vec3{r * std::cos(w * t + ph), r * std::sin(w * t + ph), size * t};
    };
    c.d1 = [=](double t) {
      const double r = size * (0.08 + 0.12 * t), dr = 0.12 * size;
      return Vec3{dr * std::cos(w * t + ph) - r * w * std::sin(w * t + ph),
                  dr * std::sin(w * t + ph) + r * w * std::cos(w * t + ph), size};
    };
    c.d2 = [=](double t) {
      const double r = size * (0.08 + 0.12 * t), dr = 0.12 * size;
      return Vec3{-2.0 * dr * w * std::sin(w * t + ph) - r * w * w * std::cos(w * t + ph),
                  2.0 * dr * w * std::cos(w * t + ph) - r * w * w * std::sin(w * t + ph), 0.0};
    };
  }
  return c;
}

struct TailCase {
  TailShape shape;
  Order order;
  double size;
  std::size_t points;
  double sigma_over_tolerance;
  double end_stray = 0.0;  // tolerances; 0: none
  bool end_stray_last = false;
};

inline const char* tail_shape_name(TailShape s) {
  static const char* names[] = {"spiral", "tanh step", "conical helix"};
  return names[static_cast<int>(s)];
}

// A tail cloud: parameters drawn by rejection from the density 1 + 2 sin²(3πt + φ) with two or three gaps
// (t-intervals 0.01–0.03 wide inside (0.1, 0.9) holding no point), the ends at t = 0 and 1;
// contaminated-normal noise of standard deviation σ per coordinate, offsets redrawn while longer than 8 σ;
// 1 % strays 1.2–30 tolerances off (feet inside (0.01, 0.99)); tolerance 0.003 × size.
inline TestCloud make_tail_cloud(const TailCase& c, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  TestCloud out;
  const KnownCurve curve = tail_curve(c.shape, c.size, rng);
  out.name = std::string("tail ") + tail_shape_name(c.shape);
  out.tolerance = 0.003 * c.size;
  out.sigma = c.sigma_over_tolerance * out.tolerance;
  out.planar = curve.planar;
  out.inflections = curve.planar ? known_inflections(curve) : 0;
  out.known_foot = [curve](const Vec3& q) { return foot(curve, q); };
  out.known_at = curve.at;

  const double phase = 2.0 * kPi * u(rng);
  const std::size_t gap_count = 2 + static_cast<std::size_t>(u(rng) < 0.5);
  std::vector<std::array<double, 2>> gaps;
  for (std::size_t g = 0; g < gap_count; ++g) {
    const double at = 0.1 + 0.8 * u(rng), w = 0.01 + 0.02 * u(rng);
    gaps.push_back({at - w / 2.0, at + w / 2.0});
  }
  std::vector<double> ts{0.0, 1.0};
  while (ts.size() < c.points) {
    const double t = u(rng);
    const double density = 1.0 + 2.0 * std::pow(std::sin(3.0 * kPi * t + phase), 2);
    if (u(rng) * 3.0 > density) continue;
    if (std::any_of(gaps.begin(), gaps.end(), [&](const auto& g) { return t > g[0] && t < g[1]; })) continue;
    ts.push_back(t);
  }
  std::sort(ts.begin(), ts.end());
  const double s = out.sigma / std::sqrt(0.9 + 0.1 * 9.0);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (const double t : ts) {
    Vec3 e{};
    do {
      const auto draw = [&] { return gauss(rng) * s * (u(rng) < 0.1 ? 3.0 : 1.0); };
      e = Vec3{draw(), draw(), curve.planar ? 0.0 : draw()};
    } while (norm(e) > 8.0 * out.sigma);
    out.points.push_back(curve.at(t) + e);
  }
  // Strays: inner points moved off until their distance from the known curve is 1.2–30 tolerances.
  const std::size_t count = std::max<std::size_t>(2, c.points / 100);
  std::vector<std::size_t> stray_at;
  for (std::size_t k = 0; k < count; ++k) stray_at.push_back(5 + (k * 7919 + seed * 31) % (c.points - 10));
  std::sort(stray_at.begin(), stray_at.end());
  stray_at.erase(std::unique(stray_at.begin(), stray_at.end()), stray_at.end());
  for (const std::size_t i : stray_at)
    for (;;) {
      Vec3 dir{u(rng) - 0.5, u(rng) - 0.5, curve.planar ? 0.0 : u(rng) - 0.5};
      if (norm(dir) < 1e-3) continue;
      const Vec3 q = curve.at(ts[i]) + dir * ((1.2 + 28.8 * u(rng)) * out.tolerance / norm(dir));
      const Foot f = foot(curve, q);
      if (f.distance < 1.2 * out.tolerance || f.t < 0.01 || f.t > 0.99) continue;
      out.points[i] = q;
      break;
    }
  if (c.end_stray > 0.0) {
    const std::size_t i = c.end_stray_last ? c.points - 1 : 0;
    out.points[i] = end_stray_point(curve, ts[i], c.end_stray * out.tolerance, curve.planar, rng);
    stray_at.insert(c.end_stray_last ? stray_at.end() : stray_at.begin(), i);
  }
  out.strays = stray_at;
  arrange(out, c.order, rng);
  return out;
}

// ---- hula::testing's generators as judged clouds --------------------------------------------------

// The first inlier of a cloud whose inliers are in curve order moved `end_stray` tolerances off across the
// curve at its start (or its last inlier at its end).
inline void move_end(TestCloud& cloud, const KnownCurve& curve, double t, std::size_t i, double end_stray,
                     std::mt19937_64& rng) {
  cloud.points[i] = end_stray_point(curve, t, end_stray * cloud.tolerance, cloud.planar, rng);
  cloud.strays.insert(std::upper_bound(cloud.strays.begin(), cloud.strays.end(), i), i);
}

// scanned_cloud (arc, S-curve, wave; ~130 units; tolerance A-class 0.3; truncated Gaussian noise; strays
// over the bounding box at least 1.2 tolerances off), generated in scan order, then the end stray, then
// `order`.
inline TestCloud scanned_test_cloud(testing::KnownCurve shape, std::size_t points, double sigma_over_tolerance,
                                    Order order, double end_stray, bool end_stray_last, std::uint64_t seed) {
  constexpr double kTol = 0.3;
  const testing::Cloud cloud = testing::scanned_cloud({.curve = shape,
                                                       .points = points,
                                                       .noise = sigma_over_tolerance * kTol,
                                                       .stray_min_distance = 1.2 * kTol,
                                                       .shuffle = false,
                                                       .seed = seed});
  TestCloud out;
  out.name = std::string("scanned_cloud ") + std::string(testing::known_curve_name(shape));
  out.points = cloud.points;
  out.strays = cloud.strays;
  out.tolerance = kTol;
  out.sigma = sigma_over_tolerance * kTol;
  out.planar = true;
  out.inflections = testing::known_curve_inflections(shape);
  KnownCurve curve;
  constexpr double kH = 1e-5;
  curve.at = [shape](double t) { return testing::known_curve_point(shape, t); };
  out.known_at = curve.at;
  curve.d1 = [shape](double t) {
    return (testing::known_curve_point(shape, t + kH) - testing::known_curve_point(shape, t - kH)) * (0.5 / kH);
  };
  out.known_foot = [curve](const Vec3& q) { return foot(curve, q); };
  std::mt19937_64 rng(seed * 7 + 3);
  if (end_stray > 0.0) {
    std::size_t i = 0;  // the first (last) inlier: the inliers are in curve order
    if (end_stray_last) {
      i = out.points.size() - 1;
      while (std::binary_search(out.strays.begin(), out.strays.end(), i)) --i;
    } else {
      while (std::binary_search(out.strays.begin(), out.strays.end(), i)) ++i;
    }
    move_end(out, curve, end_stray_last ? 1.0 : 0.0, i, end_stray, rng);
  }
  arrange(out, order, rng);
  return out;
}

// simulate_scan (open shapes: S-cubic, convex, quartic, twisted cubic, helix; its noise models; ±60 %
// density), in order, then the end stray, then `order`.
inline TestCloud simulated_test_cloud(testing::ScanShape shape, testing::ScanNoise noise, double size,
                                      std::size_t points, double sigma_over_tolerance, Order order, double end_stray,
                                      bool end_stray_last, std::uint64_t seed) {
  const double tol = 0.003 * size;
  testing::ScanSpec spec{.shape = shape,
                         .size = size,
                         .points = points,
                         .sigma = sigma_over_tolerance * tol,
                         .noise = noise,
                         .varying_density = true,
                         .order = testing::ScanOrder::InOrder,
                         .strays = std::max<std::size_t>(2, points / 100),
                         .stray_min = 1.2 * tol,
                         .stray_max = 30.0 * tol,
                         .seed = seed};
  const testing::Scan scan = testing::simulate_scan(spec);
  TestCloud out;
  out.name = "simulate_scan " + testing::scan_shape_name(shape);
  out.points = scan.points;
  out.strays = scan.strays;
  out.tolerance = tol;
  out.sigma = spec.sigma;
  out.planar = testing::scan_shape_planar(shape);
  out.inflections = out.planar ? testing::scan_shape_inflections(shape) : 0;
  out.known_foot = [spec](const Vec3& q) {
    const testing::ScanFoot f = testing::foot_on_scan_curve(spec, q);
    return Foot{f.u, f.distance};
  };
  KnownCurve curve;
  constexpr double kH = 1e-6;
  curve.at = [spec](double t) { return testing::scan_curve_point(spec, t); };
  out.known_at = curve.at;
  curve.d1 = [spec](double t) {
    const double a = std::max(0.0, t - kH), b = std::min(1.0, t + kH);
    return (testing::scan_curve_point(spec, b) - testing::scan_curve_point(spec, a)) * (1.0 / (b - a));
  };
  std::mt19937_64 rng(seed * 7 + 5);
  if (end_stray > 0.0) {
    // The inlier drawn at the end parameter (its truth is 0 or 1).
    std::size_t best = 0;
    for (std::size_t i = 0; i < out.points.size(); ++i) {
      if (std::binary_search(out.strays.begin(), out.strays.end(), i)) continue;
      const bool nearer = end_stray_last ? scan.truth[i] > scan.truth[best] : scan.truth[i] < scan.truth[best];
      if (std::binary_search(out.strays.begin(), out.strays.end(), best) || nearer) best = i;
    }
    move_end(out, curve, scan.truth[best], best, end_stray, rng);
  }
  arrange(out, order, rng);
  return out;
}

// ---- the judged criteria --------------------------------------------------------------------------

struct Verdict {
  std::size_t strays_missed = 0;      // generated strays kept
  std::size_t good_rejected = 0;      // points within 0.25 / 0.3 tolerance of the known curve called strays
  double far = 0.0;                   // largest distance of the faired curve from the known curve
  std::size_t inflections = 0;        // of the faired curve (planar), significant_inflections at 6 σ
  std::size_t known_inflections = 0;  // of the known curve by the same rule
  bool inflections_right = true;
  bool threw = false;
  std::string error;
  [[nodiscard]] bool pass(double sigma) const {
    return !threw && strays_missed == 0 && good_rejected == 0 && far <= 3.0 * sigma && inflections_right;
  }
};

inline Verdict judge(const TestCloud& cloud, const ScanFitResult& r) {
  Verdict v;
  for (const std::size_t s : cloud.strays)
    if (!std::binary_search(r.strays.begin(), r.strays.end(), s)) ++v.strays_missed;
  for (const std::size_t s : r.strays)
    if (cloud.known_foot(cloud.points[s]).distance < 0.25 / 0.3 * cloud.tolerance) ++v.good_rejected;
  const auto dom = r.faired.domain();
  for (int k = 0; k <= 400; ++k) {
    const Foot f = cloud.known_foot(r.faired.evaluate(dom.start + (dom.end - dom.start) * k / 400.0));
    if (f.t <= 1e-9 || f.t >= 1.0 - 1e-9) continue;  // beyond the known curve's ends: noise at the end points
    v.far = std::max(v.far, f.distance);
  }
  if (cloud.planar) {
    // A curve within 3 σ of the known one moves a lobe's chord ends and its crest by up to 3 σ each, so it may
    // flatten (or raise) a lobe up to 6 σ high: the inflections the 3 σ criterion can require are those beyond.
    const double height = 2.0 * 3.0 * cloud.sigma;
    v.inflections = significant_inflections([&](double t) { return r.faired.evaluate(t); }, dom.start, dom.end, height);
    v.known_inflections = significant_inflections(cloud.known_at, 0.0, 1.0, height);
    v.inflections_right = v.inflections == v.known_inflections;
  }
  return v;
}

// Fits and judges; a throw is a failure.
inline Verdict fit_and_judge(const TestCloud& cloud, const ScanFitOptions& options) {
  try {
    return judge(cloud, fit_scan(cloud.points, options));
  } catch (const std::exception& e) {
    Verdict v;
    v.threw = true;
    v.error = e.what();
    return v;
  }
}

}  // namespace hula::studies::test_clouds
