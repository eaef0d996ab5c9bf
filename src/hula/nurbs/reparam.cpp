// SPDX-License-Identifier: MIT
// Affine reparameterisation, reversal and splitting.
//
// Notation (The NURBS Book): p = degree, U = knots (m + 1 values), [a, b] = domain.
#include "hula/nurbs/reparam.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/nurbs/refine.hpp"

namespace hula::nurbs {

NurbsCurve reparameterise(const NurbsCurve& curve, Interval domain) {
  if (!(std::isfinite(domain.start) && std::isfinite(domain.end) && domain.start < domain.end))
    throw Error(Errc::InvalidArgument,
                "domain = [" + format_number(domain.start) + ", " + format_number(domain.end) +
                    "] must be finite with start < end",
                {.field = "domain"});
  const std::span<const Vec3> P = curve.control_points();
  const std::span<const double> W = curve.weights();
  return NurbsCurve(curve.knots().reparameterised(domain), {P.begin(), P.end()}, {W.begin(), W.end()},
                    curve.dimension());
}

NurbsCurve reverse(const NurbsCurve& curve) {
  const KnotVector& kv = curve.knots();
  const std::span<const double> U = kv.values();
  const Interval d = kv.domain();
  const double sum = d.start + d.end;
  const std::size_t m = U.size() - 1;
  std::vector<double> R(m + 1);
  for (std::size_t i = 0; i <= m; ++i) {
    const double u = U[m - i];
    // The domain ends swap exactly; elsewhere a + b - u (monotone under rounding).
    R[i] = u == d.start ? d.end : (u == d.end ? d.start : sum - u);
  }
  const std::span<const Vec3> P = curve.control_points();
  const std::span<const double> W = curve.weights();
  return NurbsCurve(KnotVector(std::move(R), kv.degree()), {P.rbegin(), P.rend()}, {W.rbegin(), W.rend()},
                    curve.dimension());
}

SplitResult split(const NurbsCurve& curve, double t) {
  const Interval d = curve.domain();
  if (!std::isfinite(t))
    throw Error(Errc::NonFiniteInput, "t = " + format_number(t) + " is not finite", {.field = "t"});
  if (!(t > d.start && t < d.end))
    throw Error(Errc::OutOfDomain,
                "t = " + format_number(t) + " must lie strictly inside the curve domain (" + format_number(d.start) +
                    ", " + format_number(d.end) + ")",
                {.field = "t"});
  const int p = curve.degree();
  const auto P = static_cast<std::size_t>(p);
  const NurbsCurve refined = insert_knot(curve, t, p - curve.knots().multiplicity(t));
  const std::span<const double> V = refined.knots().values();
  const std::span<const Vec3> Q = refined.control_points();
  const std::span<const double> W = refined.weights();
  // f: index of the first of the p copies of t; C(t) = Q[f - 1] is shared.
  const auto f = static_cast<std::size_t>(std::lower_bound(V.begin(), V.end(), t) - V.begin());
  const auto sf = static_cast<std::ptrdiff_t>(f);

  std::vector<double> left(V.begin(), V.begin() + sf + static_cast<std::ptrdiff_t>(P));
  left.push_back(t);
  std::vector<double> right(1, t);
  right.insert(right.end(), V.begin() + sf, V.end());
  std::vector<double> wl, wr;
  if (!W.empty()) {
    wl.assign(W.begin(), W.begin() + sf);
    wr.assign(W.begin() + sf - 1, W.end());
  }
  return SplitResult{NurbsCurve(p, std::move(left), {Q.begin(), Q.begin() + sf}, std::move(wl), curve.dimension()),
                     NurbsCurve(p, std::move(right), {Q.begin() + sf - 1, Q.end()}, std::move(wr), curve.dimension())};
}

}  // namespace hula::nurbs
