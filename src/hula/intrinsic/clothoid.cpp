// SPDX-License-Identifier: MIT
// Fresnel integrals, clothoid segments and G1 / G2 Hermite clothoid
// interpolation (Bertolazzi–Frego); see the header for the maths.
#include "hula/intrinsic/clothoid.hpp"

#include <algorithm>
#include <array>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "hula/core/banded.hpp"
#include "hula/core/error.hpp"
#include "hula/law/parser.hpp"

namespace hula::intrinsic {
namespace {

// 10-point Gauss–Legendre rule on [−1, 1] (exact for degree 19): Boost.Math's positive nodes and
// their weights, references to static arrays (no allocation on the panel loops).
using Gauss10 = boost::math::quadrature::gauss<double, 10>;

// Largest turning of the phase over one quadrature panel, radians. With the phase quadratic, the
// 20th derivative of cos(phase) on a panel is at most about this to the 20th power, and the 10-point
// rule's error bound (b−a)^21 (10!)^4 / (21 ((20)!)^3) |f^(20)| is then below 1e-18 of the panel width.
constexpr double kPanelTurn = 4.0;

// Panels needed for a phase whose rate is at most `rate` over an interval of width |h|.
int panels_for(double rate, double h) {
  const double turn = std::abs(rate * h);
  return turn <= kPanelTurn ? 1 : static_cast<int>(std::ceil(turn / kPanelTurn));
}

// ∫₀ʰ (cos θ(t), sin θ(t)) dt for θ(t) = c + b t + a t² / 2 (h of any sign).
std::array<double, 2> integrate_phase(double a, double b, double c, double h) {
  const auto& nodes = Gauss10::abscissa();
  const auto& weights = Gauss10::weights();
  const int n = panels_for(std::max(std::abs(b), std::abs(b + a * h)), h);
  const double w = h / n;
  double sx = 0.0, sy = 0.0;
  for (int p = 0; p < n; ++p) {
    const double mid = (p + 0.5) * w;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      for (const double sign : {-1.0, 1.0}) {
        const double t = mid + sign * nodes[k] * 0.5 * w;
        const double th = c + t * (b + 0.5 * a * t);
        sx += weights[k] * std::cos(th);
        sy += weights[k] * std::sin(th);
      }
    }
  }
  return {0.5 * w * sx, 0.5 * w * sy};
}

// The integrals of the G1 equation on τ ∈ [0, 1] with φ(τ) = A τ² + (δ − A) τ + φ0 and w = τ² − τ = ∂φ/∂A:
// X = ∫ cos φ, Y = ∫ sin φ and their A-derivatives Y′ = ∫ w cos φ, Y″ = −∫ w² sin φ, X′ = −∫ w sin φ,
// X″ = −∫ w² cos φ (the same cosines and sines, so the derivatives cost a few multiplications).
struct G1Integrals {
  double x = 0.0, y = 0.0, dy = 0.0, d2y = 0.0, dx = 0.0, d2x = 0.0;
};

G1Integrals g1_integrals(double big_a, double delta, double phi0) {
  const auto& nodes = Gauss10::abscissa();
  const auto& weights = Gauss10::weights();
  const double b = delta - big_a;
  const int n = panels_for(std::max(std::abs(b), std::abs(b + 2.0 * big_a)), 1.0);
  const double w = 1.0 / n;
  G1Integrals r;
  for (int p = 0; p < n; ++p) {
    const double mid = (p + 0.5) * w;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      for (const double sign : {-1.0, 1.0}) {
        const double t = mid + sign * nodes[k] * 0.5 * w;
        const double ph = phi0 + t * (b + big_a * t);
        const double cs = weights[k] * std::cos(ph), sn = weights[k] * std::sin(ph);
        const double dw = t * t - t;
        r.x += cs;
        r.y += sn;
        r.dy += dw * cs;
        r.dx -= dw * sn;
        r.d2y -= dw * dw * sn;
        r.d2x -= dw * dw * cs;
      }
    }
  }
  const double scale = 0.5 * w;
  r.x *= scale;
  r.y *= scale;
  r.dy *= scale;
  r.dx *= scale;
  r.d2y *= scale;
  r.d2x *= scale;
  return r;
}

// The moments ∫ tᵏ (cos θ(t), sin θ(t)) dt, k = 0, 1, 2, over [lo, hi] for θ(t) = c + b t + a t²/2.
struct PhaseMoments {
  std::array<double, 3> x{}, y{};
};

PhaseMoments phase_moments(double a, double b, double c, double lo, double hi) {
  const auto& nodes = Gauss10::abscissa();
  const auto& weights = Gauss10::weights();
  const double h = hi - lo;
  const int n = panels_for(std::max(std::abs(b + a * lo), std::abs(b + a * hi)), h);
  const double w = h / n;
  PhaseMoments m;
  for (int p = 0; p < n; ++p) {
    const double mid = lo + (p + 0.5) * w;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
      for (const double sign : {-1.0, 1.0}) {
        const double t = mid + sign * nodes[k] * 0.5 * w;
        const double th = c + t * (b + 0.5 * a * t);
        const double cs = weights[k] * std::cos(th), sn = weights[k] * std::sin(th);
        m.x[0] += cs;
        m.y[0] += sn;
        m.x[1] += t * cs;
        m.y[1] += t * sn;
        m.x[2] += t * t * cs;
        m.y[2] += t * t * sn;
      }
    }
  }
  for (std::size_t k = 0; k < 3; ++k) {
    m.x[k] *= 0.5 * w;
    m.y[k] *= 0.5 * w;
  }
  return m;
}

// The G2 problem in the frame p0 = (0, 0), p1 = (1, 0) (header): end angles relative to the chord,
// scaled end curvatures and the fixed outer lengths.
struct G2Scaled {
  double th0 = 0.0, th1 = 0.0, k0 = 0.0, k1 = 0.0, s0 = 0.0, s1 = 0.0;
};

// The three arcs for given (sM, θM): the middle arc's KM, aM and the outer rates a0, a1, the end-point
// residual F and its Jacobian J[i][j] = ∂F_i / ∂(sM, θM)_j, and the arc integrals (for building).
struct G2State {
  double km = 0.0, am = 0.0, a0 = 0.0, a1 = 0.0;
  std::array<double, 2> f{};
  std::array<std::array<double, 2>, 2> j{};
  std::array<double, 2> arc0{}, middle{};
};

G2State g2_state(const G2Scaled& d, double sm, double thm) {
  // The angle conditions of the header, M (KM, aM)ᵀ = r, in closed form.
  const double m11 = -0.5 * (sm + d.s0), m12 = sm * sm / 8.0 + d.s0 * sm / 4.0;
  const double m21 = 0.5 * (sm + d.s1), m22 = sm * sm / 8.0 + d.s1 * sm / 4.0;
  const double det = m11 * m22 - m12 * m21;  // < 0 for sM > 0
  const double r1 = d.th0 + 0.5 * d.s0 * d.k0 - thm, r2 = d.th1 - 0.5 * d.s1 * d.k1 - thm;
  G2State g;
  g.km = (r1 * m22 - m12 * r2) / det;
  g.am = (m11 * r2 - m21 * r1) / det;
  // ∂(KM, aM)/∂θM (r′ = (−1, −1)) and ∂(KM, aM)/∂sM (M (KM, aM)′ = −M′ (KM, aM)).
  const double dk_t = (m12 - m22) / det, da_t = (m21 - m11) / det;
  const double q1 = 0.5 * g.km - 0.25 * (sm + d.s0) * g.am, q2 = -0.5 * g.km - 0.25 * (sm + d.s1) * g.am;
  const double dk_s = (q1 * m22 - m12 * q2) / det, da_s = (m11 * q2 - m21 * q1) / det;
  const double h = 0.5 * sm;
  const double ka = g.km - g.am * h, kb = g.km + g.am * h;
  g.a0 = (ka - d.k0) / d.s0;
  g.a1 = (d.k1 - kb) / d.s1;
  const double da0_t = (dk_t - da_t * h) / d.s0, da0_s = (dk_s - da_s * h - 0.5 * g.am) / d.s0;
  const double da1_t = -(dk_t + da_t * h) / d.s1, da1_s = -(dk_s + da_s * h + 0.5 * g.am) / d.s1;
  // Arc 0 from p0 forwards, the middle arc about its midpoint, arc 1 from p1 backwards (u = s1 − s:
  // θ(u) = θ1 − K1 u + a1 u²/2, same integral).
  const PhaseMoments m0 = phase_moments(g.a0, d.k0, d.th0, 0.0, d.s0);
  const PhaseMoments mm = phase_moments(g.am, g.km, thm, -h, h);
  const PhaseMoments m1 = phase_moments(g.a1, -d.k1, d.th1, 0.0, d.s1);
  g.arc0 = {m0.x[0], m0.y[0]};
  g.middle = {mm.x[0], mm.y[0]};
  g.f = {m0.x[0] + mm.x[0] + m1.x[0] - 1.0, m0.y[0] + mm.y[0] + m1.y[0]};
  // ∂/∂q ∫ (cos θ, sin θ) = ∫ (−sin θ, cos θ) ∂θ/∂q, with ∂θ/∂q = (s²/2) ∂a/∂q on the outer arcs and
  // ∂θM/∂q + t ∂KM/∂q + (t²/2) ∂aM/∂q on the middle one; sM also moves the middle arc's ends (±h).
  const double tha = thm - g.km * h + 0.5 * g.am * h * h, thb = thm + g.km * h + 0.5 * g.am * h * h;
  const double ends_x = 0.5 * (std::cos(tha) + std::cos(thb)), ends_y = 0.5 * (std::sin(tha) + std::sin(thb));
  const auto outer = [](const PhaseMoments& m, double da) {
    return std::array<double, 2>{-0.5 * da * m.y[2], 0.5 * da * m.x[2]};
  };
  const std::array<double, 2> o0s = outer(m0, da0_s), o0t = outer(m0, da0_t), o1s = outer(m1, da1_s),
                              o1t = outer(m1, da1_t);
  g.j[0][0] = o0s[0] + o1s[0] - dk_s * mm.y[1] - 0.5 * da_s * mm.y[2] + ends_x;
  g.j[1][0] = o0s[1] + o1s[1] + dk_s * mm.x[1] + 0.5 * da_s * mm.x[2] + ends_y;
  g.j[0][1] = o0t[0] + o1t[0] - mm.y[0] - dk_t * mm.y[1] - 0.5 * da_t * mm.y[2];
  g.j[1][1] = o0t[1] + o1t[1] + mm.x[0] + dk_t * mm.x[1] + 0.5 * da_t * mm.x[2];
  return g;
}

// Newton with backtracking on |F| from (sM, θM); false when it stalls or runs out of iterations.
bool g2_newton(const G2Scaled& d, double& sm, double& thm, const ClothoidG2Options& options, int& iterations,
               G2State& g) {
  // Halvings of the Newton step before giving up: 2^-30 of a step is below any useful move.
  constexpr int kMaxHalvings = 30;
  g = g2_state(d, sm, thm);
  double norm = std::hypot(g.f[0], g.f[1]);
  for (int it = 0; it < options.max_iterations; ++it) {
    if (norm <= options.tolerance) return true;
    if (!std::isfinite(norm)) return false;
    const double det = g.j[0][0] * g.j[1][1] - g.j[0][1] * g.j[1][0];
    if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return false;
    const double ds = -(g.j[1][1] * g.f[0] - g.j[0][1] * g.f[1]) / det;
    const double dt = -(g.j[0][0] * g.f[1] - g.j[1][0] * g.f[0]) / det;
    ++iterations;
    double lambda = 1.0;
    bool accepted = false;
    for (int k = 0; k <= kMaxHalvings && !accepted; ++k, lambda *= 0.5) {
      const double sn = sm + lambda * ds, tn = thm + lambda * dt;
      if (!(sn > 0.0)) continue;
      G2State gn = g2_state(d, sn, tn);
      const double nn = std::hypot(gn.f[0], gn.f[1]);
      if (nn < (1.0 - 1e-4 * lambda) * norm) {
        sm = sn;
        thm = tn;
        g = gn;
        norm = nn;
        accepted = true;
      }
    }
    if (!accepted) return false;
  }
  return norm <= options.tolerance;
}

// Angle reduced to (−π, π].
double reduce_angle(double a) {
  const double two_pi = 2.0 * std::numbers::pi;
  double r = std::remainder(a, two_pi);
  if (r <= -std::numbers::pi) r += two_pi;
  return r;
}

void check_finite(double v, const char* field) {
  if (!std::isfinite(v))
    throw Error(Errc::NonFiniteInput, std::string(field) + " = " + format_number(v) + " is not finite",
                ErrorWhere{.field = field});
}

// The chord of a Hermite problem from (p0, θ0) to (p1, θ1), its data checked: finite, p1 ≠ p0 (the error says
// which interpolation, `what`, needs two points).
struct Chord {
  double length = 0.0;  ///< |p1 − p0| in the xy-plane
  double angle = 0.0;   ///< its direction
};

Chord hermite_chord(const Vec3& p0, double theta0, const Vec3& p1, double theta1, const char* what) {
  check_finite(p0.x, "p0");
  check_finite(p0.y, "p0");
  check_finite(p1.x, "p1");
  check_finite(p1.y, "p1");
  check_finite(theta0, "theta0");
  check_finite(theta1, "theta1");
  const double dx = p1.x - p0.x, dy = p1.y - p0.y;
  const double r = std::hypot(dx, dy);
  if (!(r > 0.0))
    throw Error(Errc::CoincidentPoints, std::string("p1 coincides with p0: ") + what + " needs two distinct points",
                ErrorWhere{.field = "p1"});
  return {r, std::atan2(dy, dx)};
}

}  // namespace

FresnelValues fresnel(double x) {
  if (std::isnan(x)) throw Error(Errc::NonFiniteInput, "x is NaN", ErrorWhere{.field = "x"});
  const double ax = std::abs(x);
  const double sign = x < 0.0 ? -1.0 : 1.0;
  if (ax <= 6.0) {
    // ∫₀^|x| of (cos, sin)(π t²/2): θ = π t²/2, a = π, b = c = 0.
    const std::array<double, 2> v = integrate_phase(std::numbers::pi, 0.0, 0.0, ax);
    return {sign * v[0], sign * v[1]};
  }
  const double x2 = ax * ax;
  if (!std::isfinite(x2)) return {sign * 0.5, sign * 0.5};
  // Asymptotic expansions (A&S 7.3.9–10 with the series of f and g); terms are summed while they
  // decrease, which at x ≥ 6 reaches below 1e-19 relative.
  const double z = std::numbers::pi * x2, z2 = z * z;
  double f = 0.0, g = 0.0, tf = 1.0, tg = 1.0;
  for (int m = 0; m < 40; ++m) {
    f += tf;
    g += tg;
    const double nf = -tf * (4.0 * m + 1.0) * (4.0 * m + 3.0) / z2;
    const double ng = -tg * (4.0 * m + 3.0) * (4.0 * m + 5.0) / z2;
    if (std::abs(nf) >= std::abs(tf) || std::abs(nf) < 1e-20) break;
    tf = nf;
    tg = ng;
  }
  f /= std::numbers::pi * ax;
  g /= std::numbers::pi * z * ax;
  // The phase π x²/2 = 2π (x²/4), reduced exactly: x² = hi + lo (fma), frac(hi/4) is exact.
  const double hi = x2, lo = std::fma(ax, ax, -hi);
  const double q = hi / 4.0;
  const double frac = (q - std::floor(q)) + lo / 4.0;
  const double phase = 2.0 * std::numbers::pi * frac;
  const double sn = std::sin(phase), cs = std::cos(phase);
  return {sign * (0.5 + f * sn - g * cs), sign * (0.5 - f * cs - g * sn)};
}

Vec3 ClothoidSegment::point(double s) const {
  const std::array<double, 2> v = integrate_phase(dkappa, kappa0, theta0, s);
  return {start.x + v[0], start.y + v[1], start.z};
}

law::Law ClothoidSegment::curvature_law(const law::Context& context, std::string_view parameter) const {
  return kappa0 + dkappa * context.parameter(parameter);
}

IntrinsicCurve ClothoidSegment::to_intrinsic(const ReconstructionOptions& options) const {
  const law::Context ctx;
  StartFrame frame;
  frame.point = start;
  frame.tangent = {std::cos(theta0), std::sin(theta0), 0.0};
  frame.normal = {-std::sin(theta0), std::cos(theta0), 0.0};
  return reconstruct_planar(curvature_law(ctx), "s", length, frame, options);
}

void ClothoidG1Options::validate() const {
  if (!(tolerance >= 1e-16 && tolerance <= 1e-6))
    throw Error(Errc::InvalidOption,
                "ClothoidG1Options.tolerance = " + format_number(tolerance) + " is outside [1e-16, 1e-6]",
                ErrorWhere{.field = "tolerance"});
  if (max_iterations < 1 || max_iterations > 1000)
    throw Error(Errc::InvalidOption,
                "ClothoidG1Options.max_iterations = " + std::to_string(max_iterations) + " is outside [1, 1000]",
                ErrorWhere{.field = "max_iterations"});
}

ClothoidG1Result fit_clothoid_g1(const Vec3& p0, double theta0, const Vec3& p1, double theta1,
                                 const ClothoidG1Options& options) {
  options.validate();
  const Chord chord = hermite_chord(p0, theta0, p1, theta1, "a G1 clothoid");
  const double r = chord.length, phi = chord.angle;
  const double phi0 = reduce_angle(theta0 - phi), phi1 = reduce_angle(theta1 - phi);
  const double delta = phi1 - phi0;
  // Bertolazzi–Frego's guess, then Halley's method on g(A) = Y(A) (their proof: the relevant root is
  // the unique one in the bracket their guess starts in, where g is monotone enough for Newton; Halley's
  // cubic correction falls back to the Newton step where it would more than halve or double it).
  // Not Boost.Math's halley_iterate: it wants a bracket, which this iteration has no use for, and stops on
  // the step relative to A, one evaluation after the cubic test below; that evaluation (the whole cost of a
  // step) would be a quarter to a third of a typical fit, and the last one's X, X′, X″ give the length here.
  double big_a = 3.0 * (phi0 + phi1);
  int it = 0;
  bool converged = false;
  G1Integrals q;
  double step = 0.0;
  while (it < options.max_iterations) {
    ++it;
    q = g1_integrals(big_a, delta, phi0);
    if (!(q.dy != 0.0) || !std::isfinite(q.dy)) break;
    const double newton = q.y / q.dy, c = 0.5 * newton * q.d2y / q.dy;
    step = std::abs(c) <= 0.5 ? newton / (1.0 - c) : newton;
    big_a -= step;
    // Cubic convergence: the error left after a step of size h is of order h³.
    if (std::abs(step * step * step) <= options.tolerance * std::max(1.0, std::abs(big_a))) {
      converged = true;
      break;
    }
  }
  if (!converged)
    throw Error(Errc::NumericalFailure,
                "G1 clothoid: Newton did not converge in " + std::to_string(it) + " iterations (phi0 = " +
                    format_number(phi0) + ", phi1 = " + format_number(phi1) + ", residual " + format_number(q.y) + ")",
                ErrorWhere{.field = "theta1"});
  // X at the final A from the last evaluation by Taylor to second order (the error is of order step³, below
  // the tolerance), instead of one more evaluation.
  const double x_end = q.x - step * q.dx + 0.5 * step * step * q.d2x;
  const double length = r / x_end;
  ClothoidG1Result result;
  result.segment.start = {p0.x, p0.y, p0.z};
  result.segment.theta0 = theta0;
  result.segment.length = length;
  result.segment.kappa0 = (delta - big_a) / length;
  result.segment.dkappa = 2.0 * big_a / (length * length);
  result.iterations = it;
  return result;
}

void ClothoidG2Options::validate() const {
  if (!(tolerance >= 1e-15 && tolerance <= 1e-6))
    throw Error(Errc::InvalidOption,
                "ClothoidG2Options.tolerance = " + format_number(tolerance) + " is outside [1e-15, 1e-6]",
                ErrorWhere{.field = "tolerance"});
  if (max_iterations < 1 || max_iterations > 1000)
    throw Error(Errc::InvalidOption,
                "ClothoidG2Options.max_iterations = " + std::to_string(max_iterations) + " is outside [1, 1000]",
                ErrorWhere{.field = "max_iterations"});
}

ClothoidG2Result fit_clothoid_g2(const Vec3& p0, double theta0, double kappa0, const Vec3& p1, double theta1,
                                 double kappa1, const ClothoidG2Options& options) {
  options.validate();
  check_finite(kappa0, "kappa0");
  check_finite(kappa1, "kappa1");
  const Chord chord = hermite_chord(p0, theta0, p1, theta1, "a G2 clothoid spline");
  const double r = chord.length, phi = chord.angle;  // not a structured binding: clang 14 cannot capture one
  G2Scaled d;
  d.th0 = reduce_angle(theta0 - phi);
  d.th1 = reduce_angle(theta1 - phi);
  d.k0 = kappa0 * r;
  d.k1 = kappa1 * r;
  check_finite(d.k0, "kappa0");
  check_finite(d.k1, "kappa1");
  // The G1 clothoid in the scaled frame: the Newton start and the reference for the outer lengths.
  const ClothoidSegment guess = fit_clothoid_g1({0.0, 0.0, 0.0}, d.th0, {1.0, 0.0, 0.0}, d.th1).segment;
  const double big_l = guess.length;
  const double gap0 = std::abs(d.k0 - guess.curvature(0.0)), gap1 = std::abs(d.k1 - guess.curvature(big_l));
  // Angle an outer arc may turn away from the G1 clothoid (header): about 2·d / |ΔK| of length.
  constexpr double kOuterTurn = std::numbers::pi / 8.0;
  // Restarts with the outer arcs halved each time; 2^-6 of the first choice is as short as is useful.
  constexpr int kRestarts = 6;
  double s0 = std::min(big_l / 3.0, gap0 > 0.0 ? 2.0 * kOuterTurn / gap0 : big_l);
  double s1 = std::min(big_l / 3.0, gap1 > 0.0 ? 2.0 * kOuterTurn / gap1 : big_l);
  int iterations = 0;
  for (int attempt = 0; attempt <= kRestarts; ++attempt, s0 *= 0.5, s1 *= 0.5) {
    d.s0 = s0;
    d.s1 = s1;
    double sm = big_l - s0 - s1, thm = guess.angle(s0 + 0.5 * sm);
    G2State g;
    if (!g2_newton(d, sm, thm, options, iterations, g)) continue;
    // Back to model coordinates: lengths × r, curvatures / r, rates / r², angles + (θ0 − φ0).
    const double c = std::cos(phi), sn = std::sin(phi), offset = theta0 - d.th0, h = 0.5 * sm;
    const auto to_model = [&](const std::array<double, 2>& v) {
      return Vec3{p0.x + r * (c * v[0] - sn * v[1]), p0.y + r * (sn * v[0] + c * v[1]), p0.z};
    };
    ClothoidG2Result out;
    out.iterations = iterations;
    out.segments[0] = {
        .start = {p0.x, p0.y, p0.z}, .theta0 = theta0, .kappa0 = kappa0, .dkappa = g.a0 / (r * r), .length = s0 * r};
    out.segments[1] = {.start = to_model(g.arc0),
                       .theta0 = thm - g.km * h + 0.5 * g.am * h * h + offset,
                       .kappa0 = (g.km - g.am * h) / r,
                       .dkappa = g.am / (r * r),
                       .length = sm * r};
    out.segments[2] = {.start = to_model({g.arc0[0] + g.middle[0], g.arc0[1] + g.middle[1]}),
                       .theta0 = thm + g.km * h + 0.5 * g.am * h * h + offset,
                       .kappa0 = (g.km + g.am * h) / r,
                       .dkappa = g.a1 / (r * r),
                       .length = s1 * r};
    return out;
  }
  const bool first = gap0 >= gap1;
  throw Error(Errc::NumericalFailure,
              "G2 clothoid: Newton did not converge after " + std::to_string(kRestarts) +
                  " restarts with shorter outer arcs (" + std::string(first ? "kappa0 = " : "kappa1 = ") +
                  format_number(first ? kappa0 : kappa1) + " is " + format_number(first ? gap0 : gap1) +
                  " / |p1 - p0| away from the G1 clothoid's end curvature; phi0 = " + format_number(d.th0) +
                  ", phi1 = " + format_number(d.th1) + ")",
              ErrorWhere{.field = first ? "kappa0" : "kappa1"});
}

double ClothoidSplineResult::length() const noexcept {
  double total = 0.0;
  for (const ClothoidSegment& s : segments) total += s.length;
  return total;
}

void ClothoidSplineOptions::validate() const {
  if (continuity != 1 && continuity != 2)
    throw Error(Errc::InvalidOption,
                "ClothoidSplineOptions.continuity = " + std::to_string(continuity) + " is not 1 (G1) or 2 (G2)",
                ErrorWhere{.field = "continuity"});
  if (!(tolerance >= 1e-15 && tolerance <= 1e-6))
    throw Error(Errc::InvalidOption,
                "ClothoidSplineOptions.tolerance = " + format_number(tolerance) + " is outside [1e-15, 1e-6]",
                ErrorWhere{.field = "tolerance"});
  if (max_iterations < 1 || max_iterations > 1000)
    throw Error(Errc::InvalidOption,
                "ClothoidSplineOptions.max_iterations = " + std::to_string(max_iterations) + " is outside [1, 1000]",
                ErrorWhere{.field = "max_iterations"});
}

namespace {

// The points of a spline, checked (finite, enough, no point equal to the one before; a closed list's repeated
// first point dropped), and the options' end angles checked against them.
std::vector<Vec3> spline_points(std::span<const Vec3> points, const ClothoidSplineOptions& options) {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y))
      throw Error(Errc::NonFiniteInput, "points[" + std::to_string(i) + "] is not finite",
                  ErrorWhere{.field = "points", .index = i});
  std::vector<Vec3> p(points.begin(), points.end());
  if (options.closed && p.size() > 1 && p.back().x == p.front().x && p.back().y == p.front().y) p.pop_back();
  const std::size_t needed = options.closed ? 3 : 2;
  if (p.size() < needed)
    throw Error(Errc::TooFewPoints,
                "points has " + std::to_string(p.size()) + (options.closed ? " distinct" : "") + " point(s): " +
                    (options.closed ? "a closed" : "an open") + " spline needs at least " + std::to_string(needed),
                ErrorWhere{.field = "points"});
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::size_t prev = i == 0 ? p.size() - 1 : i - 1;
    if ((i > 0 || options.closed) && p[i].x == p[prev].x && p[i].y == p[prev].y)
      throw Error(Errc::CoincidentPoints,
                  "points[" + std::to_string(i) + "] coincides with points[" + std::to_string(prev) +
                      "]: consecutive points must differ",
                  ErrorWhere{.field = "points", .index = i});
  }
  const std::pair<const std::optional<double>*, const char*> ends[] = {{&options.start_angle, "start_angle"},
                                                                       {&options.end_angle, "end_angle"},
                                                                       {&options.start_curvature, "start_curvature"},
                                                                       {&options.end_curvature, "end_curvature"}};
  for (const auto& [value, field] : ends) {
    if (!value->has_value()) continue;
    if (options.closed)
      throw Error(Errc::InvalidArgument, std::string(field) + " is given for a closed spline (it has no ends)",
                  ErrorWhere{.field = field});
    check_finite(**value, field);
  }
  // One clothoid per interval leaves one condition per open end: an angle or a curvature, not both (two points
  // with both at both ends are the G2 Hermite problem, fit_clothoid_spline hands them to fit_clothoid_g2).
  const bool hermite =
      p.size() == 2 && options.start_angle && options.end_angle && options.start_curvature && options.end_curvature;
  if (!hermite)
    for (const auto& [angle, curvature, field] :
         {std::tuple{&options.start_angle, &options.start_curvature, "start_curvature"},
          std::tuple{&options.end_angle, &options.end_curvature, "end_curvature"}})
      if (angle->has_value() && curvature->has_value())
        throw Error(Errc::InvalidArgument,
                    std::string(field) + " is given with the angle at that end: a spline of one clothoid per " +
                        "interval meets one condition per end (an angle or a curvature); both at both ends " +
                        "of two points is the G2 Hermite problem",
                    ErrorWhere{.field = field});
  for (Vec3& q : p) q.z = points.front().z;
  return p;
}

double chord_angle(const Vec3& a, const Vec3& b) { return std::atan2(b.y - a.y, b.x - a.x); }

// Signed angle from the direction of u to that of v.
double turn(double ux, double uy, double vx, double vy) { return std::atan2(ux * vy - uy * vx, ux * vx + uy * vy); }

// The tangent angle at b of the circle through a, b, c: the chord b → c turned back by the inscribed angle at a
// (tangent–chord theorem); the chord itself for collinear points.
double circle_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  return chord_angle(b, c) - turn(b.x - a.x, b.y - a.y, c.x - a.x, c.y - a.y);
}

// The start angles of a spline: three-point circles, the circle of the end triple at an open end (its tangent
// there is the end chord's direction mirrored about the neighbour's circle tangent), given end angles kept.
std::vector<double> guess_angles(const std::vector<Vec3>& p, const ClothoidSplineOptions& options) {
  const std::size_t n = p.size();
  std::vector<double> th(n, 0.0);
  if (!options.closed && n == 2) {
    th[0] = th[1] = chord_angle(p[0], p[1]);
  } else {
    for (std::size_t i = 0; i < n; ++i) {
      if (!options.closed && (i == 0 || i + 1 == n)) continue;
      th[i] = circle_angle(p[(i + n - 1) % n], p[i], p[(i + 1) % n]);
    }
    if (!options.closed) {
      th[0] = 2.0 * chord_angle(p[0], p[1]) - th[1];
      th[n - 1] = 2.0 * chord_angle(p[n - 2], p[n - 1]) - th[n - 2];
    }
  }
  if (options.start_angle) th[0] = *options.start_angle;
  if (options.end_angle) th[n - 1] = *options.end_angle;
  // Two points with one angle given: the circular arc (the other angle mirrored about the chord).
  if (!options.closed && n == 2 && options.start_angle.has_value() != options.end_angle.has_value()) {
    const double chord = chord_angle(p[0], p[1]);
    if (options.start_angle)
      th[1] = 2.0 * chord - th[0];
    else
      th[0] = 2.0 * chord - th[1];
  }
  return th;
}

// Each segment's tangent angle continued from the one before (a G1 fit keeps the angle it is given, which may
// differ from the previous segment's end angle by a multiple of 2π).
void unwrap_angles(std::vector<ClothoidSegment>& segments) {
  const double two_pi = 2.0 * std::numbers::pi;
  for (std::size_t i = 1; i < segments.size(); ++i) {
    const ClothoidSegment& prev = segments[i - 1];
    const double end = prev.angle(prev.length);
    segments[i].theta0 += two_pi * std::round((end - segments[i].theta0) / two_pi);
  }
}

// A G1 clothoid's end curvatures and their derivatives with respect to its end angles: with the scaled angle
// φ(τ) = φ0 + (δ − A) τ + A τ² and g(A; φ0, φ1) = ∫₀¹ sin φ = 0, dA/dφj = −g_φj / g_A; X = ∫₀¹ cos φ = r / L;
// κ0 = (δ − A) X / r, κ1 = (δ + A) X / r, δ = φ1 − φ0.
struct G1Ends {
  double k0 = 0.0, k1 = 0.0;
  double dk0[2]{}, dk1[2]{};  ///< ∂κ/∂θ0, ∂κ/∂θ1
};

G1Ends g1_ends(const ClothoidSegment& seg, const Vec3& p0, const Vec3& p1) {
  const double r = std::hypot(p1.x - p0.x, p1.y - p0.y), len = seg.length;
  const double big_a = 0.5 * seg.dkappa * len * len, b = seg.kappa0 * len, delta = b + big_a;
  const double phi0 = seg.theta0 - chord_angle(p0, p1);
  const PhaseMoments m = phase_moments(2.0 * big_a, b, phi0, 0.0, 1.0);
  const double x = m.x[0];
  const double g_a = m.x[2] - m.x[1];
  const double g_phi[2] = {m.x[0] - m.x[1], m.x[1]};
  const double d_delta[2] = {-1.0, 1.0};
  G1Ends e;
  e.k0 = seg.kappa0;
  e.k1 = seg.curvature(len);
  for (int j = 0; j < 2; ++j) {
    const double da = -g_phi[j] / g_a;
    const double dphi_sin = j == 0 ? m.y[0] - m.y[1] : m.y[1];
    const double dx = -(dphi_sin + da * (m.y[2] - m.y[1]));
    e.dk0[j] = ((d_delta[j] - da) * x + (delta - big_a) * dx) / r;
    e.dk1[j] = ((d_delta[j] + da) * x + (delta + big_a) * dx) / r;
  }
  return e;
}

// The G1 segments of a spline for the angles th.
std::vector<ClothoidSegment> g1_segments(const std::vector<Vec3>& p, const std::vector<double>& th, bool closed) {
  const std::size_t n = p.size(), m = closed ? n : n - 1;
  std::vector<ClothoidSegment> segs(m);
  for (std::size_t i = 0; i < m; ++i) segs[i] = fit_clothoid_g1(p[i], th[i], p[(i + 1) % n], th[(i + 1) % n]).segment;
  return segs;
}

// The G2 residual: rows in curvature units (an end condition "given angle" in radians divided by the mean chord,
// so that every row times the mean chord is dimensionless), with the tridiagonal Jacobian rows
// (lower, diagonal, upper; cyclic when closed).
struct G2System {
  std::vector<double> f, lower, diag, upper;
  double norm = 0.0;   ///< max |f_i| · mean chord
  double merit = 0.0;  ///< Σ (f_i · mean chord)², the line search's merit
};

G2System g2_system(const std::vector<Vec3>& p, const std::vector<ClothoidSegment>& segs,
                   const ClothoidSplineOptions& options, double mean_chord) {
  const std::size_t n = p.size(), m = segs.size();
  std::vector<G1Ends> ends(m);
  for (std::size_t i = 0; i < m; ++i) ends[i] = g1_ends(segs[i], p[i], p[(i + 1) % n]);
  G2System s;
  s.f.assign(n, 0.0);
  s.lower.assign(n, 0.0);
  s.diag.assign(n, 0.0);
  s.upper.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const bool first = !options.closed && i == 0, last = !options.closed && i + 1 == n;
    if ((first && options.start_angle) || (last && options.end_angle)) {
      s.diag[i] = 1.0 / mean_chord;                 // the given angle is held: a zero residual, a zero step
    } else if (first && options.start_curvature) {  // κ at the start of segment 0 as given
      s.f[i] = ends[0].k0 - *options.start_curvature;
      s.diag[i] = ends[0].dk0[0];
      s.upper[i] = ends[0].dk0[1];
    } else if (last && options.end_curvature) {  // κ at the end of the last segment as given
      s.f[i] = ends[m - 1].k1 - *options.end_curvature;
      s.lower[i] = ends[m - 1].dk1[0];
      s.diag[i] = ends[m - 1].dk1[1];
    } else if (first) {  // κ′ = 0 on the first segment: κ1 − κ0 of segment 0
      s.f[i] = ends[0].k1 - ends[0].k0;
      s.diag[i] = ends[0].dk1[0] - ends[0].dk0[0];
      s.upper[i] = ends[0].dk1[1] - ends[0].dk0[1];
    } else if (last) {
      s.f[i] = ends[m - 1].k1 - ends[m - 1].k0;
      s.lower[i] = ends[m - 1].dk1[0] - ends[m - 1].dk0[0];
      s.diag[i] = ends[m - 1].dk1[1] - ends[m - 1].dk0[1];
    } else {  // κ at the start of segment i − κ at the end of segment i − 1
      const G1Ends& in = ends[(i + m - 1) % m];
      const G1Ends& out = ends[i % m];
      s.f[i] = out.k0 - in.k1;
      s.lower[i] = -in.dk1[0];
      s.diag[i] = out.dk0[0] - in.dk1[1];
      s.upper[i] = out.dk0[1];
    }
    s.norm = std::max(s.norm, std::abs(s.f[i]) * mean_chord);
    s.merit += (s.f[i] * mean_chord) * (s.f[i] * mean_chord);
  }
  return s;
}

// Solves the (cyclic when closed) tridiagonal system for the Newton step; false when singular.
bool solve_g2_step(const G2System& s, bool closed, std::vector<double>& step) {
  const std::size_t n = s.f.size();
  // Columns: −f, and when closed e0 and e_{n−1} for the corner terms (Woodbury, rank 2).
  const std::size_t cols = closed ? 3 : 1;
  BandedMatrix t(n, 1, 1);
  std::vector<double> rhs(n * cols, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    t.at(i, i) = s.diag[i];
    if (i > 0) t.at(i, i - 1) = s.lower[i];
    if (i + 1 < n) t.at(i, i + 1) = s.upper[i];
    rhs[i * cols] = -s.f[i];
  }
  if (closed) {
    rhs[0 * cols + 1] = 1.0;
    rhs[(n - 1) * cols + 2] = 1.0;
  }
  if (!t.solve(rhs, cols)) {
    if (!closed) return false;
    // The cyclic matrix without its corners is singular: the whole matrix, dense (rare, O(n³)).
    BandedMatrix full(n, n - 1, n - 1);
    std::vector<double> f(n);
    for (std::size_t i = 0; i < n; ++i) {
      full.at(i, (i + n - 1) % n) += s.lower[i];
      full.at(i, i) += s.diag[i];
      full.at(i, (i + 1) % n) += s.upper[i];
      f[i] = -s.f[i];
    }
    if (!full.solve(f, 1)) return false;
    step = std::move(f);
    return true;
  }
  step.assign(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) step[i] = rhs[i * cols];
  if (!closed) return true;
  // J = T + e0 (b e_{n−1})ᵀ + e_{n−1} (c e0)ᵀ with b = J[0][n−1] = lower[0], c = J[n−1][0] = upper[n−1].
  const double b = s.lower[0], c = s.upper[n - 1];
  const auto z0 = [&](std::size_t i) { return rhs[i * cols + 1]; };
  const auto z1 = [&](std::size_t i) { return rhs[i * cols + 2]; };
  // (I + Vᵀ Z) w = Vᵀ y, Vᵀ v = (b v_{n−1}, c v_0).
  const double m11 = 1.0 + b * z0(n - 1), m12 = b * z1(n - 1), m21 = c * z0(0), m22 = 1.0 + c * z1(0);
  const double v1 = b * step[n - 1], v2 = c * step[0];
  const double det = m11 * m22 - m12 * m21;
  if (!(std::abs(det) > 0.0) || !std::isfinite(det)) return false;
  const double w1 = (v1 * m22 - m12 * v2) / det, w2 = (m11 * v2 - m21 * v1) / det;
  for (std::size_t i = 0; i < n; ++i) step[i] -= z0(i) * w1 + z1(i) * w2;
  return true;
}

}  // namespace

ClothoidSplineResult fit_clothoid_spline(std::span<const Vec3> points, const ClothoidSplineOptions& options) {
  options.validate();
  const std::vector<Vec3> p = spline_points(points, options);
  const std::size_t n = p.size();
  const bool curvatures = options.start_curvature || options.end_curvature;
  if (curvatures && options.continuity == 1)
    throw Error(Errc::InvalidArgument,
                std::string(options.start_curvature ? "start_curvature" : "end_curvature") +
                    " is given for a G1 spline, whose curvature is not solved for: ask for G2",
                ErrorWhere{.field = options.start_curvature ? "start_curvature" : "end_curvature"});
  ClothoidSplineResult out;
  if (!options.closed && n == 2 && options.start_angle && options.end_angle && curvatures) {
    const ClothoidG2Result r = fit_clothoid_g2(p[0], *options.start_angle, *options.start_curvature, p[1],
                                               *options.end_angle, *options.end_curvature);
    out.segments.assign(r.segments.begin(), r.segments.end());
    out.iterations = r.iterations;
    unwrap_angles(out.segments);
    return out;
  }
  std::vector<double> th = guess_angles(p, options);
  out.segments = g1_segments(p, th, options.closed);
  if (options.continuity == 1 || (!options.closed && n == 2 && !curvatures)) {
    unwrap_angles(out.segments);
    return out;
  }
  double mean_chord = 0.0;
  for (std::size_t i = 0; i + 1 < n || (options.closed && i < n); ++i)
    mean_chord += std::hypot(p[(i + 1) % n].x - p[i].x, p[(i + 1) % n].y - p[i].y);
  mean_chord /= static_cast<double>(options.closed ? n : n - 1);
  // Halvings of the Newton step before giving up (2^-30 of a step is below any useful move).
  constexpr int kMaxHalvings = 30;
  std::vector<double> step;
  G2System sys = g2_system(p, out.segments, options, mean_chord);
  for (int used = 0; sys.norm > options.tolerance && used < options.max_iterations; ++used) {
    if (!solve_g2_step(sys, options.closed, step)) break;
    ++out.iterations;
    bool accepted = false;
    double lambda = 1.0;
    for (int k = 0; k <= kMaxHalvings && !accepted; ++k, lambda *= 0.5) {
      std::vector<double> trial(th);
      for (std::size_t i = 0; i < n; ++i) trial[i] += lambda * step[i];
      std::vector<ClothoidSegment> segs;
      try {
        segs = g1_segments(p, trial, options.closed);
      } catch (const Error&) {
        continue;  // a trial step whose G1 fit fails is too long
      }
      G2System next = g2_system(p, segs, options, mean_chord);
      if (next.merit < (1.0 - 2e-4 * lambda) * sys.merit) {
        th = std::move(trial);
        out.segments = std::move(segs);
        sys = std::move(next);
        accepted = true;
      }
    }
    if (!accepted) break;
  }
  if (sys.norm > options.tolerance) {
    const std::size_t worst = static_cast<std::size_t>(
        std::max_element(sys.f.begin(), sys.f.end(), [](double a, double b) { return std::abs(a) < std::abs(b); }) -
        sys.f.begin());
    throw Error(Errc::NumericalFailure,
                "G2 clothoid spline: Newton stopped after " + std::to_string(out.iterations) +
                    " iterations with a curvature jump of " + format_number(sys.norm / mean_chord) +
                    " (times the mean chord " + format_number(sys.norm) + ", tolerance " +
                    format_number(options.tolerance) + "), the largest residual at points[" + std::to_string(worst) +
                    "]" +
                    (options.closed || (options.start_angle && options.end_angle)
                         ? std::string()
                         : std::string("; points that turn back and forth at the scale of their spacing may have no "
                                       "such spline with a free end or a given end curvature: give both end angles")),
                ErrorWhere{.field = "points", .index = worst});
  }
  unwrap_angles(out.segments);
  return out;
}

std::array<ClothoidSegment, 2> fit_biarc(const Vec3& p0, double theta0, const Vec3& p1, double theta1) {
  const Chord chord = hermite_chord(p0, theta0, p1, theta1, "a biarc");
  const double phi0 = reduce_angle(theta0 - chord.angle), phi1 = reduce_angle(theta1 - chord.angle);
  const double omega = -0.5 * (phi0 + phi1);
  const double a = chord.length / (2.0 * std::cos(0.25 * (phi1 - phi0)));
  // An arc of chord a turning by Δ: κ = 2 sin(Δ/2) / a, L = a (Δ/2) / sin(Δ/2).
  const auto arc = [a](double turning, ClothoidSegment& s) {
    const double h = 0.5 * turning;
    const double sinc = std::abs(h) < 1e-8 ? 1.0 - h * h / 6.0 : std::sin(h) / h;
    s.length = a / sinc;
    s.kappa0 = turning / s.length;
    s.dkappa = 0.0;
  };
  std::array<ClothoidSegment, 2> out{};
  out[0].start = {p0.x, p0.y, p0.z};
  out[0].theta0 = theta0;
  arc(omega - phi0, out[0]);
  out[1].theta0 = theta0 + (omega - phi0);
  arc(phi1 - omega, out[1]);
  // The joint on the chord's perpendicular bisector: the first arc's chord at angle (φ0 + ω)/2.
  const double alpha = chord.angle + 0.5 * (phi0 + omega);
  out[1].start = {p0.x + a * std::cos(alpha), p0.y + a * std::sin(alpha), p0.z};
  return out;
}

ClothoidSplineResult fit_biarc_spline(std::span<const Vec3> points, const ClothoidSplineOptions& options) {
  if (options.start_curvature || options.end_curvature) {
    const char* field = options.start_curvature ? "start_curvature" : "end_curvature";
    throw Error(Errc::InvalidArgument,
                std::string(field) + " is given for a biarc spline: its arcs' curvatures follow from the angles",
                ErrorWhere{.field = field});
  }
  const std::vector<Vec3> p = spline_points(points, options);
  const std::vector<double> th = guess_angles(p, options);
  const std::size_t n = p.size(), m = options.closed ? n : n - 1;
  ClothoidSplineResult out;
  out.segments.reserve(2 * m);
  for (std::size_t i = 0; i < m; ++i) {
    const std::array<ClothoidSegment, 2> b = fit_biarc(p[i], th[i], p[(i + 1) % n], th[(i + 1) % n]);
    out.segments.insert(out.segments.end(), b.begin(), b.end());
  }
  unwrap_angles(out.segments);
  return out;
}

curve::NaturalData clothoid_natural_data(std::span<const ClothoidSegment> segments, double tolerance) {
  if (segments.empty())
    throw Error(Errc::InvalidArgument, "segments is empty: a clothoid curve needs at least one segment",
                ErrorWhere{.field = "segments"});
  double total = 0.0;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const ClothoidSegment& c = segments[i];
    for (const double v : {c.theta0, c.kappa0, c.dkappa, c.length, c.start.x, c.start.y, c.start.z})
      if (!std::isfinite(v))
        throw Error(Errc::NonFiniteInput, "segments[" + std::to_string(i) + "] has a value that is not finite",
                    ErrorWhere{.field = "segments", .index = i});
    total += c.length;
  }
  if (!(total > 0.0))
    throw Error(Errc::InvalidArgument, "the segments' total length " + format_number(total) + " is not positive",
                ErrorWhere{.field = "segments"});
  // κ as nested piecewise laws from the last arc backwards: piecewise(s < s_(i+1), κ_i(s), rest).
  const law::Context ctx;
  const law::Law s = ctx.parameter("s");
  std::vector<double> starts(segments.size(), 0.0);
  for (std::size_t i = 1; i < segments.size(); ++i) starts[i] = starts[i - 1] + segments[i - 1].length;
  auto arc = [&](std::size_t i) {
    const ClothoidSegment& c = segments[i];
    return c.kappa0 + c.dkappa * (starts[i] == 0.0 ? s : s - starts[i]);
  };
  law::Law kappa = arc(segments.size() - 1);
  for (std::size_t i = segments.size() - 1; i-- > 0;)
    kappa = law::piecewise(law::less(s, ctx.constant(starts[i + 1])), arc(i), kappa);
  const ClothoidSegment& first = segments.front();
  curve::NaturalData d;
  d.curvature = law::print(kappa);
  d.torsion = "0";
  d.parameter = "s";
  d.length = total;
  d.start_point = first.start;
  d.start_tangent = {std::cos(first.theta0), std::sin(first.theta0), 0.0};
  d.start_normal = {-std::sin(first.theta0), std::cos(first.theta0), 0.0};
  d.tolerance = tolerance;
  return d;
}

}  // namespace hula::intrinsic
