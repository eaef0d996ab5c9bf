// SPDX-License-Identifier: MIT
// Conversions between laws and NURBS curves (thesis 10.2.3 "Edge to Law" and
// "Law to Edge"). NURBS → law wraps the curve as a leaf whose derivatives come
// from the kernel (exact). Law → NURBS builds a C2 piecewise quintic Hermite
// (The NURBS Book 9.3-style; nurbs::hermite_quintic) from the law's exact
// position, first and second derivatives at breakpoints chosen adaptively:
// a segment is bisected until the quintic deviates from the law by less than
// half the tolerance at its check samples, so breakpoints crowd where the
// curve bends fastest (the Hermite error is ∝ h⁶ |C⁽⁶⁾|). The achieved
// maximum deviation is then measured independently by dense sampling of the
// finished NURBS against the compiled law.
#pragma once

#include <cstddef>
#include <string_view>

#include "hula/law/expr.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::law {

/// NURBS → law: the curve as a law of `parameter` (C(parameter) on the curve's domain, undefined
/// outside it). Derivatives of the law are the kernel's derivatives.
/// @param name curve name used by print()/parse(); empty = "curve<k>"
/// @throws as Context::curve
[[nodiscard]] Law from_nurbs(const nurbs::NurbsCurve& curve, const Context& context, std::string_view parameter = "t",
                             std::string_view name = {});

/// NURBS → law, written out: the curve as a printable law of `parameter` (no curve leaf), one rational polynomial
/// per knot span — its Bézier piece in the power basis of the span's local parameter s = (t − u_i)/(u_{i+1} − u_i),
/// in Horner form — the spans chosen by piecewise(t < u_i, …, …) in a balanced tree. On the domain it evaluates as
/// the curve to rounding (relative to the control points' size); outside it the end spans' polynomials continue.
/// print() of it parses back (law::parse) to the same values.
/// @throws as Context::parameter (a reserved name)
/// Example: the line from (0, 0) to (2, 0) on [0, 1] is vec(2*t, 0).
[[nodiscard]] Law explicit_from_nurbs(const nurbs::NurbsCurve& curve, const Context& context,
                                      std::string_view parameter = "t");

/// Options of to_nurbs().
struct ToNurbsOptions {
  /// Largest allowed distance |law(t) − curve(t)| in model units. Default 1e-6 (resabs); valid > 0.
  double tolerance = 1e-6;
  /// Uniform segments to start from. Default 4; valid 1 … max_segments.
  std::size_t initial_segments = 4;
  /// Check samples per segment during refinement. Default 16; valid ≥ 2.
  std::size_t check_samples = 16;
  /// Samples per segment of the final independent verification. Default 64; valid ≥ 2.
  std::size_t verify_samples = 64;
  /// Refinement stops with Errc::NumericalFailure beyond this many segments. Default 20000.
  std::size_t max_segments = 20000;
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// Result of to_nurbs().
struct ToNurbsResult {
  /// Quintic, C2, domain [a, b] (same parameterisation as the law).
  nurbs::NurbsCurve curve;
  /// max |law(t) − curve(t)| over verify_samples per segment (independent of the refinement checks).
  double max_deviation = 0.0;
  /// Number of control points of `curve`.
  std::size_t control_points = 0;
  /// Number of Hermite segments.
  std::size_t segments = 0;
};

/// Law → NURBS within a tolerance, with adaptive breakpoints.
/// @param law a 2- or 3-vector law of `parameter` only
/// @param a, b the parameter interval, a < b
/// @throws hula::Error(Errc::InvalidArgument) if the law is scalar or uses another parameter, or unless a < b
/// @throws hula::Error(Errc::NumericalFailure) naming the parameter where the law or its first two
///   derivatives are undefined, or if the tolerance is not reached within max_segments
/// @throws hula::Error(Errc::InvalidOption) if options are invalid
[[nodiscard]] ToNurbsResult to_nurbs(const Law& law, std::string_view parameter, double a, double b,
                                     const ToNurbsOptions& options = {});

}  // namespace hula::law
