// SPDX-License-Identifier: MIT
// The figures of the study runs (thesis ch. 7 and 8), composed on
// io::SvgFigure, the one SVG writer: curves before and after with their
// curvature combs, curvature and torsion profiles, convergence graphs, fitness
// and energy maps (with their grids as CSV tables), Pareto sets, projections on
// the coordinate planes, Hermite handles, and the scan fit's cloud and
// curvature plot. `hula <study> --svg DIR` writes them (oli::study_figures
// picks those of a run). Every comb is the curve's diffgeom::analyse_curve
// curvature fins at diffgeom::auto_fin_scale (or a given scale), the one rule
// of every door.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "hula/io/curve_figures.hpp"
#include "hula/io/editing_study_file.hpp"
#include "hula/io/svg.hpp"
#include "hula/studies/curvature_torsion_match.hpp"
#include "hula/studies/fair_knots_study.hpp"
#include "hula/studies/match_study.hpp"
#include "hula/studies/scan_fit.hpp"

namespace hula::io {

/// A text file written beside the figures (a map's grid as CSV).
struct NamedTable {
  /// The file name, extension included ("fitness_map.csv").
  std::string name;
  std::string text;
};

/// The figures of one run: SVG figures by file stem, and tables.
struct StudyFigures {
  std::vector<NamedFigure> figures{};
  std::vector<NamedTable> tables{};
};

/// The automatic scale of `curve`'s curvature comb (diffgeom::auto_fin_scale through analyse_curve).
[[nodiscard]] double curvature_comb_scale(const nurbs::NurbsCurve& curve);

/// Draws `curve`'s curvature comb in the xy-plane: 150 fins P − sκN (segments in `fin_colour`) and the line
/// through their tips (`comb_colour`, with `legend`).
/// @param scale s, e.g. curvature_comb_scale of the figure's reference curve so combs compare
void add_curvature_comb(SvgFigure& figure, const nurbs::NurbsCurve& curve, double scale, const std::string& fin_colour,
                        const std::string& comb_colour, const std::string& legend);

/// "match-curvature": curve_before, curve_after (the start and the result with their combs and points),
/// profile (target, start and result κ), convergence (GA best per generation, the LM result marked) — or,
/// for the direct method, the reconstructed curve and its profile against arc length — and with a map,
/// fitness_map (log10 of the objective) and the table fitness_map.csv.
[[nodiscard]] StudyFigures match_figures(const studies::CurvatureMatch& match, const studies::MatchStudy& study,
                                         const studies::MatchResult& result);

/// "match-curvature-torsion": curve_before, curve_after (the best compromise), profile, torsion_profile,
/// pareto, convergence and, with a map, fitness_map, torsion_map and fitness_map.csv.
[[nodiscard]] StudyFigures torsion_match_figures(const studies::CurvatureMatch& match,
                                                 const studies::TorsionMatchSettings& settings,
                                                 const studies::TorsionMatchResult& result);

/// "fair-knots": curve_before (chord length), curve_after (the better optimum), convergence (GA and
/// Nelder–Mead), and with a map energy_map (log10), energy_sections (with sections) and energy_map.csv.
[[nodiscard]] StudyFigures fair_knots_figures(const studies::FairKnotsStudy& study,
                                              const studies::FairKnotsOutcome& outcome);

/// "edit-projection": projection-XY, projection-YZ, projection-ZX (original, edited, rebuilt).
[[nodiscard]] StudyFigures edit_projection_figures(const EditProjectionStudy& study,
                                                   const studies::ProjectionEditResult& result);

/// "fin-compound": before and (with an edit) after and rebuilt-<plane> for the projection technique;
/// combescure-XY and combescure-ZX for the Combescure transform.
[[nodiscard]] StudyFigures fin_compound_figures(const FinCompoundStudy& study, const FinCompoundRun& run);

/// "hermite": before (the spline and its handles) and after (the edited curve and handles), handles at one
/// display scale (the longest a fifth of the spline's size).
[[nodiscard]] StudyFigures hermite_figures(const HermiteStudy& study, const studies::HermiteEditResult& result);

/// "fit": fit (the cloud, kept points grey, strays red, the faired curve; xy view) and curvature (signed
/// curvature of planar fits, else curvature, against arc length before and after fairing).
/// @param points the study's points, indexed as the result's order and strays
[[nodiscard]] StudyFigures fit_figures(std::span<const Vec3> points, const studies::ScanFitResult& result);

}  // namespace hula::io
