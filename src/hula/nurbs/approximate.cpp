// SPDX-License-Identifier: MIT
// Least-squares curve approximation with fixed end points (thesis 5.3.3;
// The NURBS Book, Piegl & Tiller 2nd ed., 9.4.1, eq. 9.63-9.69).
//
// Notation (The NURBS Book 9.4.1): Q_0 … Q_m data points, t_k their
// parameters, p degree, P_0 … P_n control points with P_0 = Q_0 and
// P_n = Q_m, N_{i,p} the basis functions on knots U. Interior knots by
// averaging (eq. 9.69): d = (m + 1) / (n - p + 1), and for j = 1 … n - p,
// i = floor(j d), α = j d - i, U_{p+j} = (1 - α) t_{i-1} + α t_i.
// The unknowns P_1 … P_{n-1} solve the normal equations (NᵀN) P = R with
//   R_k = Q_k - N_{0,p}(t_k) Q_0 - N_{n,p}(t_k) Q_m,  R_i = Σ_{k=1}^{m-1} N_{i,p}(t_k) R_k,
// NᵀN symmetric positive definite with bandwidth p (every t_k touches p + 1
// consecutive basis functions), solved with hula::BandedMatrix in O(m p²).
// When n = m (as many control points as points) the fit is an interpolation
// and the knots are those of eq. 9.8 (averaging), see approximate().
// least_squares_fit is the solve on given t and U; rebuild samples a curve at
// its own parameters and fits them on uniform knots of its domain.
#include "hula/nurbs/approximate.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "hula/core/banded.hpp"
#include "hula/core/error.hpp"
#include "hula/nurbs/basis.hpp"
#include "hula/nurbs/detail/option_checks.hpp"
#include "hula/nurbs/deviation.hpp"

namespace hula::nurbs {

namespace {

// Fewest samples rebuild fits by default: enough that a curve with a few control points is fitted on a dense
// sampling of its shape, not only on as many samples as unknowns.
constexpr std::size_t kRebuildMinSamples = 201;

// The options approximate and rebuild share: a degree in [1, kMaxDegree] and at least degree + 1
// control points.
void check_degree_and_control_points(int degree, std::size_t control_points) {
  if (degree < 1 || degree > kMaxDegree)
    throw Error(Errc::InvalidOption,
                "degree = " + std::to_string(degree) + " must be in [1, " + std::to_string(kMaxDegree) + "]",
                {.field = "degree"});
  if (control_points < static_cast<std::size_t>(degree) + 1)
    throw Error(Errc::InvalidOption,
                "control_points = " + std::to_string(control_points) +
                    " must be at least degree + 1 = " + std::to_string(degree + 1),
                {.field = "control_points"});
}

}  // namespace

void ApproximationOptions::validate() const {
  check_degree_and_control_points(degree, control_points);
  detail::check_dimension_option(dimension);
  detail::check_parameterisation_option(parameterisation);
}

NurbsCurve least_squares_fit(std::span<const Vec3> points, std::span<const double> parameters, const KnotVector& kv,
                             int dimension) {
  detail::check_dimension_option(dimension);
  if (points.size() < 2)
    throw Error(Errc::TooFewPoints, "a least-squares fit needs at least 2 points, got " + std::to_string(points.size()),
                {.field = "points"});
  if (parameters.size() != points.size())
    throw Error(Errc::InvalidArgument,
                std::to_string(parameters.size()) + " parameters for " + std::to_string(points.size()) + " points",
                {.field = "parameters"});
  if (!kv.is_clamped())
    throw Error(Errc::InvalidArgument, "the knot vector must be clamped (end multiplicity degree + 1)",
                {.field = "knots"});
  const std::size_t m = points.size() - 1;
  const std::size_t n = kv.control_point_count() - 1;
  const auto p = static_cast<std::size_t>(kv.degree());
  if (n > m)
    throw Error(Errc::InvalidArgument,
                "the knots carry " + std::to_string(n + 1) + " control points, more than the " + std::to_string(m + 1) +
                    " points",
                {.field = "knots"});
  const Interval dom = kv.domain();
  for (std::size_t k = 0; k <= m; ++k) {
    for (std::size_t c = 0; c < 3; ++c)
      if (!std::isfinite(points[k][c]))
        throw Error(Errc::NonFiniteInput, "points[" + std::to_string(k) + "] is not finite",
                    {.field = "points", .index = k, .component = c});
    if (dimension == 2 && points[k].z != 0.0)
      throw Error(Errc::InvalidArgument,
                  "points[" + std::to_string(k) + "] has z = " + format_number(points[k].z) +
                      " but dimension = 2 (z must be 0)",
                  {.field = "points", .index = k, .component = 2});
    const double tk = parameters[k];
    if (!std::isfinite(tk))
      throw Error(Errc::NonFiniteInput, "parameters[" + std::to_string(k) + "] is not finite",
                  {.field = "parameters", .index = k});
    if (tk < dom.start || tk > dom.end || (k > 0 && tk < parameters[k - 1]))
      throw Error(Errc::InvalidArgument,
                  "parameters[" + std::to_string(k) + "] = " + format_number(tk) +
                      " is outside the knots' domain or below the parameter before it",
                  {.field = "parameters", .index = k});
  }

  std::vector<Vec3> P(n + 1);
  P.front() = points.front();
  P.back() = points.back();
  if (n >= 2) {
    const std::size_t unknowns = n - 1;
    BandedMatrix A(unknowns, p, p);
    std::vector<double> rhs(3 * unknowns, 0.0);
    std::vector<double> b(p + 1);
    for (std::size_t k = 1; k < m; ++k) {
      const std::size_t span = kv.find_span(parameters[k]);
      basis_functions(kv, span, parameters[k], b);
      const std::size_t first = span - p;  // b[j] = N_{first + j, p}(t_k)
      Vec3 R = points[k];
      if (first == 0) R -= b[0] * points.front();
      if (first + p == n) R -= b[p] * points.back();
      for (std::size_t a = 0; a <= p; ++a) {
        const std::size_t ia = first + a;
        if (ia == 0 || ia == n || b[a] == 0.0) continue;
        for (std::size_t c = 0; c < 3; ++c) rhs[(ia - 1) * 3 + c] += b[a] * R[c];
        for (std::size_t e = 0; e <= p; ++e) {
          const std::size_t ie = first + e;
          if (ie == 0 || ie == n) continue;
          A.at(ia - 1, ie - 1) += b[a] * b[e];
        }
      }
    }
    if (!A.solve(rhs, 3))
      throw Error(Errc::NumericalFailure,
                  "the least-squares normal equations are singular (" + std::to_string(n + 1) + " control points for " +
                      std::to_string(points.size()) + " points)",
                  {.field = "knots"});
    for (std::size_t i = 1; i < n; ++i) P[i] = {rhs[3 * (i - 1)], rhs[3 * (i - 1) + 1], rhs[3 * (i - 1) + 2]};
  }
  if (dimension == 2)
    for (Vec3& q : P) q.z = 0.0;
  return NurbsCurve(kv, std::move(P), {}, dimension);
}

ApproximationResult approximate(std::span<const Vec3> points, const ApproximationOptions& options) {
  options.validate();
  if (points.size() < 2)
    throw Error(Errc::TooFewPoints, "approximate needs at least 2 points, got " + std::to_string(points.size()),
                {.field = "points"});
  if (options.control_points > points.size())
    throw Error(Errc::InvalidOption,
                "control_points = " + std::to_string(options.control_points) + " exceeds the number of points " +
                    std::to_string(points.size()),
                {.field = "control_points"});
  // (A point off the plane of a 2-D fit is refused by least_squares_fit.)
  std::vector<double> t = parameterise(points, options.parameterisation);
  const std::size_t m = points.size() - 1;
  const std::size_t n = options.control_points - 1;
  const auto p = static_cast<std::size_t>(options.degree);

  std::vector<double> U(p + 1, 0.0);
  if (n == m) {
    // As many control points as points: an interpolation. Eq. 9.69 degenerates
    // here (d is barely above 1, so a knot falls within a small fraction of a
    // spacing of a data parameter and N is nearly singular); use the averaging
    // of eq. 9.8, U_{j+p} = (1/p) Σ_{i=j}^{j+p-1} t_i, the interpolation knots.
    for (std::size_t j = 1; j + p <= n; ++j) {
      double sum = 0.0;
      for (std::size_t i = j; i < j + p; ++i) sum += t[i];
      U.push_back(sum / static_cast<double>(p));
    }
  } else {
    const double d = static_cast<double>(m + 1) / static_cast<double>(n - p + 1);
    for (std::size_t j = 1; j + p <= n; ++j) {
      const double jd = static_cast<double>(j) * d;
      const auto i = static_cast<std::size_t>(std::floor(jd));
      const double alpha = jd - static_cast<double>(i);
      U.push_back((1.0 - alpha) * t[i - 1] + alpha * t[i]);
    }
  }
  U.insert(U.end(), p + 1, 1.0);
  const KnotVector kv(std::move(U), options.degree);
  ApproximationResult result{.curve = least_squares_fit(points, t, kv, options.dimension), .parameters = std::move(t)};

  std::vector<Vec3> on_curve(points.size());
  result.curve.evaluate(result.parameters, on_curve);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const double e = distance(on_curve[k], points[k]);
    if (e > result.max_deviation) {
      result.max_deviation = e;
      result.max_deviation_index = k;
    }
  }
  return result;
}

void RebuildOptions::validate() const {
  check_degree_and_control_points(degree, control_points);
  if (samples != 0 && samples < control_points)
    throw Error(Errc::InvalidOption,
                "samples = " + std::to_string(samples) +
                    " must be 0 (automatic) or at least control_points = " + std::to_string(control_points),
                {.field = "samples"});
  if (deviation_samples < 2)
    throw Error(Errc::InvalidOption, "deviation_samples = " + std::to_string(deviation_samples) + " must be >= 2",
                {.field = "deviation_samples"});
}

RebuildResult rebuild(const NurbsCurve& curve, const RebuildOptions& options) {
  options.validate();
  const std::size_t count =
      options.samples != 0 ? options.samples : std::max<std::size_t>(kRebuildMinSamples, 10 * options.control_points);
  const Interval dom = curve.domain();
  std::vector<double> t(count);
  for (std::size_t k = 0; k < count; ++k)
    t[k] = k + 1 == count
               ? dom.end
               : dom.start + (dom.end - dom.start) * (static_cast<double>(k) / static_cast<double>(count - 1));
  std::vector<Vec3> points(count);
  curve.evaluate(t, points);
  const KnotVector kv = KnotVector::uniform_clamped(options.control_points, options.degree, dom);
  RebuildResult out{.curve = least_squares_fit(points, t, kv, curve.dimension()), .samples = count};
  // Measured, not bounded: each sample of the new curve against its closest point on the original.
  const DeviationResult d =
      deviation(out.curve, curve, {.samples = options.deviation_samples, .mode = DeviationMode::Closest});
  out.max_deviation = d.max;
  out.mean_deviation = d.mean;
  out.at = dom.start + d.at * (dom.end - dom.start);
  return out;
}

ToleranceFitResult approximate_to_tolerance(std::span<const Vec3> points, double tolerance,
                                            ApproximationOptions options) {
  if (!(tolerance > 0.0 && std::isfinite(tolerance)))
    throw Error(Errc::InvalidArgument, "tolerance = " + format_number(tolerance) + " must be positive and finite",
                ErrorWhere{.field = "tolerance"});
  std::size_t fits = 0;
  auto fit = [&](std::size_t count) {
    options.control_points = count;
    ++fits;
    return approximate(points, options);
  };
  const std::size_t lowest = static_cast<std::size_t>(std::max(options.degree, 1)) + 1;
  // The interpolating count always meets the tolerance (up to rounding, which the caller's
  // tolerance must exceed): it is the upper end of the search and the fallback answer.
  std::size_t hi = points.size();
  ApproximationResult best = fit(hi);
  if (!(best.max_deviation <= tolerance))
    throw Error(Errc::NumericalFailure,
                "tolerance = " + format_number(tolerance) + " is below the interpolation's own rounding (" +
                    format_number(best.max_deviation) + ")",
                ErrorWhere{.field = "tolerance"});
  std::size_t lo = std::min(lowest, hi);  // invariant: counts < lo fail, hi meets
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    ApproximationResult r = fit(mid);
    if (r.max_deviation <= tolerance) {
      hi = mid;
      best = std::move(r);
    } else {
      lo = mid + 1;
    }
  }
  // Downward steps past a non-monotone dip: stop at the first count that fails.
  while (hi > lowest) {
    ApproximationResult r = fit(hi - 1);
    if (!(r.max_deviation <= tolerance)) break;
    --hi;
    best = std::move(r);
  }
  return ToleranceFitResult{std::move(best), fits};
}

}  // namespace hula::nurbs
