// SPDX-License-Identifier: MIT
// The kernel interface of the Oli document (thesis 9.1.2 "Top and bottom
// interface"): the document constructs and interrogates curves only through a
// Kernel, so the modeller underneath can be replaced and the application
// survives. Two backends implement it: "native" (HulaHoops' own nurbs and
// diffgeom modules) and "occt" (Open CASCADE: Geom_BSplineCurve,
// GeomAPI_Interpolate, GeomLProp_CLProps, GCPnts_AbscissaPoint). Both take and
// return the same immutable value type, nurbs::NurbsCurve, so a document can
// switch backends between two calls without converting what it holds.
//
// Both backends pass one conformance suite (tests/oli/kernel_conformance_test.cpp)
// to 1e-12 relative. Where a backend has no such operation it throws
// hula::Error(Errc::Unsupported) with where.field = the operation's name, and
// `with_fallback` answers from the native backend instead, saying so.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"
#include "hula/nurbs/reparam.hpp"

namespace hula::oli {

/// Inputs of Kernel::interpolate: the C2 cubic spline through points, on [0, 1].
struct KernelInterpolation {
  /// Data parameters, one per point, strictly increasing (mapped affinely to [0, 1]).
  /// Empty: chord length (thesis eq. 29), normalised to [0, 1].
  std::vector<double> parameters{};
  /// dC/dt at the first and last point with t ∈ [0, 1] (magnitude honoured). Give both or
  /// neither; neither: the end derivatives of the cubic through the 4 end points (the
  /// GeomAPI_Interpolate rule, nurbs::EndCondition::Kind::Occt).
  std::optional<Vec3> start_tangent{};
  std::optional<Vec3> end_tangent{};
};

/// Construction and interrogation of NURBS curves, implemented by a backend.
///
/// Every operation takes and returns values; a backend holds no state and is
/// safe for concurrent use. Derivatives are with respect to the curve's own
/// parameter, right-sided at knots (the curve's domain end takes the last span).
class Kernel {
 public:
  virtual ~Kernel() = default;

  /// The backend's registry name, "native" or "occt".
  [[nodiscard]] virtual std::string_view name() const noexcept = 0;

  /// Builds a curve from its construction data (see nurbs::NurbsCurve for the layout).
  /// @param degree p ≥ 1
  /// @param knots full knot vector, n + p + 2 values
  /// @param control_points n + 1 points in model units
  /// @param weights empty (polynomial) or n + 1 positive weights
  /// @param dimension 2 (all z = 0) or 3
  /// @throws hula::Error as the NurbsCurve constructor (InvalidDegree, InvalidKnots, InvalidWeight,
  ///   NonFiniteInput, ScaleOutOfRange, InvalidArgument), naming the input at fault
  /// @throws hula::Error(Errc::Unsupported) if the backend cannot represent the curve (e.g. OCCT's
  ///   degree limit of 25), naming the limit
  [[nodiscard]] virtual nurbs::NurbsCurve construct(int degree, std::vector<double> knots,
                                                    std::vector<Vec3> control_points, std::vector<double> weights,
                                                    int dimension) const = 0;

  /// Position C(t).
  /// @throws hula::Error(Errc::OutOfDomain) if t is outside the domain; NonFiniteInput if t is NaN
  [[nodiscard]] virtual Vec3 evaluate(const nurbs::NurbsCurve& curve, double t) const = 0;

  /// {C(t), C'(t), …, C^(order)(t)} for 0 ≤ order ≤ 3.
  /// @throws hula::Error(Errc::InvalidArgument) if order is not in [0, 3]; as evaluate otherwise
  [[nodiscard]] virtual std::vector<Vec3> derivatives(const nurbs::NurbsCurve& curve, double t, int order) const = 0;

  /// Inserts knot u `times` times (the curve is unchanged as a point set and parametrisation).
  /// @throws hula::Error(Errc::OutOfDomain) if u is outside the domain; NonFiniteInput if u is NaN;
  ///   InvalidArgument if times < 1; InvalidKnots if the multiplicity of u would exceed the degree
  [[nodiscard]] virtual nurbs::NurbsCurve insert_knot(const nurbs::NurbsCurve& curve, double u, int times) const = 0;

  /// Raises the degree by `times` ≥ 1 without changing the curve.
  /// @throws hula::Error(Errc::InvalidArgument) if times < 1; InvalidDegree past nurbs::kMaxDegree;
  ///   Unsupported past the backend's own degree limit (OCCT: 25)
  [[nodiscard]] virtual nurbs::NurbsCurve elevate_degree(const nurbs::NurbsCurve& curve, int times) const = 0;

  /// The curve on [a, t] and on [t, b], each clamped at t.
  /// @throws hula::Error(Errc::OutOfDomain) unless a < t < b; NonFiniteInput if t is NaN
  [[nodiscard]] virtual nurbs::SplitResult split(const nurbs::NurbsCurve& curve, double t) const = 0;

  /// The same point set traversed backwards on the same domain: R(t) = C(a + b − t).
  [[nodiscard]] virtual nurbs::NurbsCurve reverse(const nurbs::NurbsCurve& curve) const = 0;

  /// C2 cubic spline through N ≥ 2 points on [0, 1], C(t_i) = Q_i.
  /// @param points N ≥ 2 finite points (dimension 3 result)
  /// @throws hula::Error(Errc::TooFewPoints / CoincidentPoints / NonFiniteInput / InvalidArgument)
  ///   naming the point, parameter or tangent at fault
  [[nodiscard]] virtual nurbs::NurbsCurve interpolate(std::span<const Vec3> points,
                                                      const KernelInterpolation& options) const = 0;

  /// Curvature κ(t) = |C' × C''| / |C'|³ (1 / model units); NaN where the tangent is undefined
  /// (zero speed).
  /// @throws as evaluate
  [[nodiscard]] virtual double curvature(const nurbs::NurbsCurve& curve, double t) const = 0;

  /// Torsion τ(t) = (C' × C'') · C''' / |C' × C''|² (1 / model units); NaN where the Frenet frame
  /// is undefined (κ = 0 or zero speed).
  /// @throws hula::Error(Errc::Unsupported) with field "torsion" if the backend has no torsion
  [[nodiscard]] virtual double torsion(const nurbs::NurbsCurve& curve, double t) const = 0;

  /// Arc length ∫_a^b |C'(u)| du for a ≤ b inside the domain, to 1e-12 relative.
  /// @throws hula::Error(Errc::OutOfDomain) if a or b is outside the domain; InvalidArgument if a > b
  [[nodiscard]] virtual double arc_length(const nurbs::NurbsCurve& curve, double a, double b) const = 0;
};

/// The names of the backends built into this binary, "native" first ("occt" only when built with
/// Open CASCADE).
[[nodiscard]] std::vector<std::string> kernel_names();

/// The backend registered under `name`. Backends are stateless singletons; the pointer stays valid
/// for the life of the program.
/// @throws hula::Error(Errc::InvalidArgument) with field "backend" naming the unknown backend and
///   the known ones
[[nodiscard]] std::shared_ptr<const Kernel> make_kernel(std::string_view name);

/// The native backend (what with_fallback falls back to).
[[nodiscard]] const Kernel& native_kernel();

/// An answer from `with_fallback`: the value, the backend that computed it, and, when the asked
/// backend could not, a note saying so.
template <class T>
struct KernelAnswer {
  T value;                                ///< the result
  std::string backend;                    ///< name of the backend that computed it
  std::optional<std::string> fallback{};  ///< "torsion: not supported by the occt backend; computed by native"
};

/// Runs `operation(kernel)`; if the backend throws hula::Error(Errc::Unsupported), runs it on the
/// native backend instead and records why in `fallback`. Other errors propagate unchanged.
/// Example:
///   auto tau = with_fallback(*make_kernel("occt"), [&](const Kernel& k) { return k.torsion(c, t); });
///   // tau.backend == "native", *tau.fallback names the operation and "occt"
template <class Operation>
[[nodiscard]] auto with_fallback(const Kernel& kernel, Operation&& operation)
    -> KernelAnswer<std::invoke_result_t<Operation&, const Kernel&>> {
  try {
    return {std::invoke(operation, kernel), std::string(kernel.name()), std::nullopt};
  } catch (const Error& e) {
    if (e.code() != Errc::Unsupported || &kernel == &native_kernel()) throw;
    const Kernel& native = native_kernel();
    return {std::invoke(operation, native), std::string(native.name()),
            e.message() + "; computed by the " + std::string(native.name()) + " backend"};
  }
}

}  // namespace hula::oli
