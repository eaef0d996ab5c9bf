// SPDX-License-Identifier: MIT
// Where a law of one parameter is undefined or not smooth on an interval: the
// thesis's "singularities" of continuous law interrogation (10.2.4). Each
// node that can break definedness or smoothness contributes a condition law
// whose roots are the reported points (division by zero: roots of the
// denominator; abs kink: roots of the argument; piecewise switch: roots of
// lhs − rhs of its comparison; NURBS knot: roots of argument − knot; …), found
// with roots(); undefined regions come from sampling the compiled law and
// bisecting their ends.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hula/law/expr.hpp"
#include "hula/law/roots.hpp"

namespace hula::law {

/// What happens at a reported point.
enum class SingularityKind {
  DivisionByZero,    ///< denominator of '/' vanishes
  SqrtBoundary,      ///< sqrt argument crosses or touches 0 (undefined on the negative side, infinite slope)
  LogBoundary,       ///< log argument reaches 0
  PowerBase,         ///< base of a power with a non-integer or variable exponent reaches 0
  InverseTrigBound,  ///< asin/acos argument reaches ±1
  TanPole,           ///< tan argument at π/2 + kπ
  Atan2Origin,       ///< atan2(y, x) with x = y = 0
  NormalizeZero,     ///< normalize of a zero vector
  NormKink,          ///< norm of a vector through zero (not differentiable)
  AbsKink,           ///< abs argument changes sign
  SignJump,          ///< sign argument changes sign
  MinMaxSwitch,      ///< min/max arguments cross (kink)
  PiecewiseSwitch,   ///< piecewise condition changes (jump or kink)
  ComparisonJump,    ///< a comparison used as a value changes
  CurveKnot,         ///< argument of a NURBS leaf crosses an interior knot (reduced continuity)
  CurveDomainEnd,    ///< argument of a NURBS leaf leaves the curve's domain
};

/// Stable name of a kind, e.g. "DivisionByZero".
[[nodiscard]] const char* singularity_kind_name(SingularityKind kind);

/// One reported point.
struct Singularity {
  double t = 0.0;
  SingularityKind kind = SingularityKind::DivisionByZero;
  /// The subexpression responsible, printed (truncated to 120 characters).
  std::string expression;
};

/// A maximal sub-interval where the law is undefined (ends located by bisection to 1e-12 relative).
struct UndefinedInterval {
  double start = 0.0;
  double end = 0.0;
};

/// Result of singularities().
struct SingularityReport {
  /// Points in [a, b], increasing in t (one entry per point and kind).
  std::vector<Singularity> points;
  /// Where the law evaluates as undefined (NaN), from `samples` + 1 samples.
  std::vector<UndefinedInterval> undefined;
  /// True when nothing was found: the law is defined and smooth on [a, b] (at the sampling resolution).
  [[nodiscard]] bool smooth() const { return points.empty() && undefined.empty(); }
};

/// Options of singularities().
struct SingularityOptions {
  /// Root finding options for the condition laws.
  RootOptions roots{};
  /// Samples of the law over [a, b] for undefined intervals. Default 4096; valid ≥ 2.
  std::size_t samples = 4096;
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// Reports where the scalar or vector law f(parameter) is undefined or not smooth on [a, b].
/// Points inside a piecewise branch that is never selected may be listed too (conservative).
/// @throws hula::Error(Errc::InvalidArgument) if f depends on another parameter, or unless a < b, finite
/// @throws hula::Error(Errc::InvalidOption) if options are invalid
[[nodiscard]] SingularityReport singularities(const Law& f, std::string_view parameter, double a, double b,
                                              const SingularityOptions& options = {});

/// Why a law is undefined at one parameter value.
struct UndefinedCause {
  /// The innermost undefined subexpression, printed (truncated to 120 characters).
  std::string expression;
  /// What went wrong, e.g. "division by zero", "sqrt of a negative number".
  std::string reason;
};

/// Explains an undefined value: the innermost subexpression that is undefined at
/// parameter = t although its arguments are defined, and why.
/// @returns nullopt when the law is defined at t
/// @throws hula::Error(Errc::InvalidArgument) if the law uses another parameter
[[nodiscard]] std::optional<UndefinedCause> explain_undefined(const Law& f, std::string_view parameter, double t);

/// Why a law is not finite at one parameter value: undefined or overflowed.
struct NonFiniteCause {
  /// True when a subexpression overflowed (its value is ±inf although its arguments are finite);
  /// false when one is undefined (NaN, see explain_undefined). An overflow found under an
  /// undefined result (inf − inf) is reported as the overflow: it is the first thing that failed.
  bool overflow = false;
  /// The innermost failing subexpression, printed (truncated to 120 characters).
  std::string expression;
  /// "overflow (the value exceeds 1.8e308)" or the reason of explain_undefined.
  std::string reason;
};

/// Explains a non-finite value of f at parameter = t: descends from f through non-finite
/// arguments (the selected branch of a piecewise) to the innermost subexpression that is
/// non-finite although its arguments are finite.
/// @returns nullopt when every component of f is finite at t
/// @throws hula::Error(Errc::InvalidArgument) if the law uses another parameter
[[nodiscard]] std::optional<NonFiniteCause> explain_non_finite(const Law& f, std::string_view parameter, double t);

/// Relative parametric tolerance of nonsmooth_at(): t is on a kink when one Newton step of the
/// kink's condition law g from t is at most kKinkTolerance × max(1, |t|) long, i.e.
/// |g(t)| ≤ kKinkTolerance × max(1, |t|) × |g'(t)| (or g(t) = 0). 1e-14 covers the rounding of
/// g at a root given in decimal (sin(pi) = 1.2e-16) and no more.
inline constexpr double kKinkTolerance = 1e-14;

/// Where the derivative of a given order stops existing at one parameter value.
struct NonSmoothPoint {
  /// The lowest derivative order that is undefined at t (1 for a kink of f itself).
  int order = 1;
  SingularityKind kind = SingularityKind::AbsKink;
  /// The subexpression of f^(order − 1) responsible, printed (truncated to 120 characters).
  std::string expression;
  /// A sentence for people, e.g. "abs(t) has a kink (its argument changes sign)".
  std::string reason;
};

/// Whether the derivatives 1 … max_order of f exist at t, judged by the same conditions as
/// singularities(): f^(k) is reported undefined when f^(k−1) has, at t, a kink or jump of abs,
/// sign, min/max, a comparison, a piecewise switch, a norm through zero, or a NURBS leaf at a knot
/// where the leaf's derivative order reaches the curve's continuity there (degree − multiplicity).
/// Conservative: a piecewise join that happens to be smooth is still a join.
/// @returns the lowest failing order, or nullopt when every derivative up to max_order is smooth at t
/// @throws hula::Error(Errc::InvalidArgument) if max_order < 0 or the law uses another parameter
[[nodiscard]] std::optional<NonSmoothPoint> nonsmooth_at(const Law& f, std::string_view parameter, double t,
                                                         int max_order);

}  // namespace hula::law
