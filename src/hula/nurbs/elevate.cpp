// SPDX-License-Identifier: MIT
// Degree elevation by collocation at Greville abscissae.
//
// Notation: p = old degree, q = p + t new degree, U / V old / new knots,
// ξ_j = (V[j+1] + … + V[j+q]) / q the Greville abscissae (de Boor, "A
// Practical Guide to Splines", ch. XIII), Pw / Qw old / new homogeneous points.
// Row j of the system: Σ_i N_{i,q}(ξ_j) Qw_i = Cw(ξ_j) = Σ_i N_{i,p}(ξ_j) Pw_i.
// N_{i,q}(ξ_i) > 0 for every i (each ξ_i lies inside the support of N_{i,q},
// since no interior knot has multiplicity above q), so Schoenberg–Whitney
// holds; the matrix has bandwidth q on each side.
#include "hula/nurbs/elevate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "hula/core/banded.hpp"
#include "hula/core/error.hpp"
#include "hula/nurbs/basis.hpp"
#include "hula/nurbs/detail/homogeneous.hpp"
#include "hula/nurbs/knot_removal.hpp"
#include "hula/nurbs/refine.hpp"
#include "hula/nurbs/reparam.hpp"

namespace hula::nurbs {

NurbsCurve elevate_degree(const NurbsCurve& curve, int times) {
  if (times < 0)
    throw Error(Errc::InvalidArgument, "times = " + std::to_string(times) + " must be >= 0", {.field = "times"});
  const KnotVector& kv = curve.knots();
  const int p = kv.degree();
  if (times > kMaxDegree - p)
    throw Error(Errc::InvalidDegree,
                "degree " + std::to_string(p) + " elevated times = " + std::to_string(times) + " exceeds kMaxDegree " +
                    std::to_string(kMaxDegree),
                {.field = "times"});
  if (times == 0) return curve;
  const int q = p + times;
  const auto Q = static_cast<std::size_t>(q);
  const auto P = static_cast<std::size_t>(p);

  // New knot vector: clamped ends, interior multiplicities raised by t.
  const std::vector<double> breaks = kv.breakpoints();
  std::vector<double> V(Q + 1, breaks.front());
  for (std::size_t b = 1; b + 1 < breaks.size(); ++b)
    V.insert(V.end(), static_cast<std::size_t>(kv.multiplicity(breaks[b]) + times), breaks[b]);
  V.insert(V.end(), Q + 1, breaks.back());
  const KnotVector new_knots(V, q);
  const std::size_t N = new_knots.control_point_count();

  // Right-hand side Cw(ξ_j) (homogeneous), and the collocation matrix.
  const bool rational = curve.is_rational();
  const std::size_t columns = rational ? 4 : 3;
  const std::vector<detail::Hpoint> Pw = detail::to_homogeneous(curve);
  BandedMatrix A(N, Q, Q);
  std::vector<double> rhs(N * columns, 0.0);
  std::vector<double> Nq(Q + 1), Np(P + 1);
  const Interval dom = kv.domain();
  for (std::size_t j = 0; j < N; ++j) {
    double xi = 0.0;
    for (std::size_t l = 1; l <= Q; ++l) xi += V[j + l];
    xi /= static_cast<double>(q);
    // Rounding may push the average of equal knots off by an ulp: keep ξ in the domain.
    xi = std::clamp(xi, dom.start, dom.end);
    const std::size_t sq = new_knots.find_span(xi);
    basis_functions(new_knots, sq, xi, Nq);
    for (std::size_t l = 0; l <= Q; ++l) A.at(j, sq - Q + l) = Nq[l];
    // The old curve is continuous wherever the new one is evaluated from the
    // right, and both use the right limit, so the two sides agree.
    const std::size_t sp = kv.find_span(xi);
    basis_functions(kv, sp, xi, Np);
    for (std::size_t l = 0; l <= P; ++l)
      for (std::size_t c = 0; c < columns; ++c) rhs[j * columns + c] += Np[l] * Pw[sp - P + l][c];
  }
  if (!A.solve(rhs, columns))
    throw Error(Errc::NumericalFailure,
                "degree elevation by times = " + std::to_string(times) + ": collocation system is singular",
                {.field = "times"});
  std::vector<detail::Hpoint> Qw(N);
  for (std::size_t i = 0; i < N; ++i)
    Qw[i] = {rhs[i * columns], rhs[i * columns + 1], rhs[i * columns + 2], rational ? rhs[i * columns + 3] : 1.0};
  return detail::from_homogeneous(new_knots, Qw, rational, curve.dimension(), "elevate_degree");
}

DegreeReductionResult reduce_degree(const NurbsCurve& curve, double tolerance) {
  if (!(std::isfinite(tolerance) && tolerance >= 0.0))
    throw Error(Errc::InvalidArgument, "tolerance = " + format_number(tolerance) + " must be finite and >= 0",
                {.field = "tolerance"});
  const int p = curve.degree();
  if (p < 2) throw Error(Errc::InvalidDegree, "degree 1 cannot be reduced", {.field = "curve"});
  const bool rational = curve.is_rational();
  // Rounding floor: a curve that is exactly an elevated one reduces with a bound of a few ulps of its size.
  const double floor = 1e-12 * std::max(1.0, curve.model_size());
  const int q = p - 1;
  const int r = (p - 1) / 2;
  double worst = 0.0;
  double worst_at = curve.domain().start;
  std::optional<NurbsCurve> joined;
  for (const NurbsCurve& piece : decompose_to_bezier(curve)) {
    // Homogeneous points (w P, w): the inversion is linear in them, so a rational piece is reduced in 4-D.
    const std::vector<detail::Hpoint> P = detail::to_homogeneous(piece);
    std::vector<detail::Hpoint> Q(static_cast<std::size_t>(p));
    // From the left: Q_i = (P_i − α_i Q_{i−1}) / (1 − α_i), α_i = i/p, i = 0 … r.
    for (int i = 0; i <= r; ++i) {
      const double a = static_cast<double>(i) / p;
      const auto ui = static_cast<std::size_t>(i);
      if (i == 0)
        Q[ui] = P[0];
      else
        for (std::size_t c = 0; c < 4; ++c) Q[ui][c] = (P[ui][c] - a * Q[ui - 1][c]) / (1.0 - a);
    }
    // From the right: Q_{i−1} = (P_i − (1 − α_i) Q_i) / α_i, i = p … r + 2.
    for (int i = p; i >= r + 2; --i) {
      const double a = static_cast<double>(i) / p;
      const auto ui = static_cast<std::size_t>(i);
      if (i == p)
        Q[ui - 1] = P[ui];
      else
        for (std::size_t c = 0; c < 4; ++c) Q[ui - 1][c] = (P[ui][c] - (1.0 - a) * Q[ui][c]) / a;
    }
    const Interval d = piece.domain();
    // The reduced weights must stay positive, else no rational curve of degree p − 1 with this inversion exists.
    double min_weight = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < Q.size(); ++i) {
      if (!(Q[i][3] > 0.0) || !std::isfinite(Q[i][3]))
        throw Error(Errc::NumericalFailure,
                    "the degree cannot be reduced: on [" + format_number(d.start) + ", " + format_number(d.end) +
                        "] the reduced weight " + std::to_string(i) + " is " + format_number(Q[i][3]) +
                        " (weights must stay positive)",
                    {.field = "curve"});
      min_weight = std::min(min_weight, Q[i][3]);
    }
    // The piece minus its reduction (degree-elevated back) is B_{r+1,p}(t) Δ in homogeneous space, with
    // Δ = (ΔA, Δw) = P_{r+1} − (a Q_r + (1 − a) Q_{r+1}). In Euclidean space, with A, w the piece's numerator
    // and weight and w̃ = w − B Δw the reduction's weight:
    //   C̃ − C = −B (ΔA − C Δw) / w̃,  so |C̃ − C| ≤ (|ΔA − c Δw| + |Δw| R) / min w̃_i
    // for any point c and R = max |P_i − c| (C lies in the convex hull of the P_i), B ≤ 1, and w̃ at least
    // the least reduced weight (w̃ is their Bernstein combination). Non-rational: Δw = 0, w̃ = 1, the bound is |ΔP|.
    const double a = static_cast<double>(r + 1) / p;
    const auto ur = static_cast<std::size_t>(r);
    const detail::Hpoint delta = detail::combine(1.0, P[ur + 1], -1.0, detail::combine(a, Q[ur], 1.0 - a, Q[ur + 1]));
    const std::span<const Vec3> points = piece.control_points();
    Vec3 c{};
    for (const Vec3& x : points) c += x;
    c = c / static_cast<double>(points.size());
    double R = 0.0;
    for (const Vec3& x : points) R = std::max(R, norm(x - c));
    const Vec3 dA{delta[0], delta[1], delta[2]};
    const double e = rational ? (norm(dA - delta[3] * c) + std::abs(delta[3]) * R) / min_weight : norm(dA);
    if (e > worst) {
      worst = e;
      worst_at = 0.5 * (d.start + d.end);
    }
    std::vector<double> U(static_cast<std::size_t>(q) + 1, d.start);
    U.insert(U.end(), static_cast<std::size_t>(q) + 1, d.end);
    const NurbsCurve reduced =
        detail::from_homogeneous(KnotVector(std::move(U), q), Q, rational, curve.dimension(), "reduce_degree");
    joined = joined ? join(*joined, reduced, floor) : reduced;
  }
  if (worst > std::max(tolerance, floor))
    throw Error(Errc::NumericalFailure,
                "the degree cannot be reduced within tolerance = " + format_number(tolerance) +
                    ": the piece around t = " + format_number(worst_at) + " moves by up to " + format_number(worst),
                {.field = "tolerance"});
  // Knot removal within the rest of the tolerance restores continuity (C0 joints up to C^(q−1)).
  const KnotRemovalResult k = remove_knots(*joined, std::max(0.0, tolerance - worst));
  return {k.curve, worst + k.error_bound, worst};
}

}  // namespace hula::nurbs
