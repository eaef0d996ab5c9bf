// SPDX-License-Identifier: MIT
// Frenet frame, curvature, torsion, speed and dκ/ds of a curve from its first
// three parametric derivatives (thesis 6.1: eq. 5 for T, eq. 11 for κ, eq. 17
// for τ), never by normalising and differentiating again, which 6.1.4 warns
// loses accuracy. Also the signed curvature of planar curves with the
// non-flipping normal z × T (Nutbourne, thesis 6.3.1).
//
// Notation (thesis 6.1): r', r'', r''' are derivatives with respect to the
// parameter t; v = |r'| = ds/dt; a = r' × r''.
//   T = r'/v,  B = a/|a|,  N = B × T,
//   κ = |a| / v³,  τ = (a · r''') / |a|²,
//   dκ/dt = (a · a') / (|a| v³) − 3 |a| (r' · r'') / v⁵  with a' = r' × r''',
//   dκ/ds = (dκ/dt) / v.
//
// Undefined quantities are flagged and set to NaN (STYLE.md): the tests are
// scale-relative, so a curve at 1e-200 scale is judged like one at 1e0.
#pragma once
#include <cstdint>
#include <span>
#include <string_view>

#include "hula/core/tolerance.hpp"
#include "hula/core/vec.hpp"
#include "hula/curve/curve.hpp"
#include "hula/law/tape.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::diffgeom {

/// Why a quantity of a FrenetPoint is undefined.
enum class Undefined : std::uint8_t {
  None,           ///< everything is defined
  ZeroSpeed,      ///< |r'| is below the speed resolution (cusp or degenerate parametrisation): nothing but the position
  ZeroCurvature,  ///< r' × r'' is negligible (straight span or inflection): T, κ = 0 and speed defined; N, B, τ not
  NonFinite,      ///< a derivative is NaN or infinite (a law undefined at t): nothing is defined
};

/// The name of a reason: "none", "zero-speed", "zero-curvature", "non-finite".
[[nodiscard]] std::string_view undefined_name(Undefined reason) noexcept;

/// Options of the Frenet / curvature evaluators.
struct FrenetOptions {
  /// Resolutions. `resabs` (scaled by resolution_for_size with the model size) bounds the speed:
  /// |r'| ≤ resolution / (domain length) is a zero speed. `angular` bounds the curvature: the frame
  /// is undefined when |r' × r''| ≤ angular · |r'| · max(|r''|, |r'|² / model size), i.e. r'' is
  /// parallel to r' within `angular` radians or κ · model size ≤ angular. Default Tolerance{}.
  Tolerance tolerance{};
  /// Unit normal of the plane for the signed curvature (counter-clockwise seen from +plane_normal is
  /// positive). Default +Z, the plane of 2-D curves. Must be finite and non-zero (it is normalised).
  Vec3 plane_normal{0.0, 0.0, 1.0};
  /// Evaluation side and domain handling for NURBS curves. Default right-sided, strict domain.
  nurbs::EvalOptions eval{};
  /// Throws hula::Error(Errc::InvalidOption) naming the bad field.
  void validate() const;
};

/// The differential geometry of a curve at one parameter.
///
/// Undefined values are NaN (vectors with NaN components), never noise:
/// - `reason == ZeroSpeed`: only `t`, `position` and `speed` are meaningful; T, N, B, κ, τ, κ' are NaN.
/// - `reason == ZeroCurvature`: T, speed, κ = 0, signed curvature and the signed normal are defined;
///   N, B, τ and κ' are NaN (κ' is NaN because |a| is not differentiable where a = 0).
/// - `reason == NonFinite`: everything derived is NaN.
struct FrenetPoint {
  double t = 0.0;                      ///< the parameter
  Vec3 position{};                     ///< r(t)
  Vec3 tangent{};                      ///< unit tangent T = r'/|r'|
  Vec3 normal{};                       ///< principal normal N = B × T (points to the centre of curvature)
  Vec3 binormal{};                     ///< binormal B = (r' × r'')/|r' × r''|
  double speed = 0.0;                  ///< ds/dt = |r'| (model units per parameter unit)
  double curvature = 0.0;              ///< κ ≥ 0 (1 / model units)
  double torsion = 0.0;                ///< τ, positive for a right-handed helix (1 / model units)
  double curvature_derivative = 0.0;   ///< κ' = dκ/ds (1 / model units²)
  double signed_curvature = 0.0;       ///< κ_s = ((r' × r'') · n) / v³ about the plane normal n
  Vec3 signed_normal{};                ///< n × T: continuous through inflections; κ_s · (n × T) = κN in-plane
  bool tangent_defined = false;        ///< T, speed > 0, κ and the signed quantities are defined
  bool frame_defined = false;          ///< N, B and κ' are defined
  bool torsion_defined = false;        ///< τ is defined (same as frame_defined)
  Undefined reason = Undefined::None;  ///< why something is undefined
};

/// Resolutions for one curve, computed once per batch.
struct FrenetScale {
  double zero_speed = 0.0;  ///< |r'| at or below this is zero speed
  double model_size = 1.0;  ///< model size used for the curvature test
};

/// The scale of a NURBS curve: model_size() and its domain length.
[[nodiscard]] FrenetScale frenet_scale(const nurbs::NurbsCurve& curve, const Tolerance& tolerance);
/// The scale of a curve of the given size on a domain of the given length.
/// @throws hula::Error(Errc::InvalidArgument) if either is not finite or domain_length ≤ 0
[[nodiscard]] FrenetScale frenet_scale(double model_size, double domain_length, const Tolerance& tolerance);

/// The Frenet quantities from r, r', r'', r''' at one parameter (the kernel of every evaluator).
/// @param t the parameter (copied into the result)
/// @param d {r, r', r'', r'''}
/// @param scale the curve's resolutions (frenet_scale)
/// @param options tolerance and plane normal (not validated here; the curve-level entry points do)
/// @returns the point; see FrenetPoint for what undefined looks like
[[nodiscard]] FrenetPoint frenet_from_derivatives(double t, std::span<const Vec3, 4> d, const FrenetScale& scale,
                                                  const FrenetOptions& options);

/// Frenet frame and curvatures of a NURBS curve at t.
/// @throws hula::Error(Errc::OutOfDomain / NonFiniteInput) as NurbsCurve::derivatives
/// @throws hula::Error(Errc::InvalidOption) if options are invalid
[[nodiscard]] FrenetPoint frenet(const nurbs::NurbsCurve& curve, double t, const FrenetOptions& options = {});

/// Batch form: out[i] at ts[i]. Sorted ts are fastest; no allocation.
/// @throws hula::Error(Errc::InvalidArgument) if out.size() != ts.size(); as frenet(curve, t) otherwise,
///   naming the index of a bad parameter
void frenet(const nurbs::NurbsCurve& curve, std::span<const double> ts, std::span<FrenetPoint> out,
            const FrenetOptions& options = {});

/// Frenet frame and curvatures of a curve value at ts[i]: exactly from its law when it has one
/// (LawFrenet), from its natural evaluator for a natural curve (CurveFrenet: κ, τ and κ' to rounding,
/// position and frame to its integration tolerance), else from its NURBS.
/// @throws hula::Error(Errc::OutOfDomain) naming "t" and the index of the first parameter outside
///   the domain; as the NURBS form otherwise
void frenet(const curve::Curve& curve, std::span<const double> ts, std::span<FrenetPoint> out,
            const FrenetOptions& options = {});

/// A law curve prepared for Frenet evaluation: the law with its derivatives to order 3, compiled.
class LawFrenet {
 public:
  /// @param curve a 2- or 3-vector law of `parameter`
  /// @param parameter the curve parameter, e.g. "t"
  /// @param domain the domain [start, end] (start < end); sets the scale from 33 sampled positions
  /// @param options validated here
  /// @throws hula::Error(Errc::InvalidArgument) if the law is not a vector law of `parameter` or the
  ///   domain is empty or not finite; hula::Error(Errc::InvalidOption) for bad options
  LawFrenet(const law::Law& curve, const std::string& parameter, nurbs::Interval domain,
            const FrenetOptions& options = {});
  /// The same from a compiled law (order ≥ 3) of a curve on `domain`.
  /// @throws as above; hula::Error(Errc::InvalidArgument) naming "law" if the order is below 3
  LawFrenet(law::CurveEvaluator evaluator, Interval domain, const FrenetOptions& options = {});
  /// The quantities at t (the law is evaluated exactly, also outside the domain).
  [[nodiscard]] FrenetPoint at(double t) const;
  /// Batch form; no allocation. @throws hula::Error(Errc::InvalidArgument) if the sizes differ.
  void at(std::span<const double> ts, std::span<FrenetPoint> out) const;
  /// The scale used for the undefined tests.
  [[nodiscard]] const FrenetScale& scale() const noexcept { return scale_; }

 private:
  law::CurveEvaluator evaluator_;
  FrenetOptions options_;
  FrenetScale scale_;
};

/// A curve value prepared for Frenet evaluation from its own derivatives (Curve::derivatives): the exact
/// form of law and natural curves, the NURBS of the others. For a natural curve (parameter = arc length,
/// r' = T, r'' = κN, r''' from the exact κ', τ) the curvature, torsion, κ' and signed curvature equal
/// the laws' values to rounding.
class CurveFrenet {
 public:
  /// @param curve any curve value; the scale comes from 33 positions over its domain
  /// @throws hula::Error(Errc::InvalidOption) for bad options
  explicit CurveFrenet(curve::Curve curve, const FrenetOptions& options = {});
  /// The quantities at t.
  /// @throws as Curve::derivatives (OutOfDomain naming "t")
  [[nodiscard]] FrenetPoint at(double t) const;
  /// Batch form.
  /// @throws hula::Error(Errc::InvalidArgument) if the sizes differ; as Curve::derivatives (naming "t" and the index)
  void at(std::span<const double> ts, std::span<FrenetPoint> out) const;
  /// The scale used for the undefined tests.
  [[nodiscard]] const FrenetScale& scale() const noexcept { return scale_; }
  /// The curve.
  [[nodiscard]] const curve::Curve& curve() const noexcept { return curve_; }

 private:
  curve::Curve curve_;
  FrenetOptions options_;
  FrenetScale scale_;
};

/// Curvature and torsion only, the fast path: kappa[i] = κ(ts[i]), tau[i] = τ(ts[i]).
/// κ is NaN at zero speed; τ is NaN where the frame is undefined (FrenetPoint rules). No allocation.
/// @throws hula::Error(Errc::InvalidArgument) if the span sizes differ; as frenet otherwise
void curvature_torsion(const nurbs::NurbsCurve& curve, std::span<const double> ts, std::span<double> kappa,
                       std::span<double> tau, const FrenetOptions& options = {});

}  // namespace hula::diffgeom
