// SPDX-License-Identifier: MIT
// Knot insertion (A5.1), knot refinement (A5.4) and Bézier decomposition
// (A5.6 in refinement form) on homogeneous control points.
//
// Notation (The NURBS Book ch. 5): p = degree, U = knots (m + 1 values),
// Pw = homogeneous control points (n + 1), u = knot to insert, k = span with
// U[k] ≤ u < U[k+1], s = multiplicity of u, r = insertions, X = knots to
// insert (A5.4), Ubar / Qw = new knots / points.
#include "hula/nurbs/refine.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "hula/core/error.hpp"
#include "hula/nurbs/detail/homogeneous.hpp"

namespace hula::nurbs {

using detail::Hpoint;

namespace {

// Shared parameter checks for one knot value (field "u" or "knots[i]").
void check_knot_value(double u, const Interval& d, const std::string& name, ErrorWhere where) {
  if (!std::isfinite(u)) throw Error(Errc::NonFiniteInput, name + " = " + format_number(u) + " is not finite", where);
  if (u < d.start || u > d.end)
    throw Error(Errc::OutOfDomain,
                name + " = " + format_number(u) + " is outside the curve domain [" + format_number(d.start) + ", " +
                    format_number(d.end) + "]",
                where);
}

void check_multiplicity(double u, int existing, int added, int p, const std::string& name, ErrorWhere where) {
  if (existing + added > p)
    throw Error(Errc::InvalidKnots,
                name + " = " + format_number(u) + " has multiplicity " + std::to_string(existing) + "; inserting it " +
                    std::to_string(added) + " more time(s) would exceed the degree " + std::to_string(p),
                where);
}

}  // namespace

NurbsCurve insert_knot(const NurbsCurve& curve, double u, int times) {
  const KnotVector& kv = curve.knots();
  const int p = kv.degree();
  check_knot_value(u, curve.domain(), "u", {.field = "u"});
  if (times < 0)
    throw Error(Errc::InvalidArgument, "times = " + std::to_string(times) + " must be >= 0", {.field = "times"});
  const int s = kv.multiplicity(u);
  check_multiplicity(u, s, times, p, "u", {.field = "u"});
  if (times == 0) return curve;

  const std::span<const double> U = kv.values();
  const std::vector<Hpoint> Pw = detail::to_homogeneous(curve);
  const auto P = static_cast<std::size_t>(p);
  const auto S = static_cast<std::size_t>(s);
  const auto r = static_cast<std::size_t>(times);
  const std::size_t np = Pw.size() - 1;
  const std::size_t mp = U.size() - 1;
  // k: last index with U[k] ≤ u. It is < m because u = U[m] would mean a
  // clamped end (multiplicity p + 1), refused above.
  const auto k = static_cast<std::size_t>(std::upper_bound(U.begin(), U.end(), u) - U.begin()) - 1;
  HULA_ASSERT(k < mp && k >= P, "knot insertion span out of range");

  // Load the new knot vector.
  std::vector<double> UQ(mp + 1 + r);
  for (std::size_t i = 0; i <= k; ++i) UQ[i] = U[i];
  for (std::size_t i = 1; i <= r; ++i) UQ[k + i] = u;
  for (std::size_t i = k + 1; i <= mp; ++i) UQ[i + r] = U[i];
  // Save the unaltered control points.
  std::vector<Hpoint> Qw(np + 1 + r);
  for (std::size_t i = 0; i <= k - P; ++i) Qw[i] = Pw[i];
  for (std::size_t i = k - S; i <= np; ++i) Qw[i + r] = Pw[i];
  // Rw: the p - s + 1 points affected, updated in place for each insertion j.
  std::array<Hpoint, kMaxDegree + 1> Rw;
  for (std::size_t i = 0; i <= P - S; ++i) Rw[i] = Pw[k - P + i];
  std::size_t L = 0;
  for (std::size_t j = 1; j <= r; ++j) {
    L = k - P + j;
    for (std::size_t i = 0; i + j + S <= P; ++i) {
      const double alpha = (u - U[L + i]) / (U[i + k + 1] - U[L + i]);
      Rw[i] = detail::combine(alpha, Rw[i + 1], 1.0 - alpha, Rw[i]);
    }
    Qw[L] = Rw[0];
    Qw[k + r - j - S] = Rw[P - j - S];
  }
  // Load the remaining control points.
  for (std::size_t i = L + 1; i + S < k; ++i) Qw[i] = Rw[i - L];
  return detail::from_homogeneous(KnotVector(std::move(UQ), p), Qw, curve.is_rational(), curve.dimension(),
                                  "insert_knot");
}

NurbsCurve refine_knots(const NurbsCurve& curve, std::span<const double> X) {
  const KnotVector& kv = curve.knots();
  const int p = kv.degree();
  const Interval d = curve.domain();
  for (std::size_t j = 0; j < X.size(); ++j) {
    const std::string name = "knots[" + std::to_string(j) + "]";
    check_knot_value(X[j], d, name, {.field = "knots", .index = j});
    if (j > 0 && X[j] < X[j - 1])
      throw Error(Errc::InvalidArgument,
                  name + " = " + format_number(X[j]) + " is less than knots[" + std::to_string(j - 1) +
                      "] = " + format_number(X[j - 1]) + " (the knots to insert must be sorted)",
                  {.field = "knots", .index = j});
  }
  for (std::size_t j = 0; j < X.size();) {
    std::size_t e = j;
    while (e < X.size() && X[e] == X[j]) ++e;
    check_multiplicity(X[j], kv.multiplicity(X[j]), static_cast<int>(e - j), p, "knots[" + std::to_string(j) + "]",
                       {.field = "knots", .index = j});
    j = e;
  }
  if (X.empty()) return curve;

  const std::span<const double> U = kv.values();
  const std::vector<Hpoint> Pw = detail::to_homogeneous(curve);
  const auto P = static_cast<std::size_t>(p);
  const std::size_t n = Pw.size() - 1;
  const std::size_t m = U.size() - 1;
  const std::size_t r = X.size() - 1;
  // A5.4 step 1: the spans a and b + 1 bracketing the refined region.
  const std::size_t a = kv.find_span(X.front());
  const std::size_t b = kv.find_span(X.back()) + 1;
  std::vector<double> Ubar(m + r + 2);
  std::vector<Hpoint> Qw(n + r + 2);
  for (std::size_t j = 0; j <= a - P; ++j) Qw[j] = Pw[j];
  for (std::size_t j = b - 1; j <= n; ++j) Qw[j + r + 1] = Pw[j];
  for (std::size_t j = 0; j <= a; ++j) Ubar[j] = U[j];
  for (std::size_t j = b + P; j <= m; ++j) Ubar[j + r + 1] = U[j];
  // Step 2: insert X from the right, copying the old knots/points greater than X[j].
  std::size_t i = b + P - 1;
  std::size_t k = b + P + r;
  for (std::size_t jj = r + 1; jj-- > 0;) {
    while (X[jj] <= U[i] && i > a) {
      Qw[k - P - 1] = Pw[i - P - 1];
      Ubar[k] = U[i];
      --k;
      --i;
    }
    Qw[k - P - 1] = Qw[k - P];
    for (std::size_t l = 1; l <= P; ++l) {
      const std::size_t ind = k - P + l;
      double alpha = Ubar[k + l] - X[jj];
      if (alpha == 0.0) {
        // Exact test (A5.4): the new knot coincides with Ubar[k+l]; the point is copied.
        Qw[ind - 1] = Qw[ind];
      } else {
        alpha /= (Ubar[k + l] - U[i + l - P]);
        Qw[ind - 1] = detail::combine(alpha, Qw[ind - 1], 1.0 - alpha, Qw[ind]);
      }
    }
    Ubar[k] = X[jj];
    --k;
  }
  return detail::from_homogeneous(KnotVector(std::move(Ubar), p), Qw, curve.is_rational(), curve.dimension(),
                                  "refine_knots");
}

std::vector<NurbsCurve> decompose_to_bezier(const NurbsCurve& curve) {
  const KnotVector& kv = curve.knots();
  const int p = kv.degree();
  // Raise every breakpoint (domain ends included) to multiplicity ≥ p; then the
  // span [U[i], U[i+1]] has the Bézier points Qw[i-p .. i] (A5.6's result).
  std::vector<double> X;
  for (const double u : kv.breakpoints())
    for (int c = kv.multiplicity(u); c < p; ++c) X.push_back(u);
  const NurbsCurve refined = refine_knots(curve, X);
  const std::span<const double> U = refined.knots().values();
  const std::span<const Vec3> Q = refined.control_points();
  const std::span<const double> W = refined.weights();
  const auto P = static_cast<std::size_t>(p);
  std::vector<NurbsCurve> segments;
  for (std::size_t i = P; i < Q.size(); ++i) {
    if (!(U[i] < U[i + 1])) continue;
    std::vector<double> knots(2 * P + 2, U[i]);
    std::fill(knots.begin() + static_cast<std::ptrdiff_t>(P + 1), knots.end(), U[i + 1]);
    std::vector<Vec3> points(Q.begin() + static_cast<std::ptrdiff_t>(i - P),
                             Q.begin() + static_cast<std::ptrdiff_t>(i + 1));
    std::vector<double> weights;
    if (!W.empty())
      weights.assign(W.begin() + static_cast<std::ptrdiff_t>(i - P), W.begin() + static_cast<std::ptrdiff_t>(i + 1));
    segments.emplace_back(p, std::move(knots), std::move(points), std::move(weights), curve.dimension());
  }
  return segments;
}

}  // namespace hula::nurbs
