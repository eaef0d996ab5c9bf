// SPDX-License-Identifier: MIT
// Fins (compound renderings, thesis 6.3.2): segments from curve points P along
// a frame direction scaled by a quantity, drawn as a comb, with the polyline
// through the tips (the comb's envelope):
//   curvature fin P − s κN, torsion fin P + s τB, normal fin P − s N, binormal fin
//   P − s B, the Bishop variants P − s U, P − s V, and the Combescure compound
//   fin P + s (τ/κ T + B) (thesis 8.3 eq. 44 with C = s, diffgeom::combescure).
// κN is the curvature vector, so the curvature fin is defined wherever the
// tangent is (it has length 0 where κ = 0), also through inflections.
#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "hula/diffgeom/frenet.hpp"
#include "hula/law/convert.hpp"
#include "hula/law/expr.hpp"

namespace hula::diffgeom {

/// Which fin.
enum class FinKind {
  Curvature,  ///< P − s κN
  Torsion,    ///< P + s τB (undefined where the frame is)
  Normal,     ///< P − s N (undefined where the frame is)
  Binormal,   ///< P − s B (undefined where the frame is)
  BishopU,    ///< P − s U (Bishop frame; defined wherever T is)
  BishopV,    ///< P − s V (Bishop frame)
  /// P + s (τ/κ T + B): the Combescure compound Q of eq. 44 with C = s (combescure()); undefined where
  /// the frame is and at planar points (|τ| ≤ angular · κ), so everywhere on a planar curve (8.3, 8.5)
  Combescure,
};

/// Every fin kind, in the order of the enum.
inline constexpr std::array<FinKind, 7> kFinKinds{FinKind::Curvature, FinKind::Torsion, FinKind::Normal,
                                                  FinKind::Binormal,  FinKind::BishopU, FinKind::BishopV,
                                                  FinKind::Combescure};

/// "curvature", "torsion", "normal", "binormal", "bishop-u", "bishop-v", "combescure".
[[nodiscard]] std::string_view fin_kind_name(FinKind kind) noexcept;
/// The kind named `name` (fin_kind_name's spelling), or nullopt.
[[nodiscard]] std::optional<FinKind> fin_kind_from_name(std::string_view name) noexcept;

/// n equally spaced parameters over `domain`, ends included, the last exactly domain.end (n = 1: the
/// start alone; n < 1: none): the grid of fins() and of analyse_curve's parameter samples.
[[nodiscard]] std::vector<double> parameter_grid(nurbs::Interval domain, int n);

/// Options of fins().
struct FinOptions {
  /// Which fin. Default Curvature.
  FinKind kind = FinKind::Curvature;
  /// Scale s (model units per unit of the quantity; for the unit-vector fins, model units). Default 1.
  /// Finite, may be negative (flips the fins).
  double scale = 1.0;
  /// Number of fins, equally spaced in the parameter over the domain, ends included. Default 200.
  /// Valid: 2 … 1000000.
  int density = 200;
  /// Log scale: the fin length becomes sign(q) · log(1 + |s q|) instead of s q (log-aesthetic
  /// plots of quantities that vary over decades). Default false.
  bool log_scale = false;
  /// Frenet options. Default {}.
  FrenetOptions frenet{};
  /// Throws hula::Error(Errc::InvalidOption) naming the bad field.
  void validate() const;
};

/// A comb: base[i] on the curve, tip[i] at the fin's end; undefined fins have NaN tips and defined[i] = 0.
struct Fins {
  std::vector<double> t;              ///< parameters
  std::vector<Vec3> base;             ///< P(t_i)
  std::vector<Vec3> tip;              ///< fin ends (the envelope polyline, NaN where undefined)
  std::vector<std::uint8_t> defined;  ///< 1 where the fin is defined
};

/// The fins of a NURBS curve.
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] Fins fins(const nurbs::NurbsCurve& curve, const FinOptions& options = {});
/// The fins of a curve value over its domain, exactly from its law when it has one.
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] Fins fins(const curve::Curve& curve, const FinOptions& options = {});
/// The fins at Frenet points already evaluated, one fin per point (options.density is not used):
/// equal to fins(curve, options) when `frames` are the curve's at its fin parameters.
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] Fins fins(std::span<const FrenetPoint> frames, const FinOptions& options);

/// The fin curve (the comb's envelope) of a law curve as an exact law of `parameter`:
/// Curvature P − s κN, built as P − s ((r'·r') r'' − (r'·r'') r') / |r'|⁴ so it stays defined through
/// inflections; Torsion P + s τB, Normal P − s N, Binormal P − s B from frenet_laws (undefined where
/// the frame is); Combescure combescure_law with c = s (NaN where κ = 0). 2-vector laws are embedded
/// in z = 0.
/// @throws hula::Error(Errc::InvalidArgument) naming "law" for a scalar law
/// @throws hula::Error(Errc::InvalidOption) naming "kind" for the Bishop fins (no closed law) and
///   "log_scale" when it is set, or for other bad options
[[nodiscard]] law::Law fin_law(const law::Law& curve, std::string_view parameter, const FinOptions& options = {});
/// The fin curve of a law curve over `domain` as a NURBS within fit.tolerance (law::to_nurbs of fin_law).
/// @throws as fin_law and law::to_nurbs (Errc::NumericalFailure where the fin is undefined, e.g. a
///   torsion fin through an inflection)
[[nodiscard]] law::ToNurbsResult fin_nurbs(const law::Law& curve, std::string_view parameter, nurbs::Interval domain,
                                           const FinOptions& options = {}, const law::ToNurbsOptions& fit = {});
}  // namespace hula::diffgeom
