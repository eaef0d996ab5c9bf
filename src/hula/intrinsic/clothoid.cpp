// SPDX-License-Identifier: MIT
// Fresnel integrals, clothoid segments and G1 Hermite clothoid interpolation
// (Bertolazzi–Frego); see the header for the maths.
#include "hula/intrinsic/clothoid.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "hula/core/error.hpp"

namespace hula::intrinsic {
namespace {

// 10-point Gauss–Legendre rule on [−1, 1]: the positive nodes and their weights (exact for degree 19).
constexpr std::array<double, 5> kNodes{0.1488743389816312, 0.4333953941292472, 0.6794095682990244, 0.8650633666889845,
                                       0.9739065285171717};
constexpr std::array<double, 5> kWeights{0.2955242247147529, 0.2692667193099963, 0.2190863625159820, 0.1494513491505806,
                                         0.0666713443086881};

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
  const int n = panels_for(std::max(std::abs(b), std::abs(b + a * h)), h);
  const double w = h / n;
  double sx = 0.0, sy = 0.0;
  for (int p = 0; p < n; ++p) {
    const double mid = (p + 0.5) * w;
    for (std::size_t k = 0; k < kNodes.size(); ++k) {
      for (const double sign : {-1.0, 1.0}) {
        const double t = mid + sign * kNodes[k] * 0.5 * w;
        const double th = c + t * (b + 0.5 * a * t);
        sx += kWeights[k] * std::cos(th);
        sy += kWeights[k] * std::sin(th);
      }
    }
  }
  return {0.5 * w * sx, 0.5 * w * sy};
}

// The three integrals of the G1 equation on τ ∈ [0, 1] with φ(τ) = A τ² + (δ − A) τ + φ0:
// X = ∫ cos φ, Y = ∫ sin φ, D = ∫ (τ² − τ) cos φ = dY/dA.
struct G1Integrals {
  double x = 0.0, y = 0.0, d = 0.0;
};

G1Integrals g1_integrals(double big_a, double delta, double phi0) {
  const double b = delta - big_a;
  const int n = panels_for(std::max(std::abs(b), std::abs(b + 2.0 * big_a)), 1.0);
  const double w = 1.0 / n;
  G1Integrals r;
  for (int p = 0; p < n; ++p) {
    const double mid = (p + 0.5) * w;
    for (std::size_t k = 0; k < kNodes.size(); ++k) {
      for (const double sign : {-1.0, 1.0}) {
        const double t = mid + sign * kNodes[k] * 0.5 * w;
        const double ph = phi0 + t * (b + big_a * t);
        const double cs = std::cos(ph), sn = std::sin(ph);
        r.x += kWeights[k] * cs;
        r.y += kWeights[k] * sn;
        r.d += kWeights[k] * (t * t - t) * cs;
      }
    }
  }
  r.x *= 0.5 * w;
  r.y *= 0.5 * w;
  r.d *= 0.5 * w;
  return r;
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
  check_finite(p0.x, "p0");
  check_finite(p0.y, "p0");
  check_finite(p1.x, "p1");
  check_finite(p1.y, "p1");
  check_finite(theta0, "theta0");
  check_finite(theta1, "theta1");
  const double dx = p1.x - p0.x, dy = p1.y - p0.y;
  const double r = std::hypot(dx, dy);
  if (!(r > 0.0))
    throw Error(Errc::CoincidentPoints, "p1 coincides with p0: a G1 clothoid needs two distinct points",
                ErrorWhere{.field = "p1"});
  const double phi = std::atan2(dy, dx);
  const double phi0 = reduce_angle(theta0 - phi), phi1 = reduce_angle(theta1 - phi);
  const double delta = phi1 - phi0;
  // Bertolazzi–Frego's guess, then Newton on g(A) = Y(A) (their proof: the relevant root is the unique
  // one in the bracket their guess starts in, and g is monotone enough there for plain Newton).
  double big_a = 3.0 * (phi0 + phi1);
  int it = 0;
  bool converged = false;
  G1Integrals q;
  while (it < options.max_iterations) {
    ++it;
    q = g1_integrals(big_a, delta, phi0);
    if (!(q.d != 0.0) || !std::isfinite(q.d)) break;
    const double step = q.y / q.d;
    big_a -= step;
    if (std::abs(step) <= options.tolerance * std::max(1.0, std::abs(big_a))) {
      converged = true;
      break;
    }
  }
  if (!converged)
    throw Error(Errc::NumericalFailure,
                "G1 clothoid: Newton did not converge in " + std::to_string(it) + " iterations (phi0 = " +
                    format_number(phi0) + ", phi1 = " + format_number(phi1) + ", residual " + format_number(q.y) + ")",
                ErrorWhere{.field = "theta1"});
  // The last step changed A by at most tolerance·|A|: X from the last evaluation is exact to that order.
  const double length = r / q.x;
  ClothoidG1Result result;
  result.segment.start = {p0.x, p0.y, p0.z};
  result.segment.theta0 = theta0;
  result.segment.length = length;
  result.segment.kappa0 = (delta - big_a) / length;
  result.segment.dkappa = 2.0 * big_a / (length * length);
  result.iterations = it;
  return result;
}

}  // namespace hula::intrinsic
