// SPDX-License-Identifier: MIT
// SVG files of curves as Bézier paths in model units (not figures: io/svg.hpp
// draws polylines in pixels). Each curve is one <path> of cubic Bézier
// commands ("M x0 y0 C x1 y1 x2 y2 x3 y3 …") from nurbs::cubic_beziers:
// exact for a non-rational curve of degree ≤ 3 (its Bézier segments, degree 1
// and 2 raised to 3), within a tolerance otherwise (rational curves — circles,
// conics —, degree ≥ 4, and law or natural-equation curves through their NURBS
// form). Coordinates are the curve's x and y in model units, printed as the
// shortest text that reads back to the same double; z is dropped (the
// projection on the XY plane). The document's y axis points up: the paths sit
// in a group with transform="scale(1 -1)" and the viewBox is the flipped
// bounding box of the control points with a 2 % margin; width and height are
// given in millimetres (one model unit = 1 mm, as the STEP and IGES writers
// assume). Per path: id "curve-N", the curve's name as its <title>, its colour
// as the stroke, and data-exact / data-max-deviation saying what it is.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::io {

/// One curve to draw.
struct SvgPathCurve {
  std::string name{};                ///< written as the path's <title> (omitted when empty)
  nurbs::NurbsCurve curve;           ///< the curve (for a law or natural-equation curve, its NURBS form)
  std::string colour = "#000000";    ///< the stroke colour, "#rrggbb"
  double approximation_deviation{};  ///< how far `curve` already is from the curve it stands for (≥ 0)
};

/// Options of svg_paths.
struct SvgPathOptions {
  /// Largest deviation of the cubic pieces of a curve that has no exact cubic form, in model units.
  /// Default 1e-6 (a micrometre in millimetres: below what a plotter or laser resolves); > 0.
  double tolerance = 1e-6;
};

/// What svg_paths wrote.
struct SvgPathReport {
  std::size_t curves = 0;      ///< paths written
  std::size_t exact = 0;       ///< of them, exact (non-rational, degree ≤ 3, approximation_deviation 0)
  std::size_t pieces = 0;      ///< cubic commands written in all
  double max_deviation = 0.0;  ///< largest cubic deviation plus approximation_deviation over the paths
  bool projected = false;      ///< true when a curve had z ≠ 0 (dropped)
};

/// An SVG document and its report.
struct SvgPaths {
  std::string text;
  SvgPathReport report;
};

/// The SVG document of `curves` as Bézier paths.
/// @throws hula::Error(Errc::InvalidArgument) for no curves (field "curves"), a colour not "#rrggbb" (field
///   "colour", index) or a bad tolerance (field "tolerance")
/// @throws hula::Error(Errc::NumericalFailure) from nurbs::cubic_beziers for a tolerance below rounding
[[nodiscard]] SvgPaths svg_paths(const std::vector<SvgPathCurve>& curves, const SvgPathOptions& options = {});

}  // namespace hula::io
