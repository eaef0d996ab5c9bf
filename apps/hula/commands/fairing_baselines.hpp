// SPDX-License-Identifier: MIT
// Curvature combs for study figures and Open CASCADE's fairing baselines beside a study's curves
// (`hula fair-knots --occt`, `hula match-curvature --occt`).
#pragma once

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "commands/common.hpp"
#include "hula/io/svg.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::cli {

/// The automatic fin scale of `curve`'s curvature comb (diffgeom::auto_fin_scale, the one rule of every door).
[[nodiscard]] double fin_scale(const nurbs::NurbsCurve& curve);

/// The curvature fins of `curve` (segments in `fin_colour`) and the comb line through their tips (`comb_colour`).
void add_fins(io::SvgFigure& fig, const nurbs::NurbsCurve& curve, double scale, const char* fin_colour,
              const char* comb_colour, const std::string& legend);

/// Open CASCADE's baselines between points.front() and points.back() with the end tangents and signed end
/// curvatures of `reference`: {"ends": {"tangent_angles", "curvatures"}, "curves": [{"name", "status", "bending",
/// "variation", "max_deviation", "mean_deviation", "tangent_error", "curve"}]}, deviations measured from `points`;
/// with `svg`, writes baselines.svg with the `studied` curves and the baselines, each with its curvature comb.
/// @throws hula::Error(Errc::Unsupported) naming --occt in a build without Open CASCADE
[[nodiscard]] Json occt_baselines(std::span<const Vec3> points, const nurbs::NurbsCurve& reference,
                                  const std::vector<std::pair<std::string, const nurbs::NurbsCurve*>>& studied,
                                  const std::optional<std::filesystem::path>& svg);

}  // namespace hula::cli
