// SPDX-License-Identifier: MIT
// The Flexo optimisation problem (thesis 2.2, 10.1, appendix 2 "Individual"):
// design variables with bounds (and, for binary coding, a precision), one or
// more objectives to minimise, inequality constraints g(x) <= 0 and equality
// constraints h(x) = 0, and a batch evaluation entry point that runs the
// user's function over many points on oneTBB. Results do not depend on the
// thread count: every point is written to its own row and failures are
// reported by the lowest failing index.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

namespace hula::optim {

/// One design variable.
struct Variable {
  /// Name used in logs and error messages; may be empty ("x<i>" is used then).
  std::string name{};
  /// Lower bound, finite. Default 0.
  double lower = 0.0;
  /// Upper bound, finite, >= lower. Default 1.
  double upper = 1.0;
  /// Resolution required of the binary coding, in the variable's units: the
  /// number of bits is the smallest b with (upper - lower) / (2^b - 1) <=
  /// precision (appendix 2 "bits per variable"). 0 = not binary-coded (the
  /// binary GA then refuses the problem). Must be >= 0 and need at most 52 bits.
  double precision = 0.0;
};

/// The user's evaluation: reads the variables (size = dimension()) and writes
/// values (size = values_per_point()): the objectives, then the inequality
/// constraints g_i (feasible when g_i <= 0), then the equality constraints
/// h_j (feasible when |h_j| <= equality_tolerance). It may be called
/// concurrently from several threads, so it must not mutate shared state. It
/// may throw or return NaN: the point is then counted as a failed evaluation.
using EvaluateFn = std::function<void(std::span<const double> variables, std::span<double> values)>;

/// A whole-batch evaluation, for callers whose objective is vectorised over
/// points (a NumPy function in the Python binding): reads n points (row-major
/// n x dimension()) and writes their values (row-major n x values_per_point()).
/// It is called on the caller's thread, once per batch. A non-finite value
/// marks its point failed, as with EvaluateFn; an exception cannot be blamed
/// on one point, so it propagates and ends the run.
using BatchEvaluateFn = std::function<void(std::span<const double> points, std::span<double> values)>;

/// A minimisation problem.
struct Problem {
  /// Name for reports ("zdt1", "sphere-10"...). Default empty.
  std::string name{};
  /// Design variables, at least one.
  std::vector<Variable> variables{};
  /// Number of objectives, >= 1. All are minimised.
  std::size_t objectives = 1;
  /// Number of inequality constraints g(x) <= 0. Default 0.
  std::size_t inequality_constraints = 0;
  /// Number of equality constraints h(x) = 0. Default 0.
  std::size_t equality_constraints = 0;
  /// Tolerance on |h(x)| below which an equality constraint counts as met.
  /// Default 1e-6; must be finite and >= 0.
  double equality_tolerance = 1e-6;
  /// The evaluation function; this or evaluate_many must be set.
  EvaluateFn evaluate{};
  /// Optional batch evaluation; when set, evaluate_batch uses it instead of
  /// evaluate (which may then be empty).
  BatchEvaluateFn evaluate_many{};

  /// Number of design variables.
  [[nodiscard]] std::size_t dimension() const noexcept { return variables.size(); }
  /// Values written per point: objectives + inequality + equality constraints.
  [[nodiscard]] std::size_t values_per_point() const noexcept {
    return objectives + inequality_constraints + equality_constraints;
  }
  /// Checks the problem before any work.
  /// @throws hula::Error(Errc::InvalidOption) if there are no variables, a
  ///   bound is not finite, lower > upper ("variables[i].lower = ... > upper = ..."),
  ///   precision is negative, NaN or would need more than 52 bits, objectives
  ///   is 0, equality_tolerance is negative or not finite, or both evaluate and
  ///   evaluate_many are empty.
  void validate() const;
  /// Total constraint violation of one point's values: sum of max(0, g_i) plus
  /// sum of max(0, |h_j| - equality_tolerance). 0 means feasible.
  /// @param values values_per_point() numbers as written by evaluate.
  /// @returns the violation, NaN if a constraint value is NaN.
  [[nodiscard]] double violation(std::span<const double> values) const noexcept;
};

/// Number of bits the binary coding gives a variable (appendix 2).
/// @param variable a variable with precision > 0.
/// @param index its position in Problem::variables, used in error messages.
/// @returns the smallest b >= 1 with (upper - lower) / (2^b - 1) <= precision
///   (1 when lower == upper).
/// @throws hula::Error(Errc::InvalidOption) if precision <= 0 or more than 52
///   bits would be needed (the message names the variable and its precision).
[[nodiscard]] std::size_t bits_for(const Variable& variable, std::size_t index);

/// Options of evaluate_batch.
struct BatchOptions {
  /// Worker threads: 1 = serial on the caller's thread (default), 0 = all
  /// cores. The results never depend on this value.
  std::size_t threads = 1;
  /// When true, an exception thrown by an evaluation is rethrown after the
  /// whole batch ran (the one of the lowest index). When false (default) it
  /// is caught and the point is marked failed, as a GA needs.
  bool rethrow = false;
};

/// Summary of a batch evaluation.
struct BatchReport {
  /// Points whose evaluation threw or returned a non-finite objective or
  /// constraint value.
  std::size_t failed = 0;
  /// Lowest failing index, or SIZE_MAX when none failed.
  std::size_t first_failed = static_cast<std::size_t>(-1);
  /// What the first failure was: the exception's what() or "non-finite value".
  std::string first_message{};
};

/// Evaluates many points, possibly in parallel (hula::parallel_for).
/// @param problem a validated problem.
/// @param points n points, row-major n x dimension().
/// @param values output, row-major n x values_per_point(); failed rows hold NaN.
/// @param failed output, n flags, 1 for a failed point.
/// @returns the number of failures and the lowest failing index.
/// @throws hula::Error(Errc::InvalidArgument) if the spans' sizes disagree.
/// @throws whatever the evaluation of the lowest failing index threw, if options.rethrow.
/// @throws whatever problem.evaluate_many threw, when it is set.
/// Complexity: n evaluations; no allocation besides the evaluation's own.
BatchReport evaluate_batch(const Problem& problem, std::span<const double> points, std::span<double> values,
                           std::span<std::uint8_t> failed, const BatchOptions& options = {});

/// A variable that ended on (or within a tolerance of) one of its bounds (results that sit on a bound
/// are warned about, the thesis's cue to widen or re-centre the bounds, 7.4.1 / 8.2.1).
struct BoundHit {
  /// Index in Problem::variables.
  std::size_t variable = 0;
  /// True for the upper bound, false for the lower.
  bool upper = false;
  /// The variable's value.
  double value = 0.0;
};

/// The variables of x within `fraction` x (upper − lower) of a bound (zero-width variables are fixed, not reported).
/// @param variables the variables and bounds; @param x one value per variable
/// @param fraction relative tolerance, in [0, 0.5). Default 1e-6 (a GA's binary coding or a bounded solver lands
///   exactly on the bound; a designer reads 1e-6 of the box as "on it").
/// @throws hula::Error(Errc::InvalidArgument) if x has the wrong size or fraction is outside [0, 0.5)
[[nodiscard]] std::vector<BoundHit> bound_hits(std::span<const Variable> variables, std::span<const double> x,
                                               double fraction = 1e-6);

/// "points[3].x = 50 is on its upper bound 50": one warning line per hit.
[[nodiscard]] std::vector<std::string> bound_warnings(std::span<const Variable> variables,
                                                      std::span<const BoundHit> hits);

}  // namespace hula::optim
