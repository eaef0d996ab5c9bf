// SPDX-License-Identifier: MIT
// Direct reconstruction from prescribed profiles: initial-value problem by the
// natural-equation solver, boundary-value problem by minimum-norm Gauss–Newton
// on Bernstein corrections with the Darboux-vector Jacobian (see the header).
#include "hula/studies/direct_reconstruction.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Dense>
#include <Eigen/QR>
#include <algorithm>
#include <array>
#include <boost/math/quadrature/gauss.hpp>
#include <chrono>
#include <cmath>
#include <iterator>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/law/antiderivative.hpp"

namespace hula::studies {
namespace {

using Matrix = Eigen::MatrixXd;
using Vector = Eigen::VectorXd;

// 8-point Gauss–Legendre rule on [−1, 1]: Boost.Math's positive nodes (used ±) and their weights.
using Gauss8 = boost::math::quadrature::gauss<double, 8>;
// Quadrature panels are at most L / kMinPanels long, so the Jacobian integrals of the
// polynomial corrections are resolved even where the integrator took one long step.
constexpr double kMinPanels = 32.0;
// A step whose end residual exceeds the current one is still accepted while the residual stays
// within this factor of the tolerance: near feasibility the minimum-norm projection may trade a
// rounding-level rise of F for a smaller correction, and Gauss–Newton converges quadratically there.
constexpr double kNearFeasible = 1e3;
// Largest number of step halvings in one iteration before declaring failure.
constexpr int kMaxHalvings = 30;

[[noreturn]] void invalid_option(const std::string& field, double value, const std::string& range) {
  throw Error(Errc::InvalidOption,
              "DirectReconstructionOptions." + field + " = " + format_number(value) + " is outside " + range,
              ErrorWhere{.field = field});
}

double binomial(int n, int k) {
  double b = 1.0;
  for (int i = 1; i <= k; ++i) b = b * static_cast<double>(n - k + i) / static_cast<double>(i);
  return b;
}

// B_k(u), k = 0..n, into out (size n + 1); de Casteljau-free direct form, n ≤ 20.
void bernstein(int n, double u, std::span<double> out) {
  for (int k = 0; k <= n; ++k)
    out[static_cast<std::size_t>(k)] = binomial(n, k) * std::pow(u, k) * std::pow(1.0 - u, n - k);
}

// Σ c_k B_k(u) at u.
double bernstein_sum(std::span<const double> c, double u) {
  const int n = static_cast<int>(c.size()) - 1;
  double v = 0.0;
  for (int k = 0; k <= n; ++k)
    v += c[static_cast<std::size_t>(k)] * binomial(n, k) * std::pow(u, k) * std::pow(1.0 - u, n - k);
  return v;
}

// Panels of the envelope-weighted Gram matrix ∫₀¹ e(u)² B_i B_j du (8-point Gauss–Legendre on each):
// enough for the polynomial degree 2n ≤ 40 times a smooth envelope.
constexpr int kGramPanels = 64;

// Gram matrix ∫₀¹ B_i B_j du = C(n,i) C(n,j) / (C(2n, i+j) (2n + 1)).
Matrix bernstein_gram(int n) {
  Matrix g(n + 1, n + 1);
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      g(i, j) = binomial(n, i) * binomial(n, j) / (binomial(2 * n, i + j) * static_cast<double>(2 * n + 1));
  return g;
}

// The correction Σ c_k B_k(s / L) as a law of `s`: the power-basis coefficients
// a_j = Σ_{k ≤ j} c_k C(n,k) C(n−k, j−k) (−1)^{j−k} in Horner form, a polynomial the
// antiderivative rules integrate exactly (so planar curves keep the exact angle).
law::Law correction_law(std::span<const double> c, const law::Law& u) {
  const int n = static_cast<int>(c.size()) - 1;
  std::vector<double> a(c.size(), 0.0);
  for (int j = 0; j <= n; ++j)
    for (int k = 0; k <= j; ++k)
      a[static_cast<std::size_t>(j)] +=
          c[static_cast<std::size_t>(k)] * binomial(n, k) * binomial(n - k, j - k) * (((j - k) % 2 == 0) ? 1.0 : -1.0);
  const law::Context ctx = u.context();
  law::Law p = ctx.constant(a[static_cast<std::size_t>(n)]);
  for (int j = n - 1; j >= 0; --j) p = a[static_cast<std::size_t>(j)] + u * p;
  return p;
}

bool all_zero(std::span<const double> c) {
  return std::all_of(c.begin(), c.end(), [](double v) { return v == 0.0; });
}

// ∫₀¹ e(u)² B_i B_j du by Gauss–Legendre on kGramPanels panels.
Matrix envelope_gram(int n, const Profile& envelope) {
  const auto& gauss_nodes = Gauss8::abscissa();
  const auto& gauss_weights = Gauss8::weights();
  std::vector<double> u, w;
  for (int panel = 0; panel < kGramPanels; ++panel) {
    const double h = 1.0 / kGramPanels, mid = (panel + 0.5) * h;
    for (std::size_t g = 0; g < gauss_nodes.size(); ++g)
      for (const double sign : {-1.0, 1.0}) {
        u.push_back(mid + sign * gauss_nodes[g] * 0.5 * h);
        w.push_back(gauss_weights[g] * 0.5 * h);
      }
  }
  std::vector<double> e(u.size());
  envelope.sample(u, e);
  Matrix g = Matrix::Zero(n + 1, n + 1);
  std::vector<double> basis(static_cast<std::size_t>(n + 1));
  for (std::size_t q = 0; q < u.size(); ++q) {
    bernstein(n, u[q], basis);
    const double we = w[q] * e[q] * e[q];
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        g(i, j) += we * basis[static_cast<std::size_t>(i)] * basis[static_cast<std::size_t>(j)];
  }
  return g;
}

// Unknowns: [κ coefficients | τ coefficients (optional) | L (optional)].
struct Unknowns {
  int n = 5;
  bool torsion = false;
  bool length = false;
  [[nodiscard]] int size() const { return (n + 1) * (torsion ? 2 : 1) + (length ? 1 : 0); }
  [[nodiscard]] int torsion_offset() const { return n + 1; }
  [[nodiscard]] int length_index() const { return (n + 1) * (torsion ? 2 : 1); }
};

// The end state of one reconstruction and its residuals.
struct Evaluation {
  std::optional<intrinsic::IntrinsicCurve> curve;
  law::Law kappa;
  law::Law tau;
  double length = 0.0;
  Vector residual;           // dimensionless, see the header
  double point_error = 0.0;  // |r(L) − p*|
  double angle_error = 0.0;  // angle(T(L), t*)
  [[nodiscard]] double merit() const { return std::max(point_error / length, angle_error); }
};

class Solver {
 public:
  Solver(const DirectReconstructionProblem& problem, const DirectReconstructionOptions& options)
      : p_(problem), o_(options) {
    const law::Context ctx = p_.curvature.law().context();
    s_ = ctx.parameter("s");
    if (p_.torsion && !(p_.torsion->law().context() == ctx))
      throw Error(Errc::InvalidArgument,
                  "torsion profile belongs to another law context than the curvature profile; build both "
                  "profiles in one law::Context",
                  ErrorWhere{.field = "torsion"});
    if (p_.curvature_envelope && !(p_.curvature_envelope->law().context() == ctx))
      throw Error(Errc::InvalidArgument,
                  "curvature_envelope profile belongs to another law context than the curvature profile; build "
                  "both profiles in one law::Context",
                  ErrorWhere{.field = "curvature_envelope"});
    unknowns_.n = o_.correction_degree;
    unknowns_.torsion = p_.torsion.has_value() && o_.correct_torsion;
    unknowns_.length = o_.vary_length && (p_.end_point || p_.end_tangent || p_.end_normal);
    fixed_.assign(static_cast<std::size_t>(unknowns_.size()), std::nullopt);
    hold_end_curvature(p_.start_curvature, 0.0, 0, "start_curvature");
    hold_end_curvature(p_.end_curvature, 1.0, unknowns_.n, "end_curvature");
  }

  // The correction coefficients fixed by the held end curvatures (nullopt: free).
  [[nodiscard]] const std::vector<std::optional<double>>& fixed() const { return fixed_; }

  // e(u), 1 without an envelope.
  [[nodiscard]] double envelope(double u) const { return p_.curvature_envelope ? (*p_.curvature_envelope)(u) : 1.0; }

  [[nodiscard]] const Unknowns& unknowns() const { return unknowns_; }

  // Reconstructs the curve for unknowns x and measures its end residuals.
  [[nodiscard]] Evaluation evaluate(const Vector& x) const {
    Evaluation e;
    e.length = unknowns_.length ? x(unknowns_.length_index()) : p_.length;
    const double length = e.length;
    const law::Law u = s_ * (1.0 / length);
    const auto coefficients = [&](int offset) {
      std::vector<double> c(static_cast<std::size_t>(unknowns_.n + 1));
      for (int k = 0; k <= unknowns_.n; ++k) c[static_cast<std::size_t>(k)] = x(offset + k);
      return c;
    };
    e.kappa = law::substitute(p_.curvature.law(), p_.curvature.variable(), u);
    const std::vector<double> ck = coefficients(0);
    const bool kappa_corrected = !all_zero(ck);
    bool tau_corrected = false;
    if (kappa_corrected) {
      law::Law correction = correction_law(ck, u);
      if (p_.curvature_envelope)
        correction = law::substitute(p_.curvature_envelope->law(), p_.curvature_envelope->variable(), u) * correction;
      e.kappa = e.kappa + correction;
    }
    intrinsic::ReconstructionOptions ro;
    ro.tolerance = std::clamp(o_.integration_tolerance * length, 1e-13, 1e-2);
    ro.max_steps = o_.max_steps;
    if (p_.torsion) {
      e.tau = law::substitute(p_.torsion->law(), p_.torsion->variable(), u);
      if (unknowns_.torsion) {
        const std::vector<double> ct = coefficients(unknowns_.torsion_offset());
        tau_corrected = !all_zero(ct);
        if (tau_corrected) e.tau = e.tau + correction_law(ct, u);
      }
      ro.breaks = breaks(e.kappa, e.tau, length, kappa_corrected, tau_corrected);
      e.curve = intrinsic::reconstruct(e.kappa, e.tau, "s", length, p_.start, ro);
    } else {
      e.tau = s_.context().constant(0.0);
      ro.breaks = breaks(e.kappa, e.tau, length, kappa_corrected, false);
      if (law::antiderivative(e.kappa, "s")) {
        e.curve = intrinsic::reconstruct_planar(e.kappa, "s", length, p_.start, ro);
      } else {
        // No closed-form angle: integrate the Frenet–Serret system with τ = 0 directly (it stays
        // in the start plane). reconstruct_planar would first try a numeric definite integral of
        // κ to the rounding level, which is slow on B-spline profiles.
        ro.method = intrinsic::ReconstructionMethod::FrenetSerret;
        e.curve = intrinsic::reconstruct(e.kappa, e.tau, "s", length, p_.start, ro);
      }
    }
    ++reconstructions_;
    measure(e);
    return e;
  }

  // The kinks of κ and τ for the reconstruction at this length (intrinsic::reconstruction_breaks). A correction is
  // a polynomial in u (times the envelope profile for κ), whose coefficients add no kink and no pole: evaluations
  // at one length with the same corrections present have the same kinks, so the singularity analysis (a root
  // search per knot of a B-spline profile) runs once per such case, not once per Gauss–Newton step. (The solver
  // runs on one thread.)
  [[nodiscard]] std::vector<double> breaks(const law::Law& kappa, const law::Law& tau, double length,
                                           bool kappa_corrected, bool tau_corrected) const {
    const BreaksKey key{length, kappa_corrected, tau_corrected};
    auto it = std::find_if(breaks_.begin(), breaks_.end(), [&](const auto& b) { return b.first == key; });
    if (it == breaks_.end()) {
      breaks_.emplace_back(key, intrinsic::reconstruction_breaks(kappa, tau, "s", length));
      it = std::prev(breaks_.end());
    }
    return it->second;
  }

  // The end residuals of a reconstruction in the frame fixed by set_frame().
  void measure(Evaluation& e) const {
    const double length = e.length;
    const intrinsic::FramePoint end = e.curve->evaluate(length);
    e.point_error = 0.0;
    e.angle_error = 0.0;
    e.residual.resize(constraint_count());
    int row = 0;
    if (p_.end_point) {
      const Vec3 d = end.position - *p_.end_point;
      e.point_error = norm(d);
      if (planar()) {
        e.residual(row++) = dot(d, e_x_) / length;
        e.residual(row++) = dot(d, e_y_) / length;
      } else {
        for (std::size_t i = 0; i < 3; ++i) e.residual(row++) = d[i] / length;
      }
    }
    if (p_.end_tangent) {
      const Vec3 a = cross(t_end_, end.tangent);
      const double c = dot(t_end_, end.tangent);
      if (planar()) {
        e.residual(row++) = std::atan2(dot(a, b_), c);
        e.angle_error = std::abs(e.residual(row - 1));
      } else {
        // Rotation vector from t* to T(L): angle θ about a / |a|; its two components normal to t*.
        const double sin_angle = norm(a);
        const double angle = std::atan2(sin_angle, c);
        const Vec3 rho = sin_angle > 0.0 ? a * (angle / sin_angle) : Vec3{};
        e.residual(row++) = dot(rho, t_e1_);
        e.residual(row++) = dot(rho, t_e2_);
        e.angle_error = angle;
      }
    }
    if (p_.end_normal) {
      // The rotation about T(L) from n* (made normal to T(L)) to N(L).
      const Vec3 n_star = normalized(n_end_ - end.tangent * dot(end.tangent, n_end_));
      const double angle = std::atan2(dot(cross(n_star, end.normal), end.tangent), dot(n_star, end.normal));
      e.residual(row++) = angle;
      e.angle_error = std::max(e.angle_error, std::abs(angle));
    }
  }

  // Fixes the plane basis (planar) and the end-tangent basis from the normalised start frame.
  void set_frame(const intrinsic::FramePoint& start) {
    e_x_ = start.tangent;
    e_y_ = start.normal;
    b_ = start.binormal;
    if (p_.end_tangent) {
      t_end_ = normalized(*p_.end_tangent);
      const Vec3 helper = std::abs(t_end_.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
      t_e1_ = normalized(cross(t_end_, helper));
      t_e2_ = cross(t_end_, t_e1_);
    }
    if (p_.end_normal) n_end_ = *p_.end_normal;
  }

  [[nodiscard]] bool planar() const { return !p_.torsion.has_value(); }

  [[nodiscard]] int constraint_count() const {
    const int point_rows = p_.end_point ? (planar() ? 2 : 3) : 0;
    const int tangent_rows = p_.end_tangent ? (planar() ? 1 : 2) : 0;
    return point_rows + tangent_rows + (p_.end_normal ? 1 : 0);
  }

  // ∂F/∂x by the Darboux-vector sensitivities (header), Gauss–Legendre over the dense curve.
  [[nodiscard]] Matrix jacobian(const Evaluation& e) const {
    const intrinsic::IntrinsicCurve& curve = *e.curve;
    const double length = e.length;
    // Panels: the integration nodes, each split into pieces no longer than L / kMinPanels.
    const std::span<const double> nodes = curve.nodes();
    const auto& gauss_nodes = Gauss8::abscissa();
    const auto& gauss_weights = Gauss8::weights();
    std::vector<double> s_points, weights;
    for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
      const double a = nodes[i], b = nodes[i + 1];
      const int pieces = std::max(1, static_cast<int>(std::ceil((b - a) * kMinPanels / length)));
      const double h = (b - a) / pieces;
      for (int piece = 0; piece < pieces; ++piece) {
        const double mid = a + (piece + 0.5) * h;
        for (std::size_t g = 0; g < gauss_nodes.size(); ++g) {
          for (const double sign : {-1.0, 1.0}) {
            s_points.push_back(std::clamp(mid + sign * gauss_nodes[g] * 0.5 * h, 0.0, length));
            weights.push_back(gauss_weights[g] * 0.5 * h);
          }
        }
      }
    }
    const std::vector<intrinsic::FramePoint> frames = curve.evaluate(s_points);
    const intrinsic::FramePoint end = curve.evaluate(length);
    const int m = unknowns_.size();
    // Per unknown: δr(L) and δΩ = ∫δω (the tangent turns by δΩ × T(L)).
    std::vector<Vec3> d_r(static_cast<std::size_t>(m)), d_omega(static_cast<std::size_t>(m));
    std::vector<double> basis(static_cast<std::size_t>(unknowns_.n + 1));
    for (std::size_t q = 0; q < frames.size(); ++q) {
      const intrinsic::FramePoint& f = frames[q];
      const Vec3 lever = end.position - f.position;
      const double w = weights[q];
      bernstein(unknowns_.n, f.s / length, basis);
      const Vec3 bend = f.binormal * (w * envelope(f.s / length));  // δω of a unit δκ coefficient, times the weight
      const Vec3 bend_r = cross(bend, lever);
      for (int k = 0; k <= unknowns_.n; ++k) {
        const double bk = basis[static_cast<std::size_t>(k)];
        d_r[static_cast<std::size_t>(k)] += bend_r * bk;
        d_omega[static_cast<std::size_t>(k)] += bend * bk;
      }
      if (unknowns_.torsion) {
        const Vec3 twist = f.tangent * w;  // δω of a unit δτ
        const Vec3 twist_r = cross(twist, lever);
        for (int k = 0; k <= unknowns_.n; ++k) {
          const auto j = static_cast<std::size_t>(unknowns_.torsion_offset() + k);
          const double bk = basis[static_cast<std::size_t>(k)];
          d_r[j] += twist_r * bk;
          d_omega[j] += twist * bk;
        }
      }
      if (unknowns_.length) {
        // With u fixed, a longer curve turns at the rate ω / L more per unit length.
        const Vec3 omega = (f.binormal * f.curvature + f.tangent * f.torsion) * (w / length);
        const auto j = static_cast<std::size_t>(unknowns_.length_index());
        d_r[j] += cross(omega, lever);
        d_omega[j] += omega;
      }
    }
    if (unknowns_.length) {
      const Vec3 start = frames.empty() ? end.position : curve.evaluate(0.0).position;
      d_r[static_cast<std::size_t>(unknowns_.length_index())] += (end.position - start) / length;
    }
    Matrix jac = Matrix::Zero(constraint_count(), m);
    for (int col = 0; col < m; ++col) {
      const Vec3& dr = d_r[static_cast<std::size_t>(col)];
      const Vec3& om = d_omega[static_cast<std::size_t>(col)];
      int row = 0;
      if (p_.end_point) {
        if (planar()) {
          jac(row++, col) = dot(dr, e_x_) / length;
          jac(row++, col) = dot(dr, e_y_) / length;
        } else {
          for (std::size_t i = 0; i < 3; ++i) jac(row++, col) = dr[i] / length;
        }
      }
      if (p_.end_tangent) {
        // T × (δΩ × T) = δΩ − T (T·δΩ): the turn of T(L) seen as a rotation vector (exact at T = t*).
        const Vec3 turn = om - end.tangent * dot(end.tangent, om);
        if (planar()) {
          jac(row++, col) = dot(turn, b_);
        } else {
          jac(row++, col) = dot(turn, t_e1_);
          jac(row++, col) = dot(turn, t_e2_);
        }
      }
      if (p_.end_normal) jac(row++, col) = dot(om, end.tangent);  // δN = δΩ × N: the turn about T(L)
    }
    return jac;
  }

  // The metric M of the minimum-norm objective (header): L0² G per profile block, w / L0² for L.
  [[nodiscard]] Matrix metric() const {
    const int m = unknowns_.size();
    Matrix metric = Matrix::Zero(m, m);
    const double l2 = p_.length * p_.length;
    const Matrix g = bernstein_gram(unknowns_.n) * l2;
    const int b = unknowns_.n + 1;
    metric.block(0, 0, b, b) =
        p_.curvature_envelope ? Matrix(envelope_gram(unknowns_.n, *p_.curvature_envelope) * l2) : g;
    if (unknowns_.torsion) metric.block(b, b, b, b) = g;
    if (unknowns_.length) {
      const int j = unknowns_.length_index();
      metric(j, j) = o_.length_weight / (p_.length * p_.length);
    }
    return metric;
  }

  [[nodiscard]] Vector reference() const {
    Vector x = Vector::Zero(unknowns_.size());
    if (unknowns_.length) x(unknowns_.length_index()) = p_.length;
    return x;
  }

  // y_fix: the held coefficients' values (zero elsewhere).
  [[nodiscard]] Vector fixed_offset() const {
    Vector y = Vector::Zero(unknowns_.size());
    for (std::size_t i = 0; i < fixed_.size(); ++i)
      if (fixed_[i]) y(static_cast<Eigen::Index>(i)) = *fixed_[i];
    return y;
  }

  [[nodiscard]] int reconstructions() const { return reconstructions_; }

 private:
  // A held end curvature κ_h at u (0 or 1) fixes coefficient k: κ*(u) + e(u) c_k = κ_h. Where the
  // envelope vanishes the curvature there is κ*(u) whatever c_k is: then κ_h must already be it.
  void hold_end_curvature(const std::optional<double>& held, double u, int k, const char* field) {
    if (!held) return;
    const double target = p_.curvature(u);
    const double e = envelope(u);
    const double scale = std::max({std::abs(*held), std::abs(target), 1.0 / p_.length});
    if (std::abs(e) <= kZeroEnvelope * scale) {
      if (std::abs(*held - target) > kZeroEnvelope * scale)
        throw Error(Errc::InvalidArgument,
                    std::string(field) + " = " + format_number(*held) + " differs from the target's " +
                        format_number(target) +
                        " where the correction envelope is zero: the correction cannot change the curvature there",
                    ErrorWhere{.field = field});
      return;  // held by the envelope itself
    }
    fixed_[static_cast<std::size_t>(k)] = (*held - target) / e;
  }

  // An envelope below this fraction of the curvature scale counts as zero (a relative correction at a
  // natural end or an inflection, whose target is zero to rounding).
  static constexpr double kZeroEnvelope = 1e-10;

  const DirectReconstructionProblem& p_;
  const DirectReconstructionOptions& o_;
  law::Law s_;
  Unknowns unknowns_;
  std::vector<std::optional<double>> fixed_;
  Vec3 e_x_{}, e_y_{}, b_{}, t_end_{}, t_e1_{}, t_e2_{}, n_end_{};
  mutable int reconstructions_ = 0;
  using BreaksKey = std::tuple<double, bool, bool>;  // length, κ corrected, τ corrected
  mutable std::vector<std::pair<BreaksKey, std::vector<double>>> breaks_;
};

void check_problem(const DirectReconstructionProblem& p, const DirectReconstructionOptions& o) {
  if (!std::isfinite(p.length))
    throw Error(Errc::NonFiniteInput, "length = " + format_number(p.length) + " is not finite",
                ErrorWhere{.field = "length"});
  if (p.length <= 0.0)
    throw Error(Errc::InvalidArgument, "length = " + format_number(p.length) + " must be positive",
                ErrorWhere{.field = "length"});
  if (p.end_point) {
    for (std::size_t i = 0; i < 3; ++i)
      if (!std::isfinite((*p.end_point)[i]))
        throw Error(Errc::NonFiniteInput,
                    "end_point[" + std::to_string(i) + "] = " + format_number((*p.end_point)[i]) + " is not finite",
                    ErrorWhere{.field = "end_point", .index = i});
    if (!o.vary_length && is_finite(p.start.point)) {
      const double reach = distance(*p.end_point, p.start.point);
      if (reach > p.length * (1.0 - o.end_tolerance))
        throw Error(Errc::InvalidArgument,
                    "end_point is " + format_number(reach) +
                        " from the start point, farther than (or as far as) the length L = " + format_number(p.length) +
                        ": no curve of that length can reach it (a straight segment " +
                        "only when equal); lengthen the curve or set vary_length",
                    ErrorWhere{.field = "end_point"});
    }
  }
  if (p.end_tangent) {
    for (std::size_t i = 0; i < 3; ++i)
      if (!std::isfinite((*p.end_tangent)[i]))
        throw Error(Errc::NonFiniteInput,
                    "end_tangent[" + std::to_string(i) + "] = " + format_number((*p.end_tangent)[i]) + " is not finite",
                    ErrorWhere{.field = "end_tangent", .index = i});
    if (norm(*p.end_tangent) == 0.0)
      throw Error(Errc::InvalidArgument, "end_tangent is the zero vector: it gives no direction",
                  ErrorWhere{.field = "end_tangent"});
  }
  if (p.end_normal) {
    for (std::size_t i = 0; i < 3; ++i)
      if (!std::isfinite((*p.end_normal)[i]))
        throw Error(Errc::NonFiniteInput,
                    "end_normal[" + std::to_string(i) + "] = " + format_number((*p.end_normal)[i]) + " is not finite",
                    ErrorWhere{.field = "end_normal", .index = i});
    if (!p.torsion)
      throw Error(Errc::InvalidArgument,
                  "end_normal is for space curves: a planar curve's normal is fixed by its plane and the sign of κ",
                  ErrorWhere{.field = "end_normal"});
    if (!p.end_tangent)
      throw Error(Errc::InvalidArgument, "end_normal needs end_tangent: the normal is held about the end tangent",
                  ErrorWhere{.field = "end_normal"});
    const Vec3 t = normalized(*p.end_tangent);
    if (norm(*p.end_normal - t * dot(t, *p.end_normal)) <= 1e-9 * norm(*p.end_normal))
      throw Error(Errc::InvalidArgument, "end_normal is zero or parallel to end_tangent: it gives no normal direction",
                  ErrorWhere{.field = "end_normal"});
  }
  for (const auto& [value, field] :
       {std::pair{p.start_curvature, "start_curvature"}, std::pair{p.end_curvature, "end_curvature"}})
    if (value && !std::isfinite(*value))
      throw Error(Errc::NonFiniteInput, std::string(field) + " = " + format_number(*value) + " is not finite",
                  ErrorWhere{.field = field});
  const int held = (p.start_curvature ? 1 : 0) + (p.end_curvature ? 1 : 0);
  const int constraints =
      (p.end_point ? (p.torsion ? 3 : 2) : 0) + (p.end_tangent ? (p.torsion ? 2 : 1) : 0) + (p.end_normal ? 1 : 0);
  const int unknowns = (o.correction_degree + 1) * ((p.torsion && o.correct_torsion) ? 2 : 1) - held +
                       (o.vary_length && constraints > 0 ? 1 : 0);
  if (unknowns < constraints)
    throw Error(Errc::InvalidOption,
                "DirectReconstructionOptions.correction_degree = " + std::to_string(o.correction_degree) + " gives " +
                    std::to_string(unknowns) + " free correction coefficients for " + std::to_string(constraints) +
                    " end conditions; raise the degree" +
                    (p.torsion && !o.correct_torsion ? " or correct_torsion" : ""),
                ErrorWhere{.field = "correction_degree"});
}

// Planar curves live in the start plane: an end point or tangent off it cannot be met.
void check_planar_ends(const DirectReconstructionProblem& p, const intrinsic::FramePoint& start) {
  if (p.torsion) return;
  if (p.end_point) {
    const double off = dot(*p.end_point - start.position, start.binormal);
    if (std::abs(off) > 1e-12 * std::max(1.0, p.length) + 1e-9 * p.length)
      throw Error(Errc::InvalidArgument,
                  "end_point is " + format_number(off) +
                      " off the plane of the start tangent and normal; a planar curve (no torsion profile) "
                      "cannot reach it",
                  ErrorWhere{.field = "end_point"});
  }
  if (p.end_tangent) {
    const double off = dot(normalized(*p.end_tangent), start.binormal);
    if (std::abs(off) > 1e-9)
      throw Error(Errc::InvalidArgument,
                  "end_tangent has a component " + format_number(off) +
                      " normal to the plane of the start tangent and normal; a planar curve cannot meet it",
                  ErrorWhere{.field = "end_tangent"});
  }
}

}  // namespace

void DirectReconstructionOptions::validate() const {
  if (correction_degree < 1 || correction_degree > 20)
    invalid_option("correction_degree", correction_degree, "[1, 20]");
  if (!(length_weight > 0.0 && length_weight <= 1e6)) invalid_option("length_weight", length_weight, "(0, 1e6]");
  if (!(end_tolerance >= 1e-13 && end_tolerance <= 1e-2))
    invalid_option("end_tolerance", end_tolerance, "[1e-13, 1e-2]");
  if (!(optimality_tolerance >= 1e-12 && optimality_tolerance <= 1e-1))
    invalid_option("optimality_tolerance", optimality_tolerance, "[1e-12, 0.1]");
  if (max_iterations < 1 || max_iterations > 10'000) invalid_option("max_iterations", max_iterations, "[1, 10000]");
  if (!(integration_tolerance >= 1e-13 && integration_tolerance <= 1e-3))
    invalid_option("integration_tolerance", integration_tolerance, "[1e-13, 1e-3]");
  if (max_steps < 1 || max_steps > 100'000'000)
    invalid_option("max_steps", static_cast<double>(max_steps), "[1, 100000000]");
  if (deviation_samples < 2 || deviation_samples > 1'000'000)
    invalid_option("deviation_samples", static_cast<double>(deviation_samples), "[2, 1000000]");
  fit_options.validate();
}

DirectReconstructionResult reconstruct_direct(const DirectReconstructionProblem& problem,
                                              const DirectReconstructionOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  options.validate();
  check_problem(problem, options);
  Solver solver(problem, options);
  const Unknowns& unknowns = solver.unknowns();
  Vector x = solver.reference();
  Evaluation current = solver.evaluate(x);
  const intrinsic::FramePoint start = current.curve->evaluate(0.0);
  check_planar_ends(problem, start);
  solver.set_frame(start);

  int iterations = 0;
  const Vector x_ref = solver.reference();
  const Vector y_fix = solver.fixed_offset();
  const bool any_fixed = y_fix.cwiseAbs().maxCoeff() > 0.0;
  if (solver.constraint_count() > 0 || any_fixed) {
    solver.measure(current);  // residuals in the frame just fixed
    const Matrix metric = solver.metric();
    // The free unknowns (P of the header) and the metric restricted to them.
    std::vector<Eigen::Index> free;
    for (Eigen::Index i = 0; i < x.size(); ++i)
      if (!solver.fixed()[static_cast<std::size_t>(i)]) free.push_back(i);
    const auto nf = static_cast<Eigen::Index>(free.size());
    Matrix m_ff(nf, nf);
    Vector g(nf);
    const Vector m_yfix = metric * y_fix;
    for (Eigen::Index a = 0; a < nf; ++a) {
      g(a) = m_yfix(free[static_cast<std::size_t>(a)]);
      for (Eigen::Index b = 0; b < nf; ++b)
        m_ff(a, b) = metric(free[static_cast<std::size_t>(a)], free[static_cast<std::size_t>(b)]);
    }
    const Eigen::LLT<Matrix> llt(m_ff);
    const Matrix r_upper = llt.matrixU();
    const Vector w_shift = llt.solve(g);  // M_ff⁻¹ g
    // x for free coordinates w: x_ref + y_fix + P w.
    const auto assemble = [&](const Vector& w) {
      Vector out = x_ref + y_fix;
      for (Eigen::Index a = 0; a < nf; ++a) out(free[static_cast<std::size_t>(a)]) += w(a);
      return out;
    };
    if (solver.constraint_count() == 0) {
      // Only held end curvatures: the free coefficients that make the whole correction least (w = −M_ff⁻¹ g).
      x = assemble(-w_shift);
      current = solver.evaluate(x);
    } else {
      if (any_fixed) current = solver.evaluate(x = assemble(Vector::Zero(nf)));
      const double tol = options.end_tolerance;
      // Optimality: the minimum-norm iteration converges linearly once feasible (it ignores the
      // constraints' curvature), so it stops when a step is below optimality_tolerance times the
      // correction's own norm (or below the end tolerance in absolute terms).
      const auto step_tol = [&](const Vector& at) {
        const Vector y = at - x_ref;
        return std::max(tol, options.optimality_tolerance * std::sqrt(std::max(0.0, y.dot(metric * y))));
      };
      bool converged = false;
      while (iterations < options.max_iterations) {
        ++iterations;
        const Matrix jac = solver.jacobian(current);
        Matrix jac_free(jac.rows(), nf);
        Vector w_now(nf);
        for (Eigen::Index a = 0; a < nf; ++a) {
          jac_free.col(a) = jac.col(free[static_cast<std::size_t>(a)]);
          w_now(a) = x(free[static_cast<std::size_t>(a)]) - x_ref(free[static_cast<std::size_t>(a)]);
        }
        // Least-norm w with J P w = J P w_now − F (the held part does not move): v the least
        // M_ff-norm solution of J P v = that + J P M_ff⁻¹ g, w = v − M_ff⁻¹ g (header). With
        // M_ff = RᵀR: z = (J P R⁻¹)⁺ rhs, v = R⁻¹ z.
        const Matrix j_hat = r_upper.transpose().triangularView<Eigen::Lower>().solve(jac_free.transpose()).transpose();
        const Vector rhs = jac_free * (w_now + w_shift) - current.residual;
        const Vector z = Eigen::CompleteOrthogonalDecomposition<Matrix>(j_hat).solve(rhs);
        const Vector w = r_upper.triangularView<Eigen::Upper>().solve(z) - w_shift;
        const Vector step = assemble(w) - x;
        const double step_norm = std::sqrt(std::max(0.0, step.dot(metric * step)));
        if (current.merit() <= tol && step_norm <= step_tol(x)) {
          converged = true;
          break;
        }
        double alpha = 1.0;
        bool accepted = false;
        for (int halving = 0; halving <= kMaxHalvings; ++halving, alpha *= 0.5) {
          const Vector trial_x = x + alpha * step;
          if (unknowns.length && !(trial_x(unknowns.length_index()) > 0.0)) continue;
          Evaluation trial = solver.evaluate(trial_x);
          if (trial.merit() < current.merit() || trial.merit() <= kNearFeasible * tol) {
            x = trial_x;
            current = std::move(trial);
            accepted = true;
            break;
          }
        }
        if (!accepted) break;
        if (current.merit() <= tol && alpha * step_norm <= step_tol(x)) {
          converged = true;
          break;
        }
      }
      if (!converged && current.merit() > tol)
        throw Error(Errc::NumericalFailure,
                    "direct reconstruction did not meet the end constraints in " + std::to_string(iterations) +
                        " Gauss-Newton iterations: reached end point error " + format_number(current.point_error) +
                        " (L = " + format_number(current.length) + "), end tangent angle error " +
                        format_number(current.angle_error) + " rad, tolerance " + format_number(tol) +
                        "; raise correction_degree or max_iterations, or check that the end is reachable",
                    ErrorWhere{.field = problem.end_point ? "end_point" : "end_tangent"});
    }
  }

  DirectReconstructionResult result{.curve = std::move(*current.curve)};
  result.curvature_law = current.kappa;
  result.torsion_law = current.tau;
  result.planar = solver.planar();
  result.length = current.length;
  result.end_point_error = current.point_error;
  result.end_tangent_error = current.angle_error;
  result.iterations = iterations;
  const std::size_t nb = static_cast<std::size_t>(unknowns.n) + 1;
  result.curvature_correction.assign(x.data(), x.data() + nb);
  if (unknowns.torsion)
    result.torsion_correction.assign(x.data() + unknowns.torsion_offset(), x.data() + unknowns.torsion_offset() + nb);

  // Profile deviation: κ = κ* + δκ exactly (the integrated law), so |κ − κ*| = |δκ(u)|.
  const std::size_t n_samples = options.deviation_samples;
  double sum_k = 0.0, max_k = 0.0, sum_t = 0.0, max_t = 0.0;
  for (std::size_t i = 0; i < n_samples; ++i) {
    const double u = static_cast<double>(i) / static_cast<double>(n_samples - 1);
    const double dk = std::abs(solver.envelope(u) * bernstein_sum(result.curvature_correction, u));
    sum_k += dk;
    max_k = std::max(max_k, dk);
    if (!result.torsion_correction.empty()) {
      const double dt = std::abs(bernstein_sum(result.torsion_correction, u));
      sum_t += dt;
      max_t = std::max(max_t, dt);
    }
  }
  result.mean_curvature_deviation = sum_k / static_cast<double>(n_samples);
  result.max_curvature_deviation = max_k;
  result.mean_torsion_deviation = sum_t / static_cast<double>(n_samples);
  result.max_torsion_deviation = max_t;
  if (options.fit) result.nurbs = intrinsic::fit_nurbs(result.curve, options.fit_options);
  result.reconstructions = solver.reconstructions();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace hula::studies
