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
#include <vector>

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
