// SPDX-License-Identifier: MIT
// Curve: the one curve value type of DESIGN.md ("NURBS or law, with its
// construction data"), which documents, codecs, studies and the command line
// hold instead of their own curve classes.
//
// A Curve is immutable and cheap to copy (a shared pointer to const state, as
// Manifold's value types). It holds
//  (a) how it was made — one of six kinds of construction data: a NURBS as
//      given, a Bézier control polygon, a cubic spline through points with its
//      end conditions, a piecewise Hermite curve, a vector law of one parameter
//      (thesis 4.3, 10.2.3), or natural equations κ(s), τ(s) (thesis 8.2.2);
//  (b) what it resolves to — nurbs(): exact for the first four kinds; for law
//      and natural curves a verified approximation whose measured deviation is
//      approximation_deviation(), for drawing and export. law() is the exact
//      law where one exists; a natural curve evaluates exactly through its
//      natural_evaluator(): κ, τ and their derivatives from the laws, position
//      and frame integrated to a stated tolerance (NaturalData::tolerance).
//      point(), derivatives(), the arc length and everything diffgeom computes
//      from a Curve use the exact form of both kinds, never the stand-in.
//
// Factories validate everything, so an invalid Curve cannot exist. Natural
// curves are built by intrinsic::natural_curve (the layer that integrates
// natural equations) and by nothing else.
//
// Laws and their Context: every law curve owns one private law::Context (made
// by Curve::from_law and shared only by copies of that Curve). A Context is
// not thread-safe and only grows (docs/architecture.md, "Who owns a
// law::Context"): the Curve's own evaluation helpers serialise the one-time
// compilation of their evaluators behind a mutex and then evaluate through
// immutable tapes, so they may be called from any thread; code that builds on
// law() (derivatives, composition) grows the curve's context and must do so
// from one thread at a time.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "hula/core/interval.hpp"
#include "hula/core/vec.hpp"
#include "hula/law/expr.hpp"
#include "hula/law/tape.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::curve {

/// Largest distance between a law or natural curve and the NURBS that stands in for it
/// (Curve::nurbs()) when the caller does not choose one, model units (resabs).
inline constexpr double kApproximationTolerance = 1e-6;

/// Position tolerance of the integration of a natural curve when its data do not state one
/// (NaturalData::tolerance), model units: the accuracy of point() and of the frame (frame errors are
/// of the order of tolerance / max(1, L)).
inline constexpr double kNaturalTolerance = 1e-10;

/// The six kinds of construction data.
enum class Kind {
  Nurbs,         ///< a NURBS as given (degree, knots, control points, weights)
  Bezier,        ///< a Bézier control polygon (degree = count − 1) with optional weights
  Interpolated,  ///< a global C2 cubic spline through points (nurbs::interpolate_cubic)
  Hermite,       ///< piecewise Hermite: cubic C1 from tangents, quintic C2 with second derivatives
  Law,           ///< a 2- or 3-vector law of one parameter on a domain
  Natural,       ///< curvature κ(s) and torsion τ(s) from a start point and frame (intrinsic)
};

/// The stable name of a kind: "nurbs", "bezier", "interpolated", "hermite", "law" or "natural".
[[nodiscard]] std::string_view kind_name(Kind kind) noexcept;

/// A NURBS as given.
struct NurbsData {
  nurbs::NurbsCurve curve;
};

/// A Bézier curve on [0, 1].
struct BezierData {
  /// n ≥ 2 control points (degree n − 1 ≤ nurbs::kMaxDegree), model units; z = 0 when dimension is 2.
  std::vector<Vec3> control_points;
  /// Empty (polynomial) or one positive finite weight per control point.
  std::vector<double> weights;
  /// 2 (planar, written as [x, y]) or 3.
  int dimension = 3;
};

/// A global C2 cubic spline through data points (thesis 7.1.2, 10.2.1).
struct InterpolatedData {
  /// N ≥ 2 data points in model units (z = 0 when dimension is 2).
  std::vector<Vec3> points;
  /// 2 (planar) or 3.
  int dimension = 3;
  /// Parameter rule used when `parameters` is empty. Default chord length.
  nurbs::Parameterisation parameterisation = nurbs::Parameterisation::ChordLength;
  /// Given data parameters (strictly increasing, one per point), or empty.
  std::vector<double> parameters;
  /// End conditions. Default natural.
  nurbs::EndCondition start = nurbs::EndCondition::natural();
  nurbs::EndCondition end = nurbs::EndCondition::natural();

  /// The options of nurbs::interpolate_cubic that these data describe.
  [[nodiscard]] nurbs::InterpolationOptions options() const;
};

/// A piecewise Hermite curve on [0, 1] (thesis 5.3.2, 7.5.2).
struct HermiteData {
  /// N ≥ 2 points, model units.
  std::vector<Vec3> points;
  /// N first derivatives dC/dt (t ∈ [0, 1]).
  std::vector<Vec3> tangents;
  /// Empty (cubic, C1) or N second derivatives d²C/dt² (quintic, C2).
  std::vector<Vec3> second_derivatives;
  /// Empty (chord length) or N strictly increasing parameters, mapped to [0, 1].
  std::vector<double> parameters;
  /// 2 (planar) or 3.
  int dimension = 3;
};

/// A vector law of one parameter (thesis 4.3).
struct LawData {
  /// The expression as written (grammar in docs/formats.md), e.g. "vec(cos(t), sin(t), t/4)".
  std::string expression;
  /// The parameter name. Default "t".
  std::string parameter = "t";
  /// The domain [start, end], start < end, both finite.
  Interval domain{};
  /// The parsed law (a 2- or 3-vector), in the curve's private context. Set by Curve::from_law.
  law::Law law{};
};

/// Natural equations: κ(s) and τ(s) on [0, length] from a start point and frame (thesis 8.2.2).
struct NaturalData {
  /// Curvature κ as an expression of `parameter` (signed for planar curves).
  std::string curvature;
  /// Torsion τ as an expression of `parameter`; "0" gives a planar curve. Default "0".
  std::string torsion = "0";
  /// The arc-length parameter name. Default "s".
  std::string parameter = "s";
  /// Length L > 0 (the domain is [0, L]).
  double length = 1.0;
  /// r(0), model units.
  Vec3 start_point{0.0, 0.0, 0.0};
  /// T(0): non-zero, normalised by the integrator.
  Vec3 start_tangent{1.0, 0.0, 0.0};
  /// N(0): not parallel to T(0); its tangential part is removed.
  Vec3 start_normal{0.0, 1.0, 0.0};
  /// Position tolerance of the integration, model units, in [1e-13, 1e-2]. Default kNaturalTolerance.
  double tolerance = kNaturalTolerance;
};

/// Construction data of any kind.
using Data = std::variant<NurbsData, BezierData, InterpolatedData, HermiteData, LawData, NaturalData>;

class Curve;

/// Exact evaluation of a natural curve, implemented by intrinsic::natural_curve (the layer that integrates
/// natural equations). The parameter is the arc length s ∈ [0, L]. With T, N, B the integrated frame (N the
/// signed normal, r'' = κN) and κ, τ exact from their laws,
///     r' = T,  r'' = κN,  r''' = κ'N + κ(τB − κT),  …
/// each derivative r^(k) = a_k T + b_k N + c_k B with a_(k+1) = a_k' − κ b_k, b_(k+1) = b_k' + κ a_k − τ c_k,
/// c_(k+1) = c_k' + τ b_k (Frenet–Serret), the coefficients' derivatives by Leibniz' rule from the exact
/// κ^(j), τ^(j). So the curvature, torsion and their derivatives that diffgeom computes from these vectors are
/// the laws' values to rounding, and only position and frame carry the integration's tolerance.
/// Immutable and thread-safe.
class NaturalEvaluator {
 public:
  virtual ~NaturalEvaluator() = default;
  /// Highest derivative order of derivatives().
  static constexpr int kMaxOrder = 16;
  /// out[i * (order + 1) + k] = r^(k)(s[i]) for k = 0 … order; every s[i] within [0, L] (the caller checks).
  /// @throws hula::Error(Errc::NumericalFailure) naming "curvature" or "torsion" where a law is undefined
  virtual void derivatives(std::span<const double> s, int order, std::span<Vec3> out) const = 0;
  /// The position tolerance the integration holds, model units.
  [[nodiscard]] virtual double tolerance() const noexcept = 0;
};

/// Permission to build a natural curve, held only by intrinsic::natural_curve (which verifies
/// the NURBS it fits): the natural kind cannot be made with an unchecked representation.
class NaturalKey;

}  // namespace hula::curve

namespace hula::intrinsic {
// Declared in hula/intrinsic/natural_curve.hpp; named here only to grant it NaturalKey.
curve::Curve natural_curve(const curve::NaturalData& data, double tolerance);
}  // namespace hula::intrinsic

namespace hula::curve {

class NaturalKey {
  NaturalKey() = default;
  friend Curve intrinsic::natural_curve(const curve::NaturalData& data, double tolerance);
};

/// The curve value type. Immutable; copies share state.
class Curve {
 public:
  /// A NURBS curve as it is (implicit: every NurbsCurve is a valid Curve of kind Nurbs).
  Curve(nurbs::NurbsCurve curve);  // NOLINT(google-explicit-constructor)

  /// A Bézier curve.
  /// @throws hula::Error(Errc::TooFewPoints) naming "control_points" for fewer than 2 points
  /// @throws hula::Error(Errc::InvalidDegree) naming "control_points" for more than kMaxDegree + 1
  /// @throws hula::Error from NurbsCurve (InvalidWeight, NonFiniteInput, ...) naming the member
  [[nodiscard]] static Curve bezier(BezierData data);
  /// The cubic spline through the data.
  /// @throws hula::Error from nurbs::interpolate_cubic (TooFewPoints, CoincidentPoints,
  ///   InvalidArgument naming "parameters", NonFiniteInput, InvalidOption, NumericalFailure)
  [[nodiscard]] static Curve interpolated(InterpolatedData data);
  /// The Hermite curve: quintic when second derivatives are given, else cubic.
  /// @throws hula::Error from nurbs::hermite_cubic / hermite_quintic, naming "tangents"
  ///   (the derivatives) or "second_derivatives" and the index
  [[nodiscard]] static Curve hermite(HermiteData data);
  /// A law curve: parses `expression` in a new private context and fits the stand-in NURBS
  /// within `tolerance` (law::to_nurbs, verified by dense sampling).
  /// @param expression a 2- or 3-vector law of `parameter` only
  /// @param parameter an identifier, default "t"
  /// @param domain start < end, both finite
  /// @param tolerance of the stand-in NURBS, model units, > 0
  /// @throws hula::Error(Errc::ParseError) with field "expression" (and line/column) for a bad
  ///   or scalar expression
  /// @throws hula::Error(Errc::InvalidArgument) with field "domain" for a bad domain or a law
  ///   undefined inside it (naming the parameter value)
  /// @throws hula::Error(Errc::NumericalFailure) if the tolerance cannot be met
  [[nodiscard]] static Curve from_law(std::string expression, std::string parameter, Interval domain,
                                      double tolerance = kApproximationTolerance);
  /// A natural curve from its exact evaluator and its verified fit; only intrinsic::natural_curve can call it.
  [[nodiscard]] static Curve natural(NaturalKey key, NaturalData data, std::shared_ptr<const NaturalEvaluator> exact,
                                     nurbs::NurbsCurve fit, double deviation);

  /// What kind of construction data the curve holds.
  [[nodiscard]] Kind kind() const noexcept;
  /// kind_name(kind()).
  [[nodiscard]] std::string_view kind_name() const noexcept;
  /// The construction data.
  [[nodiscard]] const Data& data() const noexcept;
  /// The NURBS: exact for nurbs, bezier, interpolated and hermite; for law and natural curves the
  /// verified approximation (deviation ≤ the tolerance it was built with).
  [[nodiscard]] const nurbs::NurbsCurve& nurbs() const noexcept;
  /// max |exact − nurbs()| measured by dense sampling: 0 for the exact kinds.
  [[nodiscard]] double approximation_deviation() const noexcept;
  /// The exact law (law kind), else nullptr. Its parameter is law_parameter().
  [[nodiscard]] const law::Law* law() const noexcept;
  /// The law's parameter name ("t" unless the data say otherwise); empty without a law.
  [[nodiscard]] const std::string& law_parameter() const noexcept;
  /// The exact evaluator of a natural curve (parameter = arc length), else nullptr.
  [[nodiscard]] const NaturalEvaluator* natural_evaluator() const noexcept;
  /// True when point() and derivatives() are exact rather than those of a stand-in: every kind but law and
  /// natural is its NURBS; law curves evaluate their law, natural curves their natural_evaluator().
  [[nodiscard]] bool has_exact_evaluation() const noexcept;
  /// The parameter domain: the law's domain, [0, L] for natural curves, else nurbs().domain().
  [[nodiscard]] Interval domain() const noexcept;
  /// 2 (planar, z = 0) or 3.
  [[nodiscard]] int dimension() const noexcept;

  /// C(t): from the law of a law curve, from the natural evaluator of a natural curve, else from nurbs().
  /// @throws hula::Error(Errc::OutOfDomain) naming "t" under Domain::Strict (the default), and for a natural
  ///   curve outside [0, L] under Domain::Extrapolate too (it is integrated on [0, L] only)
  [[nodiscard]] Vec3 point(double t, const nurbs::EvalOptions& options = {}) const;
  /// {C(t), C'(t), …, C^(order)(t)} (exact for laws and natural curves; orders 0 … 16 for both).
  /// @throws as point(), and hula::Error(Errc::InvalidArgument) for a bad order
  [[nodiscard]] std::vector<Vec3> derivatives(double t, int order, const nurbs::EvalOptions& options = {}) const;
  /// Batch form: out[i * (order + 1) + k] = C^(k)(ts[i]).
  /// @throws hula::Error(Errc::OutOfDomain) naming "t" and the index of the first parameter outside
  ///   the domain (Domain::Strict); hula::Error(Errc::InvalidArgument) if out has the wrong size
  void derivatives(std::span<const double> ts, int order, std::span<Vec3> out,
                   const nurbs::EvalOptions& options = {}) const;

  /// The exact law compiled with its derivatives up to `order` (0 … 16), made once per order and
  /// shared by copies of the curve; immutable and safe to evaluate from any thread. nullptr for
  /// curves without a law.
  /// @throws hula::Error(Errc::InvalidArgument) for an order outside [0, 16]
  [[nodiscard]] std::shared_ptr<const law::CurveEvaluator> law_evaluator(int order) const;

  /// Arc length from domain().start to t: ∫|C'| of the exact law (law::integrate) when there is
  /// one, t itself for a natural curve (its parameter is the arc length), else nurbs::arc_length of nurbs().
  /// @throws hula::Error(Errc::OutOfDomain) naming "t" outside the domain
  [[nodiscard]] double length_to(double t) const;
  /// Arc length of the whole curve.
  [[nodiscard]] double length() const;
  /// The parameter at arc length s from the start (inverse of length_to; for laws a Newton
  /// iteration safeguarded by bisection, converged to 1e-15 relative in t).
  /// @throws hula::Error(Errc::OutOfDomain) naming "s" outside [0, length()]
  [[nodiscard]] double parameter_at_length(double s) const;

  /// Same kind, same construction data (doubles compared bit for bit; laws by their text,
  /// parameter and domain) and the same nurbs().
  friend bool operator==(const Curve& a, const Curve& b);

  struct State;

 private:
  explicit Curve(std::shared_ptr<const State> state);
  std::shared_ptr<const State> state_;
};

}  // namespace hula::curve
