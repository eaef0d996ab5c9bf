// SPDX-License-Identifier: MIT
// What `hula fin-compound`, `hula edit-projection` and `hula hermite` share:
// curves drawn in a projection plane's own coordinates (XY: x, y; YZ: y, z;
// ZX: z, x, so that the plane normal +Z, +X, +Y points at the viewer), fins
// and handles as segments, and the run record (seed, threads, log) these
// deterministic studies accept for uniformity with the stochastic ones.
#pragma once
#include <span>
#include <string>
#include <vector>

#include "commands/study_common.hpp"
#include "hula/diffgeom/projection.hpp"
#include "hula/io/svg.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::cli {

/// The two in-plane coordinates of p (XY: x, y; YZ: y, z; ZX: z, x).
[[nodiscard]] std::pair<double, double> in_plane(const Vec3& p, diffgeom::Plane plane);

/// Axis labels of a plane ("x", "y") etc.
[[nodiscard]] std::pair<std::string, std::string> plane_axes(diffgeom::Plane plane);

/// A figure of curves in a plane: equal aspect, axes named after the plane's coordinates.
[[nodiscard]] io::SvgFigure plane_figure(const std::string& title, diffgeom::Plane plane);

/// Draws `samples` + 1 points of a curve (equally spaced in its parameter) in the plane.
void draw_curve(io::SvgFigure& figure, const nurbs::NurbsCurve& curve, diffgeom::Plane plane, const io::SvgStyle& style,
                const std::string& legend, int samples = 400);

/// Draws segments base[i] → tip[i] in the plane (fins, handles).
void draw_segments(io::SvgFigure& figure, std::span<const Vec3> base, std::span<const Vec3> tip, diffgeom::Plane plane,
                   const io::SvgStyle& style, const std::string& legend);

/// Adds "seed", "threads" and "log" (the --log path or null) to an output document and, with --log,
/// writes the output document there too (these studies have no generations to log).
void record_run(Json& output, const studies::StudyHeader& header, const StudyArgs& args);

}  // namespace hula::cli
