// SPDX-License-Identifier: MIT
// Curves through data points: parameterisation, the global C2 cubic spline,
// Lagrange (Bézier) interpolation and piecewise Hermite curves.
//
// References:
//   thesis 5.3.1 (Lagrange), 5.3.2 (Hermite), 7.1.2 and eq. 29 (chord length),
//     7.5.1/7.5.2 (interpolation through points, tangents), 10.2.1, 10.2.5;
//   The NURBS Book (Piegl & Tiller, 2nd ed.) 9.2.1-9.2.2 (global interpolation,
//     end derivatives), A2.2/A2.3 (basis functions and derivatives);
//   E. T. Y. Lee, "Choosing nodes in parametric curve interpolation", CAD 21(6), 1989 (centripetal);
//   T. A. Foley, G. M. Nielson, "Knot selection for parametric spline interpolation", in Mathematical
//     Methods in Computer Aided Geometric Design, Academic Press, 1989, pp. 261-271 (Foley; with
//     Euclidean chords as in Lee's and Fang & Hung's comparisons);
//   C. de Boor, "A Practical Guide to Splines", ch. IV (Bessel and not-a-knot ends);
//   Open CASCADE GeomAPI_Interpolate::PerformNonPeriodic / BuildTangents (the Occt end condition).
//
// Notation: Q_i = data points (i = 0 … N-1), t_i = data parameters in [0, 1],
// P_j = control points (j = 0 … N+1), U = knots {0,0,0,0, t_1 … t_{N-2}, 1,1,1,1}.
// The cubic spline is solved for the unknowns P_1 … P_N (P_0 = Q_0 and
// P_{N+1} = Q_{N-1} are known) as one banded system: row 0 the start
// condition, rows 1 … N-2 the interpolation conditions C(t_i) = Q_i, row N-1
// the end condition. Interpolation rows are tridiagonal; a not-a-knot row
// reaches three columns further. The end rows are reduced to tridiagonal form
// and the system solved by the Thomas algorithm in O(N), with the pivoting
// band solver (kl = ku = 3) as the fallback.
//
// Hermite curves are built by blossoming (polar forms): the control point
// P_j of a spline is its blossom at (U_{j+1}, …, U_{j+p}), which any polynomial
// piece gives where the spline is smooth enough; the Bézier points of a
// Hermite segment follow from its end derivatives.
#include "hula/nurbs/interpolate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>

#include "hula/core/banded.hpp"
#include "hula/core/error.hpp"
#include "hula/core/huge_pages.hpp"
#include "hula/nurbs/basis.hpp"
#include "hula/nurbs/detail/curve_access.hpp"
#include "hula/nurbs/detail/option_checks.hpp"
#include "hula/nurbs/knot_removal.hpp"
#include "hula/nurbs/reparam.hpp"

namespace hula::nurbs {

namespace {

constexpr int kCubic = 3;
constexpr int kQuintic = 5;

std::string indexed(const char* field, std::size_t i) { return std::string(field) + "[" + std::to_string(i) + "]"; }

void check_dimension_argument(int dimension) {
  if (dimension != 2 && dimension != 3)
    throw Error(Errc::InvalidArgument, "dimension = " + std::to_string(dimension) + " must be 2 or 3",
                {.field = "dimension"});
}

// Rejects non-finite coordinates (naming point and coordinate) and, for
// dimension 2, a non-zero z (naming the point).
// `box`, if given, receives the box of the vectors (one pass for both).
void check_vectors(std::span<const Vec3> v, int dimension, const char* field, Box3* box = nullptr) {
  // One pass without branches first: (x − x) is 0 for finite x and NaN otherwise, and Σ |z| > 0 flags a
  // planar violation; only a bad input pays for the loop below that names the culprit.
  double probe = 0.0, z_sum = 0.0;
  Box3 b;
  for (const Vec3& q : v) {
    probe += (q.x - q.x) + (q.y - q.y) + (q.z - q.z);
    z_sum += std::fabs(q.z);
    b.add(q);
  }
  if (box != nullptr) *box = b;
  if (probe == 0.0 && (dimension != 2 || z_sum == 0.0)) return;
  for (std::size_t i = 0; i < v.size(); ++i) {
    for (std::size_t c = 0; c < 3; ++c) {
      if (!std::isfinite(v[i][c]))
        throw Error(Errc::NonFiniteInput,
                    indexed(field, i) + "[" + std::to_string(c) + "] = " + format_number(v[i][c]) + " is not finite",
                    {.field = field, .index = i, .component = c});
    }
    if (dimension == 2 && v[i].z != 0.0)
      throw Error(Errc::InvalidArgument,
                  indexed(field, i) + " has z = " + format_number(v[i].z) + " but dimension = 2 (z must be 0)",
                  {.field = field, .index = i, .component = 2});
  }
}

void check_count(std::size_t n, std::size_t needed, const char* what) {
  if (n < needed)
    throw Error(Errc::TooFewPoints,
                std::string(what) + " needs at least " + std::to_string(needed) + " points, got " + std::to_string(n),
                {.field = "points"});
}

void check_same_count(std::size_t got, std::size_t points, const char* field) {
  if (got != points)
    throw Error(Errc::InvalidArgument,
                std::string(field) + " has " + std::to_string(got) + " values but there are " + std::to_string(points) +
                    " points (one per point required)",
                {.field = field});
}

// Scratch of interpolate_cubic and parameterise, one per thread: no allocation once warm.
struct Scratch {
  std::vector<double> a, b, c, turn, chord;
  BasisWorkspace basis;
};
Scratch& scratch() {
  thread_local Scratch s;
  return s;
}

// Given parameters: finite, strictly increasing, mapped affinely to [0, 1] into t (u.size() values).
void map_given_parameters(std::span<const double> u, std::size_t points, double* t) {
  check_same_count(u.size(), points, "parameters");
  for (std::size_t i = 0; i < u.size(); ++i) {
    if (!std::isfinite(u[i]))
      throw Error(Errc::NonFiniteInput, indexed("parameters", i) + " = " + format_number(u[i]) + " is not finite",
                  {.field = "parameters", .index = i});
    if (i > 0 && !(u[i] > u[i - 1]))
      throw Error(Errc::InvalidArgument,
                  indexed("parameters", i) + " = " + format_number(u[i]) + " is not greater than " +
                      indexed("parameters", i - 1) + " = " + format_number(u[i - 1]) +
                      " (parameters must be strictly increasing)",
                  {.field = "parameters", .index = i});
  }
  const std::size_t last = u.size() - 1;
  // Halve before subtracting when the range overflows (|u| near DBL_MAX).
  const bool halve = !std::isfinite(u[last] - u[0]);
  const double a = halve ? 0.5 * u[0] : u[0];
  const double range = halve ? 0.5 * u[last] - a : u[last] - a;
  t[0] = 0.0;
  for (std::size_t i = 1; i < last; ++i) t[i] = ((halve ? 0.5 * u[i] : u[i]) - a) / range;
  t[last] = 1.0;
  for (std::size_t i = 1; i <= last; ++i)
    if (!(t[i] > t[i - 1]))
      throw Error(Errc::InvalidArgument,
                  indexed("parameters", i) + " = " + format_number(u[i]) + " and " + indexed("parameters", i - 1) +
                      " = " + format_number(u[i - 1]) + " coincide after mapping to [0, 1]",
                  {.field = "parameters", .index = i});
}

std::vector<double> map_given_parameters(std::span<const double> u, std::size_t points) {
  check_same_count(u.size(), points, "parameters");
  std::vector<double> t(u.size());
  map_given_parameters(u, points, t.data());
  return t;
}

// Data parameters of N ≥ 2 points already checked finite (check_vectors, which gave their box) by `rule`
// into t (N values): parameterise without its argument checks.
void parameterise_checked(std::span<const Vec3> points, Parameterisation rule, const Tolerance& tolerance,
                          const Box3& box, double* t);

// Data parameters from the given values, or from the rule (points already checked, their box), into t.
void data_parameters(std::span<const Vec3> points, std::span<const double> given, Parameterisation rule,
                     const Tolerance& tolerance, const Box3& box, double* t) {
  if (!given.empty()) return map_given_parameters(given, points.size(), t);
  parameterise_checked(points, rule, tolerance, box, t);
}

std::vector<double> data_parameters(std::span<const Vec3> points, std::span<const double> given, Parameterisation rule,
                                    const Tolerance& tolerance) {
  if (!given.empty()) return map_given_parameters(given, points.size());
  return parameterise(points, rule, tolerance);
}

// Derivative at node t[at] of the Lagrange polynomial through (t[j], q[j]),
// j = 0 … count-1 (distinct nodes). Written with the differences q_j - q_at
// (Σ_j l_j' = 0), so a far-away origin costs no accuracy:
//   L'(t_a) = Σ_{j≠a} (q_j - q_a) Π_{m≠j,a} (t_a - t_m) / Π_{m≠j} (t_j - t_m).
Vec3 lagrange_derivative_at_node(const Vec3* q, const double* t, std::size_t count, std::size_t at) {
  Vec3 d{};
  for (std::size_t j = 0; j < count; ++j) {
    if (j == at) continue;
    double num = 1.0;
    double den = 1.0;
    for (std::size_t m = 0; m < count; ++m) {
      if (m == j) continue;
      den *= t[j] - t[m];
      if (m != at) num *= t[at] - t[m];
    }
    d += (num / den) * (q[j] - q[at]);
  }
  return d;
}

// Dense Gaussian elimination with partial pivoting, A (n × n, row-major) X = B (n × 3).
bool dense_solve(std::vector<double>& A, std::vector<Vec3>& B, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k) {
    std::size_t piv = k;
    for (std::size_t i = k + 1; i < n; ++i)
      if (std::fabs(A[i * n + k]) > std::fabs(A[piv * n + k])) piv = i;
    if (!(std::fabs(A[piv * n + k]) > 0.0)) return false;
    if (piv != k) {
      for (std::size_t j = 0; j < n; ++j) std::swap(A[k * n + j], A[piv * n + j]);
      std::swap(B[k], B[piv]);
    }
    for (std::size_t i = k + 1; i < n; ++i) {
      const double f = A[i * n + k] / A[k * n + k];
      if (f == 0.0) continue;
      for (std::size_t j = k; j < n; ++j) A[i * n + j] -= f * A[k * n + j];
      B[i] -= f * B[k];
    }
  }
  for (std::size_t k = n; k-- > 0;) {
    Vec3 s = B[k];
    for (std::size_t j = k + 1; j < n; ++j) s -= A[k * n + j] * B[j];
    B[k] = s / A[k * n + k];
  }
  return true;
}

// Resolved end condition: what the row of the banded system imposes.
struct EndRow {
  enum class Kind { SecondDerivativeZero, FirstDerivative, ThirdDerivativeJump };
  Kind kind;
  Vec3 derivative{};
};

// Turns an EndCondition into a row kind, falling back for small N (documented
// in interpolate.hpp and docs): Bessel uses the Lagrange polynomial of degree
// min(2, N-1) through the end points, Occt of degree min(3, N-1); not-a-knot
// with N = 2 (no interior knot) becomes Bessel (the chord), and with N = 3 at
// both ends (a single interior knot) both ends become Bessel (the parabola).
EndRow resolve_end(const EndCondition& ec, bool at_start, bool both_not_a_knot, std::span<const Vec3> q,
                   std::span<const double> t) {
  const std::size_t N = q.size();
  auto lagrange_end = [&](std::size_t degree) {
    const std::size_t count = std::min(degree, N - 1) + 1;
    const std::size_t first = at_start ? 0 : N - count;
    const std::size_t at = at_start ? 0 : count - 1;
    return EndRow{EndRow::Kind::FirstDerivative, lagrange_derivative_at_node(&q[first], &t[first], count, at)};
  };
  switch (ec.kind) {
    case EndCondition::Kind::Natural:
      return {EndRow::Kind::SecondDerivativeZero, {}};
    case EndCondition::Kind::Clamped:
      return {EndRow::Kind::FirstDerivative, ec.derivative};
    case EndCondition::Kind::Bessel:
      return lagrange_end(2);
    case EndCondition::Kind::Occt:
      return lagrange_end(3);
    case EndCondition::Kind::Direction: {
      double m = norm(lagrange_end(2).derivative);
      if (!(m > 0.0)) {
        const std::size_t i = at_start ? 0 : N - 2;
        m = distance(q[i], q[i + 1]) / (t[i + 1] - t[i]);
      }
      return {EndRow::Kind::FirstDerivative, (m / norm(ec.derivative)) * ec.derivative};
    }
    case EndCondition::Kind::NotAKnot:
      if (N == 2 || (N == 3 && both_not_a_knot)) return lagrange_end(2);
      return {EndRow::Kind::ThirdDerivativeJump, {}};
  }
  throw InternalError("unknown end condition kind");
}

// Coefficients of an end row of the clamped cubic on U = {0,0,0,0, t_1 … t_{N−2}, 1,1,1,1} (N points): of
// the end control point, its neighbour and the next one, for C'(end) or C''(end) (The NURBS Book eq. 3.7
// applied twice): at t = 0 with h1 = U[4], h2 = U[5], C' = 3 (P1 − P0) / h1 and
// C'' = 6 / h1 ((P2 − P1) / h2 − (P1 − P0) / h1); at t = 1 the mirror image with h1 = 1 − U[N + 1],
// h2 = 1 − U[N] and the last three control points.
std::array<double, 3> end_coefficients(const KnotVector& kv, std::size_t N, EndRow::Kind kind, bool at_start) {
  const double h1 = at_start ? kv[4] : 1.0 - kv[N + 1];
  const double h2 = at_start ? kv[5] : 1.0 - kv[N];
  if (kind == EndRow::Kind::FirstDerivative) {
    const double g = 3.0 / h1;
    return at_start ? std::array<double, 3>{-g, g, 0.0} : std::array<double, 3>{g, -g, 0.0};
  }
  return {6.0 / (h1 * h1), -6.0 / h1 * (1.0 / h1 + 1.0 / h2), 6.0 / (h1 * h2)};
}

// The cubic system in compact storage for N ≥ 4: interpolation rows 1 … N-2
// are tridiagonal (three cubic basis functions are non-zero at a simple
// knot), a[i], b[i], c[i] at columns i-1, i, i+1; only the two end rows reach
// further (a not-a-knot row spans four unknowns): first[j] is column j,
// last[j] is column N-4+j. The right-hand side is overwritten by the solution.
struct CubicSystem {
  std::size_t n;
  std::vector<double>&a, &b, &c;  // the thread's scratch (no allocation once warm)
  double* rhs;                    // 3 × n values, row-major (the caller's storage: the control points)
  std::array<double, 4> first{}, last{};
  // `zero`: clear the rows (assembly by add()); else the caller writes every entry.
  CubicSystem(std::size_t size, double* rhs_storage, Scratch& w, bool zero = true)
      : n(size), a(w.a), b(w.b), c(w.c), rhs(rhs_storage) {
    for (std::vector<double>* v : {&a, &b, &c}) {
      if (zero) v->clear();
      resize_advised(*v, size);
    }
    if (!zero) return;
    std::fill(rhs, rhs + 3 * size, 0.0);
  }
  void add(std::size_t i, std::size_t j, double v) {
    if (i == 0) {
      first[j] += v;
    } else if (i + 1 == n) {
      last[j + 4 - n] += v;
    } else {
      HULA_ASSERT(j + 1 >= i && j <= i + 1, "interpolation row outside the tridiagonal band");
      (j + 1 == i ? a[i] : (j == i ? b[i] : c[i])) += v;
    }
  }
};

// Removes column `col` from an end row (coefficients `row`, column of row[0]
// is `base`) with tridiagonal row k, which holds columns k-1 … k+1.
inline void eliminate_with(CubicSystem& s, std::array<double, 4>& row, std::size_t base, std::size_t k, std::size_t col,
                           std::size_t rhs_row) {
  const double v = row[col - base];
  if (v == 0.0) return;
  const double pivot = col + 1 == k ? s.a[k] : (col == k ? s.b[k] : s.c[k]);
  const double f = v / pivot;
  row[k - 1 - base] -= f * s.a[k];
  row[k - base] -= f * s.b[k];
  row[k + 1 - base] -= f * s.c[k];
  row[col - base] = 0.0;
  for (std::size_t d = 0; d < 3; ++d) s.rhs[rhs_row * 3 + d] -= f * s.rhs[k * 3 + d];
}

// Solves in place (solution in s.rhs). Each end row is reduced to two
// entries with its two tridiagonal neighbours, then the Thomas algorithm runs
// without pivoting: the collocation matrix is totally positive (de Boor), so
// this is stable, and a pivot below 1e-13 of its row scale returns false so
// the caller can use the pivoting band solver instead.
bool solve_cubic_system(CubicSystem& s) {
  const std::size_t N = s.n;
  constexpr double kPivot = 1e-13;
  double scale0 = 0.0, scale_last = 0.0;
  for (std::size_t j = 0; j < 4; ++j) scale0 = std::max(scale0, std::fabs(s.first[j]));
  for (std::size_t j = 0; j < 4; ++j) scale_last = std::max(scale_last, std::fabs(s.last[j]));
  // Start row: clear column 3 with row 2, then column 2 with row 1 (N ≥ 4 keeps them interior).
  eliminate_with(s, s.first, 0, 2, 3, 0);
  eliminate_with(s, s.first, 0, 1, 2, 0);
  // End row: clear column N-4 with row N-3, then column N-3 with row N-2.
  eliminate_with(s, s.last, N - 4, N - 3, N - 4, N - 1);
  eliminate_with(s, s.last, N - 4, N - 2, N - 3, N - 1);
  s.b[0] = s.first[0];
  s.c[0] = s.first[1];
  s.a[N - 1] = s.last[2];
  s.b[N - 1] = s.last[3];
  s.c[N - 1] = 0.0;
  // Thomas forward sweep; b and rhs become the eliminated diagonal and right-hand side.
  double* d = s.rhs;
  // b[i] is replaced by its reciprocal once it is known: one division per row.
  if (!(std::fabs(s.b[0]) > kPivot * scale0)) return false;
  s.b[0] = 1.0 / s.b[0];
  // The previous row's reciprocal pivot, super-diagonal and right-hand side stay in registers (locals):
  // reloading them from the arrays just written put a store-to-load forward on the critical path.
  double* const binv = s.b.data();
  const double* const a = s.a.data();
  const double* const c = s.c.data();
  double binv_prev = binv[0], c_prev = c[0];
  double d_prev[3] = {d[0], d[1], d[2]};
  for (std::size_t i = 1; i < N; ++i) {
    const double ai = a[i], bi = binv[i], ci = c[i];
    const double row_scale = i + 1 == N ? scale_last : std::max({std::fabs(ai), std::fabs(bi), std::fabs(ci)});
    const double m = ai * binv_prev;
    const double pivot = bi - m * c_prev;
    if (!(std::fabs(pivot) > kPivot * row_scale)) return false;
    binv_prev = 1.0 / pivot;
    binv[i] = binv_prev;
    for (std::size_t k = 0; k < 3; ++k) {
      d_prev[k] = d[i * 3 + k] - m * d_prev[k];
      d[i * 3 + k] = d_prev[k];
    }
    c_prev = ci;
  }
  double x_next[3];
  for (std::size_t k = 0; k < 3; ++k) {
    x_next[k] = d[(N - 1) * 3 + k] * binv[N - 1];
    d[(N - 1) * 3 + k] = x_next[k];
  }
  for (std::size_t i = N - 1; i-- > 0;) {
    const double ci = c[i], bi = binv[i];
    for (std::size_t k = 0; k < 3; ++k) {
      x_next[k] = (d[i * 3 + k] - ci * x_next[k]) * bi;
      d[i * 3 + k] = x_next[k];
    }
  }
  return true;
}

// Adapts BandedMatrix (kl = ku = 3) to the assembly interface of CubicSystem.
struct BandSystem {
  BandedMatrix matrix;
  std::vector<double> storage;
  double* rhs;
  explicit BandSystem(std::size_t n) : matrix(n, 3, 3), storage(3 * n, 0.0), rhs(storage.data()) {}
  void add(std::size_t i, std::size_t j, double v) { matrix.at(i, j) += v; }
};

NurbsCurve make_curve(KnotVector knots, std::vector<Vec3> control_points, int dimension) {
  if (dimension == 2)
    for (Vec3& p : control_points) p.z = 0.0;
  return NurbsCurve(std::move(knots), std::move(control_points), {}, dimension);
}

}  // namespace

void InterpolationOptions::validate() const {
  detail::check_dimension_option(dimension);
  detail::check_parameterisation_option(parameterisation);
  tolerance.validate();
  const std::array<std::pair<const EndCondition*, const char*>, 2> ends{{{&start, "start"}, {&end, "end"}}};
  for (const auto& [ec, name] : ends) {
    const auto k = static_cast<int>(ec->kind);
    if (k < 0 || k > static_cast<int>(EndCondition::Kind::Direction))
      throw Error(Errc::InvalidOption,
                  std::string(name) + ".kind = " + std::to_string(k) + " is not an EndCondition::Kind value",
                  {.field = std::string(name) + ".kind"});
    if (ec->kind != EndCondition::Kind::Clamped && ec->kind != EndCondition::Kind::Direction) continue;
    for (std::size_t c = 0; c < 3; ++c)
      if (!std::isfinite(ec->derivative[c]))
        throw Error(Errc::InvalidOption,
                    std::string(name) + ".derivative[" + std::to_string(c) + "] = " + format_number(ec->derivative[c]) +
                        " is not finite",
                    {.field = std::string(name) + ".derivative", .component = c});
    // A direction is scaled by 1/|d|: it must have a length (and one that does not overflow).
    if (ec->kind == EndCondition::Kind::Direction &&
        !(norm(ec->derivative) > 0.0 && std::isfinite(norm(ec->derivative))))
      throw Error(Errc::InvalidOption, std::string(name) + ".derivative is a zero direction (it needs a length)",
                  {.field = std::string(name) + ".derivative"});
    if (dimension == 2 && ec->derivative.z != 0.0)
      throw Error(Errc::InvalidOption,
                  std::string(name) + ".derivative has z = " + format_number(ec->derivative.z) +
                      " but dimension = 2 (z must be 0)",
                  {.field = std::string(name) + ".derivative", .component = 2});
  }
}

std::vector<double> cumulative_chord_lengths(std::span<const Vec3> points) {
  check_vectors(points, 3, "points");
  std::vector<double> L(points.size(), 0.0);
  for (std::size_t i = 1; i < points.size(); ++i) L[i] = L[i - 1] + distance(points[i - 1], points[i]);
  return L;
}

std::vector<double> parameterise(std::span<const Vec3> points, Parameterisation rule, const Tolerance& tolerance) {
  tolerance.validate();
  check_count(points.size(), 2, "parameterise");
  Box3 box;
  check_vectors(points, 3, "points", &box);
  std::vector<double> t(points.size());
  parameterise_checked(points, rule, tolerance, box, t.data());
  return t;
}

namespace {

void parameterise_checked(std::span<const Vec3> points, Parameterisation rule, const Tolerance& tolerance,
                          const Box3& box, double* t) {
  const std::size_t N = points.size();
  t[0] = 0.0;
  if (rule == Parameterisation::Uniform) {
    for (std::size_t i = 1; i + 1 < N; ++i) t[i] = static_cast<double>(i) / static_cast<double>(N - 1);
    t[N - 1] = 1.0;
    return;
  }
  if (rule != Parameterisation::ChordLength && rule != Parameterisation::Centripetal && rule != Parameterisation::Foley)
    throw Error(Errc::InvalidArgument,
                "parameterisation = " + std::to_string(static_cast<int>(rule)) + " is not a Parameterisation value",
                {.field = "parameterisation"});
  const double resolution = resolution_for_size(tolerance, box.diagonal());
  double sum = 0.0;  // t[i − 1], kept in a register (not reloaded from t)
  for (std::size_t i = 1; i < N; ++i) {
    const double d = distance(points[i - 1], points[i]);
    if (!(d > resolution))
      throw Error(Errc::CoincidentPoints,
                  indexed("points", i - 1) + " and " + indexed("points", i) + " coincide (distance " +
                      format_number(d) + " <= resolution " + format_number(resolution) + ")",
                  {.field = "points", .index = i});
    sum += rule == Parameterisation::Centripetal ? std::sqrt(d) : d;
    t[i] = sum;
  }
  if (rule == Parameterisation::Foley) {
    // Foley–Nielson: span i (Q_i to Q_i+1, chord d_i) is
    //   d_i (1 + 3/2 θ_i d_i-1 / (d_i-1 + d_i) + 3/2 θ_i+1 d_i+1 / (d_i + d_i+1)),
    // θ_j = min(π − angle(Q_j-1 − Q_j, Q_j+1 − Q_j), π/2) the turning angle at Q_j, capped at π/2;
    // the terms at the ends (no d_-1, no d_N-1) are absent. t holds the cumulative chords here.
    Scratch& w = scratch();
    std::vector<double>& turn = w.turn;
    turn.assign(N, 0.0);
    for (std::size_t j = 1; j + 1 < N; ++j) {
      const Vec3 a = points[j - 1] - points[j], b = points[j + 1] - points[j];
      const double interior = std::atan2(norm(cross(a, b)), dot(a, b));
      turn[j] = std::min(std::numbers::pi - interior, std::numbers::pi / 2);
    }
    std::vector<double>& chord = w.chord;
    chord.resize(N - 1);
    for (std::size_t i = 0; i + 1 < N; ++i) chord[i] = t[i + 1] - t[i];
    for (std::size_t i = 0; i + 1 < N; ++i) {
      double span = chord[i];
      if (i > 0) span += 1.5 * turn[i] * chord[i - 1] * chord[i] / (chord[i - 1] + chord[i]);
      if (i + 2 < N) span += 1.5 * turn[i + 1] * chord[i + 1] * chord[i] / (chord[i] + chord[i + 1]);
      t[i + 1] = t[i] + span;
    }
  }
  // Scaled by the reciprocal, as SplineProfileSampler does (the divisions were a tenth of a
  // 10-point interpolation); each parameter moves by at most one ulp against t_i / total.
  const double inv_total = 1.0 / t[N - 1];
  for (std::size_t i = 1; i + 1 < N; ++i) t[i] *= inv_total;
  t[N - 1] = 1.0;
  for (std::size_t i = 1; i < N; ++i)
    if (!(t[i] > t[i - 1]))
      throw Error(Errc::CoincidentPoints,
                  indexed("points", i - 1) + " and " + indexed("points", i) +
                      " are too close to get distinct parameters relative to the total length",
                  {.field = "points", .index = i});
}

}  // namespace

NurbsCurve interpolate_cubic(std::span<const Vec3> points, const InterpolationOptions& options) {
  options.validate();
  check_count(points.size(), 2, "interpolate_cubic");
  Box3 box;
  check_vectors(points, options.dimension, "points", &box);
  const std::size_t N = points.size();
  Scratch& work = scratch();
  // U = {0,0,0,0, t_1 … t_{N-2}, 1,1,1,1}: U[i + 3] = t_i, the data parameters written in place. Strictly
  // increasing parameters make it a valid knot vector by construction (no second validation pass).
  std::vector<double> U;
  resize_advised(U, N + 6);
  U[0] = U[1] = U[2] = 0.0;
  data_parameters(points, options.parameters, options.parameterisation, options.tolerance, box, U.data() + 3);
  U[N + 3] = U[N + 4] = U[N + 5] = 1.0;
  KnotVector kv = detail::CurveAccess::knots(std::move(U), kCubic);
  const std::span<const double> t = kv.values().subspan(3, N);

  const bool both_nak =
      options.start.kind == EndCondition::Kind::NotAKnot && options.end.kind == EndCondition::Kind::NotAKnot;
  const EndRow start = resolve_end(options.start, true, both_nak, points, t);
  const EndRow end = resolve_end(options.end, false, both_nak, points, t);

  // Unknown column j holds P_{j+1}; P_0 = Q_0 and P_{N+1} = Q_{N-1} go to the right-hand side.
  const Vec3 P0 = points.front();
  const Vec3 Pn = points.back();
  // Assembles the N rows into any system with add(row, column, value) and rhs.
  auto assemble = [&](auto& A) {
    double* rhs = A.rhs;
    const std::size_t last_ctrl = N + 1;
    auto add = [&](std::size_t row, std::size_t ctrl, double a) {
      if (a == 0.0) return;
      const Vec3* known = ctrl == 0 ? &P0 : (ctrl == last_ctrl ? &Pn : nullptr);
      if (known != nullptr) {
        for (std::size_t c = 0; c < 3; ++c) rhs[row * 3 + c] -= a * (*known)[c];
      } else {
        A.add(row, ctrl - 1, a);
      }
    };
    auto set_rhs = [&](std::size_t row, const Vec3& v) {
      for (std::size_t c = 0; c < 3; ++c) rhs[row * 3 + c] += v[c];
    };

    BasisWorkspace& basis = work.basis;
    // End row: `span` is the end span, `inner` the not-a-knot knot's index in U.
    auto end_row = [&](std::size_t row, const EndRow& er, double at, std::size_t span, std::size_t left_span) {
      switch (er.kind) {
        case EndRow::Kind::FirstDerivative:
        case EndRow::Kind::SecondDerivativeZero: {
          const bool at_start = at == 0.0;
          const std::array<double, 3> d = end_coefficients(kv, N, er.kind, at_start);
          const std::size_t end_ctrl = at_start ? 0 : N + 1;
          for (std::size_t j = 0; j < 3; ++j) add(row, at_start ? end_ctrl + j : end_ctrl - j, d[j]);
          if (er.kind == EndRow::Kind::FirstDerivative) set_rhs(row, er.derivative);
          (void)span;
          break;
        }
        case EndRow::Kind::ThirdDerivativeJump: {
          // C'''(u⁻) - C'''(u⁺) = 0 at u = U[left_span + 1]; pieces on spans left_span and left_span + 1.
          const double u = kv[left_span + 1];
          std::array<double, 4> left{};
          const auto dl = basis_derivatives(kv, left_span, u, 3, basis);
          for (std::size_t j = 0; j <= kCubic; ++j) left[j] = dl[12 + j];
          for (std::size_t j = 0; j <= kCubic; ++j) add(row, left_span - kCubic + j, left[j]);
          const auto dr = basis_derivatives(kv, left_span + 1, u, 3, basis);
          for (std::size_t j = 0; j <= kCubic; ++j) add(row, left_span + 1 - kCubic + j, -dr[12 + j]);
          break;
        }
      }
    };
    // Start: span 3 = [0, t_1); the not-a-knot knot t_1 = U[4] joins spans 3 and 4.
    end_row(0, start, 0.0, kCubic, kCubic);
    // Interpolation rows: C(t_i) = Q_i at the simple knot u = t_i = U[k], k = i + 3, where the three
    // non-zero cubic basis functions have the closed form (de Boor's recurrence at a knot)
    //   N_{k−3}(u) = (U[k+1] − u)² / ((U[k+1] − U[k−2]) (U[k+1] − U[k−1])),
    //   N_{k−1}(u) = (u − U[k−1])² / ((U[k+2] − U[k−1]) (U[k+1] − U[k−1])),
    //   N_{k−2}(u) = 1 − N_{k−3}(u) − N_{k−1}(u)   (partition of unity).
    const std::span<const double> K = kv.values();
    for (std::size_t i = 1; i + 1 < N; ++i) {
      const std::size_t k = i + kCubic;
      const double u = K[k], right = K[k + 1] - u, left = u - K[k - 1], gap = K[k + 1] - K[k - 1];
      const double n0 = right * right / ((K[k + 1] - K[k - 2]) * gap);
      const double n2 = left * left / ((K[k + 2] - K[k - 1]) * gap);
      add(i, k - 3, n0);
      add(i, k - 2, 1.0 - n0 - n2);
      add(i, k - 1, n2);
      set_rhs(i, points[i]);
    }
    // End: span N + 1 = [t_{N-2}, 1]; the not-a-knot knot t_{N-2} = U[N + 1] joins spans N and N + 1.
    end_row(N - 1, end, 1.0, N + 1, N);
  };
  // The unknowns P_1 … P_N are solved in place inside the control point array.
  static_assert(sizeof(Vec3) == 3 * sizeof(double), "Vec3 must be three packed doubles");
  std::vector<Vec3> P;
  resize_advised(P, N + 2);
  double* unknowns = &P[1].x;
  bool solved = false;
  if (N >= 4 && start.kind != EndRow::Kind::ThirdDerivativeJump && end.kind != EndRow::Kind::ThirdDerivativeJump) {
    // First- or second-derivative ends: every row is tridiagonal, assembled in place.
    CubicSystem fast(N, unknowns, work, false);
    double* rhs = fast.rhs;
    const std::array<double, 3> d0 = end_coefficients(kv, N, start.kind, true);
    fast.first[0] = d0[1];
    fast.first[1] = d0[2];
    const std::array<double, 3> d1 = end_coefficients(kv, N, end.kind, false);
    fast.last[3] = d1[1];
    fast.last[2] = d1[2];
    const Vec3 r0 = (start.kind == EndRow::Kind::FirstDerivative ? start.derivative : Vec3{}) - d0[0] * P0;
    const Vec3 r1 = (end.kind == EndRow::Kind::FirstDerivative ? end.derivative : Vec3{}) - d1[0] * Pn;
    for (std::size_t c = 0; c < 3; ++c) {
      rhs[c] = r0[c];
      rhs[3 * (N - 1) + c] = r1[c];
    }
    // Interpolation rows C(t_i) = Q_i at the simple knot u = t_i = U[k], k = i + 3: the three non-zero
    // cubic basis functions in closed form (de Boor's recurrence at a knot)
    //   N_{k−3}(u) = (U[k+1] − u)² / ((U[k+1] − U[k−2]) (U[k+1] − U[k−1])),
    //   N_{k−1}(u) = (u − U[k−1])² / ((U[k+2] − U[k−1]) (U[k+1] − U[k−1])),
    //   N_{k−2}(u) = 1 − N_{k−3}(u) − N_{k−1}(u)   (partition of unity),
    // on the unknowns P_i, P_{i+1}, P_{i+2} (columns i − 1, i, i + 1).
    const double* K = kv.values().data();
    for (std::size_t i = 1; i + 1 < N; ++i) {
      const std::size_t k = i + kCubic;
      const double u = K[k], right = K[k + 1] - u, left = u - K[k - 1], gap = K[k + 1] - K[k - 1];
      const double n0 = right * right / ((K[k + 1] - K[k - 2]) * gap);
      const double n2 = left * left / ((K[k + 2] - K[k - 1]) * gap);
      fast.a[i] = n0;
      fast.b[i] = 1.0 - n0 - n2;
      fast.c[i] = n2;
      for (std::size_t c = 0; c < 3; ++c) rhs[3 * i + c] = points[i][c];
    }
    solved = solve_cubic_system(fast);
  } else if (N >= 4) {
    CubicSystem fast(N, unknowns, work);
    assemble(fast);
    solved = solve_cubic_system(fast);
  }
  if (!solved) {
    // Small N, or a pivot too small for elimination without interchanges.
    BandSystem band(N);
    assemble(band);
    if (!band.matrix.solve(band.storage, 3))
      throw Error(Errc::NumericalFailure,
                  "the cubic interpolation system for " + std::to_string(N) +
                      " points is singular to working precision (check the end conditions and parameters)",
                  {.field = "points"});
    std::copy(band.storage.begin(), band.storage.end(), unknowns);
  }
  P[0] = P0;
  P[N + 1] = Pn;
  if (options.dimension == 2)
    for (Vec3& p : P) p.z = 0.0;
  // The points were checked finite; the solution is checked here, once, for what NurbsCurve requires,
  // in the pass that finds the control box: first without branches ((x − x) is NaN for a non-finite x),
  // then, only for a bad solution, point by point to name the culprit.
  Box3 control_box;
  double probe = 0.0;
  for (const Vec3& p : P) {
    probe += (p.x - p.x) + (p.y - p.y) + (p.z - p.z);
    control_box.add(p);
  }
  if (probe == 0.0 && control_box.extent() <= kMaxCoordinate)
    return detail::CurveAccess::curve(std::move(kv), std::move(P), options.dimension, control_box);
  for (std::size_t j = 0; j < P.size(); ++j) {
    if (!is_finite(P[j]))
      throw Error(Errc::NumericalFailure,
                  "control point " + std::to_string(j) + " of the interpolant overflowed (scale of the data too large)",
                  {.field = "points"});
    for (std::size_t c = 0; c < 3; ++c)
      if (std::fabs(P[j][c]) > kMaxCoordinate)
        throw Error(Errc::ScaleOutOfRange,
                    "control_points[" + std::to_string(j) + "][" + std::to_string(c) + "] = " + format_number(P[j][c]) +
                        " exceeds the largest supported coordinate magnitude 1e300; rescale the model",
                    {.field = "control_points", .index = j, .component = c});
  }
  HULA_ASSERT(false, "control points failed the probe but passed the check");
  return detail::CurveAccess::curve(std::move(kv), std::move(P), options.dimension, control_box);
}

NurbsCurve interpolate_lagrange(std::span<const Vec3> points, std::span<const double> parameters, int dimension) {
  check_dimension_argument(dimension);
  check_count(points.size(), 2, "interpolate_lagrange");
  const std::size_t N = points.size();
  if (N - 1 > static_cast<std::size_t>(kMaxDegree))
    throw Error(Errc::InvalidDegree,
                std::to_string(N) + " points need degree " + std::to_string(N - 1) +
                    " > kMaxDegree = " + std::to_string(kMaxDegree),
                {.field = "points"});
  check_vectors(points, dimension, "points");
  const std::vector<double> t = data_parameters(points, parameters, Parameterisation::Uniform, Tolerance{});
  // Bernstein collocation: Σ_j B_{j,n}(t_i) P_j = Q_i; rows 0 and n are unit rows (t = 0, 1).
  const int n = static_cast<int>(N) - 1;
  std::vector<double> A(N * N);
  for (std::size_t i = 0; i < N; ++i) bernstein_all(n, t[i], std::span<double>(A).subspan(i * N, N));
  std::vector<Vec3> P(points.begin(), points.end());
  if (!dense_solve(A, P, N))
    throw Error(Errc::NumericalFailure, "the Lagrange collocation system is singular", {.field = "parameters"});
  P.front() = points.front();
  P.back() = points.back();
  std::vector<double> U(N, 0.0);
  U.insert(U.end(), N, 1.0);
  return make_curve(KnotVector(std::move(U), n), std::move(P), dimension);
}

NurbsCurve hermite_cubic(std::span<const Vec3> points, std::span<const Vec3> derivatives,
                         std::span<const double> parameters, int dimension) {
  check_dimension_argument(dimension);
  check_count(points.size(), 2, "hermite_cubic");
  check_vectors(points, dimension, "points");
  check_same_count(derivatives.size(), points.size(), "derivatives");
  check_vectors(derivatives, dimension, "derivatives");
  const std::size_t N = points.size();
  const std::vector<double> t = data_parameters(points, parameters, Parameterisation::ChordLength, Tolerance{});
  // U = {0^4, t_1^2, …, t_{N-2}^2, 1^4}; control points by blossoming:
  //   segment i (h = t_{i+1} - t_i) has Bézier points Q_i, Q_i + h/3 D_i, Q_{i+1} - h/3 D_{i+1}, Q_{i+1};
  //   P = Q_0, then the two inner Bézier points of every segment, then Q_{N-1} (2N points).
  std::vector<double> U(4, 0.0);
  std::vector<Vec3> P;
  P.reserve(2 * N);
  P.push_back(points[0]);
  for (std::size_t i = 0; i + 1 < N; ++i) {
    const double h = t[i + 1] - t[i];
    P.push_back(points[i] + (h / 3.0) * derivatives[i]);
    P.push_back(points[i + 1] - (h / 3.0) * derivatives[i + 1]);
    if (i + 2 < N) U.insert(U.end(), 2, t[i + 1]);
  }
  P.push_back(points[N - 1]);
  U.insert(U.end(), 4, 1.0);
  return make_curve(KnotVector(std::move(U), kCubic), std::move(P), dimension);
}

NurbsCurve hermite_quintic(std::span<const Vec3> points, std::span<const Vec3> derivatives,
                           std::span<const Vec3> second_derivatives, std::span<const double> parameters,
                           int dimension) {
  check_dimension_argument(dimension);
  check_count(points.size(), 2, "hermite_quintic");
  check_vectors(points, dimension, "points");
  check_same_count(derivatives.size(), points.size(), "derivatives");
  check_vectors(derivatives, dimension, "derivatives");
  check_same_count(second_derivatives.size(), points.size(), "second_derivatives");
  check_vectors(second_derivatives, dimension, "second_derivatives");
  const std::size_t N = points.size();
  const std::vector<double> t = data_parameters(points, parameters, Parameterisation::ChordLength, Tolerance{});
  // Quintic Bézier points of segment i (h = t_{i+1} - t_i), from C', C'' at both ends:
  //   B0 = Q_i, B1 = Q_i + h/5 D_i, B2 = Q_i + 2h/5 D_i + h²/20 S_i,
  //   B3 = Q_{i+1} - 2h/5 D_{i+1} + h²/20 S_{i+1}, B4 = Q_{i+1} - h/5 D_{i+1}, B5 = Q_{i+1}.
  // U = {0^6, t_1^3, …, t_{N-2}^3, 1^6}. Blossoms: P = B0, B1, B2, B3 of segment 0; for each
  // interior t_i the mixed point f_i(t_{i-1}, t_i³, t_{i+1}) = B1 - (h_{i-1}/h_i)(B2 - B1) of
  // segment i, then B2, B3 of segment i; finally B4, B5 of the last segment (3N points).
  auto bezier = [&](std::size_t i) {
    const double h = t[i + 1] - t[i];
    const double h2 = h * h / 20.0;
    return std::array<Vec3, 6>{points[i],
                               points[i] + (h / 5.0) * derivatives[i],
                               points[i] + (2.0 * h / 5.0) * derivatives[i] + h2 * second_derivatives[i],
                               points[i + 1] - (2.0 * h / 5.0) * derivatives[i + 1] + h2 * second_derivatives[i + 1],
                               points[i + 1] - (h / 5.0) * derivatives[i + 1],
                               points[i + 1]};
  };
  std::vector<double> U(6, 0.0);
  std::vector<Vec3> P;
  P.reserve(3 * N);
  std::array<Vec3, 6> B = bezier(0);
  P.insert(P.end(), B.begin(), B.begin() + 4);
  for (std::size_t i = 1; i + 1 < N; ++i) {
    B = bezier(i);
    const double ratio = (t[i] - t[i - 1]) / (t[i + 1] - t[i]);
    P.push_back(B[1] - ratio * (B[2] - B[1]));
    P.push_back(B[2]);
    P.push_back(B[3]);
    U.insert(U.end(), 3, t[i]);
  }
  P.push_back(B[4]);
  P.push_back(B[5]);
  U.insert(U.end(), 6, 1.0);
  return make_curve(KnotVector(std::move(U), kQuintic), std::move(P), dimension);
}

NurbsCurve interpolate_closed_cubic(std::span<const Vec3> points, const InterpolationOptions& options) {
  options.validate();
  Box3 box;
  check_vectors(points, options.dimension, "points", &box);
  // The closed point list: Q_0 … Q_{N−1} then Q_0 again (a given repeat of Q_0 at the end is dropped).
  std::vector<Vec3> q(points.begin(), points.end());
  if (q.size() >= 2 && distance(q.front(), q.back()) <= resolution_for_size(options.tolerance, box.diagonal()))
    q.pop_back();
  if (q.size() < 3)
    throw Error(Errc::TooFewPoints, "a closed spline needs at least 3 distinct points, got " + std::to_string(q.size()),
                {.field = "points"});
  const std::size_t N = q.size();
  q.push_back(q.front());
  const std::vector<double> t = data_parameters(q, options.parameters, options.parameterisation, options.tolerance);

  // Cyclic tridiagonal system for the derivatives D_0 … D_{N−1} (row i: a_i D_{i−1} + b_i D_i + c_i D_{i+1}).
  std::vector<double> a(N), b(N), c(N);
  std::vector<Vec3> r(N);
  for (std::size_t i = 0; i < N; ++i) {
    const std::size_t prev = (i + N - 1) % N;
    const double hp = t[prev + 1] - t[prev];  // h_{i−1}, the closing chord's for i = 0
    const double hi = t[i + 1] - t[i];
    a[i] = hi;
    b[i] = 2.0 * (hp + hi);
    c[i] = hp;
    r[i] = 3.0 * ((hi / hp) * (q[i] - q[prev]) + (hp / hi) * (q[i + 1] - q[i]));
  }
  // Sherman–Morrison (Numerical Recipes 2.7 "cyclic"): the corners alpha = a_0 (D_{N−1} in row 0) and
  // beta = c_{N−1} (D_0 in the last row) moved into a rank-one correction of a tridiagonal matrix T.
  const double gamma = -b[0];
  const double corner_top = a[0];
  const double corner_bottom = c[N - 1];
  std::vector<double> diag(N);
  for (std::size_t i = 0; i < N; ++i) diag[i] = b[i];
  diag[0] = b[0] - gamma;
  diag[N - 1] = b[N - 1] - corner_bottom * corner_top / gamma;
  // Thomas algorithm for T x = rhs (sub-diagonal a_i, i ≥ 1; super-diagonal c_i, i ≤ N − 2); T is diagonally
  // dominant, so no pivoting is needed.
  std::vector<double> cp(N);
  auto thomas = [&](auto rhs) {
    using V = typename decltype(rhs)::value_type;
    std::vector<V> x(N);
    double m = diag[0];
    x[0] = rhs[0] / m;
    for (std::size_t i = 1; i < N; ++i) {
      cp[i - 1] = c[i - 1] / m;
      m = diag[i] - a[i] * cp[i - 1];
      x[i] = (rhs[i] - a[i] * x[i - 1]) / m;
    }
    for (std::size_t i = N - 1; i-- > 0;) x[i] = x[i] - cp[i] * x[i + 1];
    return x;
  };
  std::vector<Vec3> D = thomas(r);
  std::vector<double> u(N, 0.0);
  u[0] = gamma;
  u[N - 1] = corner_bottom;
  const std::vector<double> z = thomas(u);
  const double denom = 1.0 + z[0] + corner_top * z[N - 1] / gamma;
  const Vec3 fact = (D[0] + (corner_top / gamma) * D[N - 1]) / denom;
  for (std::size_t i = 0; i < N; ++i) D[i] = D[i] - z[i] * fact;
  D.push_back(D.front());

  NurbsCurve curve = hermite_cubic(q, D, t, options.dimension);
  // hermite_cubic doubles each interior knot; the C2 data make the second copy removable exactly.
  std::vector<double> interior;
  for (double k : curve.knots().values())
    if (k > 0.0 && k < 1.0 && (interior.empty() || interior.back() != k)) interior.push_back(k);
  for (double k : interior) curve = remove_knot(curve, k, 1, 0.0).curve;
  return curve;
}

NurbsCurve hermite_septic(std::span<const Vec3> points, std::span<const Vec3> derivatives,
                          std::span<const Vec3> second_derivatives, std::span<const Vec3> third_derivatives,
                          std::span<const double> parameters, int dimension) {
  check_dimension_argument(dimension);
  check_count(points.size(), 2, "hermite_septic");
  check_vectors(points, dimension, "points");
  check_same_count(derivatives.size(), points.size(), "derivatives");
  check_vectors(derivatives, dimension, "derivatives");
  check_same_count(second_derivatives.size(), points.size(), "second_derivatives");
  check_vectors(second_derivatives, dimension, "second_derivatives");
  check_same_count(third_derivatives.size(), points.size(), "third_derivatives");
  check_vectors(third_derivatives, dimension, "third_derivatives");
  const std::size_t N = points.size();
  const std::vector<double> t = data_parameters(points, parameters, Parameterisation::ChordLength, Tolerance{});
  constexpr int kSeptic = 7;
  std::optional<NurbsCurve> joined;
  for (std::size_t i = 0; i + 1 < N; ++i) {
    const double h = t[i + 1] - t[i];
    // Bézier derivatives at an end: C' = 7/h ΔB, C'' = 42/h² Δ²B, C''' = 210/h³ Δ³B (mirrored at the end,
    // where the odd orders change sign).
    std::vector<Vec3> B(8);
    B[0] = points[i];
    B[1] = B[0] + (h / 7.0) * derivatives[i];
    B[2] = 2.0 * B[1] - B[0] + (h * h / 42.0) * second_derivatives[i];
    B[3] = 3.0 * B[2] - 3.0 * B[1] + B[0] + (h * h * h / 210.0) * third_derivatives[i];
    B[7] = points[i + 1];
    B[6] = B[7] - (h / 7.0) * derivatives[i + 1];
    B[5] = 2.0 * B[6] - B[7] + (h * h / 42.0) * second_derivatives[i + 1];
    B[4] = 3.0 * B[5] - 3.0 * B[6] + B[7] - (h * h * h / 210.0) * third_derivatives[i + 1];
    std::vector<double> U(8, t[i]);
    U.insert(U.end(), 8, t[i + 1]);
    NurbsCurve piece = make_curve(KnotVector(std::move(U), kSeptic), std::move(B), dimension);
    joined = joined ? join(*joined, piece, 0.0) : piece;
  }
  // The pieces meet C3 by construction: three of the seven copies of each joint come out (to rounding).
  NurbsCurve c = *joined;
  for (std::size_t i = 1; i + 1 < N; ++i) c = remove_knot(c, c.knots().values()[8 + 4 * (i - 1)], 3, 0.0).curve;
  return c;
}

NurbsCurve hermite_frenet(std::span<const FrenetHandle> handles, std::span<const double> parameters, int dimension) {
  check_dimension_argument(dimension);
  check_count(handles.size(), 2, "hermite_frenet");
  const std::size_t N = handles.size();
  std::vector<Vec3> P(N), D1(N), D2(N), D3(N);
  for (std::size_t i = 0; i < N; ++i) {
    const FrenetHandle& h = handles[i];
    auto finite = [&](const Vec3& v, const char* field) {
      if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z)))
        throw Error(Errc::NonFiniteInput, std::string(field) + "[" + std::to_string(i) + "] is not finite",
                    {.field = field, .index = i});
    };
    finite(h.point, "point");
    finite(h.tangent, "tangent");
    finite(h.normal, "normal");
    finite({h.curvature, h.torsion, 0.0}, "curvature");
    const double v = norm(h.tangent);
    if (!(v > 0.0))
      throw Error(Errc::InvalidArgument, "tangent[" + std::to_string(i) + "] is zero: a handle needs a direction",
                  {.field = "tangent", .index = i});
    if (h.curvature < 0.0)
      throw Error(Errc::InvalidArgument,
                  "curvature[" + std::to_string(i) + "] = " + format_number(h.curvature) +
                      " must be >= 0 (the normal gives its direction)",
                  {.field = "curvature", .index = i});
    const Vec3 T = h.tangent / v;
    P[i] = h.point;
    D1[i] = h.tangent;
    if (h.curvature == 0.0) continue;  // C'' = C''' = 0: a flat point
    const Vec3 n = h.normal - dot(h.normal, T) * T;
    if (!(norm(n) > 1e-12 * std::max(1.0, norm(h.normal))))
      throw Error(Errc::InvalidArgument,
                  "normal[" + std::to_string(i) + "] is zero or parallel to the tangent: the curvature needs a normal",
                  {.field = "normal", .index = i});
    const Vec3 Nn = n / norm(n);
    const Vec3 Bn = cross(T, Nn);
    const double k = h.curvature;
    D2[i] = (v * v * k) * Nn;
    D3[i] = (v * v * v) * (-k * k * T + (k * h.torsion) * Bn);
  }
  return hermite_septic(P, D1, D2, D3, parameters, dimension);
}

}  // namespace hula::nurbs
