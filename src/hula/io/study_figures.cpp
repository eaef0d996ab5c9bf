// SPDX-License-Identifier: MIT
// The figures of the study runs (study_figures.hpp).
#include "hula/io/study_figures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <utility>

#include "hula/core/nan.hpp"
#include "hula/diffgeom/analysis.hpp"
#include "hula/diffgeom/frenet.hpp"
#include "hula/diffgeom/plot.hpp"
#include "hula/io/fair_knots_study_file.hpp"
#include "hula/io/match_study_file.hpp"

namespace hula::io {

namespace {

// The curvature comb of `curve` as every door draws it (diffgeom::analyse_curve, 150 fins): at `scale`, or at
// the automatic scale (diffgeom::auto_fin_scale) when absent.
diffgeom::AnalysedFins curvature_comb(const nurbs::NurbsCurve& curve, std::optional<double> scale) {
  diffgeom::AnalysisOptions o;
  o.samples = 2;
  o.fins = {diffgeom::FinKind::Curvature};
  o.fin_density = 150;
  o.fin_scale = scale;
  return std::move(diffgeom::analyse_curve(curve, o).fins.front());
}

// `samples` + 1 points of the curve equally spaced in its parameter, as x and y.
std::pair<std::vector<double>, std::vector<double>> xy_samples(const nurbs::NurbsCurve& c, int samples) {
  std::vector<double> x, y;
  const nurbs::Interval d = c.domain();
  for (int i = 0; i <= samples; ++i) {
    const Vec3 p = c.evaluate(i == samples ? d.end : d.start + d.length() * i / samples);
    x.push_back(p.x);
    y.push_back(p.y);
  }
  return {std::move(x), std::move(y)};
}

void add_xy_points(SvgFigure& fig, std::span<const Vec3> points, const SvgStyle& style, double radius,
                   const std::string& legend = {}) {
  std::vector<double> px, py;
  for (const Vec3& p : points) {
    px.push_back(p.x);
    py.push_back(p.y);
  }
  fig.add_points(px, py, style, radius, legend);
}

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::vector<double> counting(std::size_t n) {
  std::vector<double> g(n);
  for (std::size_t i = 0; i < n; ++i) g[i] = static_cast<double>(i);
  return g;
}

// ---- the matching studies --------------------------------------------------------------------------------

// A matching study's curve in the xy view: the curve, with its curvature comb, and its data points.
void add_match_curve(SvgFigure& fig, const nurbs::NurbsCurve& curve, std::span<const Vec3> points,
                     const SvgStyle& style, const std::string& legend, bool comb) {
  const auto [x, y] = xy_samples(curve, 300);
  fig.add_polyline(x, y, style, legend);
  if (comb) add_curvature_comb(fig, curve, curvature_comb_scale(curve), style.stroke, style.stroke, legend + " comb");
  add_xy_points(fig, points, style, 3.0);
}

// The before / after pair of a matching study: the start spline, then the result over the dashed start.
void add_before_after(StudyFigures& out, const nurbs::NurbsCurve& start, std::span<const Vec3> before,
                      const nurbs::NurbsCurve& result, std::span<const Vec3> after, const std::string& before_title,
                      const std::string& after_title, const std::string& result_name) {
  const SvgStyle grey{"#888888", 1.5, {}, "6 4"}, blue{"#1f5fbf", 2.0, {}, {}};
  SvgFigure first;
  first.set_equal_aspect(true);
  first.set_title(before_title);
  add_match_curve(first, start, before, blue, "start", true);
  out.figures.push_back({"curve_before", std::move(first)});
  SvgFigure second;
  second.set_equal_aspect(true);
  second.set_title(after_title);
  add_match_curve(second, start, before, grey, "start", false);
  add_match_curve(second, result, after, blue, result_name, true);
  out.figures.push_back({"curve_after", std::move(second)});
}

// The fitness map (the study's `map` member) of one objective in log10 (the distance rises by decades away from
// the minimum), with the start and the result marked.
SvgFigure map_figure(const std::string& title, const studies::MatchMapSettings& settings, const optim::SweepResult& map,
                     std::size_t objective, std::size_t objectives, std::span<const double> start,
                     std::span<const double> best, std::span<const optim::Variable> variables) {
  const std::array<std::size_t, 2> axes = settings.axes(variables);
  std::vector<double> shown(map.objective.size());
  for (std::size_t i = 0; i < shown.size(); ++i) {
    const double e = map.values[i * objectives + objective];
    shown[i] = e > 0.0 ? std::log10(e) : kNaN;
  }
  SvgFigure fig(800, 700);
  fig.set_title(title + " over " + settings.variables[0] + " and " + settings.variables[1] +
                " (other variables at the result)");
  fig.set_axes(settings.variables[0], settings.variables[1]);
  fig.add_heatmap(map.x_values, map.y_values, shown, "log10 " + title);
  fig.add_points(std::vector<double>{start[axes[0]]}, std::vector<double>{start[axes[1]]},
                 SvgStyle{.stroke = "#ffffff", .fill = "#ffffff"}, 5.0, "start");
  fig.add_points(std::vector<double>{best[axes[0]]}, std::vector<double>{best[axes[1]]},
                 SvgStyle{.stroke = "#d62728", .fill = "#d62728"}, 5.0, "result");
  return fig;
}

// The direct method's figures: the start spline and the reconstructed curve, and the profiles (the target, the
// start spline's and the reconstruction's, against normalised arc length).
void direct_figures(StudyFigures& out, const studies::CurvatureMatch& match,
                    const studies::DirectReconstructionResult& d, const std::vector<Vec3>& before) {
  const nurbs::NurbsCurve& curve = d.nurbs->curve;
  const nurbs::NurbsCurve start = match.sampler().curve(before);
  add_before_after(out, start, before, curve, {}, "Start curve (x-y view)", "Direct reconstruction (x-y view)",
                   "reconstructed");
  const auto& u = match.sampler().abscissae();
  std::vector<double> t(u.size()), kappa(u.size()), tau(u.size());
  for (std::size_t i = 0; i < u.size(); ++i) t[i] = curve.domain().start + u[i] * curve.domain().length();
  diffgeom::curvature_torsion(curve, t, kappa, tau);
  SvgFigure fig;
  fig.set_title("Curvature profile");
  fig.set_axes("u (normalised arc length)", "curvature");
  fig.add_polyline(u, match.curvature_samples(match.start_variables()), SvgStyle{"#888888", 1.5, {}, "6 4"}, "start");
  fig.add_polyline(u, match.target_samples(), SvgStyle{"#c03030", 2.0, {}, "3 3"}, "target");
  fig.add_polyline(u, kappa, SvgStyle{"#1f5fbf", 2.0, {}, {}}, "reconstructed");
  out.figures.push_back({"profile", std::move(fig)});
}

// ---- the editing studies ----------------------------------------------------------------------------------

// The two in-plane coordinates of p (XY: x, y; YZ: y, z; ZX: z, x, so that the plane normal +Z, +X, +Y points at
// the viewer).
std::pair<double, double> in_plane(const Vec3& p, diffgeom::Plane plane) {
  switch (plane) {
    case diffgeom::Plane::XY:
      return {p.x, p.y};
    case diffgeom::Plane::YZ:
      return {p.y, p.z};
    case diffgeom::Plane::ZX:
      return {p.z, p.x};
  }
  return {p.x, p.y};
}

// A figure of curves in a plane: equal aspect, axes named after the plane's coordinates.
SvgFigure plane_figure(const std::string& title, diffgeom::Plane plane) {
  SvgFigure f(640, 480);
  f.set_title(title);
  switch (plane) {
    case diffgeom::Plane::XY:
      f.set_axes("x", "y");
      break;
    case diffgeom::Plane::YZ:
      f.set_axes("y", "z");
      break;
    case diffgeom::Plane::ZX:
      f.set_axes("z", "x");
      break;
  }
  f.set_equal_aspect(true);
  return f;
}

// 401 points of a curve, equally spaced in its parameter, drawn in the plane.
void draw_curve(SvgFigure& figure, const nurbs::NurbsCurve& curve, diffgeom::Plane plane, const SvgStyle& style,
                const std::string& legend) {
  constexpr int kSamples = 400;
  std::vector<double> x, y;
  const nurbs::Interval d = curve.domain();
  for (int i = 0; i <= kSamples; ++i) {
    const double u = static_cast<double>(i) / kSamples;
    const auto [a, b] = in_plane(curve.evaluate(d.start * (1.0 - u) + d.end * u), plane);
    x.push_back(a);
    y.push_back(b);
  }
  figure.add_polyline(x, y, style, legend);
}

// Segments base[i] → tip[i] in the plane (fins, handles).
void draw_segments(SvgFigure& figure, std::span<const Vec3> base, std::span<const Vec3> tip, diffgeom::Plane plane,
                   const SvgStyle& style, const std::string& legend) {
  std::vector<double> x0, y0, x1, y1;
  for (std::size_t i = 0; i < base.size(); ++i) {
    const auto [a, b] = in_plane(base[i], plane);
    const auto [c, d] = in_plane(tip[i], plane);
    x0.push_back(a);
    y0.push_back(b);
    x1.push_back(c);
    y1.push_back(d);
  }
  figure.add_segments(x0, y0, x1, y1, style, legend);
}

constexpr int kCompoundFins = 60;  // fins drawn per curve in the fin-compound figures

// P(t_i) and Q(t_i) at kCompoundFins + 1 parameters of P's domain (Q on the same normalised parameterisation).
void fin_points(const nurbs::NurbsCurve& p, const nurbs::NurbsCurve& q, std::vector<Vec3>& base,
                std::vector<Vec3>& tip) {
  for (int i = 0; i <= kCompoundFins; ++i) {
    const double u = static_cast<double>(i) / kCompoundFins;
    base.push_back(p.evaluate(p.domain().start * (1 - u) + p.domain().end * u));
    tip.push_back(q.evaluate(q.domain().start * (1 - u) + q.domain().end * u));
  }
}

// The figures of the projection technique (before; after, given a prescribed compound).
void projection_figures(StudyFigures& out, const FinCompoundStudy& s, const FinCompoundRun& run) {
  const diffgeom::Plane plane = s.projection.plane;
  const nurbs::NurbsCurve& curve = s.curve->nurbs();
  const nurbs::NurbsCurve& projection = *run.projection;
  const studies::LawCurveFit& compound = *run.compound;
  std::vector<Vec3> base, tip;
  fin_points(projection, compound.curve, base, tip);
  SvgFigure before = plane_figure("normal fin compound of the projection (before)", plane);
  draw_segments(before, base, tip, plane, {.stroke = "#999999", .width = 0.8}, "fins");
  draw_curve(before, projection, plane, {.stroke = "black"}, "projection");
  draw_curve(before, compound.curve, plane, {.stroke = "#1f77b4"}, "compound");
  out.figures.push_back({"before", std::move(before)});
  if (!run.edit) return;
  const studies::CompoundEditResult& edit = *run.edit;
  base.clear();
  tip.clear();
  fin_points(edit.planar.curve, s.compound->nurbs(), base, tip);
  SvgFigure after = plane_figure("prescribed compound and its curve (after)", plane);
  draw_curve(after, projection, plane, {.stroke = "#999999", .dash = "6 4"}, "original projection");
  draw_segments(after, base, tip, plane, {.stroke = "#bbbbbb", .width = 0.8}, "fins");
  draw_curve(after, edit.planar.curve, plane, {.stroke = "#d62728"}, "new projection");
  draw_curve(after, s.compound->nurbs(), plane, {.stroke = "#1f77b4"}, "prescribed compound");
  out.figures.push_back({"after", std::move(after)});
  for (const diffgeom::Plane other : {diffgeom::Plane::XY, diffgeom::Plane::YZ, diffgeom::Plane::ZX}) {
    if (other == plane) continue;
    SvgFigure f = plane_figure(std::string("3-D curve seen on ") + std::string(diffgeom::plane_name(other)) +
                                   " (the unchanged coordinate is kept)",
                               other);
    draw_curve(f, curve, other, {.stroke = "#999999", .dash = "6 4"}, "original");
    draw_curve(f, edit.curve, other, {.stroke = "#d62728"}, "rebuilt");
    out.figures.push_back({"rebuilt-" + std::string(diffgeom::plane_name(other)), std::move(f)});
  }
}

// The figures of the Combescure transform: parent, compound and the fins between them on XY and ZX.
void combescure_figures(StudyFigures& out, const FinCompoundStudy& s, const FinCompoundRun& run) {
  const bool forward = s.curve.has_value();
  const nurbs::NurbsCurve& input = forward ? s.curve->nurbs() : s.compound->nurbs();
  const nurbs::NurbsCurve& result = run.result_curve();
  const nurbs::NurbsCurve& p = forward ? input : result;
  const nurbs::NurbsCurve& q = forward ? result : input;
  std::vector<Vec3> base, tip;
  fin_points(p, q, base, tip);
  for (const diffgeom::Plane plane : {diffgeom::Plane::XY, diffgeom::Plane::ZX}) {
    SvgFigure f = plane_figure(std::string("Combescure compound Q = P + C (tau/kappa T + B), seen on ") +
                                   std::string(diffgeom::plane_name(plane)),
                               plane);
    draw_segments(f, base, tip, plane, {.stroke = "#999999", .width = 0.8}, "R = Q - P");
    draw_curve(f, p, plane, {.stroke = "black"}, "parent P");
    draw_curve(f, q, plane, {.stroke = "#1f77b4"}, "compound Q");
    out.figures.push_back({"combescure-" + std::string(diffgeom::plane_name(plane)), std::move(f)});
  }
}

// Hermite handles at a common display scale: T|P'| and N|P''| from each knot, and the knots.
void draw_handles(SvgFigure& f, const studies::HermiteHandles& h, double scale_first, double scale_second) {
  std::vector<Vec3> tip1, tip2;
  for (std::size_t i = 0; i < h.points.size(); ++i) {
    tip1.push_back(h.points[i] + scale_first * h.first[i]);
    tip2.push_back(h.points[i] + scale_second * h.normal_handle[i]);
  }
  draw_segments(f, h.points, tip1, diffgeom::Plane::XY, {.stroke = "#2ca02c", .width = 2.0}, "T|P'|");
  draw_segments(f, h.points, tip2, diffgeom::Plane::XY, {.stroke = "#9467bd", .width = 2.0}, "N|P''|");
  add_xy_points(f, h.points, {.stroke = "black"}, 3.0, "points");
}

// ---- fair-knots -------------------------------------------------------------------------------------------

std::string energy_label(studies::FairingEnergy e) {
  return e == studies::FairingEnergy::Bending ? "∫κ² ds" : "∫(dκ/ds)² ds";
}

// The curve with its curvature fins (Figures 59, 63, 65–67), the data points, and optionally a reference curve
// dashed.
SvgFigure fairing_curve_figure(const studies::KnotFairingSetup& setup, const studies::ParameterEvaluation& e,
                               const std::string& title, const studies::ParameterEvaluation* reference) {
  SvgFigure fig(800, 700);
  fig.set_title(title);
  fig.set_equal_aspect(true);
  add_curvature_comb(fig, e.curve, curvature_comb_scale(e.curve), "#9ecae1", "#3182bd", "curvature fins");
  if (reference != nullptr) {
    const auto [rx, ry] = xy_samples(reference->curve, 600);
    fig.add_polyline(rx, ry, SvgStyle{.stroke = "#888888", .width = 1.2, .dash = "6,4"}, "chord length");
  }
  const auto [cx, cy] = xy_samples(e.curve, 600);
  fig.add_polyline(cx, cy, SvgStyle{.stroke = "#000000", .width = 2.0}, "curve");
  add_xy_points(fig, setup.points, SvgStyle{.stroke = "#d62728", .fill = "#d62728"}, 4.0, "data points");
  return fig;
}

}  // namespace

double curvature_comb_scale(const nurbs::NurbsCurve& curve) { return curvature_comb(curve, std::nullopt).scale; }

void add_curvature_comb(SvgFigure& figure, const nurbs::NurbsCurve& curve, double scale, const std::string& fin_colour,
                        const std::string& comb_colour, const std::string& legend) {
  const diffgeom::Fins f = curvature_comb(curve, scale).fins;
  std::vector<double> x0, y0, x1, y1, tx, ty;
  for (std::size_t i = 0; i < f.t.size(); ++i) {
    tx.push_back(f.defined[i] ? f.tip[i].x : kNaN);
    ty.push_back(f.defined[i] ? f.tip[i].y : kNaN);
    if (!f.defined[i]) continue;
    x0.push_back(f.base[i].x);
    y0.push_back(f.base[i].y);
    x1.push_back(f.tip[i].x);
    y1.push_back(f.tip[i].y);
  }
  figure.add_segments(x0, y0, x1, y1, SvgStyle{.stroke = fin_colour, .width = 0.8});
  figure.add_polyline(tx, ty, SvgStyle{.stroke = comb_colour, .width = 1.0}, legend);
}

StudyFigures match_figures(const studies::CurvatureMatch& match, const studies::MatchStudy& study,
                           const studies::MatchResult& r) {
  StudyFigures out;
  if (r.map) {
    out.figures.push_back(
        {"fitness_map", map_figure("mean |k - k*|", *study.map, *r.map, 0, 1, r.start, r.best, r.variables)});
    const std::vector<std::string> names{"objective"};
    out.tables.push_back({"fitness_map.csv", match_map_csv(*r.map, names)});
  }
  const std::size_t n = match.setup().points.size();
  std::vector<Vec3> before(n), after(n);
  match.points_from(r.start, before);
  match.points_from(r.best, after);
  if (r.direct && r.direct->nurbs) {
    direct_figures(out, match, *r.direct, before);
    return out;
  }
  add_before_after(out, match.sampler().curve(before), before, match.sampler().curve(after), after,
                   "Start curve (x-y view)", "Optimised curve (x-y view)", "optimised");
  const SvgStyle grey{"#888888", 1.5, {}, "6 4"}, blue{"#1f5fbf", 2.0, {}, {}};
  {
    SvgFigure fig;
    fig.set_title("Curvature profile");
    fig.set_axes("u (parameter on [0, 1])", "curvature");
    const auto& u = match.sampler().abscissae();
    fig.add_polyline(u, match.curvature_samples(r.start), grey, "start");
    fig.add_polyline(u, match.target_samples(), SvgStyle{"#c03030", 2.0, {}, "3 3"}, "target");
    fig.add_polyline(u, match.curvature_samples(r.best), blue, "achieved");
    out.figures.push_back({"profile", std::move(fig)});
  }
  SvgFigure fig;
  fig.set_title("Convergence: best mean curvature distance");
  fig.set_axes("generation", "mean |k - k*|");
  fig.set_log_y(true);
  const std::vector<double> g = counting(r.convergence.size());
  fig.add_polyline(g, r.convergence, blue, "GA best");
  if (r.lm)
    fig.add_points(std::vector<double>{g.empty() ? 0.0 : g.back()}, std::vector<double>{r.after.mean},
                   SvgStyle{"#c03030", 1.5, {}, {}}, 4.0, "after LM");
  out.figures.push_back({"convergence", std::move(fig)});
  return out;
}

StudyFigures torsion_match_figures(const studies::CurvatureMatch& match, const studies::TorsionMatchSettings& settings,
                                   const studies::TorsionMatchResult& r) {
  StudyFigures out;
  const std::size_t n = match.setup().points.size();
  const std::vector<double> start = match.start_variables();
  const std::vector<double>& best = r.front.empty() ? start : r.front[r.compromise].variables;
  if (r.map) {
    out.figures.push_back(
        {"fitness_map", map_figure("mean |k - k*|", *settings.map, *r.map, 0, 2, start, best, r.variables)});
    out.figures.push_back(
        {"torsion_map", map_figure("mean |tau - tau*|", *settings.map, *r.map, 1, 2, start, best, r.variables)});
    const std::vector<std::string> names{"curvature", "torsion"};
    out.tables.push_back({"fitness_map.csv", match_map_csv(*r.map, names)});
  }
  std::vector<Vec3> before(n), after(n);
  match.points_from(start, before);
  match.points_from(best, after);
  add_before_after(out, match.sampler().curve(before), before, match.sampler().curve(after), after,
                   "Start curve (x-y view)", "Best compromise (x-y view)", "best compromise");
  const SvgStyle grey{"#888888", 1.5, {}, "6 4"}, blue{"#1f5fbf", 2.0, {}, {}}, red{"#c03030", 2.0, {}, "3 3"};
  const auto& u = match.sampler().abscissae();
  {
    SvgFigure fig;
    fig.set_title("Curvature profile");
    fig.set_axes("u", "curvature");
    fig.add_polyline(u, match.curvature_samples(start), grey, "start");
    fig.add_polyline(u, match.target_samples(), red, "target");
    fig.add_polyline(u, match.curvature_samples(best), blue, "best compromise");
    out.figures.push_back({"profile", std::move(fig)});
  }
  {
    SvgFigure fig;
    fig.set_title("Torsion profile");
    fig.set_axes("u", "torsion");
    fig.add_polyline(u, match.torsion_samples(start), grey, "start");
    fig.add_polyline(u, match.torsion_target_samples(), red, "target");
    fig.add_polyline(u, match.torsion_samples(best), blue, "best compromise");
    out.figures.push_back({"torsion_profile", std::move(fig)});
  }
  {
    SvgFigure fig;
    fig.set_title("Pareto set: mean curvature error vs mean torsion error");
    fig.set_axes("mean |k - k*|", "mean |tau - tau*|");
    std::vector<double> ek, et, pk, pt;
    for (const auto& m : r.front) {
      (m.polished ? pk : ek).push_back(m.curvature);
      (m.polished ? pt : et).push_back(m.torsion);
    }
    fig.add_points(ek, et, blue, 3.0, "NSGA-II front");
    if (!pk.empty()) fig.add_points(pk, pt, SvgStyle{"#c03030", 1.5, {}, {}}, 5.0, "polished");
    out.figures.push_back({"pareto", std::move(fig)});
  }
  SvgFigure fig;
  fig.set_title("Convergence: best errors in the population");
  fig.set_axes("generation", "mean error");
  fig.set_log_y(true);
  const std::vector<double> g = counting(r.best_curvature.size());
  fig.add_polyline(g, r.best_curvature, blue, "curvature");
  fig.add_polyline(g, r.best_torsion, SvgStyle{"#2a9d4a", 2.0, {}, {}}, "torsion");
  out.figures.push_back({"convergence", std::move(fig)});
  return out;
}

StudyFigures fair_knots_figures(const studies::FairKnotsStudy& study, const studies::FairKnotsOutcome& outcome) {
  const studies::KnotFairingSetup& setup = study.setup;
  const std::string energy = energy_label(setup.energy);
  StudyFigures out;
  const studies::ParameterEvaluation& before = outcome.chord_length;
  out.figures.push_back(
      {"curve_before",
       fairing_curve_figure(setup, before, "chord length: " + energy + " = " + fmt(before.energy), nullptr)});
  const studies::FairingResult* best = outcome.best();
  if (best != nullptr) {
    const bool deterministic = outcome.deterministic && best == &*outcome.deterministic;
    out.figures.push_back(
        {"curve_after", fairing_curve_figure(setup, best->best,
                                             std::string(deterministic ? "deterministic" : "GA") +
                                                 " optimum: " + energy + " = " + fmt(best->best.energy),
                                             &before)});
    SvgFigure conv(800, 500);
    conv.set_title("convergence: best " + energy);
    conv.set_axes("generation (GA) / iteration (Nelder-Mead)", energy);
    const auto add = [&](const studies::FairingResult& r, const char* colour, const char* legend) {
      conv.add_polyline(counting(r.convergence.size()), r.convergence, SvgStyle{.stroke = colour, .width = 1.5},
                        legend);
    };
    if (outcome.ga) add(*outcome.ga, "#d62728", "GA (all rounds)");
    if (outcome.deterministic) add(*outcome.deterministic, "#1f77b4", "Nelder-Mead");
    out.figures.push_back({"convergence", std::move(conv)});
  }
  if (const std::optional<studies::EnergyMap>& map = outcome.map) {
    const std::string k1 = "k" + std::to_string(map->first), k2 = "k" + std::to_string(map->second);
    SvgFigure fig(800, 700);
    fig.set_title("energy map " + energy + " over parameters " + std::to_string(map->first) + " and " +
                  std::to_string(map->second));
    fig.set_axes(k1, k2);
    // log10: the energy rises by decades towards the edges of the triangle, which would leave the region of the
    // minimum in one colour.
    std::vector<double> shown(map->energy.size());
    for (std::size_t i = 0; i < shown.size(); ++i) shown[i] = std::log10(map->energy[i]);
    fig.add_heatmap(map->k1, map->k2, shown, "log10 " + energy);
    const std::vector<double>& chord = before.parameters;
    fig.add_points(std::vector<double>{chord[map->first]}, std::vector<double>{chord[map->second]},
                   SvgStyle{.stroke = "#ffffff", .fill = "#ffffff"}, 5.0, "chord length");
    if (best != nullptr)
      fig.add_points(std::vector<double>{best->best.parameters[map->first]},
                     std::vector<double>{best->best.parameters[map->second]},
                     SvgStyle{.stroke = "#d62728", .fill = "#d62728"}, 5.0, "optimum");
    out.figures.push_back({"energy_map", std::move(fig)});
    if (!outcome.sections.empty()) {
      SvgFigure sections(800, 500);
      sections.set_title("energy map cross sections (Figures 56-57)");
      sections.set_axes(k2, energy);
      sections.set_log_y(true);
      const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e"};
      for (std::size_t i = 0; i < outcome.sections.size(); ++i) {
        const studies::MapSection& s = outcome.sections[i];
        sections.add_polyline(s.k2, s.energy, SvgStyle{.stroke = colours[i % 5], .width = 1.5}, k1 + " = " + fmt(s.k1));
      }
      out.figures.push_back({"energy_sections", std::move(sections)});
    }
    out.tables.push_back({"energy_map.csv", energy_map_csv(*map)});
  }
  return out;
}

StudyFigures edit_projection_figures(const EditProjectionStudy& s, const studies::ProjectionEditResult& r) {
  StudyFigures out;
  for (const diffgeom::Plane plane : {diffgeom::Plane::XY, diffgeom::Plane::YZ, diffgeom::Plane::ZX}) {
    const std::string name(diffgeom::plane_name(plane));
    SvgFigure f = plane_figure("projection on " + name + (plane == s.plane ? " (edited)" : ""), plane);
    draw_curve(f, s.curve.nurbs(), plane, {.stroke = "#999999", .dash = "6 4"}, "original");
    if (plane == s.plane) draw_curve(f, s.edited.nurbs(), plane, {.stroke = "#1f77b4", .width = 4.0}, "edited");
    draw_curve(f, r.curve, plane, {.stroke = "#d62728"}, "rebuilt");
    out.figures.push_back({"projection-" + name, std::move(f)});
  }
  return out;
}

StudyFigures fin_compound_figures(const FinCompoundStudy& study, const FinCompoundRun& run) {
  StudyFigures out;
  if (study.method == FinCompoundMethod::Projection)
    projection_figures(out, study, run);
  else
    combescure_figures(out, study, run);
  return out;
}

StudyFigures hermite_figures(const HermiteStudy&, const studies::HermiteEditResult& r) {
  // The derivatives are per unit of t ∈ [0, 1], so about the curve's length: scaled so the longest handle is a
  // fifth of the curve's size.
  double m1 = 0.0, m2 = 0.0;
  for (const studies::HermiteHandles* h : {&r.before, &r.after})
    for (std::size_t i = 0; i < h->points.size(); ++i) {
      m1 = std::max(m1, norm(h->first[i]));
      m2 = std::max(m2, norm(h->normal_handle[i]));
    }
  const double size = r.spline.model_size();
  const double s1 = m1 > 0 ? 0.2 * size / m1 : 0.0, s2 = m2 > 0 ? 0.2 * size / m2 : 0.0;
  StudyFigures out;
  SvgFigure before = plane_figure("cubic spline and its handles (before)", diffgeom::Plane::XY);
  draw_curve(before, r.spline, diffgeom::Plane::XY, {.stroke = "black"}, "C2 cubic spline");
  draw_handles(before, r.before, s1, s2);
  out.figures.push_back({"before", std::move(before)});
  SvgFigure after = plane_figure("Hermite curve from the edited handles (after)", diffgeom::Plane::XY);
  draw_curve(after, r.spline, diffgeom::Plane::XY, {.stroke = "#999999", .dash = "6 4"}, "spline");
  draw_curve(after, r.curve, diffgeom::Plane::XY, {.stroke = "#d62728"}, "edited");
  draw_handles(after, r.after, s1, s2);
  out.figures.push_back({"after", std::move(after)});
  return out;
}

StudyFigures fit_figures(std::span<const Vec3> points, const studies::ScanFitResult& r) {
  StudyFigures out;
  {
    SvgFigure fig(900, 600);
    fig.set_title("Scanned points, strays and the faired curve (XY)");
    fig.set_equal_aspect(true);
    std::vector<Vec3> kept, strays;
    for (const std::size_t i : r.order) kept.push_back(points[i]);
    for (const std::size_t i : r.strays) strays.push_back(points[i]);
    add_xy_points(fig, kept, SvgStyle{.stroke = "#aaaaaa", .width = 0.5}, 1.0, "kept points");
    add_xy_points(fig, strays, SvgStyle{.stroke = "#d62728", .width = 1.0}, 3.0, "strays");
    const auto [cx, cy] = xy_samples(r.faired, 1000);
    fig.add_polyline(cx, cy, SvgStyle{.stroke = "#1f77b4", .width = 1.8}, "faired curve");
    out.figures.push_back({"fit", std::move(fig)});
  }
  SvgFigure fig(800, 500);
  const bool planar = r.faired.dimension() == 2;
  fig.set_title("Signed curvature before (tolerance fit) and after fairing");
  fig.set_axes("arc length s", planar ? "signed curvature" : "curvature");
  diffgeom::PlotOptions o;
  o.quantity = planar ? diffgeom::PlotQuantity::SignedCurvature : diffgeom::PlotQuantity::Curvature;
  o.abscissa = diffgeom::PlotAbscissa::ArcLength;
  o.samples = 800;
  const diffgeom::Plot before = diffgeom::plot(r.fit, o);
  const diffgeom::Plot after = diffgeom::plot(r.faired, o);
  fig.add_polyline(before.x, before.y, SvgStyle{.stroke = "#999999", .width = 1.2, .dash = "6 4"},
                   "before: " + std::to_string(r.before.inflections) + " inflections, " +
                       std::to_string(r.before.curvature_extrema) + " extrema");
  fig.add_polyline(after.x, after.y, SvgStyle{.stroke = "#d62728", .width = 1.8},
                   "after: " + std::to_string(r.after.inflections) + " inflections, " +
                       std::to_string(r.after.curvature_extrema) + " extrema");
  out.figures.push_back({"curvature", std::move(fig)});
  return out;
}

}  // namespace hula::io
