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
#include "hula/nurbs/elevate.hpp"
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

NurbsCurve segment(const NurbsCurve& curve, Interval part) {
  const Interval d = curve.domain();
  if (!(part.start >= d.start && part.end <= d.end && part.start < part.end))
    throw Error(Errc::OutOfDomain,
                "part = [" + format_number(part.start) + ", " + format_number(part.end) +
                    "] must satisfy start < end inside the domain [" + format_number(d.start) + ", " +
                    format_number(d.end) + "]",
                {.field = "part"});
  NurbsCurve c = part.end < d.end ? split(curve, part.end).before : curve;
  return part.start > d.start ? split(c, part.start).after : c;
}

NurbsCurve join(const NurbsCurve& a, const NurbsCurve& b, double gap) {
  if (!a.knots().is_clamped()) throw Error(Errc::InvalidArgument, "a: knot vector must be clamped", {.field = "a"});
  if (!b.knots().is_clamped()) throw Error(Errc::InvalidArgument, "b: knot vector must be clamped", {.field = "b"});
  const NurbsCurve A = a.degree() < b.degree() ? elevate_degree(a, b.degree() - a.degree()) : a;
  const NurbsCurve B = b.degree() < a.degree() ? elevate_degree(b, a.degree() - b.degree()) : b;
  const std::span<const Vec3> PA = A.control_points();
  const std::span<const Vec3> PB = B.control_points();
  const Vec3 ea = PA.back();
  const Vec3 sb = PB.front();
  if (!(norm(ea - sb) <= gap))
    throw Error(Errc::InvalidArgument,
                "a ends at (" + format_number(ea.x) + ", " + format_number(ea.y) + ", " + format_number(ea.z) +
                    ") and b starts at (" + format_number(sb.x) + ", " + format_number(sb.y) + ", " +
                    format_number(sb.z) + "), farther apart than gap = " + format_number(gap),
                {.field = "gap"});
  const int p = A.degree();
  const Interval da = A.domain();
  const Interval db = B.domain();
  // b follows a with its own parameter length, so its derivatives keep their size.
  // (kept as it is when it already starts where a ends, so adjacent pieces keep their exact knots)
  const KnotVector kb =
      db.start == da.end ? B.knots() : B.knots().reparameterised({da.end, da.end + (db.end - db.start)});
  const std::span<const double> UB = kb.values();
  const std::span<const double> UA = A.knots().values();
  // U = a's knots without the last copy of its end, then b's knots without the p + 1 copies of its start:
  // the joint keeps multiplicity p (C0).
  std::vector<double> U(UA.begin(), UA.end() - 1);
  U.insert(U.end(), UB.begin() + p + 1, UB.end());
  std::vector<Vec3> P(PA.begin(), PA.end());
  P.back() = 0.5 * (ea + sb);
  P.insert(P.end(), PB.begin() + 1, PB.end());
  std::vector<double> W;
  if (A.is_rational() || B.is_rational()) {
    const std::span<const double> WA = A.weights();
    const std::span<const double> WB = B.weights();
    const double wa = WA.empty() ? 1.0 : WA.back();
    const double wb = WB.empty() ? 1.0 : WB.front();
    W.assign(PA.size(), 1.0);
    if (!WA.empty()) std::copy(WA.begin(), WA.end(), W.begin());
    // Scaling every weight of b by one factor leaves b unchanged and makes the shared weight agree.
    for (std::size_t i = 1; i < PB.size(); ++i) W.push_back((WB.empty() ? 1.0 : WB[i]) * wa / wb);
  }
  const int dim = a.dimension() == 2 && b.dimension() == 2 ? 2 : 3;
  return NurbsCurve(p, std::move(U), std::move(P), std::move(W), dim);
}

}  // namespace hula::nurbs
