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
#include <string>
#include <vector>

#include "hula/core/banded.hpp"
#include "hula/core/error.hpp"
#include "hula/nurbs/basis.hpp"
#include "hula/nurbs/detail/homogeneous.hpp"

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

}  // namespace hula::nurbs
