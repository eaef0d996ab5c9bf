// SPDX-License-Identifier: MIT
// The figures of one curve (thesis figures 32–48), built on io::SvgFigure,
// the one SVG writer: the curve in a named view with its fins (any of
// diffgeom's fin kinds, each with its scale in the legend), and graphs of
// curvature, torsion, radius of curvature and speed against t and the
// logarithmic curvature graph. The samples and fins are the curve's
// diffgeom::analyse_curve, so the fins drawn are the ones every door reports.
// `hula analyse --svg` writes them.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "hula/curve/curve.hpp"
#include "hula/diffgeom/analysis.hpp"
#include "hula/io/svg.hpp"

namespace hula::io {

/// How a curve is projected on the page.
enum class CurveView {
  /// XY seen from +Z for a curve in a plane z = const (YZ or ZX likewise for x or y = const); a space
  /// curve obliquely: from −Y 20° above when tall (z extent > half its x or y extent), else from +Z
  /// tilted 35° towards −Y.
  Auto,
  Xy,         ///< seen from +Z (page x = x, page y = y)
  Yz,         ///< seen from +X (page x = y, page y = z)
  Zx,         ///< seen from +Y (page x = z, page y = x)
  Isometric,  ///< seen from (1, 1, 1), z up: page x = (y − x)/√2, page y = (2z − x − y)/√6
};

/// "auto", "xy", "yz", "zx", "isometric".
[[nodiscard]] std::string_view curve_view_name(CurveView view) noexcept;
/// The view of a name of curve_view_name().
/// @throws hula::Error(Errc::InvalidOption) naming `field` and the allowed names
[[nodiscard]] CurveView parse_curve_view(std::string_view name, std::string_view field = "view");
/// The fin kinds of a comma-separated list of "curvature", "torsion", "normal", "binormal", "bishop"
/// (both Bishop fins, U and V), "bishop-u", "bishop-v", "combescure"; duplicates are kept once, in list
/// order.
/// @throws hula::Error(Errc::InvalidOption) naming `field`, the unknown entry and the allowed names
[[nodiscard]] std::vector<diffgeom::FinKind> parse_fin_kinds(std::string_view list, std::string_view field = "fins");

/// Options of curve_figures().
struct CurveFigureOptions {
  /// The fins drawn on the curve figure. Default curvature and torsion.
  std::vector<diffgeom::FinKind> fins{diffgeom::FinKind::Curvature, diffgeom::FinKind::Torsion};
  /// Fin scale s (diffgeom::FinOptions::scale) for every kind; absent: diffgeom::auto_fin_scale per
  /// kind. Finite and non-zero when given.
  std::optional<double> fin_scale{};
  /// Fins per kind, equally spaced in t, ends included. Default 120. Valid: 2 … 100000.
  int fin_density = 120;
  /// Projection of the curve figure. Default Auto.
  CurveView view = CurveView::Auto;
  /// Samples of the curve and the graphs, ends included. Default 400. Valid: 2 … 100000.
  int samples = 400;
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// A figure with its file stem ("curve", "kappa", …).
struct NamedFigure {
  std::string name;
  SvgFigure figure;
};

/// The figures of a curve.
struct CurveFigures {
  /// curve (the curve and its fins), kappa (signed about +Z for curves in a plane z = const), tau, radius
  /// (limited to ten times the box diagonal), speed, logcurvature; graphs whose range contains 0 (but
  /// logcurvature), NaN (undefined) samples break the lines.
  std::vector<NamedFigure> figures;
  /// The combs drawn (the analysis's: diffgeom::analyse_curve with the options' fins), in options.fins order.
  std::vector<diffgeom::AnalysedFins> fins;
  /// The view used (Auto resolved).
  CurveView view = CurveView::Xy;
  /// Its description, e.g. "seen from +Z" (also in the curve figure's title).
  std::string view_description;
};

/// Builds the figures of `curve`.
/// @throws hula::Error(Errc::InvalidOption) for bad options
[[nodiscard]] CurveFigures curve_figures(const curve::Curve& curve, const CurveFigureOptions& options = {});

}  // namespace hula::io
