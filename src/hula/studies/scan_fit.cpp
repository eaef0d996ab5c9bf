// SPDX-License-Identifier: MIT
// fit_scan: ordering, robust IRLS fit with parameter correction, fewest control
// points within the tolerance, and ∫|C'''|² fairing under the tolerance (see
// scan_fit.hpp for the method and its references).
#include "hula/studies/scan_fit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <boost/math/quadrature/gauss.hpp>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <string>

#include "hula/core/error.hpp"
#include "hula/diffgeom/energy.hpp"
#include "hula/diffgeom/features.hpp"
#include "hula/nurbs/basis.hpp"
#include "hula/nurbs/closest_point.hpp"

namespace hula::studies {

void ScanFitOptions::validate() const {
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
    throw Error(Errc::InvalidOption, "tolerance must be > 0 and finite, got " + std::to_string(tolerance),
                ErrorWhere{.field = "tolerance"});
  if (degree < 3 || degree > 9)
    throw Error(Errc::InvalidOption, "degree must be in [3, 9], got " + std::to_string(degree),
                ErrorWhere{.field = "degree"});
  if (min_degree < 3 || min_degree > degree)
    throw Error(Errc::InvalidOption,
                "min_degree must be in [3, degree = " + std::to_string(degree) + "], got " + std::to_string(min_degree),
                ErrorWhere{.field = "min_degree"});
  if (max_control_points < static_cast<std::size_t>(degree) + 1)
    throw Error(Errc::InvalidOption,
                "max_control_points must be at least degree + 1, got " + std::to_string(max_control_points),
                ErrorWhere{.field = "max_control_points"});
  if (robust_control_points != 0 && robust_control_points < static_cast<std::size_t>(degree) + 1)
    throw Error(Errc::InvalidOption,
                "robust_control_points must be 0 or at least degree + 1, got " + std::to_string(robust_control_points),
                ErrorWhere{.field = "robust_control_points"});
  order.validate();
}

namespace {

using Matrix = Eigen::MatrixXd;

// Tukey's biweight constant (95 % efficiency under Gaussian noise) and Huber's.
constexpr double kTukey = 4.685;
constexpr double kHuber = 1.345;
// σ = 1.4826 · MAD for Gaussian noise (1 / Φ⁻¹(3/4)).
constexpr double kMadToSigma = 1.4826;
// IRLS rounds of stage 2: Huber's convex weights first (a start the biweight can
// trust), then the biweight until the set of zero weights stops changing.
constexpr int kHuberRounds = 3;
constexpr int kMaxRobustRounds = 12;
// Newton steps of the foot-parameter correction per round (warm-started).
constexpr int kProjectionSteps = 2;
// Relative ridge added to the normal equations of stage 2 and 3 so that knot spans without
// data stay determined (λ relative to trace(BᵀB) / trace(G)); far below any fairing weight.
constexpr double kRidge = 1e-9;
// Fairing search: log10 λ in [kLogLambdaLow, kLogLambdaHigh], bisected kFairingSteps times.
constexpr double kLogLambdaLow = -10.0;
constexpr double kLogLambdaHigh = 4.0;
constexpr int kFairingSteps = 24;
// Rounds of one count-search candidate (a point-distance solve, then tangent-distance solves, each
// followed by the foot correction), and the stall rule: a round that lowers the root of the sum of
// squared distances by less than this fraction ends a candidate that has not met the tolerance.
constexpr int kCorrectionRounds = 12;
constexpr double kStallFraction = 0.01;
// Share α of the point distance in the tangent-distance solve (the rest is the distance to the
// tangent line at the foot).
constexpr double kPointDistanceShare = 0.1;
// Rounds of stage 3 that re-admit rejected points the tolerance fit passes within the tolerance.
constexpr int kReadmissionPasses = 3;

// Foot parameters, spans and non-zero basis values of every point on one knot vector.
struct Design {
  std::size_t p1 = 0;              // p + 1
  std::vector<std::size_t> first;  // index of the first non-zero basis function per point
  std::vector<double> values;      // p + 1 values per point
};

Design make_design(const nurbs::KnotVector& knots, std::span<const double> params) {
  Design d;
  const int p = knots.degree();
  d.p1 = static_cast<std::size_t>(p) + 1;
  d.first.resize(params.size());
  d.values.resize(params.size() * d.p1);
  for (std::size_t i = 0; i < params.size(); ++i) {
    const std::size_t span = knots.find_span(params[i]);
    d.first[i] = span - static_cast<std::size_t>(p);
    nurbs::basis_functions(knots, span, params[i], std::span<double>(d.values).subspan(i * d.p1, d.p1));
  }
  return d;
}

// G_jk = ∫ N_j'''(t) N_k'''(t) dt, exact by 8-point Gauss–Legendre per span (degree ≤ 2(9 − 3) = 12).
Matrix penalty_matrix(const nurbs::KnotVector& knots) {
  const int p = knots.degree();
  const std::size_t n = knots.control_point_count();
  Matrix g = Matrix::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  using Gauss = boost::math::quadrature::gauss<double, 8>;
  const auto& x = Gauss::abscissa();
  const auto& w = Gauss::weights();
  const auto u = knots.values();
  nurbs::BasisWorkspace work;
  for (std::size_t s = static_cast<std::size_t>(p); s < n; ++s) {
    const double a = u[s], b = u[s + 1];
    if (!(b > a)) continue;
    const double mid = 0.5 * (a + b), half = 0.5 * (b - a);
    for (std::size_t q = 0; q < x.size(); ++q)
      for (const double sign : {-1.0, 1.0}) {
        const double t = mid + sign * half * x[q];
        const auto ders = nurbs::basis_derivatives(knots, s, t, 3, work);
        const auto third = ders.subspan(3 * static_cast<std::size_t>(p + 1), static_cast<std::size_t>(p + 1));
        for (int j = 0; j <= p; ++j)
          for (int k = 0; k <= p; ++k)
            g(static_cast<Eigen::Index>(s) - p + j, static_cast<Eigen::Index>(s) - p + k) +=
                w[q] * half * third[static_cast<std::size_t>(j)] * third[static_cast<std::size_t>(k)];
      }
  }
  return g;
}

// The weighted normal equations BᵀWB and BᵀWQ of the points whose weight is positive.
struct Normal {
  Matrix a;
  Matrix rhs;  // n × 3
};

Normal assemble(const Design& d, std::size_t n, std::span<const Vec3> pts, std::span<const double> weights) {
  Normal ne{Matrix::Zero(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n)),
            Matrix::Zero(static_cast<Eigen::Index>(n), 3)};
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double wi = weights[i];
    if (wi <= 0.0) continue;
    const double* v = &d.values[i * d.p1];
    const auto f = static_cast<Eigen::Index>(d.first[i]);
    for (std::size_t j = 0; j < d.p1; ++j) {
      const double wv = wi * v[j];
      const Eigen::Index r = f + static_cast<Eigen::Index>(j);
      for (std::size_t k = 0; k < d.p1; ++k) ne.a(r, f + static_cast<Eigen::Index>(k)) += wv * v[k];
      ne.rhs(r, 0) += wv * pts[i].x;
      ne.rhs(r, 1) += wv * pts[i].y;
      ne.rhs(r, 2) += wv * pts[i].z;
    }
  }
  return ne;
}

// Solves (BᵀWB + λ_rel · s · G) P = BᵀWQ with s = trace(BᵀWB) / trace(G) (λ scale-free).
std::vector<Vec3> solve(const Normal& ne, const Matrix& g, double lambda_rel) {
  const double scale = ne.a.trace() / std::max(g.trace(), std::numeric_limits<double>::min());
  const Matrix m = ne.a + (lambda_rel * scale) * g;
  const Eigen::LDLT<Matrix> ldlt(m);
  const Matrix x = ldlt.solve(ne.rhs);
  if (ldlt.info() != Eigen::Success || !x.allFinite())
    throw Error(Errc::NumericalFailure, "the least-squares system of the scan fit is singular",
                ErrorWhere{.field = "points"});
  std::vector<Vec3> ctrl(static_cast<std::size_t>(x.rows()));
  for (Eigen::Index r = 0; r < x.rows(); ++r) ctrl[static_cast<std::size_t>(r)] = {x(r, 0), x(r, 1), x(r, 2)};
  return ctrl;
}

// The curve as one polynomial per knot span in the local variable x = t − u_s, its Taylor
// coefficients at the span start (A2.3 once per span): C, C' and C'' by Horner in a few flops,
// for the foot corrections and tangent-distance solves that evaluate every point each round.
class SpanPolynomials {
 public:
  SpanPolynomials(const nurbs::KnotVector& knots, std::span<const Vec3> ctrl) : p1_(knots.degree() + 1) {
    const int p = knots.degree();
    const auto u = knots.values();
    nurbs::BasisWorkspace work;
    for (std::size_t s = static_cast<std::size_t>(p); s + 1 < u.size() - static_cast<std::size_t>(p); ++s) {
      if (!(u[s + 1] > u[s])) continue;
      starts_.push_back(u[s]);
      const auto ders = nurbs::basis_derivatives(knots, s, u[s], p, work);
      double factorial = 1.0;
      for (int k = 0; k <= p; ++k) {
        if (k > 0) factorial *= k;
        Vec3 a{};
        for (int j = 0; j <= p; ++j)
          a = a + ders[static_cast<std::size_t>(k * p1_ + j)] * ctrl[s - static_cast<std::size_t>(p - j)];
        coefficients_.push_back((1.0 / factorial) * a);
      }
    }
  }

  // {C(t), C'(t), C''(t)} (order 0 leaves the derivatives zero).
  std::array<Vec3, 3> evaluate(double t, int order) const {
    const auto it = std::upper_bound(starts_.begin() + 1, starts_.end(), t);
    const auto s = static_cast<std::size_t>(it - starts_.begin()) - 1;
    const double x = t - starts_[s];
    const Vec3* a = &coefficients_[s * static_cast<std::size_t>(p1_)];
    Vec3 c = a[p1_ - 1], d1{}, d2{};
    for (int k = p1_ - 2; k >= 0; --k) {
      if (order >= 2) d2 = d2 * x + 2.0 * d1;
      if (order >= 1) d1 = d1 * x + c;
      c = c * x + a[k];
    }
    return {c, d1, d2};
  }

 private:
  int p1_;
  std::vector<double> starts_;      // first parameter of each non-empty span
  std::vector<Vec3> coefficients_;  // p + 1 Taylor coefficients per span
};

// Tangent-distance step (Wang, Pottmann, Liu, "Fitting B-spline curves to point clouds by
// curvature-based squared distance minimization", ACM TOG 25, 2006: TDM with a share α of the
// point distance): minimises Σ wᵢ (|rᵢ|² − (1 − α)(rᵢ·Tᵢ)²) over the control points, rᵢ = C(tᵢ) − Qᵢ and
// Tᵢ the unit tangent of the current curve `ctrl` at the foot tᵢ — the squared distance to the
// tangent line, a Gauss–Newton step of the foot-point distance. It moves the curve across the
// data, where plain parameter correction mostly slides the feet along it and crawls. The α share
// keeps the tangential motion of the control points determined. `dim` is 2 (planar, z = 0) or 3.
std::vector<Vec3> solve_tangent_distance(const nurbs::KnotVector& knots, std::span<const Vec3> ctrl,
                                         std::span<const Vec3> pts, std::span<const double> params,
                                         std::span<const double> weights, const Matrix& g, int dim) {
  const int p = knots.degree();
  const std::size_t p1 = static_cast<std::size_t>(p) + 1;
  const auto d = static_cast<Eigen::Index>(dim);
  const auto size = static_cast<Eigen::Index>(ctrl.size()) * d;
  Matrix a = Matrix::Zero(size, size);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(size);
  const SpanPolynomials curve(knots, ctrl);
  std::vector<double> ders(p1);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const double wi = weights[i];
    if (wi <= 0.0) continue;
    const std::size_t span = knots.find_span(params[i]);
    nurbs::basis_functions(knots, span, params[i], ders);
    const std::size_t first = span - static_cast<std::size_t>(p);
    Vec3 tangent = curve.evaluate(params[i], 1)[1];
    const double speed = std::sqrt(norm_squared(tangent));
    if (speed > 0.0) tangent = (1.0 / speed) * tangent;
    // M = I − (1 − α) T Tᵀ (T = 0 where the curve stops: the point distance alone).
    const double tv[3] = {tangent.x, tangent.y, tangent.z};
    const double qv[3] = {pts[i].x, pts[i].y, pts[i].z};
    double mm[3][3];
    double mq[3];
    for (Eigen::Index r = 0; r < d; ++r) {
      mq[r] = 0.0;
      for (Eigen::Index c = 0; c < d; ++c) {
        mm[r][c] = (r == c ? 1.0 : 0.0) - (1.0 - kPointDistanceShare) * tv[r] * tv[c];
        mq[r] += mm[r][c] * qv[c];
      }
    }
    for (std::size_t j = 0; j < p1; ++j) {
      const double wj = wi * ders[j];
      const Eigen::Index rj = static_cast<Eigen::Index>(first + j) * d;
      for (Eigen::Index r = 0; r < d; ++r) rhs(rj + r) += wj * mq[r];
      for (std::size_t k = 0; k < p1; ++k) {
        const double wjk = wj * ders[k];
        const Eigen::Index ck = static_cast<Eigen::Index>(first + k) * d;
        for (Eigen::Index r = 0; r < d; ++r)
          for (Eigen::Index c = 0; c < d; ++c) a(rj + r, ck + c) += wjk * mm[r][c];
      }
    }
  }
  const double scale = a.trace() / (static_cast<double>(dim) * std::max(g.trace(), std::numeric_limits<double>::min()));
  for (Eigen::Index j = 0; j < g.rows(); ++j)
    for (Eigen::Index k = 0; k < g.cols(); ++k)
      for (Eigen::Index r = 0; r < d; ++r) a(j * d + r, k * d + r) += kRidge * scale * g(j, k);
  const Eigen::LDLT<Matrix> ldlt(a);
  const Eigen::VectorXd x = ldlt.solve(rhs);
  if (ldlt.info() != Eigen::Success || !x.allFinite())
    throw Error(Errc::NumericalFailure, "the tangent-distance system of the scan fit is singular",
                ErrorWhere{.field = "points"});
  std::vector<Vec3> out(ctrl.size());
  for (std::size_t j = 0; j < ctrl.size(); ++j) {
    const Eigen::Index r = static_cast<Eigen::Index>(j) * d;
    out[j] = {x(r), x(r + 1), dim == 3 ? x(r + 2) : 0.0};
  }
  return out;
}

// C(tᵢ) from a design.
Vec3 eval_design(const Design& d, std::size_t i, std::span<const Vec3> ctrl) {
  Vec3 c{};
  const double* v = &d.values[i * d.p1];
  for (std::size_t j = 0; j < d.p1; ++j) c = c + v[j] * ctrl[d.first[i] + j];
  return c;
}

// Newton on f(t) = C'(t)·(C(t) − Q) from each point's current parameter, clamped to [0, 1];
// returns the distances |C(t) − Q| at the corrected parameters.
void correct_parameters(const nurbs::KnotVector& knots, std::span<const Vec3> ctrl, std::span<const Vec3> pts,
                        std::span<double> params, std::span<double> dist, int steps) {
  const SpanPolynomials curve(knots, ctrl);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    double t = params[i];
    bool moved = true;
    for (int it = 0; it < steps; ++it) {
      const auto [d0, d1, d2] = curve.evaluate(t, 2);
      const Vec3 r = d0 - pts[i];
      const double f = dot(d1, r);
      const double df = dot(d2, r) + dot(d1, d1);
      const double next = df > 0.0 ? std::clamp(t - f / df, 0.0, 1.0) : t;
      if (next == t) {
        // Converged (or no descent): d0 is C(t) already.
        dist[i] = std::sqrt(norm_squared(r));
        moved = false;
        break;
      }
      t = next;
    }
    params[i] = t;
    // The distance at the last Newton iterate needs the position only.
    if (moved) dist[i] = std::sqrt(norm_squared(pts[i] - curve.evaluate(t, 0)[0]));
  }
}

double median(std::vector<double> v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// Deviation of the design's points with positive weight at fixed parameters.
double max_design_deviation(const Design& d, std::span<const Vec3> ctrl, std::span<const Vec3> pts,
                            std::span<const double> weights) {
  // Squared distances (model-scale data: no overflow), one square root at the end.
  double worst = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (weights[i] > 0.0) worst = std::max(worst, norm_squared(eval_design(d, i, ctrl) - pts[i]));
  return std::sqrt(worst);
}

ScanCurveReport report(const nurbs::NurbsCurve& curve, std::span<const double> dist, std::span<const double> kept) {
  ScanCurveReport r;
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < dist.size(); ++i)
    if (kept[i] > 0.0) {
      r.max_deviation = std::max(r.max_deviation, dist[i]);
      sum += dist[i];
      ++count;
    }
  r.mean_deviation = count > 0 ? sum / static_cast<double>(count) : 0.0;
  r.control_points = curve.control_points().size();
  r.inflections = diffgeom::inflections(curve).size();
  r.curvature_extrema = diffgeom::curvature_extrema(curve).size();
  r.curvature_variation = diffgeom::curvature_variation_energy(curve).value;
  r.bending = diffgeom::bending_energy(curve).value;
  return r;
}

// Everything of a ScanFitResult but its curves, filled while they are computed.
struct Tally {
  std::vector<std::size_t> strays, order;
  double noise_scale = 0.0, biweight_scale = 0.0, smoothing = 0.0;
  std::size_t fits = 0;
};

}  // namespace

ScanFitResult fit_scan(std::span<const Vec3> points, const ScanFitOptions& options) {
  options.validate();
  const std::size_t m = points.size();
  if (m < 10)
    throw Error(Errc::TooFewPoints, "a scan fit needs at least 10 points, got " + std::to_string(m),
                ErrorWhere{.field = "points"});
  bool planar = true;
  for (std::size_t i = 0; i < m; ++i) {
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y) || !std::isfinite(points[i].z))
      throw Error(Errc::NonFiniteInput, "point " + std::to_string(i) + " is not finite",
                  ErrorWhere{.field = "points", .index = i});
    planar = planar && points[i].z == 0.0;
  }
  const int p = options.degree;
  const int dimension = planar ? 2 : 3;
  Tally out;

  // Stage 1: initial parameters from the order along the curve.
  // The ordering's isolated points (far from all others) start stage 2 with weight 0, so that no
  // stray pulls the first, least robust rounds; the biweight rounds judge them like any point.
  PointOrder order = order_along_curve(points, options.order);
  std::vector<double> params = std::move(order.key);
  if (options.ordered)
    for (std::size_t i = 0; i < m; ++i) params[i] = static_cast<double>(i) / static_cast<double>(m - 1);

  // Stage 2: robust IRLS fit with parameter correction.
  const std::size_t n_robust = options.robust_control_points != 0
                                   ? options.robust_control_points
                                   : std::clamp<std::size_t>(m / 10, static_cast<std::size_t>(p) + 1, 40);
  if (n_robust > m)
    throw Error(Errc::TooFewPoints, "the robust fit needs at least as many points as control points",
                ErrorWhere{.field = "points"});
  std::vector<double> weights(m, 1.0), dist(m, 0.0);
  for (const std::size_t i : order.isolated) weights[i] = 0.0;
  {
    const nurbs::KnotVector knots = nurbs::KnotVector::uniform_clamped(n_robust, p, {0.0, 1.0});
    const Matrix g = penalty_matrix(knots);
    std::vector<char> rejected(m, 0);
    for (int round = 0; round < kMaxRobustRounds; ++round) {
      const Design d = make_design(knots, params);
      const std::vector<Vec3> ctrl = solve(assemble(d, n_robust, points, weights), g, kRidge);
      ++out.fits;
      correct_parameters(knots, ctrl, points, params, dist, kProjectionSteps);
      out.noise_scale = kMadToSigma * median(dist);
      const double sigma = std::max(out.noise_scale, options.tolerance * 1e-3);
      out.biweight_scale = std::max(kTukey * sigma, options.tolerance);
      bool changed = false;
      for (std::size_t i = 0; i < m; ++i) {
        const double r = dist[i];
        if (round < kHuberRounds) {
          weights[i] = r <= kHuber * sigma ? 1.0 : kHuber * sigma / r;
        } else {
          const double u = r / out.biweight_scale;
          weights[i] = u < 1.0 ? (1.0 - u * u) * (1.0 - u * u) : 0.0;
          const char now = u < 1.0 ? 0 : 1;
          changed = changed || now != rejected[i];
          rejected[i] = now;
        }
      }
      if (round > kHuberRounds && !changed) break;
    }
    // A stray lies farther than the tolerance from the robust fit: no fair curve keeps it.
    for (std::size_t i = 0; i < m; ++i) weights[i] = dist[i] > options.tolerance ? 0.0 : 1.0;
  }

  // Stage 3: the fewest control points within the tolerance, measured at corrected feet.
  // A candidate (degree q, n control points, uniform knots) is fitted with parameter correction
  // (Hoschek's intrinsic parametrisation): a least-squares solve at the current feet t, then each
  // foot moved to its Newton projection on the new curve, then tangent-distance solves (the
  // Gauss–Newton step of the foot-point distance, solve_tangent_distance) each followed by the
  // projection. The deviation of a round is |C(tᵢ) − Qᵢ| at the corrected feet of the curve just
  // solved: at least the closest-point distance and close to it, so a candidate meets the tolerance
  // only if every kept point truly lies within it. Rounds stop when the tolerance is met, after
  // kCorrectionRounds, or when the root of the sum of squares stalls (a count that fails); the round
  // with the lowest worst deviation is the candidate's curve.
  struct Candidate {
    nurbs::NurbsCurve curve;
    std::vector<double> params, dist;
    double worst = 0.0;
  };
  auto fit_count = [&](int q, std::size_t n, std::span<const double> t0) {
    const nurbs::KnotVector knots = nurbs::KnotVector::uniform_clamped(n, q, {0.0, 1.0});
    const Matrix g = penalty_matrix(knots);
    std::vector<double> t(t0.begin(), t0.end()), d(m, 0.0);
    std::optional<Candidate> last;
    double previous_rms = std::numeric_limits<double>::infinity();
    for (int round = 0; round < kCorrectionRounds; ++round) {
      std::vector<Vec3> ctrl =
          !last ? solve(assemble(make_design(knots, t), n, points, weights), g, kRidge)
                : solve_tangent_distance(knots, last->curve.control_points(), points, t, weights, g, dimension);
      ++out.fits;
      correct_parameters(knots, ctrl, points, t, d, kProjectionSteps);
      double worst = 0.0, squares = 0.0;
      for (std::size_t i = 0; i < m; ++i)
        if (weights[i] > 0.0) {
          worst = std::max(worst, d[i]);
          squares += d[i] * d[i];
        }
      // The worst deviation is not monotone over the rounds (the squares are): the lowest is kept.
      if (!last || worst < last->worst)
        last = Candidate{nurbs::NurbsCurve(knots, std::move(ctrl), {}, dimension), t, d, worst};
      if (last->worst <= options.tolerance) break;
      const double rms = std::sqrt(squares);
      if (rms > (1.0 - kStallFraction) * previous_rms) break;
      previous_rms = rms;
    }
    return *last;
  };
  std::optional<Candidate> chosen;
  for (int pass = 0;; ++pass) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < m; ++i) kept += weights[i] > 0.0 ? 1 : 0;
    if (kept < static_cast<std::size_t>(options.min_degree) + 1)
      throw Error(Errc::TooFewPoints, "only " + std::to_string(kept) + " points are kept after rejecting strays",
                  ErrorWhere{.field = "points"});
    const std::size_t n_max = std::min(options.max_control_points, kept);
    // At the highest degree p: growth by half from p + 1 until a count meets the tolerance, then
    // bisection between the last count that failed and the first that met it (counts far above the
    // need overfit the noise and make the foot correction unreliable, so they are not tried first).
    const int top = std::min(p, static_cast<int>(n_max) - 1);  // ≥ min_degree: kept > min_degree
    std::size_t lo = static_cast<std::size_t>(top), hi = lo + 1;
    std::optional<Candidate> best;
    for (;;) {
      if (Candidate c = fit_count(top, hi, params); c.worst <= options.tolerance) {
        best = std::move(c);
        break;
      }
      if (hi >= n_max)
        throw Error(Errc::NumericalFailure,
                    "no fit with up to " + std::to_string(n_max) + " control points keeps every kept point within " +
                        std::to_string(options.tolerance),
                    ErrorWhere{.field = "tolerance"});
      lo = hi;
      hi = std::min(n_max, hi + std::max<std::size_t>(1, hi / 2));
    }
    while (hi - lo > 1) {
      const std::size_t mid = lo + (hi - lo) / 2;
      Candidate c = fit_count(top, mid, params);
      if (c.worst <= options.tolerance) {
        hi = mid;
        best = std::move(c);
      } else {
        lo = mid;
      }
    }
    // Lower degrees (as Open CASCADE's approximation tries degree after degree): at degree q < p a
    // single Bézier piece needs only q + 1 control points, so fewer counts than p + 1 are reachable;
    // from the best count minus one, downward while the count still meets the tolerance. Among equal
    // counts the higher degree (smoother, Cᵖ⁻¹ at the knots) is kept.
    for (int q = top - 1; q >= options.min_degree; --q)
      for (std::size_t n = best->curve.control_points().size() - 1; n >= static_cast<std::size_t>(q) + 1; --n) {
        Candidate c = fit_count(q, n, params);
        if (c.worst > options.tolerance) break;
        best = std::move(c);
      }
    chosen = std::move(best);
    params = chosen->params;
    dist = chosen->dist;
    if (pass == kReadmissionPasses) break;
    // Re-admission: a rejected point the tolerance fit passes within the tolerance (by the global
    // closest point) was rejected only because the robust fit fell short there (typically at an end).
    bool readmitted = false;
    for (std::size_t i = 0; i < m; ++i)
      if (weights[i] == 0.0) {
        const nurbs::ClosestPointResult foot = nurbs::closest_point(chosen->curve, points[i]);
        if (foot.distance <= options.tolerance) {
          weights[i] = 1.0;
          params[i] = foot.t;
          readmitted = true;
        }
      }
    if (!readmitted) break;
  }
  for (std::size_t i = 0; i < m; ++i)
    if (weights[i] == 0.0) out.strays.push_back(i);
  const nurbs::NurbsCurve fit = chosen->curve;

  // Stage 4: fairing on fit's knots at the fit's foot parameters: the largest λ within the tolerance.
  nurbs::NurbsCurve faired = fit;
  std::vector<double> fit_dist = dist;
  if (options.fair) {
    const nurbs::KnotVector& knots = fit.knots();
    const std::size_t n = fit.control_points().size();
    const Design d = make_design(knots, params);
    const Normal ne = assemble(d, n, points, weights);
    const Matrix g = penalty_matrix(knots);
    double good = kLogLambdaLow, bad = kLogLambdaHigh;
    std::vector<Vec3> best;
    {
      std::vector<Vec3> ctrl = solve(ne, g, std::pow(10.0, bad));
      ++out.fits;
      if (max_design_deviation(d, ctrl, points, weights) <= options.tolerance) {
        good = bad;
        best = std::move(ctrl);
      }
    }
    for (int step = 0; step < kFairingSteps && good < bad; ++step) {
      const double mid = 0.5 * (good + bad);
      std::vector<Vec3> ctrl = solve(ne, g, std::pow(10.0, mid));
      ++out.fits;
      if (max_design_deviation(d, ctrl, points, weights) <= options.tolerance) {
        good = mid;
        best = std::move(ctrl);
      } else {
        bad = mid;
      }
    }
    if (best.empty()) {
      best = solve(ne, g, std::pow(10.0, good));
      ++out.fits;
      if (max_design_deviation(d, best, points, weights) > options.tolerance) best.clear();
    }
    if (!best.empty()) {
      out.smoothing = std::pow(10.0, good);
      faired = nurbs::NurbsCurve(knots, std::move(best), {}, dimension);
      correct_parameters(knots, faired.control_points(), points, params, dist, kProjectionSteps);
    }
  }

  // Distances of the strays by the global closest point (their local parameters mean nothing).
  for (const std::size_t i : out.strays) {
    const nurbs::ClosestPointResult foot = nurbs::closest_point(faired, points[i]);
    dist[i] = foot.distance;
    params[i] = foot.t;
    fit_dist[i] = nurbs::closest_point(fit, points[i]).distance;
  }
  for (std::size_t i = 0; i < m; ++i)
    if (weights[i] > 0.0) out.order.push_back(i);
  std::stable_sort(out.order.begin(), out.order.end(),
                   [&](std::size_t a, std::size_t b) { return params[a] < params[b]; });
  ScanCurveReport before = report(fit, fit_dist, weights);
  ScanCurveReport after = report(faired, dist, weights);
  // The penalty is ∫|C'''|² dt, not ∫κ'² ds itself: when the faired curve's ∫κ'² ds is not below the
  // tolerance fit's (gentle curves, where both are tiny), the tolerance fit is returned as faired.
  if (after.curvature_variation > before.curvature_variation) {
    faired = fit;
    after = before;
    dist = fit_dist;
    out.smoothing = 0.0;
  }
  ScanFitResult result{.fit = fit,
                       .faired = faired,
                       .strays = std::move(out.strays),
                       .order = std::move(out.order),
                       .parameters = {},
                       .deviations = {},
                       .noise_scale = out.noise_scale,
                       .biweight_scale = out.biweight_scale,
                       .smoothing = out.smoothing,
                       .fits = out.fits,
                       .before = before,
                       .after = after};
  result.deviations = std::move(dist);
  result.parameters = std::move(params);
  return result;
}

}  // namespace hula::studies
