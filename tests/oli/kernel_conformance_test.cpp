// SPDX-License-Identifier: MIT
// The kernel conformance suite (issue 11 item 8): one parameterised suite run
// on every backend of this build ("native", "occt"). Each operation on seeded
// random curves (degree 1–5, rational or not, clamped or not) is checked
// against the *other* backend (independent code: HulaHoops' nurbs/diffgeom
// against Open CASCADE) to 1e-12 relative, against its defining invariant
// (knot insertion, degree elevation, split and reverse leave the curve
// unchanged; an interpolant passes through its points), and against closed
// forms (circle: κ = 1/R, length 2πR; helix: constant κ and τ). Operations a
// backend lacks must throw Errc::Unsupported naming the operation, and
// with_fallback must then answer from the native backend and say so.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "hula/core/rng.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/oli/kernel/kernel.hpp"
#include "hula/testing/curve_generators.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::oli {
namespace {

using nurbs::NurbsCurve;

constexpr double kRel = 1e-12;
constexpr int kCurves = 40;

// The backend that serves as reference: the other one when this build has two.
const Kernel& reference_for(const Kernel& k) {
  const auto names = kernel_names();
  for (const auto& n : names)
    if (n != k.name()) return *make_kernel(n);
  return k;
}

// Seeded random curves covering degree 1–5, rational or not, clamped or not.
std::vector<NurbsCurve> random_curves(std::uint64_t seed) {
  Rng rng(seed);
  std::vector<NurbsCurve> out;
  for (int i = 0; i < kCurves; ++i) {
    testing::RandomCurveSpec spec;
    spec.degree = 1 + i % 5;
    spec.rational = (i / 5) % 2 == 1;
    spec.clamped = (i / 10) % 2 == 0;
    spec.extra_points = 1 + static_cast<int>(rng.below(6));
    out.push_back(testing::random_curve(rng, spec));
  }
  return out;
}

// Parameters inside the domain including both ends and every knot (right-sided there).
std::vector<double> sample_parameters(const NurbsCurve& c, int n = 24) {
  const auto d = c.domain();
  std::vector<double> ts;
  ts.push_back(d.end);
  for (int i = 0; i < n; ++i) ts.push_back(d.start + d.length() * i / n);
  for (double u : c.knots().values())
    if (u >= d.start && u <= d.end) ts.push_back(u);
  return ts;
}

// max |a(t) - b(t)| / model size over samples of a's domain (b must share it).
double relative_deviation(const Kernel& k, const NurbsCurve& a, const NurbsCurve& b) {
  double worst = 0.0;
  for (double t : sample_parameters(a, 64)) worst = std::fmax(worst, norm(k.evaluate(a, t) - k.evaluate(b, t)));
  return worst / a.model_size();
}

class KernelConformance : public ::testing::TestWithParam<std::string> {
 protected:
  const Kernel& kernel() const { return *make_kernel(GetParam()); }
  const Kernel& reference() const { return reference_for(kernel()); }
};

// checks construct returns exactly the construction data, and refuses a bad knot vector with the
// native kernel's code and index
TEST_P(KernelConformance, ConstructKeepsDataAndRefusesBadInput) {
  for (const auto& c : random_curves(11)) {
    const auto made =
        kernel().construct(c.degree(), std::vector<double>(c.knots().values().begin(), c.knots().values().end()),
                           std::vector<Vec3>(c.control_points().begin(), c.control_points().end()),
                           std::vector<double>(c.weights().begin(), c.weights().end()), 3);
    EXPECT_EQ(made, c);
  }
  HULA_EXPECT_ERROR(kernel().construct(2, {0, 0, 0, 0.7, 0.5, 1, 1, 1},
                                       {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 1, 0}, {3, 0, 0}}, {}, 3),
                    Errc::InvalidKnots, "knots[4]");
  HULA_EXPECT_ERROR(kernel().construct(1, {0, 0, 1, 1}, {{0, 0, 0}, {1, 0, 0}}, {1.0, -1.0}, 3), Errc::InvalidWeight,
                    "weights[1]");
}

// checks position and derivatives to order 3 against the other backend, 1e-12 relative to each
// derivative's scale model_size / L^k
TEST_P(KernelConformance, DerivativesMatchTheOtherBackend) {
  for (const auto& c : random_curves(12)) {
    const double L = c.domain().length();
    for (double t : sample_parameters(c)) {
      const auto d = kernel().derivatives(c, t, 3);
      const auto r = reference().derivatives(c, t, 3);
      ASSERT_EQ(d.size(), 4U);
      EXPECT_LE(norm(kernel().evaluate(c, t) - r[0]), kRel * c.model_size()) << "t = " << t;
      for (int k = 0; k <= 3; ++k) {
        const double scale = std::fmax(norm(r[static_cast<std::size_t>(k)]), c.model_size() / std::pow(L, k));
        EXPECT_LE(norm(d[static_cast<std::size_t>(k)] - r[static_cast<std::size_t>(k)]), kRel * scale)
            << kernel().name() << " order " << k << " at t = " << t << " degree " << c.degree();
      }
    }
  }
  const auto c = random_curves(12).front();
  HULA_EXPECT_ERROR(kernel().derivatives(c, c.domain().start, 4), Errc::InvalidArgument, "order 4");
  HULA_EXPECT_ERROR(kernel().evaluate(c, c.domain().end + 1.0), Errc::OutOfDomain, "outside the curve domain");
  HULA_EXPECT_ERROR(kernel().evaluate(c, std::nan("")), Errc::NonFiniteInput, "t = nan");
}

// checks knot insertion leaves the curve unchanged and adds exactly `times` knots
TEST_P(KernelConformance, KnotInsertionLeavesTheCurveUnchanged) {
  Rng rng(13);
  for (const auto& c : random_curves(13)) {
    if (c.degree() < 2) continue;
    const auto d = c.domain();
    const double u = rng.uniform(d.start + 0.1 * d.length(), d.end - 0.1 * d.length());
    const auto r = kernel().insert_knot(c, u, 2);
    EXPECT_EQ(r.knots().values().size(), c.knots().values().size() + 2);
    EXPECT_EQ(r.degree(), c.degree());
    EXPECT_LE(relative_deviation(kernel(), c, r), kRel) << "u = " << u;
  }
  const auto c = random_curves(13)[2];  // clamped cubic: the ends have multiplicity p + 1 already
  HULA_EXPECT_ERROR(kernel().insert_knot(c, c.domain().start, 1), Errc::InvalidKnots, "would exceed the degree");
  HULA_EXPECT_ERROR(kernel().insert_knot(c, c.domain().end + 1.0, 1), Errc::OutOfDomain, "outside the curve domain");
  HULA_EXPECT_ERROR(kernel().insert_knot(c, c.domain().start, 0), Errc::InvalidArgument, "times = 0");
}

// checks degree elevation raises the degree and leaves the curve unchanged
TEST_P(KernelConformance, DegreeElevationLeavesTheCurveUnchanged) {
  for (const auto& c : random_curves(14)) {
    const auto r = kernel().elevate_degree(c, 2);
    EXPECT_EQ(r.degree(), c.degree() + 2);
    EXPECT_LE(relative_deviation(kernel(), c, r), kRel) << "degree " << c.degree();
  }
}

// checks split halves equal the curve on [a, t] and [t, b], share the point at t, and keep the
// domain ends exactly
TEST_P(KernelConformance, SplitHalvesEqualTheCurve) {
  Rng rng(15);
  for (const auto& c : random_curves(15)) {
    const auto d = c.domain();
    const double t = rng.uniform(d.start + 0.05 * d.length(), d.end - 0.05 * d.length());
    const auto s = kernel().split(c, t);
    EXPECT_EQ(s.before.domain().start, d.start);
    EXPECT_EQ(s.after.domain().end, d.end);
    EXPECT_NEAR(s.before.domain().end, t, 1e-15 * d.length());
    for (const auto* half : {&s.before, &s.after})
      for (double u : sample_parameters(*half, 32))
        EXPECT_LE(norm(kernel().evaluate(*half, u) - kernel().evaluate(c, std::clamp(u, d.start, d.end))),
                  kRel * c.model_size())
            << "u = " << u;
  }
  const auto c = random_curves(15).front();
  HULA_EXPECT_ERROR(kernel().split(c, c.domain().start), Errc::OutOfDomain, "t = ");
}

// checks reverse traverses the same points backwards on the same domain: R(t) = C(a + b - t)
TEST_P(KernelConformance, ReverseTraversesBackwards) {
  for (const auto& c : random_curves(16)) {
    const auto r = kernel().reverse(c);
    const auto d = c.domain();
    EXPECT_EQ(r.domain().start, d.start);
    EXPECT_EQ(r.domain().end, d.end);
    for (double t : sample_parameters(c))
      EXPECT_LE(norm(kernel().evaluate(r, t) - kernel().evaluate(c, std::clamp(d.start + d.end - t, d.start, d.end))),
                kRel * c.model_size());
  }
}

// checks interpolation passes through its points and equals the other backend's interpolant, with
// and without end tangents and with given parameters
TEST_P(KernelConformance, InterpolationPassesThroughPointsAndMatches) {
  Rng rng(17);
  for (int trial = 0; trial < 12; ++trial) {
    const std::size_t n = 2 + static_cast<std::size_t>(rng.below(12));
    std::vector<Vec3> points(n);
    for (auto& p : points) p = {rng.uniform(-10, 10), rng.uniform(-10, 10), rng.uniform(-10, 10)};
    KernelInterpolation o;
    if (trial % 3 == 1) {
      o.start_tangent = Vec3{rng.uniform(-20, 20), rng.uniform(-20, 20), rng.uniform(-20, 20)};
      o.end_tangent = Vec3{rng.uniform(-20, 20), rng.uniform(-20, 20), rng.uniform(-20, 20)};
    }
    if (trial % 3 == 2) {
      double t = rng.uniform(-5, 5);
      for (std::size_t i = 0; i < n; ++i) o.parameters.push_back(t += rng.uniform(0.1, 2.0));
    }
    const auto c = kernel().interpolate(points, o);
    const auto r = reference().interpolate(points, o);
    EXPECT_EQ(c.domain().start, 0.0);
    EXPECT_EQ(c.domain().end, 1.0);
    // The data parameters: the given ones mapped to [0, 1], else the normalised chord length (eq. 29).
    std::vector<double> t(n, 0.0);
    for (std::size_t i = 1; i < n; ++i)
      t[i] = o.parameters.empty() ? t[i - 1] + norm(points[i] - points[i - 1]) : o.parameters[i] - o.parameters[0];
    for (std::size_t i = 0; i < n; ++i)
      EXPECT_LE(norm(kernel().evaluate(c, std::fmin(t[i] / t[n - 1], 1.0)) - points[i]), kRel * c.model_size())
          << "trial " << trial << ", point " << i;
    EXPECT_LE(relative_deviation(kernel(), c, r), kRel) << "trial " << trial << ", n = " << n;
  }
  const std::vector<Vec3> pts{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 1, 0}};
  HULA_EXPECT_ERROR(kernel().interpolate(pts, {}), Errc::CoincidentPoints, "points[1] and points[2]");
  HULA_EXPECT_ERROR(kernel().interpolate(std::vector<Vec3>{{0, 0, 0}}, {}), Errc::TooFewPoints, "2 points");
  KernelInterpolation one;
  one.start_tangent = Vec3{1, 0, 0};
  HULA_EXPECT_ERROR(kernel().interpolate(pts, one), Errc::InvalidArgument, "end_tangent");
}

// checks curvature against the other backend on random curves and κ = 1/R on a rational circle
TEST_P(KernelConformance, CurvatureMatchesOtherBackendAndCircle) {
  for (const auto& c : random_curves(18)) {
    if (c.degree() < 2) continue;
    for (double t : sample_parameters(c)) {
      const double a = kernel().curvature(c, t), b = reference().curvature(c, t);
      if (std::isnan(b)) {
        EXPECT_TRUE(std::isnan(a)) << "t = " << t;
        continue;
      }
      EXPECT_LE(std::fabs(a - b), kRel * std::fmax(b, 1.0 / c.model_size())) << "t = " << t;
    }
  }
  const auto circle = testing::rational_circle(2.5, 0.3);
  for (double t : sample_parameters(circle)) EXPECT_NEAR(kernel().curvature(circle, t), 1.0 / 2.5, kRel / 2.5);
}

// checks arc length against 2πR on a circle and against the other backend on random curves
TEST_P(KernelConformance, ArcLengthMatchesCircleAndOtherBackend) {
  const auto circle = testing::rational_circle(2.5);
  EXPECT_NEAR(kernel().arc_length(circle, 0.0, 1.0), 2 * std::numbers::pi * 2.5, kRel * 2 * std::numbers::pi * 2.5);
  for (const auto& c : random_curves(19)) {
    const auto d = c.domain();
    const double a = d.start + 0.1 * d.length(), b = d.end;
    const double s = kernel().arc_length(c, a, b), r = reference().arc_length(c, a, b);
    EXPECT_LE(std::fabs(s - r), kRel * r) << "degree " << c.degree() << (c.is_rational() ? " rational" : "");
  }
  HULA_EXPECT_ERROR(kernel().arc_length(circle, 0.5, 0.25), Errc::InvalidArgument, "greater than");
}

// checks torsion: the native backend gives the helix's τ = c / (r² + c²); a backend without torsion
// throws Unsupported naming "torsion" and with_fallback answers from native, saying so
TEST_P(KernelConformance, TorsionOrUnsupportedWithFallback) {
  // Helix r(t) = (R cos t, R sin t, h t) on [0, 1] interpolated densely with clamped end tangents.
  const double R = 2.0, h = 0.5;
  std::vector<Vec3> pts;
  std::vector<double> ts;
  for (int i = 0; i <= 60; ++i) {
    const double t = i / 60.0;
    pts.push_back({R * std::cos(t), R * std::sin(t), h * t});
    ts.push_back(t);
  }
  KernelInterpolation o;
  o.parameters = ts;
  o.start_tangent = Vec3{0, R, h};
  o.end_tangent = Vec3{-R * std::sin(1.0), R * std::cos(1.0), h};
  const auto helix = native_kernel().interpolate(pts, o);
  const double expected = h / (R * R + h * h);
  const auto answer = with_fallback(kernel(), [&](const Kernel& k) { return k.torsion(helix, 0.5); });
  EXPECT_NEAR(answer.value, expected, 1e-4 * expected);  // the spline approximates the helix to O(h^2) in τ
  if (kernel().name() == "native") {
    EXPECT_EQ(answer.backend, "native");
    EXPECT_FALSE(answer.fallback.has_value());
  } else {
    HULA_EXPECT_ERROR(kernel().torsion(helix, 0.5), Errc::Unsupported, "torsion: not supported by the occt backend");
    EXPECT_EQ(answer.backend, "native");
    ASSERT_TRUE(answer.fallback.has_value());
    EXPECT_NE(answer.fallback->find("torsion"), std::string::npos);
    EXPECT_NE(answer.fallback->find("native"), std::string::npos);
  }
}

INSTANTIATE_TEST_SUITE_P(Backends, KernelConformance, ::testing::ValuesIn(kernel_names()),
                         [](const auto& param_info) { return param_info.param; });

// checks the registry refuses an unknown backend naming it and the known ones
TEST(KernelRegistry, RefusesUnknownBackendNamingKnownOnes) {
  HULA_EXPECT_ERROR(make_kernel("acis"), Errc::InvalidArgument, "unknown kernel backend 'acis'");
  HULA_EXPECT_ERROR(make_kernel("acis"), Errc::InvalidArgument, "native");
  EXPECT_EQ(make_kernel("native")->name(), "native");
#ifdef HULA_WITH_OCCT
  EXPECT_EQ(make_kernel("occt")->name(), "occt");
#endif
}

}  // namespace
}  // namespace hula::oli
