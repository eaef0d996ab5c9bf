// SPDX-License-Identifier: MIT
// Arc length against closed forms (straight line, rational circle, half
// quarter-arc) and an independent reference (Boost.Math's adaptive
// Gauss–Kronrod-61 on a hand-written Bézier hodograph); parameter_at_length
// inverts arc_length; documented errors.
#include "hula/nurbs/arc_length.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <cstdlib>
#include <new>
#include <numbers>
#include <string>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/testing/counting_allocator.hpp"
#include "hula/testing/curve_generators.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::nurbs {
namespace {

const std::vector<Vec3> kBezier = {{0, 0, 0}, {1, 3, 0}, {4, -2, 0}, {5, 1, 0}};

// Independent speed of the cubic Bézier kBezier: |3 Σ (P_{i+1} - P_i) B_{i,2}(t)|.
double bezier_speed(double t) {
  const double b[3] = {(1 - t) * (1 - t), 2 * t * (1 - t), t * t};
  double x = 0, y = 0;
  for (int i = 0; i < 3; ++i) {
    x += 3 * (kBezier[i + 1].x - kBezier[i].x) * b[i];
    y += 3 * (kBezier[i + 1].y - kBezier[i].y) * b[i];
  }
  return std::hypot(x, y);
}

// checks: a cubic with collinear, unevenly spaced control points has length |P3 - P0| (closed form).
TEST(ArcLength, StraightLine) {
  const NurbsCurve c(3, {0, 0, 0, 0, 0.3, 1, 1, 1, 1},
                     {{0, 0, 0}, {0.3, 0.4, 0}, {0.6, 0.8, 0}, {2.7, 3.6, 0}, {3, 4, 0}});
  EXPECT_NEAR(arc_length(c) / 5.0, 1.0, 1e-12);
}

// checks: the four-arc rational quadratic circle has length 2πR and its first eighth πR/4 (closed form).
TEST(ArcLength, RationalCircle) {
  for (double R : {1.0, 7.5, 1e-100, 1e100}) {
    const NurbsCurve c = testing::rational_circle(R);
    EXPECT_NEAR(arc_length(c) / (2 * std::numbers::pi * R), 1.0, 1e-12) << R;
    EXPECT_NEAR(arc_length(c, 0.0, 0.125) / (std::numbers::pi * R / 4), 1.0, 1e-12) << R;
    EXPECT_NEAR(arc_length(c, 0.1, 0.6) + arc_length(c, 0.6, 1.0), arc_length(c, 0.1, 1.0), 1e-12 * R) << R;
  }
}

// checks: a planar cubic Bézier against Boost.Math gauss_kronrod<61> of an independently coded hodograph.
TEST(ArcLength, CubicBezierAgainstBoost) {
  const NurbsCurve c(3, {0, 0, 0, 0, 1, 1, 1, 1}, kBezier);
  double err = 0;
  const double reference =
      boost::math::quadrature::gauss_kronrod<double, 61>::integrate(bezier_speed, 0.0, 1.0, 12, 1e-14, &err);
  ASSERT_LT(err, 1e-13 * reference);
  EXPECT_NEAR(arc_length(c) / reference, 1.0, 1e-12);
  const double part =
      boost::math::quadrature::gauss_kronrod<double, 61>::integrate(bezier_speed, 0.2, 0.7, 12, 1e-14, &err);
  EXPECT_NEAR(arc_length(c, 0.2, 0.7) / part, 1.0, 1e-12);
  EXPECT_NEAR(arc_length(c, {.tolerance = 1e-6}) / reference, 1.0, 1e-6);
}

// checks: parameter_at_length inverts arc_length to 1e-10 (both directions) on the Bézier and the circle.
TEST(ArcLength, ParameterAtLengthInverts) {
  for (const NurbsCurve& c : {NurbsCurve(3, {0, 0, 0, 0, 1, 1, 1, 1}, kBezier), testing::rational_circle(3.0)}) {
    const double L = arc_length(c);
    for (int i = 0; i <= 40; ++i) {
      const double s = L * i / 40.0;
      const double t = parameter_at_length(c, s);
      EXPECT_NEAR(arc_length(c, 0.0, t), s, 1e-10 * L) << "s = " << s;
      const double t2 = (i + 0.5) / 41.0;
      EXPECT_NEAR(parameter_at_length(c, arc_length(c, 0.0, t2)), t2, 1e-10) << "t = " << t2;
    }
  }
  EXPECT_NEAR(parameter_at_length(testing::rational_circle(2.0), std::numbers::pi / 2), 0.125, 1e-12);
}

// checks: documented errors carry their code and name the offending value.
TEST(ArcLength, ErrorsNameTheInput) {
  const NurbsCurve c = testing::rational_circle(1.0);
  HULA_EXPECT_ERROR(parameter_at_length(c, -0.5), Errc::OutOfDomain, "s = -0.5");
  HULA_EXPECT_ERROR(parameter_at_length(c, 7.0), Errc::OutOfDomain, "s = 7");
  HULA_EXPECT_ERROR(parameter_at_length(c, NAN), Errc::NonFiniteInput, "s = nan");
  HULA_EXPECT_ERROR(arc_length(c, 0.5, 0.25), Errc::InvalidArgument, "a = 0.5");
  HULA_EXPECT_ERROR(arc_length(c, -1.0, 0.25), Errc::OutOfDomain, "a = -1");
  HULA_EXPECT_ERROR(arc_length(c, 0.0, 1.5), Errc::OutOfDomain, "b = 1.5");
  HULA_EXPECT_ERROR(arc_length(c, {.tolerance = 0.0}), Errc::InvalidOption, "options.tolerance = 0");
  HULA_EXPECT_ERROR(arc_length(c, {.tolerance = 0.5}), Errc::InvalidOption, "options.tolerance = 0.5");
  // A speed beyond double range (1e300 coordinates on a 1e-20 domain) is reported, not integrated.
  const NurbsCurve huge(1, {0, 0, 1e-20, 1e-20}, {{0, 0, 0}, {1e300, 0, 0}});
  HULA_EXPECT_ERROR(arc_length(huge), Errc::NumericalFailure, "overflow");
  EXPECT_EQ(parameter_at_length(c, 0.0), 0.0);
  EXPECT_NEAR(parameter_at_length(c, arc_length(c)), 1.0, 1e-12);
}

// checks: the integration loop does not allocate per evaluation: a 1e-6 and a 1e-14 run (many more
// speed evaluations) make the same number of allocations (counting allocator).
TEST(ArcLength, IntegrationLoopIsAllocationFree) {
  const NurbsCurve c(3, {0, 0, 0, 0, 0.2, 0.7, 1, 1, 1, 1},
                     {{0, 0, 0}, {1, 3, 0}, {4, -2, 1}, {5, 1, 0}, {7, 7, 2}, {8, 0, 0}});
  (void)arc_length(c);  // builds the evaluation cache
  const auto count = [&](double tolerance) {
    const long before = testing::allocation_count();
    (void)arc_length(c, {.tolerance = tolerance});
    return testing::allocation_count() - before;
  };
  EXPECT_GT(count(1e-6), 0);  // the counter is live
  EXPECT_EQ(count(1e-6), count(1e-14));
  const auto count_inverse = [&](double s) {
    const long before = testing::allocation_count();
    (void)parameter_at_length(c, s);
    return testing::allocation_count() - before;
  };
  EXPECT_EQ(count_inverse(1.0), count_inverse(7.0));
}

// Curves of 20,000 spans: their lengths are computed on several threads.
constexpr std::size_t kSpans = 20000;

// The length on 1, 2 and all threads, which must be the same double; returns it.
double length_on_any_threads(const NurbsCurve& c, double a, double b, double tolerance = 1e-12) {
  const double one = arc_length(c, a, b, {.tolerance = tolerance, .threads = 1});
  EXPECT_EQ(arc_length(c, a, b, {.tolerance = tolerance, .threads = 2}), one);
  EXPECT_EQ(arc_length(c, a, b, {.tolerance = tolerance, .threads = 0}), one);
  return one;
}

// A chain of cubic Bézier arcs along the helix (cos θ, sin θ, θ / 10), 64 arcs a turn, each with the
// circular-arc handles (4/3) tan(Δθ / 4), joined at interior knots of multiplicity 3 (one span each).
std::vector<Vec3> helix_bezier_chain() {
  const double dt = 2.0 * std::numbers::pi / 64.0;
  const double handle = 4.0 / 3.0 * std::tan(dt / 4.0);
  const auto at = [](double t) { return Vec3{std::cos(t), std::sin(t), 0.1 * t}; };
  const auto tangent = [](double t) { return Vec3{-std::sin(t), std::cos(t), 0.1}; };
  std::vector<Vec3> P;
  for (std::size_t k = 0; k < kSpans; ++k) {
    const double t0 = dt * static_cast<double>(k), t1 = t0 + dt;
    if (k == 0) P.push_back(at(t0));
    P.push_back(at(t0) + handle * tangent(t0));
    P.push_back(at(t1) - handle * tangent(t1));
    P.push_back(at(t1));
  }
  return P;
}

// Knots 0…N with the ends of multiplicity p + 1 and the interior ones of multiplicity m.
std::vector<double> chain_knots(int p, int m) {
  std::vector<double> U;
  for (std::size_t k = 0; k <= kSpans; ++k)
    for (int r = 0; r < (k == 0 || k == kSpans ? p + 1 : m); ++r) U.push_back(static_cast<double>(k));
  return U;
}

// checks: on 20,000-span curves (lengths computed on several threads) the length is the same double on
// 1, 2 and all threads, for the whole curve and a part, and meets the closed forms: a straight cubic
// (|P_n − P_0|), a circle of 20,000 rational quadratic arcs (2πR), and a chain of 20,000 cubic Bézier arcs
// along a helix against Boost.Math's gauss_kronrod<61> of each arc's hand-coded hodograph.
TEST(ArcLength, ManySpansSameOnAnyThreadCountAndClosedForms) {
  // Straight: control points on a line at uniform knots (the cubic is the segment itself).
  const std::size_t n = kSpans + 3;
  std::vector<double> U(n + 4);
  for (std::size_t i = 0; i < U.size(); ++i) U[i] = static_cast<double>(std::min(std::max<std::size_t>(i, 3), n)) - 3.0;
  std::vector<Vec3> L(n);
  for (std::size_t i = 0; i < n; ++i) L[i] = Vec3{1.0, 2.0, 2.0} * static_cast<double>(i);
  const NurbsCurve line(3, U, L);
  const double line_length = 3.0 * static_cast<double>(n - 1);
  EXPECT_NEAR(length_on_any_threads(line, 0.0, static_cast<double>(kSpans)) / line_length, 1.0, 1e-12);
  // Circle: arc k from θ_k to θ_k+1 has poles (cos, sin) θ_k, (cos, sin) θ_mid / cos(Δθ/2) (weight
  // cos(Δθ/2)), (cos, sin) θ_k+1.
  const double R = 3.5;
  const double dth = 2.0 * std::numbers::pi / static_cast<double>(kSpans);
  std::vector<Vec3> C;
  std::vector<double> W;
  for (std::size_t k = 0; k < kSpans; ++k) {
    const double t0 = dth * static_cast<double>(k);
    if (k == 0) {
      C.push_back({R, 0.0, 0.0});
      W.push_back(1.0);
    }
    const double tm = t0 + 0.5 * dth, t1 = t0 + dth;
    C.push_back(Vec3{std::cos(tm), std::sin(tm), 0.0} * (R / std::cos(0.5 * dth)));
    W.push_back(std::cos(0.5 * dth));
    C.push_back(Vec3{std::cos(t1), std::sin(t1), 0.0} * R);
    W.push_back(1.0);
  }
  const NurbsCurve circle(2, chain_knots(2, 2), C, W);
  const double N = static_cast<double>(kSpans);
  EXPECT_NEAR(length_on_any_threads(circle, 0.0, N) / (2.0 * std::numbers::pi * R), 1.0, 1e-12);
  EXPECT_NEAR(length_on_any_threads(circle, 0.25 * N + 0.5, 0.75 * N + 0.5) / (std::numbers::pi * R), 1.0, 1e-12);
  // Helix chain against Boost's adaptive Gauss–Kronrod-61 of each arc's hodograph, summed in long double.
  const std::vector<Vec3> H = helix_bezier_chain();
  const NurbsCurve helix(3, chain_knots(3, 3), H);
  long double reference = 0.0L;
  for (std::size_t k = 0; k < kSpans; ++k) {
    const Vec3* q = &H[3 * k];
    const auto speed = [q](double t) {
      const double b[3] = {(1 - t) * (1 - t), 2 * t * (1 - t), t * t};
      Vec3 d{};
      for (int i = 0; i < 3; ++i) d += (3.0 * b[i]) * (q[i + 1] - q[i]);
      return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
    };
    double err = 0.0;
    reference += boost::math::quadrature::gauss_kronrod<double, 61>::integrate(speed, 0.0, 1.0, 12, 1e-15, &err);
  }
  const double helix_length = length_on_any_threads(helix, 0.0, N);
  EXPECT_NEAR(helix_length / static_cast<double>(reference), 1.0, 1e-12);
  // The helix itself is 2π √(1 + 0.01) a turn: the chain is within its arcs' approximation error.
  EXPECT_NEAR(helix_length / (N / 64.0 * 2.0 * std::numbers::pi * std::sqrt(1.01)), 1.0, 1e-5);
}

// checks: where the evaluation budget runs out (20,000 quadratic spans, each with a cusp at a third of
// the span, where the speed |C'| has a kink and bisection converges slowly), the error is the same —
// code and message, with its evaluation count — on 1, 2 and all threads; at a looser tolerance the length
// converges to the closed form 5/3 per span on every thread count.
TEST(ArcLength, ManySpansBudgetErrorSameOnAnyThreadCount) {
  // Span k: x(t) = P0 + (u (2 t (1 − t)) − u t²) along u, out by 1/3 then back by 4/3 (C' = 0 at t = 1/3).
  const Vec3 u{1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0};
  std::vector<Vec3> P;
  for (std::size_t k = 0; k < kSpans; ++k) {
    const Vec3 p0 = -static_cast<double>(k) * u;
    if (k == 0) P.push_back(p0);
    P.push_back(p0 + u);
    P.push_back(p0 - u);
  }
  const NurbsCurve c(2, chain_knots(2, 2), P);
  const double N = static_cast<double>(kSpans);
  EXPECT_NEAR(length_on_any_threads(c, 0.0, N, 1e-3) / (5.0 / 3.0 * N), 1.0, 1e-3);
  std::string messages[3];
  const std::size_t threads[3] = {1, 2, 0};
  for (int i = 0; i < 3; ++i) {
    try {
      (void)arc_length(c, {.tolerance = 1e-12, .threads = threads[i]});
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), Errc::NumericalFailure);
      messages[i] = e.what();
    }
  }
  EXPECT_NE(messages[0].find("within the recursion budget"), std::string::npos) << messages[0];
  EXPECT_EQ(messages[1], messages[0]);
  EXPECT_EQ(messages[2], messages[0]);
}

}  // namespace
}  // namespace hula::nurbs
