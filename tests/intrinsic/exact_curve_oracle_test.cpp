// SPDX-License-Identifier: MIT
// Natural curves are exact curve values (issue 26 item 1): their analysis
// (diffgeom on the curve::Curve) against closed forms written here, never the
// library's own — log-aesthetic curves of many slopes (κ and κ' to 1e-12, the
// logarithmic curvature graph a line of slope α to 1e-10), clothoids and a G2
// clothoid spline against the Fresnel integrals (their Maclaurin series in
// long double) to 1e-12, the helix's frame to 1e-10 and its derivatives of
// order ≤ 6; features at the laws' roots; the curve file round trip and the
// conversion to NURBS on request.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "hula/diffgeom/features.hpp"
#include "hula/diffgeom/fins.hpp"
#include "hula/diffgeom/frenet.hpp"
#include "hula/diffgeom/plot.hpp"
#include "hula/intrinsic/clothoid.hpp"
#include "hula/intrinsic/log_aesthetic.hpp"
#include "hula/intrinsic/natural_curve.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::intrinsic {
namespace {

// Fresnel integrals C(x) + i S(x) by their Maclaurin series in long double (A&S 7.3.11, 7.3.13):
// C = Σ (−1)^n (π/2)^(2n) x^(4n+1)/((2n)! (4n+1)), S = Σ (−1)^n (π/2)^(2n+1) x^(4n+3)/((2n+1)! (4n+3)).
std::complex<long double> fresnel_series(long double x) {
  const long double z = 0.5L * std::numbers::pi_v<long double> * x * x;
  long double c = 0, s = 0, term = x;  // term = z^k x / k!
  for (int k = 0; k < 80; ++k) {
    const long double t = term / (2 * k + 1);
    if (k % 4 == 0) c += t;
    if (k % 4 == 1) s += t;
    if (k % 4 == 2) c -= t;
    if (k % 4 == 3) s -= t;
    term *= z / (k + 1);
  }
  return {c, s};
}

// The clothoid θ(σ) = θ0 + κ0 σ + c σ²/2 (c > 0) from p0, at arc length s, by completing the square:
// ∫₀ˢ e^{iθ} = e^{i(θ0 − κ0²/2c)} a [F((s + κ0/c)/a) − F(κ0/(c a))], a = √(π/c), F = C + iS. c = 0 is the
// circle (or line) e^{iθ0} (e^{iκ0 s} − 1)/(iκ0).
Vec3 clothoid_point(const Vec3& p0, double theta0, double kappa0, double c, double s) {
  if (c == 0.0) {
    const std::complex<double> z = kappa0 == 0.0 ? std::polar(s, theta0)
                                                 : std::polar(1.0, theta0) * (std::polar(1.0, kappa0 * s) - 1.0) /
                                                       std::complex<double>(0.0, kappa0);
    return {p0.x + z.real(), p0.y + z.imag(), p0.z};
  }
  const long double a = std::sqrt(std::numbers::pi_v<long double> / c);
  const long double shift = static_cast<long double>(kappa0) / c;
  const std::complex<long double> w = a * (fresnel_series((s + shift) / a) - fresnel_series(shift / a));
  const std::complex<long double> z =
      std::polar(1.0L, static_cast<long double>(theta0) - 0.5L * kappa0 * kappa0 / c) * w;
  return {p0.x + static_cast<double>(z.real()), p0.y + static_cast<double>(z.imag()), p0.z};
}

StartFrame planar_start(const Vec3& p, double theta) {
  return {p, {std::cos(theta), std::sin(theta), 0.0}, {-std::sin(theta), std::cos(theta), 0.0}};
}

struct LogAestheticCase {
  double alpha, rho0, lambda, length;
};

// κ(s) = (ρ0^α + αλs)^(−1/α) (ρ0 e^{λs} for α = 0) and dκ/ds = −λ ρ^(−1−α), written out here.
double la_kappa(const LogAestheticCase& c, double s) {
  if (c.alpha == 0.0) return std::exp(-c.lambda * s) / c.rho0;
  return std::pow(std::pow(c.rho0, c.alpha) + c.alpha * c.lambda * s, -1.0 / c.alpha);
}
double la_kappa_prime(const LogAestheticCase& c, double s) {
  return -c.lambda * std::pow(la_kappa(c, s), 1.0 + c.alpha);
}

// Two generators: the special slopes (with the κ = 1/(1.5 + 0.4 s)) and seeded random ones.
std::vector<LogAestheticCase> log_aesthetic_cases() {
  std::vector<LogAestheticCase> cases = {{1.0, 1.5, 0.4, 6.0}, {-1.0, 2.0, 0.3, 1.5}, {0.0, 1.0, 0.25, 5.0},
                                         {2.0, 0.8, 0.6, 4.0}, {0.5, 1.2, -0.1, 3.0}, {-2.0, 3.0, 0.02, 2.0},
                                         {3.0, 1.0, 0.5, 2.0}};
  std::mt19937_64 rng(2626);
  std::uniform_real_distribution<double> alpha(-3.0, 3.0), rho(0.5, 4.0), lambda(-0.5, 0.5);
  for (int i = 0; i < 12; ++i) {
    LogAestheticCase c{alpha(rng), rho(rng), lambda(rng), 0.0};
    const LogAestheticCurve probe{c.alpha, c.rho0, c.lambda, 1.0};
    c.length = std::min(8.0, 0.8 * probe.max_length());
    cases.push_back(c);
  }
  return cases;
}

curve::Curve la_curve(const LogAestheticCase& c, double theta0) {
  const LogAestheticCurve la{c.alpha, c.rho0, c.lambda, c.length};
  return natural_curve(la.natural_data(planar_start({0.3, -0.2, 0.0}, theta0)), curve::kApproximationTolerance);
}

// checks: the analysis of a log-aesthetic natural curve gives κ and κ' equal to the closed forms to 1e-12
// (relative), at 101 arc lengths, for every slope of both generators — the stand-in NURBS was off by 0.45 %.
TEST(ExactCurve, LogAestheticCurvatureAndRateAreExact) {
  for (const LogAestheticCase& c : log_aesthetic_cases()) {
    SCOPED_TRACE("alpha " + std::to_string(c.alpha) + " rho0 " + std::to_string(c.rho0) + " lambda " +
                 std::to_string(c.lambda));
    const curve::Curve curve = la_curve(c, 0.7);
    std::vector<double> ts(101);
    for (std::size_t i = 0; i < ts.size(); ++i) ts[i] = c.length * static_cast<double>(i) / 100.0;
    std::vector<diffgeom::FrenetPoint> f(ts.size());
    diffgeom::frenet(curve, ts, f);
    for (std::size_t i = 0; i < ts.size(); ++i) {
      const double k = la_kappa(c, ts[i]), kp = la_kappa_prime(c, ts[i]);
      EXPECT_NEAR(f[i].signed_curvature, k, 1e-12 * std::fabs(k)) << "s = " << ts[i];
      EXPECT_NEAR(f[i].curvature, k, 1e-12 * std::fabs(k)) << "s = " << ts[i];
      if (c.lambda != 0.0) {
        EXPECT_NEAR(f[i].curvature_derivative, kp, 1e-12 * std::fabs(kp) + 1e-15 * k * k) << "s = " << ts[i];
      }
      EXPECT_DOUBLE_EQ(f[i].speed, 1.0);
    }
  }
}

// checks: the logarithmic curvature graph of the analysis is a straight line of slope α: the least-squares
// slope to 1e-10, and every local slope between neighbouring samples to 1e-8.
TEST(ExactCurve, LogCurvatureGraphIsAStraightLineOfSlopeAlpha) {
  for (const LogAestheticCase& c : log_aesthetic_cases()) {
    if (c.lambda == 0.0) continue;
    SCOPED_TRACE("alpha " + std::to_string(c.alpha));
    diffgeom::PlotOptions o;
    o.quantity = diffgeom::PlotQuantity::LogCurvatureGraph;
    o.samples = 200;
    const diffgeom::Plot p = diffgeom::plot(la_curve(c, -1.2), o);
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    int n = 0;
    for (std::size_t i = 0; i < p.x.size(); ++i) {
      ASSERT_TRUE(p.defined[i]);
      sx += p.x[i], sy += p.y[i], sxx += p.x[i] * p.x[i], sxy += p.x[i] * p.y[i], ++n;
      if (i > 0) {
        EXPECT_NEAR((p.y[i] - p.y[i - 1]) / (p.x[i] - p.x[i - 1]), c.alpha, 1e-8) << "sample " << i;
      }
    }
    const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
    EXPECT_NEAR(slope, c.alpha, 1e-10);
  }
}

// checks: a clothoid segment written as a natural curve (clothoid_natural_data) lies on the Fresnel closed form
// to 1e-12 at 101 arc lengths (integration tolerance 1e-13 stated), with κ = κ0 + κ' s to rounding.
TEST(ExactCurve, ClothoidMatchesFresnelClosedForm) {
  const ClothoidSegment seg{{1.0, -2.0, 0.0}, 0.3, 0.2, 0.5, 2.0};
  const std::vector<ClothoidSegment> one{seg};
  const curve::Curve c = natural_curve(clothoid_natural_data(one, 1e-13), curve::kApproximationTolerance);
  std::vector<double> ts(101);
  for (std::size_t i = 0; i < ts.size(); ++i) ts[i] = 2.0 * static_cast<double>(i) / 100.0;
  std::vector<diffgeom::FrenetPoint> f(ts.size());
  diffgeom::frenet(c, ts, f);
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const Vec3 want = clothoid_point(seg.start, seg.theta0, seg.kappa0, seg.dkappa, ts[i]);
    EXPECT_LT(distance(f[i].position, want), 1e-12) << "s = " << ts[i];
    EXPECT_NEAR(f[i].signed_curvature, 0.2 + 0.5 * ts[i], 1e-15) << "s = " << ts[i];
    const double theta = 0.3 + 0.2 * ts[i] + 0.25 * ts[i] * ts[i];
    EXPECT_LT(distance(f[i].tangent, Vec3{std::cos(theta), std::sin(theta), 0.0}), 1e-14) << "s = " << ts[i];
  }
}

// checks: the G2 three-clothoid spline of fit_clothoid_g2 as one natural curve: each arc on its own Fresnel
// closed form (from the arc's start data) to 1e-12, the end point on p1, κ continuous at the joins.
TEST(ExactCurve, ClothoidSplineArcsMatchFresnel) {
  const ClothoidG2Result g2 = fit_clothoid_g2({0, 0, 0}, 0.2, 0.5, {4, 1, 0}, -0.3, -0.2);
  const curve::Curve c = natural_curve(clothoid_natural_data(g2.segments, 1e-13), curve::kApproximationTolerance);
  EXPECT_NEAR(c.length(), g2.length(), 1e-15 * g2.length());
  double start = 0.0;
  for (const ClothoidSegment& arc : g2.segments) {
    for (int j = 0; j <= 10; ++j) {
      const double local = arc.length * j / 10.0;
      const Vec3 want =
          arc.dkappa >= 0 ? clothoid_point(arc.start, arc.theta0, arc.kappa0, arc.dkappa, local) : [&] {  // mirror a
                                                                                                          // decreasing
                                                                                                          // curvature:
                                                                                                          // y → −y
                                                                                                          // turns c
                                                                                                          // into −c
            const Vec3 m = clothoid_point({arc.start.x, -arc.start.y, 0}, -arc.theta0, -arc.kappa0, -arc.dkappa, local);
            return Vec3{m.x, -m.y, 0.0};
          }();
      EXPECT_LT(distance(c.point(std::min(start + local, c.length())), want), 1e-11) << "s = " << start + local;
    }
    start += arc.length;
  }
  EXPECT_LT(distance(c.point(c.length()), Vec3{4, 1, 0}), 1e-11);
}

// checks: κ = 0.8, τ = 0.4 (radius 1, pitch 0.5), and a left-handed tight helix and a near-circle (two more
// generators of the same closed form: radius a = κ/(κ² + τ²), pitch b = τ/(κ² + τ²)): the analysis' frame equals
// the helix's closed-form frame to 1e-10 at the default integration tolerance, κ and τ to rounding, and
// Curve::derivatives of order 0 … 6 the closed-form derivatives to 1e-9.
TEST(ExactCurve, HelixFrameAndDerivatives) {
  struct Helix {
    const char* kappa;
    const char* tau;
    double k, t;
  };
  for (const Helix& h :
       {Helix{"0.8", "0.4", 0.8, 0.4}, Helix{"1.5", "-0.9", 1.5, -0.9}, Helix{"0.3", "0.02", 0.3, 0.02}}) {
    SCOPED_TRACE(std::string("kappa ") + h.kappa + " tau " + h.tau);
    curve::NaturalData d;
    d.curvature = h.kappa;
    d.torsion = h.tau;
    d.length = 20.0;
    const curve::Curve c = natural_curve(d, curve::kApproximationTolerance);
    const double w = h.k * h.k + h.t * h.t, a = h.k / w, b = h.t / w, k = std::sqrt(a * a + b * b);
    // The standard helix (a cos φ, a sin φ, bφ), φ = s/k, seen in its start frame (T0, N0, B0) = (X, Y, Z).
    const Vec3 T0{0, a / k, b / k}, N0{-1, 0, 0}, B0{0, -b / k, a / k};
    const auto local = [&](const Vec3& v) { return Vec3{dot(T0, v), dot(N0, v), dot(B0, v)}; };
    std::vector<double> ts(81);
    for (std::size_t i = 0; i < ts.size(); ++i) ts[i] = 20.0 * static_cast<double>(i) / 80.0;
    std::vector<diffgeom::FrenetPoint> f(ts.size());
    diffgeom::frenet(c, ts, f);
    for (std::size_t i = 0; i < ts.size(); ++i) {
      const double phi = ts[i] / k;
      SCOPED_TRACE("s = " + std::to_string(ts[i]));
      EXPECT_LT(distance(f[i].tangent, local(Vec3{-a * std::sin(phi), a * std::cos(phi), b} / k)), 1e-10);
      EXPECT_LT(distance(f[i].normal, local(Vec3{-std::cos(phi), -std::sin(phi), 0})), 1e-10);
      EXPECT_LT(distance(f[i].binormal, local(Vec3{b * std::sin(phi), -b * std::cos(phi), a} / k)), 1e-10);
      EXPECT_NEAR(f[i].curvature, h.k, 1e-15);
      EXPECT_NEAR(f[i].torsion, h.t, 1e-14);
      const std::vector<Vec3> r = c.derivatives(ts[i], 6);
      for (int order = 1; order <= 6; ++order) {
        // d^k/ds^k of (a cos φ, a sin φ, bφ): a/k^k (cos(φ + kπ/2), sin(φ + kπ/2), 0), plus (0, 0, b/k) for k = 1.
        const double g = a / std::pow(k, order), q = phi + order * std::numbers::pi / 2;
        const Vec3 want = local(Vec3{g * std::cos(q), g * std::sin(q), order == 1 ? b / k : 0.0});
        EXPECT_LT(distance(r[static_cast<std::size_t>(order)], want), 1e-9) << "order " << order;
      }
    }
  }
  curve::NaturalData d;
  d.curvature = "0.8";
  d.torsion = "0.4";
  d.length = 20.0;
  const curve::Curve c = natural_curve(d, curve::kApproximationTolerance);
  EXPECT_EQ(c.length(), 20.0);
  EXPECT_EQ(c.length_to(7.5), 7.5);
  EXPECT_EQ(c.parameter_at_length(7.5), 7.5);
  HULA_EXPECT_ERROR((void)c.point(21.0, {.domain = nurbs::Domain::Extrapolate}), Errc::OutOfDomain, "not extrapolated");
}

// checks: features come from the laws: the inflection of κ = s − 1 at s = 1, the curvature maximum of
// κ = 3 − (s − 1.5)² at 1.5, the torsion maximum of τ = sin s at π/2.
TEST(ExactCurve, FeaturesAtTheLawsRoots) {
  curve::NaturalData d;
  d.curvature = "s - 1";
  d.length = 3.0;
  const std::vector<diffgeom::Feature> inflections = diffgeom::inflections(natural_curve(d, 1e-6));
  ASSERT_EQ(inflections.size(), 1U);
  // Located to where |κ| falls below the Frenet resolution (angular tolerance 1e-10 × the curve's scale).
  EXPECT_NEAR(inflections[0].t, 1.0, 1e-10);
  d.curvature = "3 - (s - 1.5)^2";
  const std::vector<diffgeom::Feature> extrema = diffgeom::curvature_extrema(natural_curve(d, 1e-6));
  ASSERT_EQ(extrema.size(), 1U);
  EXPECT_EQ(extrema[0].kind, diffgeom::FeatureKind::CurvatureMaximum);
  EXPECT_NEAR(extrema[0].t, 1.5, 1e-9);
  EXPECT_NEAR(extrema[0].curvature, 3.0, 1e-14);
  d.curvature = "1";
  d.torsion = "sin(s)";
  d.length = 4.0;
  const std::vector<diffgeom::Feature> torsion = diffgeom::torsion_extrema(natural_curve(d, 1e-6));
  ASSERT_EQ(torsion.size(), 1U);
  EXPECT_EQ(torsion[0].kind, diffgeom::FeatureKind::TorsionMaximum);
  EXPECT_NEAR(torsion[0].t, std::numbers::pi / 2, 1e-8);
}

// checks: the curvature fins of a log-aesthetic curve stand κ·scale from the curve, κ the closed form (1e-12).
TEST(ExactCurve, FinsUseTheExactCurvature) {
  const LogAestheticCase c{1.0, 1.5, 0.4, 6.0};
  diffgeom::FinOptions o;
  o.kind = diffgeom::FinKind::Curvature;
  o.scale = 0.5;
  o.density = 50;
  const diffgeom::Fins f = diffgeom::fins(la_curve(c, 0.0), o);
  for (std::size_t i = 0; i < f.t.size(); ++i) {
    ASSERT_TRUE(f.defined[i]);
    EXPECT_NEAR(distance(f.tip[i], f.base[i]), 0.5 * la_kappa(c, f.t[i]), 1e-12) << "s = " << f.t[i];
  }
}

// checks: the curve file stores the laws and the integration tolerance, reads back equal (bit for bit), and a
// file written before the tolerance member reads with the default.
TEST(ExactCurve, CurveFileStoresTheLaws) {
  const LogAestheticCurve la{1.0, 1.5, 0.4, 6.0};
  const curve::Curve c = natural_curve(la.natural_data({}, 1e-12), curve::kApproximationTolerance);
  const io::Json j = io::curve_to_json(c);
  EXPECT_EQ(j["kind"], "natural");
  EXPECT_EQ(j["tolerance"].get<double>(), 1e-12);
  const curve::Curve back = io::curve_from_json(j);
  EXPECT_TRUE(back == c);
  EXPECT_EQ(back.point(3.0).x, c.point(3.0).x);
  io::Json old = j;
  old.erase("tolerance");
  EXPECT_EQ(std::get<curve::NaturalData>(io::curve_from_json(old).data()).tolerance, curve::kNaturalTolerance);
}

// checks: to_nurbs converts on request within the tolerance, measured here against the closed-form helix at
// 1000 arc lengths; a tolerance below the integration's is refused by name.
TEST(ExactCurve, ToNurbsOnRequest) {
  curve::NaturalData d;
  d.curvature = "0.8";
  d.torsion = "0.4";
  d.length = 10.0;
  const curve::Curve c = natural_curve(d, curve::kApproximationTolerance);
  const CurveToNurbsResult n = to_nurbs(c, 1e-8);
  EXPECT_LE(n.max_deviation, 1e-8);
  EXPECT_EQ(n.curve.domain().end, 10.0);
  const double a = 1.0, b = 0.5, k = std::sqrt(a * a + b * b);
  const Vec3 T0{0, a / k, b / k}, N0{-1, 0, 0}, B0{0, -b / k, a / k};
  for (int i = 0; i <= 1000; ++i) {
    const double s = 10.0 * i / 1000.0, phi = s / k;
    const Vec3 v = Vec3{a * std::cos(phi) - a, a * std::sin(phi), b * phi};
    EXPECT_LT(distance(n.curve.derivatives(s, 0)[0], Vec3{dot(T0, v), dot(N0, v), dot(B0, v)}), 1e-8 + 1e-9);
  }
  HULA_EXPECT_ERROR((void)to_nurbs(c, 1e-12), Errc::InvalidArgument, "integration tolerance");
  const nurbs::NurbsCurve plain = n.curve;
  EXPECT_EQ(to_nurbs(curve::Curve(plain), 1e-6).curve, plain);
}

}  // namespace
}  // namespace hula::intrinsic
