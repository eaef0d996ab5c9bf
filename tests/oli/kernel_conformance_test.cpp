// SPDX-License-Identifier: MIT
// The kernel conformance suite (issue 11 item 8): one parameterised suite run
// on every backend of this build ("native", "occt"). Each operation on seeded
// random curves (degree 1–5, rational or not, clamped or not) is checked
// against an independent reference written in this file (Cox–de Boor
// recursion for the basis and its derivatives, the rational quotient rule,
// adaptive Gauss–Legendre arc length, the cubic spline by its slope system),
// so the suite can fail in a build with one backend; when the build has two,
// also against the *other* backend (HulaHoops' nurbs/diffgeom against Open
// CASCADE) to 1e-12 relative; against its defining invariant (knot insertion,
// degree elevation, split and reverse leave the curve unchanged; an
// interpolant passes through its points), and against closed forms (circle:
// κ = 1/R, length 2πR; helix: constant κ and τ). Operations a backend lacks
// must throw Errc::Unsupported naming the operation, and with_fallback must
// then answer from the native backend and say so.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <span>
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

// The other backend of this build, or nullptr when it has one backend (the independent reference below
// is then the only one).
const Kernel* other_backend(const Kernel& k) {
  for (const auto& n : kernel_names())
    if (n != k.name()) return make_kernel(n).get();  // the registry's instances live as long as the process
  return nullptr;
}

// --- The independent reference: no call into the kernel or nurbs/ -------------------------------------------

// N_{i,p}^{(k)}(t) by the Cox–de Boor recursion and its derivative rule (The NURBS Book eqs. 2.5, 2.9), with
// degree-0 functions right-continuous except at the domain end, which takes the last non-empty span.
double basis(std::span<const double> u, std::size_t i, int p, int k, double t, std::size_t span) {
  if (p == 0) return k == 0 && i == span ? 1.0 : 0.0;
  auto ratio = [](double a, double b) { return b == 0.0 ? 0.0 : a / b; };
  const auto q = static_cast<std::size_t>(p);
  if (k > 0)
    return p * (ratio(basis(u, i, p - 1, k - 1, t, span), u[i + q] - u[i]) -
                ratio(basis(u, i + 1, p - 1, k - 1, t, span), u[i + q + 1] - u[i + 1]));
  return ratio(t - u[i], u[i + q] - u[i]) * basis(u, i, p - 1, 0, t, span) +
         ratio(u[i + q + 1] - t, u[i + q + 1] - u[i + 1]) * basis(u, i + 1, p - 1, 0, t, span);
}

// The point and its derivatives to order `orders` (≤ 3) at t: the homogeneous derivatives A^(k), w^(k) from the basis,
// then C^(k) = (A^(k) - sum over j = 1..k of binom(k, j) w^(j) C^(k-j)) / w (The NURBS Book eq. 4.8).
std::array<Vec3, 4> reference_derivatives(const NurbsCurve& c, double t, std::size_t orders = 3) {
  const auto u = c.knots().values();
  const auto first_above = static_cast<std::size_t>(std::upper_bound(u.begin(), u.end(), t) - u.begin());
  const auto first_at = static_cast<std::size_t>(std::lower_bound(u.begin(), u.end(), t) - u.begin());
  const std::size_t span = (t >= c.domain().end ? first_at : first_above) - 1;
  const auto pts = c.control_points();
  const auto w = c.weights();
  std::array<Vec3, 4> a{}, out{};
  std::array<double, 4> wd{};
  // Only N_{span-p..span} are non-zero at t.
  const auto p = static_cast<std::size_t>(c.degree());
  for (std::size_t i = span >= p ? span - p : 0; i <= span && i < pts.size(); ++i) {
    const double wi = w.empty() ? 1.0 : w[i];
    for (std::size_t k = 0; k <= orders; ++k) {
      const double n = basis(u, i, c.degree(), static_cast<int>(k), t, span);
      a[k] = a[k] + (n * wi) * pts[i];
      wd[k] += n * wi;
    }
  }
  constexpr std::array<std::array<double, 4>, 4> binom{{{1, 0, 0, 0}, {1, 1, 0, 0}, {1, 2, 1, 0}, {1, 3, 3, 1}}};
  for (std::size_t k = 0; k <= orders; ++k) {
    Vec3 v = a[k];
    for (std::size_t j = 1; j <= k; ++j) v = v - (binom[k][j] * wd[j]) * out[k - j];
    out[k] = (1.0 / wd[0]) * v;
  }
  return out;
}

double reference_curvature(const NurbsCurve& c, double t) {
  const auto d = reference_derivatives(c, t);
  const double speed = norm(d[1]);
  return speed == 0.0 ? std::nan("") : norm(cross(d[1], d[2])) / (speed * speed * speed);
}

// The integral of |C'| on [a, b]: adaptive 5-point Gauss–Legendre within each knot span, a panel accepted
// when its two halves agree with it to 1e-14 relative (or at 12 halvings).
double reference_arc_length(const NurbsCurve& c, double a, double b) {
  const double r = std::sqrt(5.0 - 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
  const double s = std::sqrt(5.0 + 2.0 * std::sqrt(10.0 / 7.0)) / 3.0;
  const std::array<double, 5> x{-s, -r, 0.0, r, s};
  const double wr = (322.0 + 13.0 * std::sqrt(70.0)) / 900.0, ws = (322.0 - 13.0 * std::sqrt(70.0)) / 900.0;
  const std::array<double, 5> w{ws, wr, 128.0 / 225.0, wr, ws};
  auto panel = [&](double lo, double hi) {
    double sum = 0.0;
    for (std::size_t g = 0; g < 5; ++g)
      sum += w[g] * norm(reference_derivatives(c, 0.5 * (lo + hi) + 0.5 * (hi - lo) * x[g], 1)[1]);
    return 0.5 * (hi - lo) * sum;
  };
  auto adapt = [&](auto&& self, double lo, double hi, double whole, int depth) -> double {
    const double mid = 0.5 * (lo + hi), left = panel(lo, mid), right = panel(mid, hi);
    if (depth >= 12 || std::fabs(left + right - whole) <= 1e-14 * std::fabs(whole)) return left + right;
    return self(self, lo, mid, left, depth + 1) + self(self, mid, hi, right, depth + 1);
  };
  std::vector<double> cuts{a};
  for (double k : c.knots().values())
    if (k > a && k < b && k != cuts.back()) cuts.push_back(k);
  cuts.push_back(b);
  double total = 0.0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
    total += adapt(adapt, cuts[i], cuts[i + 1], panel(cuts[i], cuts[i + 1]), 0);
  return total;
}

// The interpolant KernelInterpolation defines, built without the kernel: per coordinate the C2 cubic with
// knots at the data parameters t_i (on [0, 1]) and end slopes given or, without tangents, those of the
// Lagrange polynomial of degree min(3, N - 1) through the end points; its interior slopes from the
// tridiagonal system h_i s_{i-1} + 2 (h_{i-1} + h_i) s_i + h_{i-1} s_{i+1} = 3 (h_i d_{i-1} + h_{i-1} d_i)
// (d_i the chord slopes), evaluated as cubic Hermite pieces.
struct ReferenceSpline {
  std::vector<double> t;
  std::vector<Vec3> q, slope;
  Vec3 operator()(double x) const {
    std::size_t i = 0;
    while (i + 2 < t.size() && x >= t[i + 1]) ++i;
    const double h = t[i + 1] - t[i], v = (x - t[i]) / h;
    const double h00 = (1 + 2 * v) * (1 - v) * (1 - v), h10 = v * (1 - v) * (1 - v), h01 = v * v * (3 - 2 * v);
    const double h11 = v * v * (v - 1);
    return h00 * q[i] + (h10 * h) * slope[i] + h01 * q[i + 1] + (h11 * h) * slope[i + 1];
  }
};

// The derivative at t[at] of the Lagrange polynomial through (t, q).
Vec3 lagrange_slope(std::span<const Vec3> q, std::span<const double> t, std::size_t at) {
  Vec3 sum{0, 0, 0};
  for (std::size_t j = 0; j < q.size(); ++j) {
    double lj = 0.0;
    if (j == at) {
      for (std::size_t k = 0; k < q.size(); ++k)
        if (k != at) lj += 1.0 / (t[at] - t[k]);
    } else {
      lj = 1.0;
      for (std::size_t k = 0; k < q.size(); ++k) {
        if (k != j) lj /= t[j] - t[k];
        if (k != j && k != at) lj *= t[at] - t[k];
      }
    }
    sum = sum + lj * q[j];
  }
  return sum;
}

ReferenceSpline reference_interpolant(const std::vector<Vec3>& points, const KernelInterpolation& o) {
  const std::size_t n = points.size();
  ReferenceSpline r{std::vector<double>(n, 0.0), points, std::vector<Vec3>(n, Vec3{0, 0, 0})};
  for (std::size_t i = 1; i < n; ++i)
    r.t[i] = o.parameters.empty() ? r.t[i - 1] + norm(points[i] - points[i - 1]) : o.parameters[i] - o.parameters[0];
  const double total = r.t[n - 1];
  for (double& x : r.t) x /= total;
  r.t[n - 1] = 1.0;
  const std::size_t m = std::min<std::size_t>(4, n);
  const std::span<const Vec3> q(points);
  const std::span<const double> ts(r.t);
  r.slope[0] = o.start_tangent ? *o.start_tangent : lagrange_slope(q.first(m), ts.first(m), 0);
  r.slope[n - 1] = o.end_tangent ? *o.end_tangent : lagrange_slope(q.last(m), ts.last(m), m - 1);
  if (n > 2) {  // the Thomas algorithm on the interior slopes
    const std::size_t k = n - 2;
    std::vector<double> diag(k), lower(k), upper(k);
    std::vector<Vec3> rhs(k);
    for (std::size_t j = 0; j < k; ++j) {
      const std::size_t i = j + 1;
      const double h0 = r.t[i] - r.t[i - 1], h1 = r.t[i + 1] - r.t[i];
      lower[j] = h1;
      diag[j] = 2.0 * (h0 + h1);
      upper[j] = h0;
      rhs[j] = (3.0 * h1 / h0) * (points[i] - points[i - 1]) + (3.0 * h0 / h1) * (points[i + 1] - points[i]);
    }
    rhs[0] = rhs[0] - lower[0] * r.slope[0];
    rhs[k - 1] = rhs[k - 1] - upper[k - 1] * r.slope[n - 1];
    for (std::size_t j = 1; j < k; ++j) {
      const double f = lower[j] / diag[j - 1];
      diag[j] -= f * upper[j - 1];
      rhs[j] = rhs[j] - f * rhs[j - 1];
    }
    for (std::size_t j = k; j-- > 0;)
      r.slope[j + 1] = (1.0 / diag[j]) * (rhs[j] - (j + 1 < k ? upper[j] * r.slope[j + 2] : Vec3{0, 0, 0}));
  }
  return r;
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
  const Kernel* other() const { return other_backend(kernel()); }
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

// checks position and derivatives to order 3 against the independent Cox–de Boor reference and the other
// backend, 1e-12 relative to each derivative's scale model_size / L^k (1e-11 for the reference's third
// derivative)
TEST_P(KernelConformance, DerivativesMatchTheReferences) {
  for (const auto& c : random_curves(12)) {
    const double L = c.domain().length();
    for (double t : sample_parameters(c)) {
      const auto d = kernel().derivatives(c, t, 3);
      ASSERT_EQ(d.size(), 4U);
      const auto independent = reference_derivatives(c, t);
      std::vector<std::vector<Vec3>> references{std::vector<Vec3>(independent.begin(), independent.end())};
      if (other() != nullptr) references.push_back(other()->derivatives(c, t, 3));
      for (std::size_t which = 0; which < references.size(); ++which) {
        const auto& r = references[which];
        EXPECT_LE(norm(kernel().evaluate(c, t) - r[0]), kRel * c.model_size()) << "t = " << t;
        for (std::size_t k = 0; k <= 3; ++k) {
          const double scale = std::fmax(norm(r[k]), c.model_size() / std::pow(L, static_cast<double>(k)));
          // The quotient rule of the independent reference loses a few digits on C''' of a rational curve.
          const double tolerance = which == 0 && k == 3 ? 1e-11 : kRel;
          EXPECT_LE(norm(d[k] - r[k]), tolerance * scale)
              << kernel().name() << " order " << k << " at t = " << t << " degree " << c.degree()
              << (which == 0 ? " (independent)" : " (other backend)");
        }
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

// checks interpolation passes through its points and equals the independent cubic spline (and the other
// backend's interpolant), with and without end tangents and with given parameters
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
    const ReferenceSpline spline = reference_interpolant(points, o);
    EXPECT_EQ(c.domain().start, 0.0);
    EXPECT_EQ(c.domain().end, 1.0);
    // The data parameters: the given ones mapped to [0, 1], else the normalised chord length (eq. 29).
    std::vector<double> t(n, 0.0);
    for (std::size_t i = 1; i < n; ++i)
      t[i] = o.parameters.empty() ? t[i - 1] + norm(points[i] - points[i - 1]) : o.parameters[i] - o.parameters[0];
    for (std::size_t i = 0; i < n; ++i)
      EXPECT_LE(norm(kernel().evaluate(c, std::fmin(t[i] / t[n - 1], 1.0)) - points[i]), kRel * c.model_size())
          << "trial " << trial << ", point " << i;
    for (double u : sample_parameters(c, 64))
      EXPECT_LE(norm(kernel().evaluate(c, u) - spline(u)), 1e-11 * c.model_size())
          << "trial " << trial << ", u = " << u;
    if (other() != nullptr) {
      EXPECT_LE(relative_deviation(kernel(), c, other()->interpolate(points, o)), kRel)
          << "trial " << trial << ", n = " << n;
    }
  }
  const std::vector<Vec3> pts{{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {2, 1, 0}};
  HULA_EXPECT_ERROR(kernel().interpolate(pts, {}), Errc::CoincidentPoints, "points[1] and points[2]");
  HULA_EXPECT_ERROR(kernel().interpolate(std::vector<Vec3>{{0, 0, 0}}, {}), Errc::TooFewPoints, "2 points");
  KernelInterpolation one;
  one.start_tangent = Vec3{1, 0, 0};
  HULA_EXPECT_ERROR(kernel().interpolate(pts, one), Errc::InvalidArgument, "end_tangent");
}

// checks curvature against the independent reference and the other backend on random curves and κ = 1/R on
// a rational circle
TEST_P(KernelConformance, CurvatureMatchesReferencesAndCircle) {
  for (const auto& c : random_curves(18)) {
    if (c.degree() < 2) continue;
    for (double t : sample_parameters(c)) {
      const double a = kernel().curvature(c, t);
      std::vector<double> references{reference_curvature(c, t)};
      if (other() != nullptr) references.push_back(other()->curvature(c, t));
      for (const double b : references) {
        if (std::isnan(b)) {
          EXPECT_TRUE(std::isnan(a)) << "t = " << t;
          continue;
        }
        EXPECT_LE(std::fabs(a - b), kRel * std::fmax(b, 1.0 / c.model_size())) << "t = " << t;
      }
    }
  }
  const auto circle = testing::rational_circle(2.5, 0.3);
  for (double t : sample_parameters(circle)) EXPECT_NEAR(kernel().curvature(circle, t), 1.0 / 2.5, kRel / 2.5);
}

// checks arc length against 2πR on a circle and against the independent quadrature and the other backend on
// random curves
TEST_P(KernelConformance, ArcLengthMatchesCircleAndReferences) {
  const auto circle = testing::rational_circle(2.5);
  EXPECT_NEAR(kernel().arc_length(circle, 0.0, 1.0), 2 * std::numbers::pi * 2.5, kRel * 2 * std::numbers::pi * 2.5);
  for (const auto& c : random_curves(19)) {
    const auto d = c.domain();
    const double a = d.start + 0.1 * d.length(), b = d.end;
    const double s = kernel().arc_length(c, a, b), r = reference_arc_length(c, a, b);
    EXPECT_LE(std::fabs(s - r), kRel * r) << "degree " << c.degree() << (c.is_rational() ? " rational" : "");
    if (other() != nullptr) {
      EXPECT_LE(std::fabs(s - other()->arc_length(c, a, b)), kRel * r);
    }
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
