// SPDX-License-Identifier: MIT
// Design by curvature on an existing curve: target profile, start curve (the
// original, or the least-squares fit of the boundary-value reconstruction),
// Levenberg–Marquardt on the control points with the end rows held exactly,
// refinement up to the handle budget (see the header).
//
// Notation: a, b the original's domain; L its length; s arc length, u = s / L;
// t_j the samples' parameters (on a fit: where its arc length is u_j times its
// own length L'), κ*_j the target at u_j, r_j = r(s_j) the
// reconstruction's points; R_i the fit's (rational) basis of degree p; P_i its
// control points, x their coordinates stacked; T, N, B the Frenet frame
// (planar: N = n × T the signed normal, B = n the plane normal); σ = |C'| the
// parameter speed.
#include "hula/studies/curvature_edit.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/diffgeom/features.hpp"
#include "hula/diffgeom/frenet.hpp"
#include "hula/nurbs/arc_length.hpp"
#include "hula/nurbs/basis.hpp"
#include "hula/nurbs/knot_vector.hpp"
#include "hula/nurbs/refine.hpp"
#include "hula/studies/detail/curve_plane.hpp"

namespace hula::studies {
namespace {

using Matrix = Eigen::MatrixXd;
using Vector = Eigen::VectorXd;

// The profiles' B-spline functions have spans at most this long in u (plus a knot at every breakpoint of the
// original): a cubic least-squares fit of a smooth κ(u) within about 1e-6 of its range.
constexpr double kProfileSpan = 1.0 / 48.0;
// A uniform profile knot closer than this (in u) to a breakpoint is dropped (no sliver spans).
constexpr double kProfileKnotGap = 1.0 / 192.0;
// The smoothed sign σ(κ) = κ / √(κ² + ε²) of a Change edit uses ε = this × max |κ|: the change flips over a
// short stretch across an inflection instead of jumping (the reconstruction needs a continuous κ*).
constexpr double kSignSmoothing = 1e-3;
// A drag lowers |κ| to at most this fraction of what it was, never to zero or past it.
constexpr double kMinMagnitude = 0.1;
// The refinement resolves the edit: its curvature tolerance is at most this fraction of the largest change asked.
constexpr double kEditResolution = 0.2;
// Extra weight of a drag's samples in the profile fit, times the change there over the largest change. Measured
// on S-splines and a quarter circle: 0.5 moves the dragged spot 0.57–1.04 of the drag (0.41–0.73 unweighted) and
// lowers the worst miss; 1.5 and more let the fit trade a spike elsewhere (misses of 7–80 drags on the S).
constexpr double kDragWeight = 0.5;
// A space drag's height is corrected until the fit moves the dragged spot by the drag within this fraction of it,
// in at most this many more fits, the height kept within this range of the drag's (a secant step on a fit that
// barely responds could ask for a wild one).
constexpr double kReachTolerance = 0.01;
constexpr int kReachIterations = 4;
constexpr std::pair<double, double> kReachScale{0.25, 4.0};
// An end curvature this small relative to the curve's largest counts as zero (a natural end): the fit keeps it
// zero so no inflection appears at the end.
constexpr double kZeroEndCurvature = 1e-9;

// Sign changes along count samples of a profile, values within kZeroEndCurvature × scale of zero counting as zero.
template <class KappaOf>
int sign_changes(std::size_t count, double scale, const KappaOf& kappa_of) {
  int changes = 0, previous = 0;
  for (std::size_t j = 0; j < count; ++j) {
    const double k = kappa_of(j);
    const int sign = k > kZeroEndCurvature * scale ? 1 : (k < -kZeroEndCurvature * scale ? -1 : 0);
    if (sign != 0 && previous != 0 && sign != previous) ++changes;
    if (sign != 0) previous = sign;
  }
  return changes;
}
// A target sample this large relative to max |κ*| bends: the fit may not make the curve straight there.
constexpr double kStraightTarget = 1e-3;
// Null space of the end rows: singular values below this fraction of the largest count as zero.
constexpr double kNullSpace = 1e-10;
// Central-difference step of the polish's Jacobian, as a fraction of the curve's size.
constexpr double kDifferenceStep = 1e-6;
// Levenberg–Marquardt iterations of the profile fit, and damping increases tried per iteration.
constexpr int kPolishIterations = 30;
constexpr int kDampingTries = 8;
// Parameter-correction rounds per fit, and Newton steps per round.
constexpr int kCorrectionRounds = 3;
constexpr int kNewtonSteps = 2;

[[noreturn]] void invalid_edit_option(const std::string& field, double value, const std::string& range) {
  throw Error(Errc::InvalidOption,
              "CurvatureEditOptions." + field + " = " + format_number(value) + " is outside " + range,
              ErrorWhere{.field = field});
}

[[noreturn]] void bad_curve(const std::string& message) {
  throw Error(Errc::InvalidArgument, message, ErrorWhere{.field = "curve"});
}

// Two unit vectors normal to the unit vector t.
std::pair<Vec3, Vec3> normals_of(const Vec3& t) {
  const Vec3 helper = std::abs(t.x) < 0.6 ? Vec3{1, 0, 0} : Vec3{0, 1, 0};
  const Vec3 e1 = normalized(cross(t, helper));
  return {e1, cross(t, e1)};
}

// The original sampled at M uniform arc lengths.
struct Sampled {
  std::vector<double> u, s, t;
  std::vector<double> kappa;  // signed about the plane (planar) or ≥ 0 (space)
  std::vector<double> tau;    // space curves
};

// The end state a curve must keep: point, unit tangent, (signed) curvature, normal and binormal.
struct EndState {
  Vec3 point{}, tangent{}, normal{}, binormal{};
  double curvature = 0.0;
};

diffgeom::FrenetOptions frenet_options(const std::optional<Vec3>& plane) {
  diffgeom::FrenetOptions o;
  if (plane) o.plane_normal = *plane;
  return o;
}

EndState end_state(const diffgeom::FrenetPoint& f, const std::optional<Vec3>& plane) {
  if (!f.tangent_defined) bad_curve("the curve has no tangent at t = " + format_number(f.t) + " (zero speed)");
  EndState e{.point = f.position, .tangent = f.tangent};
  if (plane) {
    e.normal = f.signed_normal;
    e.binormal = *plane;
    e.curvature = f.signed_curvature;
  } else {
    e.normal = f.normal;
    e.binormal = f.binormal;
    e.curvature = f.curvature;
  }
  return e;
}

// The breakpoints of the original in u, each with the multiplicity its κ needs in a cubic profile (κ of a
// degree-p curve at a knot of multiplicity m is C^(p − m − 2): a triple knot lets the profile kink there).
std::vector<double> profile_knots(const nurbs::NurbsCurve& c, double length) {
  const nurbs::KnotVector& kv = c.knots();
  const Interval dom = c.domain();
  std::vector<std::pair<double, int>> breaks;
  for (const double k : kv.breakpoints()) {
    if (!(k > dom.start && k < dom.end)) continue;
    const double u = nurbs::arc_length(c, dom.start, k) / length;
    const int cont = c.degree() - kv.multiplicity(k) - 2;
    breaks.emplace_back(u, cont >= 2 ? 1 : 3 - std::max(cont, 0));
  }
  std::vector<double> interior;
  const int fill = static_cast<int>(std::ceil(1.0 / kProfileSpan));
  for (int i = 1; i < fill; ++i) {
    const double u = static_cast<double>(i) / fill;
    const bool near = std::any_of(breaks.begin(), breaks.end(),
                                  [&](const auto& b) { return std::abs(b.first - u) < kProfileKnotGap; });
    if (!near) interior.push_back(u);
  }
  for (const auto& [u, m] : breaks)
    if (u > kProfileKnotGap && u < 1.0 - kProfileKnotGap)
      interior.insert(interior.end(), static_cast<std::size_t>(m), u);
  std::sort(interior.begin(), interior.end());
  std::vector<double> knots(4, 0.0);
  knots.insert(knots.end(), interior.begin(), interior.end());
  knots.insert(knots.end(), 4, 1.0);
  return knots;
}

// A cubic B-spline function of u through the end values that fits (u_i, v_i) in least squares.
Profile fitted_profile(const std::vector<double>& knots, std::span<const double> u, std::span<const double> v,
                       const law::Context& ctx) {
  const nurbs::KnotVector kv(knots, 3);
  const std::size_t n = kv.control_point_count();
  // Unknowns c_1 … c_{n−2}; c_0 = v_0 and c_{n−1} = v_last (a clamped function takes its end coefficients).
  const auto inner = static_cast<Eigen::Index>(n - 2);
  Matrix design = Matrix::Zero(static_cast<Eigen::Index>(u.size()), inner);
  Vector rhs(static_cast<Eigen::Index>(u.size()));
  std::array<double, 4> basis{};
  for (std::size_t i = 0; i < u.size(); ++i) {
    const std::size_t span = kv.find_span(u[i]);
    nurbs::basis_functions(kv, span, u[i], basis);
    double r = v[i];
    for (std::size_t j = 0; j < 4; ++j) {
      const std::size_t col = span - 3 + j;
      if (col == 0)
        r -= basis[j] * v.front();
      else if (col == n - 1)
        r -= basis[j] * v.back();
      else
        design(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(col - 1)) = basis[j];
    }
    rhs(static_cast<Eigen::Index>(i)) = r;
  }
  const Vector c = design.colPivHouseholderQr().solve(rhs);
  std::vector<double> coefficients(n);
  coefficients.front() = v.front();
  coefficients.back() = v.back();
  for (Eigen::Index j = 0; j < inner; ++j) coefficients[static_cast<std::size_t>(j + 1)] = c(j);
  return Profile::from_bspline(3, knots, coefficients, ctx);
}

// The fit's basis: the rational basis R_i = N_i w_i / W, W = Σ N_j w_j, of fixed weights (all 1 for a
// non-rational curve), so C = Σ R_i P_i and its derivatives are linear in the control points.
struct FitBasis {
  nurbs::KnotVector knots;
  std::vector<double> weights;  // one per control point
};

// R_i and its first two derivatives at t for the p + 1 non-zero functions (differentiating N_i w_i = R_i W:
// R_i' = (N_i' w_i − R_i W') / W, R_i'' = (N_i'' w_i − 2 R_i' W' − R_i W'') / W).
struct BasisAt {
  std::size_t first = 0;           // index of the first non-zero basis function
  std::vector<double> d0, d1, d2;  // p + 1 values each (d1, d2 only when asked)
};

BasisAt basis_at(const FitBasis& fb, double t, int order, nurbs::BasisWorkspace& ws,
                 nurbs::Side side = nurbs::Side::Right) {
  const int p = fb.knots.degree();
  const auto n = static_cast<std::size_t>(p + 1);
  const std::size_t span = fb.knots.find_span(t, side);
  const std::span<const double> d = nurbs::basis_derivatives(fb.knots, span, t, order, ws);
  BasisAt b;
  b.first = span - static_cast<std::size_t>(p);
  std::array<double, 3> w_sum{};
  for (int k = 0; k <= order; ++k)
    for (std::size_t i = 0; i < n; ++i)
      w_sum[static_cast<std::size_t>(k)] += d[static_cast<std::size_t>(k) * n + i] * fb.weights[b.first + i];
  b.d0.resize(n);
  for (std::size_t i = 0; i < n; ++i) b.d0[i] = d[i] * fb.weights[b.first + i] / w_sum[0];
  if (order >= 1) {
    b.d1.resize(n);
    for (std::size_t i = 0; i < n; ++i) b.d1[i] = (d[n + i] * fb.weights[b.first + i] - b.d0[i] * w_sum[1]) / w_sum[0];
  }
  if (order >= 2) {
    b.d2.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      b.d2[i] = (d[2 * n + i] * fb.weights[b.first + i] - 2.0 * b.d1[i] * w_sum[1] - b.d0[i] * w_sum[2]) / w_sum[0];
  }
  return b;
}

// What an end of the fit keeps. Point: its position always. Direction: C' ∥ T. ZeroCurvature: C' ∥ T and
// C''·N = 0 (a natural end stays one; linear without the speed). Frame: C' = σ T with σ fixed, C''·N = κ σ²,
// C''·B = 0 (G2, the end speed frozen so the rows are linear).
enum class EndRule { None, Direction, ZeroCurvature, Frame };

struct FitEnd {
  EndState state;
  EndRule rule = EndRule::Direction;
  double speed = 0.0;  // σ for EndRule::Frame
};

// The end conditions as linear rows C x = d over x = (P_0x, P_0y, P_0z, P_1x, …).
struct EndRows {
  Matrix c;
  Vector d;
};

EndRows end_rows(const FitBasis& fb, const FitEnd& start, const FitEnd& end) {
  const auto n = static_cast<Eigen::Index>(fb.knots.control_point_count());
  nurbs::BasisWorkspace ws;
  std::vector<Vector> rows;
  std::vector<double> values;
  const auto add_row = [&](const std::vector<double>& basis, std::size_t first, const Vec3& direction, double value) {
    Vector row = Vector::Zero(3 * n);
    for (std::size_t i = 0; i < basis.size(); ++i)
      for (std::size_t c = 0; c < 3; ++c) row(static_cast<Eigen::Index>(3 * (first + i) + c)) = basis[i] * direction[c];
    rows.push_back(std::move(row));
    values.push_back(value);
  };
  const Interval dom = fb.knots.domain();
  const auto hold = [&](const FitEnd& e, double at, nurbs::Side side) {
    if (e.rule == EndRule::None) return;
    const BasisAt b = basis_at(fb, at, 2, ws, side);
    for (std::size_t c = 0; c < 3; ++c) {
      Vec3 axis{};
      axis[c] = 1.0;
      add_row(b.d0, b.first, axis, e.state.point[c]);
    }
    if (e.rule == EndRule::Frame) {
      for (std::size_t c = 0; c < 3; ++c) {
        Vec3 axis{};
        axis[c] = 1.0;
        add_row(b.d1, b.first, axis, e.speed * e.state.tangent[c]);
      }
      add_row(b.d2, b.first, e.state.normal, e.state.curvature * e.speed * e.speed);
      add_row(b.d2, b.first, e.state.binormal, 0.0);
      return;
    }
    const auto [m1, m2] = normals_of(e.state.tangent);
    add_row(b.d1, b.first, m1, 0.0);
    add_row(b.d1, b.first, m2, 0.0);
    if (e.rule == EndRule::ZeroCurvature) add_row(b.d2, b.first, e.state.normal, 0.0);
  };
  hold(start, dom.start, nurbs::Side::Right);
  hold(end, dom.end, nurbs::Side::Left);
  EndRows r{.c = Matrix(static_cast<Eigen::Index>(rows.size()), 3 * n),
            .d = Vector(static_cast<Eigen::Index>(rows.size()))};
  for (std::size_t q = 0; q < rows.size(); ++q) {
    r.c.row(static_cast<Eigen::Index>(q)) = rows[q].transpose();
    r.d(static_cast<Eigen::Index>(q)) = values[q];
  }
  return r;
}

std::vector<Vec3> points_of(const Vector& x) {
  std::vector<Vec3> points(static_cast<std::size_t>(x.size() / 3));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(3 * i);
    points[i] = {x(k), x(k + 1), x(k + 2)};
  }
  return points;
}

// Constrained least squares: min Σ_j |C(t_j) − r_j|² over the control points, subject to the end rows (a KKT
// system: the objective is separable by coordinate, the rows are not).
std::vector<Vec3> position_fit(const FitBasis& fb, std::span<const double> t, std::span<const Vec3> r,
                               const FitEnd& start, const FitEnd& end) {
  const nurbs::KnotVector& kv = fb.knots;
  const int p = kv.degree();
  const auto n = static_cast<Eigen::Index>(kv.control_point_count());
  nurbs::BasisWorkspace ws;
  Matrix btb = Matrix::Zero(n, n);
  Matrix btr = Matrix::Zero(n, 3);
  for (std::size_t j = 0; j < t.size(); ++j) {
    const BasisAt b = basis_at(fb, t[j], 0, ws);
    for (int i = 0; i <= p; ++i) {
      const auto ii = static_cast<Eigen::Index>(b.first + static_cast<std::size_t>(i));
      for (int k = 0; k <= p; ++k)
        btb(ii, static_cast<Eigen::Index>(b.first + static_cast<std::size_t>(k))) +=
            b.d0[static_cast<std::size_t>(i)] * b.d0[static_cast<std::size_t>(k)];
      for (std::size_t c = 0; c < 3; ++c)
        btr(ii, static_cast<Eigen::Index>(c)) += b.d0[static_cast<std::size_t>(i)] * r[j][c];
    }
  }
  const EndRows rows = end_rows(fb, start, end);
  const Eigen::Index m = rows.c.rows();
  Matrix kkt = Matrix::Zero(3 * n + m, 3 * n + m);
  Vector rhs = Vector::Zero(3 * n + m);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index k = 0; k < n; ++k)
      for (Eigen::Index c = 0; c < 3; ++c) kkt(3 * i + c, 3 * k + c) = btb(i, k);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index c = 0; c < 3; ++c) rhs(3 * i + c) = btr(i, c);
  kkt.block(3 * n, 0, m, 3 * n) = rows.c;
  kkt.block(0, 3 * n, 3 * n, m) = rows.c.transpose();
  rhs.tail(m) = rows.d;
  const Vector x = kkt.fullPivLu().solve(rhs);
  return points_of(x.head(3 * n));
}

// κ at t: signed about the plane, or unsigned for space curves.
double curvature_at(const diffgeom::FrenetPoint& f, bool planar) { return planar ? f.signed_curvature : f.curvature; }

// The profile targets of the fit at the fractions u_j of the curve's own length: κ*_j, and for a space curve τ*_j
// with the weight that puts a torsion miss on the scale of a curvature miss. t_j: the start curve's parameters there
// (the arc-length grid's nodes).
struct ProfileTargets {
  std::vector<double> u, t, kappa, tau;
  double torsion_weight = 0.0;
  std::vector<double> weight;  // of each sample's κ miss; empty: all 1
};

// Gauss–Lobatto's 4-point rule on [−1, 1]: nodes ±1, ±1/√5, weights 1/6, 5/6 (exact to degree 5).
constexpr double kLobattoNode = 0.44721359549995793928;  // 1/√5
constexpr double kLobattoEnd = 1.0 / 6.0;
constexpr double kLobattoInner = 5.0 / 6.0;
// Newton steps of the arc-length inversion on one grid interval (it converges to rounding in 3–5).
constexpr int kInverseSteps = 30;

// A curve's parameters at fractions of its own length: s(t) = ∫ σ integrated on a grid fixed while the control
// points move (the start curve's sample parameters and the knots) by Gauss–Lobatto's 4-point rule per interval,
// and inverted by Newton on the cubic Hermite interpolant of s on the interval (s and s' = σ at both ends). The
// grid being fixed, t_j is a smooth function of the control points (a finite-difference Jacobian sees no switch of
// an adaptive rule); the error is O(h⁴ max|σ‴|) per interval of width h.
class OwnArcLength {
 public:
  OwnArcLength(const nurbs::KnotVector& knots, std::span<const double> t) {
    const Interval dom = knots.domain();
    nodes_.assign(t.begin(), t.end());
    for (const double k : knots.breakpoints()) nodes_.push_back(k);
    nodes_.push_back(dom.start);
    nodes_.push_back(dom.end);
    std::erase_if(nodes_, [&](double x) { return !(x >= dom.start && x <= dom.end); });
    std::sort(nodes_.begin(), nodes_.end());
    nodes_.erase(std::unique(nodes_.begin(), nodes_.end()), nodes_.end());
    const std::vector<double> breaks = knots.breakpoints();
    for (std::size_t k = 0; k + 1 < nodes_.size(); ++k) {
      const double mid = 0.5 * (nodes_[k] + nodes_[k + 1]), half = 0.5 * (nodes_[k + 1] - nodes_[k]);
      inner_.push_back(mid - kLobattoNode * half);
      inner_.push_back(mid + kLobattoNode * half);
      // σ just left of an interior knot (the curve may be only C0 there); elsewhere σ is continuous.
      const bool knot = nodes_[k + 1] < dom.end && std::binary_search(breaks.begin(), breaks.end(), nodes_[k + 1]);
      if (knot) left_knots_.push_back(k + 1);
    }
  }

  // t_j with s(t_j) = u_j · L for u_j in [0, 1] (u = 0 and 1 give the domain's ends exactly); returns L.
  double parameters(const nurbs::NurbsCurve& c, std::span<const double> u, std::span<double> t) {
    const std::size_t n = nodes_.size();
    d_.resize(2 * std::max(n, inner_.size()));
    speed_.resize(n);
    speed_left_.resize(n);
    c.derivatives(nodes_, 1, std::span<Vec3>(d_).first(2 * n));
    for (std::size_t k = 0; k < n; ++k) speed_[k] = speed_left_[k] = norm(d_[2 * k + 1]);
    start_derivative_ = d_[1];
    regular_ = true;
    for (std::size_t k = 0; k + 1 < n && regular_; ++k) regular_ = dot(d_[2 * k + 1], d_[2 * k + 3]) > 0.0;
    for (const std::size_t k : left_knots_)
      speed_left_[k] = norm(c.derivatives(nodes_[k], 1, {.side = nurbs::Side::Left})[1]);
    end_derivative_ = c.derivatives(nodes_.back(), 1, {.side = nurbs::Side::Left})[1];
    speed_left_.back() = norm(end_derivative_);
    c.derivatives(inner_, 1, std::span<Vec3>(d_).first(2 * inner_.size()));
    s_.assign(n, 0.0);
    for (std::size_t k = 0; k + 1 < n; ++k) {
      const double half = 0.5 * (nodes_[k + 1] - nodes_[k]);
      s_[k + 1] = s_[k] + half * (kLobattoEnd * (speed_[k] + speed_left_[k + 1]) +
                                  kLobattoInner * (norm(d_[4 * k + 1]) + norm(d_[4 * k + 3])));
    }
    const double length = s_.back();
    for (std::size_t j = 0; j < u.size(); ++j) {
      if (u[j] <= 0.0) {
        t[j] = nodes_.front();
        continue;
      }
      if (u[j] >= 1.0) {
        t[j] = nodes_.back();
        continue;
      }
      const double target = u[j] * length;
      const auto above = static_cast<std::size_t>(std::upper_bound(s_.begin(), s_.end(), target) - s_.begin());
      const std::size_t k = std::min(std::max<std::size_t>(above, 1) - 1, n - 2);
      t[j] = nodes_[k] + (nodes_[k + 1] - nodes_[k]) * inverse_hermite(k, target);
    }
    return length;
  }

  // Of the last curve given to parameters(): false if its tangent turns by more than a right angle between two
  // neighbouring nodes (a cusp between them: the fit went through zero speed), and C' at both ends.
  [[nodiscard]] bool regular() const noexcept { return regular_; }
  [[nodiscard]] const Vec3& start_derivative() const noexcept { return start_derivative_; }
  [[nodiscard]] const Vec3& end_derivative() const noexcept { return end_derivative_; }

 private:
  // θ in [0, 1] where the interval k's Hermite cubic of s reaches `target`: Newton inside a bisection bracket.
  [[nodiscard]] double inverse_hermite(std::size_t k, double target) const {
    const double h = nodes_[k + 1] - nodes_[k], ds = s_[k + 1] - s_[k];
    const double a = h * speed_[k], b = h * speed_left_[k + 1];
    const auto value = [&](double x) {
      return s_[k] + a * x * (1 - x) * (1 - x) - b * x * x * (1 - x) + ds * x * x * (3 - 2 * x);
    };
    const auto slope = [&](double x) { return a * (1 - x) * (1 - 3 * x) - b * x * (2 - 3 * x) + 6 * ds * x * (1 - x); };
    double lo = 0.0, hi = 1.0, x = ds > 0.0 ? std::clamp((target - s_[k]) / ds, 0.0, 1.0) : 0.5;
    for (int step = 0; step < kInverseSteps; ++step) {
      const double f = value(x) - target;
      if (f == 0.0) break;
      (f < 0.0 ? lo : hi) = x;
      const double d = slope(x);
      double next = d > 0.0 ? x - f / d : 0.5 * (lo + hi);
      if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
      const bool done = std::abs(next - x) <= 4 * std::numeric_limits<double>::epsilon();
      x = next;
      if (done) break;
    }
    return x;
  }

  std::vector<double> nodes_, inner_;
  std::vector<std::size_t> left_knots_;
  std::vector<Vec3> d_;
  std::vector<double> speed_, speed_left_, s_;
  Vec3 start_derivative_{}, end_derivative_{};
  bool regular_ = true;
};

// Levenberg–Marquardt on the control points x: min Σ_j (κ(t_j(x); x) − κ*_j)² (+ w_τ² (τ(t_j(x); x) − τ*_j)²),
// t_j(x) where the candidate's own arc length is u_j times its own length (OwnArcLength): the profile is compared
// where the designer drew it on the κ(s) graph, the length free (a held end makes an edited curve longer or
// shorter, and a sharp peak compared at fixed parameters slides along s). The end rows (and a planar curve's
// plane) are linear in x and held exactly: x = x₀ + Z y, Z an orthonormal basis of their null space (SVD). The
// Jacobian is by central differences in y.
nurbs::NurbsCurve profile_fit(const FitBasis& fb, const nurbs::NurbsCurve& start, const FitEnd& first,
                              const FitEnd& last, const std::optional<Vec3>& plane, const ProfileTargets& targets) {
  const auto n = static_cast<Eigen::Index>(fb.knots.control_point_count());
  EndRows rows = end_rows(fb, first, last);
  if (plane) {
    // Every control point stays in the curve's plane.
    Matrix c(rows.c.rows() + n, 3 * n);
    c.topRows(rows.c.rows()) = rows.c;
    c.bottomRows(n).setZero();
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index k = 0; k < 3; ++k) c(rows.c.rows() + i, 3 * i + k) = (*plane)[static_cast<std::size_t>(k)];
    rows.c = std::move(c);
  }
  const Eigen::JacobiSVD<Matrix> svd(rows.c, Eigen::ComputeFullV);
  const double s_max = svd.singularValues().size() > 0 ? svd.singularValues()(0) : 1.0;
  Eigen::Index rank = 0;
  for (Eigen::Index i = 0; i < svd.singularValues().size(); ++i)
    if (svd.singularValues()(i) > kNullSpace * s_max) ++rank;
  const Matrix z = svd.matrixV().rightCols(3 * n - rank);
  if (z.cols() == 0) return start;
  Vector x0(3 * n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index k = 0; k < 3; ++k)
      x0(3 * i + k) = start.control_points()[static_cast<std::size_t>(i)][static_cast<std::size_t>(k)];
  const auto curve_of = [&](const Vector& y) {
    return nurbs::NurbsCurve(fb.knots, points_of(x0 + z * y), fb.weights, 3);
  };
  const bool planar = plane.has_value();
  diffgeom::FrenetOptions fo;
  if (plane) fo.plane_normal = *plane;
  const std::size_t count = targets.u.size();
  const auto m = static_cast<Eigen::Index>(planar ? count : 2 * count);
  std::vector<diffgeom::FrenetPoint> frames(count);
  OwnArcLength own(fb.knots, targets.t);
  std::vector<double> t(count);
  // Sign changes of a planar profile, values within kZeroEndCurvature of the largest |κ*| counting as zero.
  double kappa_scale = 0.0;
  for (const double k : targets.kappa) kappa_scale = std::max(kappa_scale, std::abs(k));
  const auto sign_changes_of = [&](const auto& kappa_of) { return sign_changes(count, kappa_scale, kappa_of); };
  int candidate_changes = 0;
  // Samples where the candidate is straight (|κ| within kZeroEndCurvature of the scale) but the target clearly bends
  // (|κ*| above kStraightTarget of the scale): a fit that flattens a stretch to rounding leaves sign noise there.
  std::size_t candidate_flat = 0;
  const auto residual = [&](const nurbs::NurbsCurve& c) {
    static_cast<void>(own.parameters(c, targets.u, t));
    diffgeom::frenet(c, t, frames, fo);
    if (planar) {
      candidate_changes = sign_changes_of([&](std::size_t j) { return frames[j].signed_curvature; });
      candidate_flat = 0;
      for (std::size_t j = 0; j < count; ++j)
        if (std::abs(frames[j].signed_curvature) <= kZeroEndCurvature * kappa_scale &&
            std::abs(targets.kappa[j]) > kStraightTarget * kappa_scale)
          ++candidate_flat;
    }
    Vector r(m);
    for (std::size_t j = 0; j < count; ++j) {
      r(static_cast<Eigen::Index>(j)) =
          (targets.weight.empty() ? 1.0 : targets.weight[j]) * (curvature_at(frames[j], planar) - targets.kappa[j]);
      if (!planar) {
        const double tau = frames[j].torsion_defined ? frames[j].torsion : targets.tau[j];
        r(static_cast<Eigen::Index>(count + j)) = targets.torsion_weight * (tau - targets.tau[j]);
      }
    }
    return r;
  };
  const double step = kDifferenceStep * std::max(start.model_size(), 1e-300);
  Vector y = Vector::Zero(z.cols());
  double lambda = 1e-3;
  nurbs::NurbsCurve current = start;
  Vector r0 = residual(current);
  // A planar fit keeps to the inflections the target (or the start) has: a step that adds one is refused.
  const int allowed_changes =
      std::max(candidate_changes, sign_changes_of([&](std::size_t j) { return targets.kappa[j]; }));
  const std::size_t allowed_flat = candidate_flat;
  for (int iteration = 0; iteration < kPolishIterations; ++iteration) {
    Matrix jac(m, z.cols());
    for (Eigen::Index k = 0; k < z.cols(); ++k) {
      Vector yp = y, ym = y;
      yp(k) += step;
      ym(k) -= step;
      jac.col(k) = (residual(curve_of(yp)) - residual(curve_of(ym))) / (2.0 * step);
    }
    const Matrix jtj = jac.transpose() * jac;
    const Vector jtr = jac.transpose() * r0;
    const double floor = 1e-12 * std::max(jtj.diagonal().maxCoeff(), 1e-300);
    bool improved = false;
    for (int tries = 0; tries < kDampingTries && !improved; ++tries) {
      Matrix a = jtj;
      a.diagonal() += lambda * jtj.diagonal().cwiseMax(floor);
      const Vector dy = a.ldlt().solve(-jtr);
      if (!dy.allFinite()) {
        lambda *= 4.0;
        continue;
      }
      nurbs::NurbsCurve trial = curve_of(y + dy);
      const Vector r1 = residual(trial);
      // A step through zero speed (a cusp, or an end tangent reversed), one that adds an inflection or straightens
      // a stretch the target bends is refused like a worse one: more damping.
      const bool regular = own.regular() && candidate_changes <= allowed_changes && candidate_flat <= allowed_flat &&
                           dot(own.start_derivative(), first.state.tangent) > 0.0 &&
                           (last.rule == EndRule::None || dot(own.end_derivative(), last.state.tangent) > 0.0);
      if (regular && r1.allFinite() && r1.squaredNorm() < r0.squaredNorm()) {
        y += dy;
        current = std::move(trial);
        r0 = r1;
        lambda = std::max(lambda / 3.0, 1e-9);
        improved = true;
      } else {
        lambda *= 4.0;
      }
    }
    if (!improved) break;
  }
  return current;
}

// The samples' parameters moved to the foot of r_j on the curve (Newton on (C − r)·C' = 0), ends pinned.
void correct_parameters(const nurbs::NurbsCurve& c, std::span<const Vec3> r, std::span<double> t) {
  const Interval dom = c.domain();
  for (std::size_t j = 1; j + 1 < t.size(); ++j) {
    double tj = t[j];
    for (int step = 0; step < kNewtonSteps; ++step) {
      const std::vector<Vec3> d = c.derivatives(tj, 2);
      const Vec3 diff = d[0] - r[j];
      const double f = dot(diff, d[1]);
      const double df = dot(d[1], d[1]) + dot(diff, d[2]);
      if (!(df > 0.0)) break;
      tj = std::clamp(tj - f / df, dom.start, dom.end);
    }
    t[j] = tj;
  }
}

std::size_t interpolated_handles(const nurbs::KnotVector& kv) {
  return kv.breakpoints().size();  // the data points are at the breakpoints, ends included
}

std::size_t count_inflections(const curve::Curve& c, const std::optional<Vec3>& plane) {
  if (!plane) return 0;
  diffgeom::FeatureOptions o;
  o.frenet.plane_normal = *plane;
  return diffgeom::inflections(c, o).size();
}

}  // namespace

std::string_view end_hold_name(EndHold hold) noexcept {
  switch (hold) {
    case EndHold::Free:
      return "free";
    case EndHold::Tangent:
      return "tangent";
    case EndHold::Curvature:
      return "curvature";
  }
  return "tangent";
}

EndHold end_hold_from_name(std::string_view name, std::string_view field) {
  if (name == "free") return EndHold::Free;
  if (name == "tangent") return EndHold::Tangent;
  if (name == "curvature") return EndHold::Curvature;
  throw Error(Errc::InvalidArgument,
              std::string(field) + " = \"" + std::string(name) + "\": expected \"free\", \"tangent\" or \"curvature\"",
              ErrorWhere{.field = std::string(field)});
}

std::string_view curvature_target_name(CurvatureTarget target) noexcept {
  return target == CurvatureTarget::Change ? "change" : "curvature";
}

CurvatureTarget curvature_target_from_name(std::string_view name, std::string_view field) {
  if (name == "curvature") return CurvatureTarget::Curvature;
  if (name == "change") return CurvatureTarget::Change;
  throw Error(Errc::InvalidArgument,
              std::string(field) + " = \"" + std::string(name) + "\": expected \"curvature\" or \"change\"",
              ErrorWhere{.field = std::string(field)});
}

void CurvatureEditOptions::validate() const {
  if (!(max_handles_factor >= 1.0 && max_handles_factor <= 10.0))
    invalid_edit_option("max_handles_factor", max_handles_factor, "[1, 10]");
  if (!(curvature_tolerance >= 1e-6 && curvature_tolerance <= 1.0))
    invalid_edit_option("curvature_tolerance", curvature_tolerance, "[1e-6, 1]");
  if (samples < 50 || samples > 100'000) invalid_edit_option("samples", static_cast<double>(samples), "[50, 100000]");
  reconstruction.validate();
}

std::size_t handle_count(const curve::Curve& c) {
  return std::visit(
      [&](const auto& data) -> std::size_t {
        using T = std::decay_t<decltype(data)>;
        if constexpr (std::is_same_v<T, curve::InterpolatedData> || std::is_same_v<T, curve::HermiteData>)
          return data.points.size();
        else if constexpr (std::is_same_v<T, curve::BezierData>)
          return data.control_points.size();
        else
          return c.nurbs().control_points().size();
      },
      c.data());
}

CurvatureEditResult edit_curvature(const curve::Curve& original, const CurvatureEdit& edit,
                                   const CurvatureEditOptions& options) {
  const auto t0 = std::chrono::steady_clock::now();
  options.validate();
  if (!edit.curvature.valid() || edit.curvature.dimension() != 1)
    throw Error(Errc::InvalidArgument, "the curvature edit must be a scalar law of " + edit.parameter,
                ErrorWhere{.field = "curvature"});
  if (edit.torsion && (!edit.torsion->valid() || edit.torsion->dimension() != 1 ||
                       !(edit.torsion->context() == edit.curvature.context())))
    throw Error(Errc::InvalidArgument,
                "the torsion must be a scalar law of " + edit.parameter + " in the curvature law's context",
                ErrorWhere{.field = "torsion"});
  const nurbs::NurbsCurve& base = original.nurbs();
  if (base.degree() < 2) bad_curve("a curve of degree 1 has no curvature to edit");
  if (!base.knots().is_clamped()) bad_curve("the curve's knot vector is not clamped; clamp it (hula edit) first");
  const std::optional<Vec3> plane = detail::plane_normal(base);
  const bool planar = plane.has_value();
  if (planar && edit.torsion)
    throw Error(Errc::InvalidArgument, "a planar curve has no torsion to edit", ErrorWhere{.field = "torsion"});
  const Interval dom = base.domain();
  const double length = nurbs::arc_length(base);
  if (!(length > 0.0)) bad_curve("the curve has zero length");
  const diffgeom::FrenetOptions fo = frenet_options(plane);

  // 1. The original sampled by arc length.
  const std::size_t count = options.samples;
  Sampled o;
  o.u.resize(count);
  o.s.resize(count);
  o.t.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    o.u[i] = static_cast<double>(i) / static_cast<double>(count - 1);
    o.s[i] = o.u[i] * length;
    o.t[i] = i == 0 ? dom.start : (i + 1 == count ? dom.end : nurbs::parameter_at_length(base, o.s[i]));
  }
  std::vector<diffgeom::FrenetPoint> frames(count);
  diffgeom::frenet(base, o.t, frames, fo);
  o.kappa.resize(count);
  o.tau.resize(count);
  double kappa_max = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    if (!frames[i].tangent_defined)
      bad_curve("the curve has zero speed at t = " + format_number(o.t[i]) + " (s = " + format_number(o.s[i]) + ")");
    o.kappa[i] = curvature_at(frames[i], planar);
    kappa_max = std::max(kappa_max, std::abs(o.kappa[i]));
    if (!planar) {
      if (!frames[i].torsion_defined)
        bad_curve("the curvature of this space curve vanishes at s = " + format_number(o.s[i]) +
                  ": its torsion and Frenet frame are undefined there, so its profiles cannot be edited");
      o.tau[i] = frames[i].torsion;
    }
  }
  if (!(kappa_max > 0.0) && edit.target == CurvatureTarget::Change && planar)
    bad_curve("the curve is straight: a change of |κ| has no side to bend to; type a signed κ(s) instead");
  const EndState start = end_state(frames.front(), plane);
  const EndState end = end_state(frames.back(), plane);

  // 2. The target profiles at the samples.
  const Profile edit_law = Profile::from_law(edit.curvature, edit.parameter);
  std::vector<double> target(count);
  edit_law.sample(o.s, target);
  if (edit.target == CurvatureTarget::Change) {
    // |κ| + δ on the side the curve bends to (a smoothed sign through an inflection), never below a tenth of |κ|:
    // a drag bends the curve more or less, never the other way (type a law to straighten or reverse a stretch).
    const double eps = kSignSmoothing * kappa_max;
    for (std::size_t i = 0; i < count; ++i) {
      const double magnitude = std::max(std::abs(o.kappa[i]) + target[i], kMinMagnitude * std::abs(o.kappa[i]));
      target[i] = planar ? magnitude * o.kappa[i] / std::sqrt(o.kappa[i] * o.kappa[i] + eps * eps) : magnitude;
    }
  }
  std::vector<double> tau_target = o.tau;
  if (edit.torsion) Profile::from_law(*edit.torsion, edit.parameter).sample(o.s, tau_target);
  double edit_max = 0.0, target_max = 0.0;
  for (std::size_t i = 0; i < count; ++i) {
    edit_max = std::max(edit_max, std::abs(target[i] - o.kappa[i]));
    target_max = std::max(target_max, std::abs(target[i]));
  }

  // 3. The start curve and its sample parameters. A change of the drawn profile starts from the original itself
  //    (a drag is a small edit: the nearest curve with the new profile is near the original); a typed law starts
  //    from the boundary-value reconstruction, fitted by least squares on the original's knots.
  const bool interpolated = original.kind() == curve::Kind::Interpolated;
  const std::size_t handles_before = handle_count(original);
  const auto budget =
      std::max(handles_before,
               static_cast<std::size_t>(std::floor(options.max_handles_factor * static_cast<double>(handles_before))));
  const auto handles_of = [&](const nurbs::KnotVector& kv) {
    return interpolated ? interpolated_handles(kv) : kv.control_point_count();
  };
  const auto basis_of = [](const nurbs::NurbsCurve& c) {
    FitBasis fb{.knots = c.knots(), .weights = {}};
    const std::span<const double> w = c.weights();
    fb.weights.assign(w.begin(), w.end());
    if (fb.weights.empty()) fb.weights.assign(c.control_points().size(), 1.0);
    return fb;
  };
  // What each end keeps (the start always its point and tangent; the end unless EndHold::Free).
  const double zero_curvature = kZeroEndCurvature * std::max(kappa_max, 1.0 / length);
  const auto rule_of = [&](const EndState& e, bool held) {
    if (!held) return EndRule::None;
    if (options.hold == EndHold::Curvature) return EndRule::Frame;
    return planar && std::abs(e.curvature) <= zero_curvature ? EndRule::ZeroCurvature : EndRule::Direction;
  };
  FitEnd first{.state = start, .rule = rule_of(start, true)};
  FitEnd last{.state = end, .rule = rule_of(end, options.hold != EndHold::Free)};
  const auto freeze_speeds = [&](const nurbs::NurbsCurve& c) {
    first.speed = dot(c.derivatives(dom.start, 1)[1], start.tangent);
    last.speed = dot(c.derivatives(dom.end, 1, {.side = nurbs::Side::Left})[1], end.tangent);
    if (!(first.speed > 0.0) || (last.rule != EndRule::None && !(last.speed > 0.0)))
      throw Error(Errc::NumericalFailure,
                  "the fit of the edited curve reverses an end tangent (end speeds " + format_number(first.speed) +
                      ", " + format_number(last.speed) + "); try a smaller edit or EndHold::Free",
                  ErrorWhere{.field = "curve"});
  };

  ProfileTargets targets{.u = o.u, .t = o.t, .kappa = target, .tau = tau_target, .torsion_weight = 0.0, .weight = {}};
  if (!planar) {
    double tau_max = 0.0;
    for (const double v : tau_target) tau_max = std::max(tau_max, std::abs(v));
    targets.torsion_weight = tau_max > 0.0 ? target_max / tau_max : 1.0;
  }
  if (edit.target == CurvatureTarget::Change && planar && edit_max > 0.0) {
    // A drag's support weighs more: the held ends take back the turning the drag adds, and the least squares
    // would miss evenly, at the dragged spot too; weighted, more of the miss goes where the designer did not
    // drag. (Planar only: on a space Bézier the weight moved the dragged spot less, not more.)
    targets.weight.resize(count);
    for (std::size_t i = 0; i < count; ++i)
      targets.weight[i] = 1.0 + kDragWeight * std::abs(target[i] - o.kappa[i]) / edit_max;
  }
  nurbs::NurbsCurve current = base;
  int iterations = 0;
  double mean_target_deviation = 0.0, max_target_deviation = 0.0;
  const bool consistent_drag =
      edit.target == CurvatureTarget::Change && edit_max > 0.0 && options.hold != EndHold::Free;
  // The drag's target with its change scaled by α (1: as asked), made consistent with the held ends (below).
  const auto drag_target = [&](double alpha) {
    // A drag asks for κ* = κ + δ, which the held ends generally cannot have (the bump adds turning the end
    // tangent takes back): fitted as it is, the miss spreads over the profile, the dragged spot included. The
    // consistent target is the boundary-value reconstruction of κ* with the held ends whose correction is
    // relative and fades out under the drag, e(u) = κ*(u) (1 − |δ(u)| / max |δ|): the dragged peak keeps the
    // asked value, the rest of the curve takes back the turning, and zeros of κ* stay zeros (no inflection). A
    // space curve keeps its torsion profile but for the minimum-norm correction the held end frame needs.
    std::vector<double> scaled(count), envelope(count);
    for (std::size_t i = 0; i < count; ++i) {
      scaled[i] = alpha == 1.0 ? target[i]
                               : std::max(o.kappa[i] + alpha * (target[i] - o.kappa[i]),
                                          kMinMagnitude * o.kappa[i]);  // (α ≠ 1: space, κ ≥ 0)
      envelope[i] = scaled[i] * (1.0 - std::abs(target[i] - o.kappa[i]) / edit_max);
    }
    const law::Context ctx;
    const std::vector<double> knots = profile_knots(base, length);
    DirectReconstructionProblem problem{.curvature = fitted_profile(knots, o.u, scaled, ctx)};
    problem.length = length;
    if (!planar) problem.torsion = fitted_profile(knots, o.u, tau_target, ctx);
    problem.start = {.point = start.point, .tangent = start.tangent, .normal = start.normal};
    problem.end_point = end.point;
    problem.end_tangent = end.tangent;
    if (options.hold == EndHold::Curvature) {
      problem.start_curvature = start.curvature;
      problem.end_curvature = end.curvature;
      if (!planar) problem.end_normal = end.normal;
    }
    problem.curvature_envelope = fitted_profile(knots, o.u, envelope, ctx);
    DirectReconstructionOptions ro = options.reconstruction;
    ro.fit = false;
    // A space drag whose held end frame the solver cannot meet is fitted as asked (as before this target existed).
    std::optional<DirectReconstructionResult> rec;
    try {
      rec = reconstruct_direct(problem, ro);
    } catch (const Error& e) {
      if (planar || e.code() != Errc::NumericalFailure) throw;
    }
    std::vector<intrinsic::FramePoint> fp;
    if (rec) {
      std::vector<double> s_rec(count);
      for (std::size_t j = 0; j < count; ++j) s_rec[j] = o.u[j] * rec->length;
      fp = rec->curve.evaluate(s_rec);
    }
    // A correction that holds the ends only by reversing the bend somewhere (1 + Σ c_k B_k < 0) is no target for a
    // drag, which never adds an inflection: the drag is then fitted as asked.
    if (rec && sign_changes(count, target_max, [&](std::size_t j) { return fp[j].curvature; }) <=
                   sign_changes(count, target_max, [&](std::size_t j) { return scaled[j]; })) {
      iterations = rec->iterations;
      mean_target_deviation = rec->mean_curvature_deviation;
      max_target_deviation = rec->max_curvature_deviation;
      for (std::size_t j = 0; j < count; ++j) {
        targets.kappa[j] = fp[j].curvature;
        if (!planar) targets.tau[j] = fp[j].torsion;
      }
    } else {
      targets.kappa = scaled;
      targets.tau = tau_target;
      iterations = 0;
      mean_target_deviation = max_target_deviation = 0.0;
    }
  };
  if (consistent_drag) drag_target(1.0);
  if (edit.target == CurvatureTarget::Curvature) {
    const law::Context ctx = edit.curvature.context();
    const law::Law s_of_u = length * ctx.parameter("u");
    const std::vector<double> knots = profile_knots(base, length);
    const Profile kappa_u = Profile::from_law(law::substitute(edit.curvature, edit.parameter, s_of_u), "u");
    DirectReconstructionProblem problem{.curvature = kappa_u};
    problem.length = length;
    if (!planar)
      problem.torsion = edit.torsion ? Profile::from_law(law::substitute(*edit.torsion, edit.parameter, s_of_u), "u")
                                     : fitted_profile(knots, o.u, o.tau, ctx);
    problem.start = {.point = start.point, .tangent = start.tangent, .normal = start.normal};
    if (options.hold != EndHold::Free) {
      problem.end_point = end.point;
      problem.end_tangent = end.tangent;
    }
    if (options.hold == EndHold::Curvature) {
      problem.start_curvature = start.curvature;
      problem.end_curvature = end.curvature;
      if (!planar) problem.end_normal = end.normal;
    }
    // A relative correction: where the typed κ* is zero the reconstruction's κ is zero too.
    problem.curvature_envelope = kappa_u;
    DirectReconstructionOptions ro = options.reconstruction;
    ro.fit = false;
    const DirectReconstructionResult rec = reconstruct_direct(problem, ro);
    iterations = rec.iterations;
    mean_target_deviation = rec.mean_curvature_deviation;
    max_target_deviation = rec.max_curvature_deviation;
    std::vector<Vec3> r(count);
    std::vector<double> s_rec(count);
    for (std::size_t j = 0; j < count; ++j) s_rec[j] = o.u[j] * rec.length;
    const std::vector<intrinsic::FramePoint> fp = rec.curve.evaluate(s_rec);
    for (std::size_t j = 0; j < count; ++j) {
      r[j] = fp[j].position;
      targets.kappa[j] = fp[j].curvature;  // the reconstruction's profile: κ* made to meet the ends
      if (!planar) targets.tau[j] = fp[j].torsion;
    }
    const FitBasis fb = basis_of(base);
    std::vector<double> t = o.t;
    const auto fit_once = [&] {
      FitEnd a = first, b = last;
      if (a.rule == EndRule::Frame) a.rule = EndRule::Direction;
      if (b.rule == EndRule::Frame) b.rule = EndRule::Direction;
      nurbs::NurbsCurve c(fb.knots, position_fit(fb, t, r, a, b), fb.weights, 3);
      freeze_speeds(c);
      return nurbs::NurbsCurve(fb.knots, position_fit(fb, t, r, first, last), fb.weights, 3);
    };
    current = fit_once();
    for (int round = 0; round < kCorrectionRounds; ++round) {
      correct_parameters(current, r, t);
      current = fit_once();
    }
    targets.t = t;
  }
  freeze_speeds(current);

  // 4. The profile fit, refined a knot at a time while it misses the target and the budget allows.
  double curvature_tol = options.curvature_tolerance * std::max(target_max, 1e-300);
  if (edit_max > 0.0) curvature_tol = std::min(curvature_tol, kEditResolution * edit_max);
  struct Fitted {
    nurbs::NurbsCurve curve;
    double worst = 0.0, mean = 0.0, at_drag = 0.0;  // |κ − κ*|: max, mean, at the drag's peak sample
    double reached = 0.0;                           // κ at the drag's peak sample
  };
  std::size_t peak = 0;
  for (std::size_t j = 0; j < count; ++j)
    if (std::abs(target[j] - o.kappa[j]) > std::abs(target[peak] - o.kappa[peak])) peak = j;
  const auto fit_profile = [&](nurbs::NurbsCurve c, const ProfileTargets& pt) {
    Fitted f{.curve = std::move(c)};
    for (;;) {
      const FitBasis fb = basis_of(f.curve);
      f.curve = profile_fit(fb, f.curve, first, last, plane, pt);
      std::vector<double> own_t(count);
      static_cast<void>(OwnArcLength(fb.knots, pt.t).parameters(f.curve, pt.u, own_t));
      std::vector<diffgeom::FrenetPoint> ff(count);
      diffgeom::frenet(f.curve, own_t, ff, fo);
      f.worst = 0.0;
      f.mean = 0.0;
      std::size_t at = 0;
      for (std::size_t j = 0; j < count; ++j) {
        const double miss = std::abs(curvature_at(ff[j], planar) - pt.kappa[j]);
        f.mean += miss;
        if (j == peak) {
          f.at_drag = miss;
          f.reached = curvature_at(ff[j], planar);
        }
        if (miss > f.worst) {
          f.worst = miss;
          at = j;
        }
      }
      f.mean /= static_cast<double>(count);
      if (f.worst <= curvature_tol || handles_of(fb.knots) >= budget) break;
      // Refine: a knot at the middle of the worst sample's span (exact: the curve is unchanged).
      const std::size_t span = fb.knots.find_span(std::min(own_t[at], std::nextafter(dom.end, dom.start)));
      f.curve = nurbs::insert_knot(f.curve, 0.5 * (fb.knots[span] + fb.knots[span + 1]));
    }
    return f;
  };
  Fitted best = fit_profile(current, targets);
  if (!targets.weight.empty()) {
    // The weighted fit is not always nearer at the drag (the held ends and the handle budget trade differently
    // per curve): the plain fit is kept when it is.
    ProfileTargets plain = targets;
    plain.weight.clear();
    Fitted other = fit_profile(current, plain);
    if (other.at_drag < best.at_drag) best = std::move(other);
  }
  if (consistent_drag && !planar) {
    // Few handles cannot follow the consistent target everywhere, and a space fit trades κ for the torsion and
    // the held end frame: it moved the dragged spot 0.76–1.07 of the drag (helices and random Béziers). The
    // drag's height α is corrected by the secant method on the κ the fit reaches there (moved(0) = 0: the
    // original fits itself) until it moves by the drag within kReachTolerance; the nearest fit is kept.
    const double asked = target[peak] - o.kappa[peak];
    double alpha_prev = 0.0, moved_prev = 0.0, alpha = 1.0, moved = best.reached - o.kappa[peak];
    std::tuple<int, double, double> stats{iterations, mean_target_deviation, max_target_deviation};
    for (int k = 0; k < kReachIterations && std::abs(moved - asked) > kReachTolerance * std::abs(asked); ++k) {
      if (!(std::abs(moved - moved_prev) > 0.0)) break;
      const double next = std::clamp(alpha + (asked - moved) * (alpha - alpha_prev) / (moved - moved_prev),
                                     kReachScale.first, kReachScale.second);
      alpha_prev = std::exchange(alpha, next);
      moved_prev = moved;
      drag_target(alpha);
      // Warm start: the nearest fit so far already has the refined knots and is near the new target (α moves by a
      // few per cent), so the fit needs no knot refinement from the original's knots and few steps.
      Fitted trial = fit_profile(best.curve, targets);
      moved = trial.reached - o.kappa[peak];
      if (std::abs(moved - asked) < std::abs(best.reached - o.kappa[peak] - asked)) {
        best = std::move(trial);
        stats = {iterations, mean_target_deviation, max_target_deviation};
      }
    }
    std::tie(iterations, mean_target_deviation, max_target_deviation) = stats;
  }
  current = std::move(best.curve);
  const double worst = best.worst, mean = best.mean;

  // 5. The curve value: of the original's kind where the kind can hold the fit.
  const nurbs::NurbsCurve& fitted = current;
  std::vector<Vec3> cps(fitted.control_points().begin(), fitted.control_points().end());
  const int dimension = original.dimension();
  const auto flat = [&](Vec3 v) {
    if (dimension == 2) v.z = 0.0;
    return v;
  };
  const bool hold_end = last.rule != EndRule::None;
  CurvatureEditResult result{.curve = original};
  if (interpolated) {
    const auto& data = std::get<curve::InterpolatedData>(original.data());
    curve::InterpolatedData out;
    out.dimension = data.dimension;
    out.parameters = fitted.knots().breakpoints();
    for (const double tk : out.parameters) out.points.push_back(flat(fitted.evaluate(tk)));
    out.points.front() = flat(start.point);
    const Vec3 d0 = fitted.derivatives(dom.start, 1)[1];
    const Vec3 d1 = fitted.derivatives(dom.end, 1, {.side = nurbs::Side::Left})[1];
    out.start = nurbs::EndCondition::clamped(flat(start.tangent * dot(d0, start.tangent)));
    if (hold_end) {
      out.points.back() = flat(end.point);
      out.end = nurbs::EndCondition::clamped(flat(end.tangent * dot(d1, end.tangent)));
    } else {
      out.end = nurbs::EndCondition::clamped(flat(d1));
    }
    result.curve = curve::Curve::interpolated(std::move(out));
  } else {
    // Exact ends and end tangent directions (the rows hold them to rounding; this removes the rounding).
    cps.front() = start.point;
    cps[1] = cps.front() + start.tangent * dot(cps[1] - cps.front(), start.tangent);
    if (hold_end) {
      cps.back() = end.point;
      cps[cps.size() - 2] = cps.back() + end.tangent * dot(cps[cps.size() - 2] - cps.back(), end.tangent);
    }
    for (Vec3& p : cps) p = flat(p);
    const std::span<const double> w = fitted.weights();
    std::vector<double> weights(w.begin(), w.end());
    if (original.kind() == curve::Kind::Bezier && fitted.knots().breakpoints().size() == 2)
      result.curve = curve::Curve::bezier({.control_points = cps, .weights = weights, .dimension = dimension});
    else
      result.curve = curve::Curve(nurbs::NurbsCurve(fitted.knots(), cps, weights, dimension));
  }

  // What the designer checks, measured on the result.
  const nurbs::NurbsCurve& out = result.curve.nurbs();
  const Interval out_dom = out.domain();
  const diffgeom::FrenetPoint f0 = diffgeom::frenet(out, out_dom.start, fo);
  diffgeom::FrenetOptions fo_left = fo;
  fo_left.eval.side = nurbs::Side::Left;
  const diffgeom::FrenetPoint f1 = diffgeom::frenet(out, out_dom.end, fo_left);
  const auto angle = [](const Vec3& a, const Vec3& b) { return std::atan2(norm(cross(a, b)), dot(a, b)); };
  result.handles_before = handles_before;
  result.handles_after = handle_count(result.curve);
  result.planar = planar;
  result.reconstructed = edit.target == CurvatureTarget::Curvature;
  result.length_before = length;
  result.length_after = nurbs::arc_length(out);
  result.max_curvature_deviation = worst;
  result.mean_curvature_deviation = mean;
  result.reconstruction_mean_deviation = mean_target_deviation;
  result.reconstruction_max_deviation = max_target_deviation;
  result.iterations = iterations;
  result.start_point_error = distance(f0.position, start.point);
  result.end_point_error = distance(f1.position, end.point);
  result.start_tangent_error = angle(f0.tangent, start.tangent);
  result.end_tangent_error = angle(f1.tangent, end.tangent);
  result.start_curvature_error = std::abs(curvature_at(f0, planar) - start.curvature);
  result.end_curvature_error = std::abs(curvature_at(f1, planar) - end.curvature);
  result.inflections_before = count_inflections(original, plane);
  result.inflections_after = count_inflections(result.curve, plane);
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace hula::studies
