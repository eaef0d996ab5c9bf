// SPDX-License-Identifier: MIT
// NurbsCurve: an immutable, validated non-uniform rational B-spline curve of
// any degree ≥ 1, rational or not, planar (2-D, z = 0) or spatial (thesis 5.5,
// The NURBS Book ch. 2–4). An invalid curve cannot be constructed; evaluators
// rely on the invariants.
//
// Evaluation goes through a per-span polynomial cache (built once, lazily and
// thread-safely, on first use): each non-empty span stores the Taylor
// coefficients of the homogeneous curve at the span's midpoint in the local
// variable x = (t - mid) / half ∈ [-1, 1], so position and derivatives cost a
// Horner scheme, and rational derivatives follow from the quotient rule
// (The NURBS Book eq. 4.8 / A4.2). Degrees above kCachedDegreeLimit, where the
// monomial form loses accuracy, use de Boor–Cox (A2.3) directly.
#pragma once

#include <cstddef>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/nurbs/knot_vector.hpp"

namespace hula::nurbs {

/// What to do with a parameter outside the curve's domain [t0, t1].
enum class Domain {
  Strict,       ///< refuse it: hula::Error(Errc::OutOfDomain) naming the parameter (default)
  Clamp,        ///< evaluate at the nearest domain end
  Extrapolate,  ///< continue the end span's polynomial (or rational) piece
};

/// Options shared by every evaluator.
struct EvalOptions {
  /// One-sided limit taken at a knot (matters where the curve is not C^k there). Default Right.
  Side side = Side::Right;
  /// Handling of parameters outside the domain. Default Strict.
  Domain domain = Domain::Strict;
};

/// Largest coordinate magnitude accepted in control points. Beyond it the
/// derivatives of a curve on a unit domain overflow double precision.
inline constexpr double kMaxCoordinate = 1e300;

/// Degree above which evaluation bypasses the monomial span cache.
inline constexpr int kCachedDegreeLimit = 9;

namespace detail {
struct CurveAccess;  // detail/curve_access.hpp: construction from data valid by construction
}  // namespace detail
class PieceEvaluator;  // piece_evaluator.hpp: evaluation without the per-span cache

/// A NURBS curve C(t) = Σ N_{i,p}(t) w_i P_i / Σ N_{i,p}(t) w_i, t ∈ [U[p], U[n+1]].
///
/// Copying is cheap (the data are shared and immutable). Thread-safe for
/// concurrent const use.
class NurbsCurve {
 public:
  /// Builds and validates a curve.
  /// @param degree p ≥ 1 and < number of control points
  /// @param knots full knot vector with n + p + 2 values (see KnotVector)
  /// @param control_points n + 1 points in model units
  /// @param weights empty for a non-rational curve, else n + 1 positive finite weights
  /// @param dimension 2 (planar; every z must be 0) or 3
  /// @throws hula::Error(Errc::InvalidDegree) if degree < 1 or degree ≥ number of control points
  /// @throws hula::Error(Errc::InvalidKnots) if the knot count is not n + p + 2 or the knots are invalid
  /// @throws hula::Error(Errc::NonFiniteInput) naming the point/knot/weight index that is NaN or infinite
  /// @throws hula::Error(Errc::InvalidWeight) if a weight is ≤ 0 (names the index), or the weight count is wrong
  /// @throws hula::Error(Errc::ScaleOutOfRange) if a coordinate exceeds kMaxCoordinate in magnitude
  /// @throws hula::Error(Errc::InvalidArgument) if dimension is not 2 or 3, or a 2-D curve has z ≠ 0
  NurbsCurve(int degree, std::vector<double> knots, std::vector<Vec3> control_points, std::vector<double> weights = {},
             int dimension = 3);
  /// As above with an already validated knot vector.
  NurbsCurve(KnotVector knots, std::vector<Vec3> control_points, std::vector<double> weights = {}, int dimension = 3);

  [[nodiscard]] int degree() const noexcept;
  [[nodiscard]] const KnotVector& knots() const noexcept;
  [[nodiscard]] std::span<const Vec3> control_points() const noexcept;
  /// Weights, empty when the curve is not rational.
  [[nodiscard]] std::span<const double> weights() const noexcept;
  [[nodiscard]] bool is_rational() const noexcept;
  /// 2 for a planar curve (all z = 0, written as [x, y]), else 3.
  [[nodiscard]] int dimension() const noexcept;
  [[nodiscard]] Interval domain() const noexcept;
  /// Box of the control points (contains the curve; convex hull property).
  [[nodiscard]] Box3 control_box() const noexcept;
  /// Model size: the diagonal of control_box(), used for relative tolerances.
  [[nodiscard]] double model_size() const noexcept;

  /// Position C(t).
  /// @throws hula::Error(Errc::OutOfDomain) if t is outside the domain under Domain::Strict
  /// @throws hula::Error(Errc::NonFiniteInput) if t is NaN or infinite
  [[nodiscard]] Vec3 evaluate(double t, const EvalOptions& options = {}) const;
  /// {C(t), C'(t), …, C^(order)(t)}: order + 1 vectors (derivatives with respect to t).
  /// @throws as evaluate, and hula::Error(Errc::InvalidArgument) if order < 0,
  ///   hula::Error(Errc::NumericalFailure) if a derivative overflows
  [[nodiscard]] std::vector<Vec3> derivatives(double t, int order, const EvalOptions& options = {}) const;
  /// Allocation-free form: `out` receives order + 1 vectors.
  void derivatives(double t, int order, std::span<Vec3> out, const EvalOptions& options = {}) const;

  /// Batch position: out[i] = C(ts[i]). Sorted ts are fastest (hinted span
  /// search); any order is accepted. No allocation per point.
  /// @throws as evaluate, naming the index of the first bad parameter
  void evaluate(std::span<const double> ts, std::span<Vec3> out, const EvalOptions& options = {}) const;
  /// Batch derivatives: out[i * (order + 1) + k] = C^(k)(ts[i]). No allocation per point.
  void derivatives(std::span<const double> ts, int order, std::span<Vec3> out, const EvalOptions& options = {}) const;

  /// Structural equality (same degree, knots, points, weights, dimension; exact).
  friend bool operator==(const NurbsCurve& a, const NurbsCurve& b);

 private:
  friend struct detail::CurveAccess;
  friend class PieceEvaluator;
  struct Data;
  explicit NurbsCurve(std::shared_ptr<const Data> data) noexcept : data_(std::move(data)) {}
  std::shared_ptr<const Data> data_;
};

}  // namespace hula::nurbs
