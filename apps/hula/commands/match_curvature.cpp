// SPDX-License-Identifier: MIT
// `hula match-curvature STUDY [--method ga|hybrid|direct] [--seed N] [--threads N] [--log FILE] [--svg DIR]`:
// a prescribed curvature profile matched over data points (thesis 8.2.1,
// appendix 5) by Flexo's GA, optionally refined by Levenberg–Marquardt
// (studies/match_study.hpp). Prints the result JSON (start/best points,
// distances before/after, evaluations, time, the curve, the resolved study).
// A further method is a new MatchMethod value: match_method_from_name accepts
// its name and run_curvature_match dispatches it; this command needs no change
// beyond the help text.
//
// `hula match-curvature-torsion STUDY [--seed N] [--threads N] [--log FILE] [--svg DIR]`: curvature and
// torsion as two objectives by NSGA-II, with the optional LM polish of the best compromise
// (studies/curvature_torsion_match.hpp). Prints the Pareto set with both errors of every curve.
#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "commands/common.hpp"
#include "commands/fairing_baselines.hpp"
#include "commands/study_common.hpp"
#include "hula/diffgeom/frenet.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/match_study_file.hpp"
#include "hula/studies/curvature_torsion_match.hpp"
#include "hula/studies/match_study.hpp"

namespace hula::cli {

namespace {

struct MatchArgs {
  StudyArgs study;
  std::optional<std::string> method;
  std::optional<std::string> abscissa;
  bool occt = false;
};

void add_curve(io::SvgFigure& fig, const nurbs::NurbsCurve& curve, std::span<const Vec3> points,
               const io::SvgStyle& style, const std::string& legend, bool fins) {
  constexpr int kSamples = 300;
  std::vector<double> x(kSamples + 1), y(kSamples + 1);
  for (int i = 0; i <= kSamples; ++i) {
    const Vec3 p = curve.evaluate(curve.domain().start + curve.domain().length() * i / kSamples);
    x[static_cast<std::size_t>(i)] = p.x;
    y[static_cast<std::size_t>(i)] = p.y;
  }
  fig.add_polyline(x, y, style, legend);
  // Curvature fins P - s κ N (DESIGN, thesis 6.4) at 120 parameters, the longest 15% of the curve's extent.
  constexpr int kFins = 120;
  std::vector<double> t(kFins + 1), kappa(kFins + 1), x1(kFins + 1), y1(kFins + 1), x0(kFins + 1), y0(kFins + 1);
  std::vector<diffgeom::FrenetPoint> frames(kFins + 1);
  for (int i = 0; i <= kFins; ++i)
    t[static_cast<std::size_t>(i)] = curve.domain().start + curve.domain().length() * i / kFins;
  diffgeom::frenet(curve, t, frames);
  double kmax = 0.0;
  for (const auto& f : frames)
    if (f.frame_defined) kmax = std::max(kmax, f.curvature);
  const double extent = std::max(*std::max_element(x.begin(), x.end()) - *std::min_element(x.begin(), x.end()),
                                 *std::max_element(y.begin(), y.end()) - *std::min_element(y.begin(), y.end()));
  if (fins && kmax > 0.0) {
    const double scale = 0.15 * extent / kmax;
    std::size_t m = 0;
    for (const auto& f : frames) {
      if (!f.frame_defined) continue;
      const Vec3 end = f.position - scale * f.curvature * f.normal;
      x0[m] = f.position.x;
      y0[m] = f.position.y;
      x1[m] = end.x;
      y1[m] = end.y;
      ++m;
    }
    for (auto* v : {&x0, &y0, &x1, &y1}) v->resize(m);
    io::SvgStyle fin = style;
    fin.width = 0.6;
    fin.dash.clear();
    fig.add_segments(x0, y0, x1, y1, fin);
  }
  std::vector<double> px, py;
  for (const Vec3& p : points) {
    px.push_back(p.x);
    py.push_back(p.y);
  }
  fig.add_points(px, py, style, 3.0);
}

// The direct method's figures: the start spline and the reconstructed curve, and the profiles (the target,
// the start spline's and the reconstruction's, against normalised arc length).
void write_direct_figures(const std::filesystem::path& dir, const studies::CurvatureMatch& match,
                          const studies::DirectReconstructionResult& d, const std::vector<Vec3>& before) {
  const io::SvgStyle grey{"#888888", 1.5, {}, "6 4"}, blue{"#1f5fbf", 2.0, {}, {}};
  const nurbs::NurbsCurve& curve = d.nurbs->curve;
  for (const bool is_after : {false, true}) {
    io::SvgFigure fig;
    fig.set_equal_aspect(true);
    fig.set_title(is_after ? "Direct reconstruction (x-y view)" : "Start curve (x-y view)");
    if (is_after) add_curve(fig, match.sampler().curve(before), before, grey, "start", false);
    add_curve(fig, is_after ? curve : match.sampler().curve(before), is_after ? std::vector<Vec3>{} : before, blue,
              is_after ? "reconstructed" : "start", true);
    write_svg(dir, is_after ? "curve_after" : "curve_before", fig);
  }
  const auto& u = match.sampler().abscissae();
  std::vector<double> s(u.size()), kappa(u.size()), tau(u.size());
  for (std::size_t i = 0; i < u.size(); ++i) s[i] = curve.domain().start + u[i] * curve.domain().length();
  diffgeom::curvature_torsion(curve, s, kappa, tau);
  io::SvgFigure fig;
  fig.set_title("Curvature profile");
  fig.set_axes("u (normalised arc length)", "curvature");
  fig.add_polyline(u, match.curvature_samples(match.start_variables()), grey, "start");
  fig.add_polyline(u, match.target_samples(), io::SvgStyle{"#c03030", 2.0, {}, "3 3"}, "target");
  fig.add_polyline(u, kappa, blue, "reconstructed");
  write_svg(dir, "profile", fig);
}

// The fitness map (the study's `map` member) of one objective, log10 as fair-knots' energy map (the distance
// rises by decades away from the minimum), with the start and the result marked; and the map as CSV.
void write_map_figure(const std::filesystem::path& dir, const std::string& name, const std::string& title,
                      const studies::MatchMapSettings& settings, const optim::SweepResult& map, std::size_t objective,
                      std::size_t objectives, std::span<const double> start, std::span<const double> best,
                      std::span<const optim::Variable> variables) {
  const std::array<std::size_t, 2> axes = settings.axes(variables);
  std::vector<double> shown(map.objective.size());
  for (std::size_t i = 0; i < shown.size(); ++i) {
    const double e = map.values[i * objectives + objective];
    shown[i] = e > 0.0 ? std::log10(e) : std::numeric_limits<double>::quiet_NaN();
  }
  io::SvgFigure fig(800, 700);
  fig.set_title(title + " over " + settings.variables[0] + " and " + settings.variables[1] +
                " (other variables at the result)");
  fig.set_axes(settings.variables[0], settings.variables[1]);
  fig.add_heatmap(map.x_values, map.y_values, shown, "log10 " + title);
  fig.add_points(std::vector<double>{start[axes[0]]}, std::vector<double>{start[axes[1]]},
                 io::SvgStyle{.stroke = "#ffffff", .fill = "#ffffff"}, 5.0, "start");
  fig.add_points(std::vector<double>{best[axes[0]]}, std::vector<double>{best[axes[1]]},
                 io::SvgStyle{.stroke = "#d62728", .fill = "#d62728"}, 5.0, "result");
  write_svg(dir, name, fig);
}

void write_figures(const std::filesystem::path& dir, const studies::CurvatureMatch& match,
                   const studies::MatchResult& r, const studies::MatchStudy& study) {
  if (r.map) {
    write_map_figure(dir, "fitness_map", "mean |k - k*|", *study.map, *r.map, 0, 1, r.start, r.best, r.variables);
    const std::vector<std::string> names{"objective"};
    io::write_file_atomically(dir / "fitness_map.csv", io::match_map_csv(*r.map, names));
  }
  const std::size_t n = match.setup().points.size();
  std::vector<Vec3> before(n), after(n);
  match.points_from(r.start, before);
  match.points_from(r.best, after);
  if (r.direct && r.direct->nurbs) {
    write_direct_figures(dir, match, *r.direct, before);
    return;
  }
  const io::SvgStyle grey{"#888888", 1.5, {}, "6 4"}, blue{"#1f5fbf", 2.0, {}, {}};
  for (const bool is_after : {false, true}) {
    io::SvgFigure fig;
    fig.set_equal_aspect(true);
    fig.set_title(is_after ? "Optimised curve (x-y view)" : "Start curve (x-y view)");
    if (is_after) add_curve(fig, match.sampler().curve(before), before, grey, "start", false);
    add_curve(fig, match.sampler().curve(is_after ? after : before), is_after ? after : before, blue,
              is_after ? "optimised" : "start", true);
    write_svg(dir, is_after ? "curve_after" : "curve_before", fig);
  }
  {
    io::SvgFigure fig;
    fig.set_title("Curvature profile");
    fig.set_axes("u (parameter on [0, 1])", "curvature");
    const auto& u = match.sampler().abscissae();
    fig.add_polyline(u, match.curvature_samples(r.start), grey, "start");
    fig.add_polyline(u, match.target_samples(), io::SvgStyle{"#c03030", 2.0, {}, "3 3"}, "target");
    fig.add_polyline(u, match.curvature_samples(r.best), blue, "achieved");
    write_svg(dir, "profile", fig);
  }
  {
    io::SvgFigure fig;
    fig.set_title("Convergence: best mean curvature distance");
    fig.set_axes("generation", "mean |k - k*|");
    fig.set_log_y(true);
    std::vector<double> g(r.convergence.size());
    for (std::size_t i = 0; i < g.size(); ++i) g[i] = static_cast<double>(i);
    fig.add_polyline(g, r.convergence, blue, "GA best");
    if (r.lm) {
      const double x = g.empty() ? 0.0 : g.back();
      fig.add_points(std::vector<double>{x}, std::vector<double>{r.after.mean}, io::SvgStyle{"#c03030", 1.5, {}, {}},
                     4.0, "after LM");
    }
    write_svg(dir, "convergence", fig);
  }
}

int run_match(const MatchArgs& a) {
  io::StudyDocument doc = load_study(a.study, "match-curvature");
  // --abscissa replaces the file's member before it is read, so a target given "of_points" is derived in it.
  if (a.abscissa)
    doc.body["abscissa"] =
        std::string(studies::profile_abscissa_name(studies::profile_abscissa_from_name(*a.abscissa, "--abscissa")));
  const std::filesystem::path base = std::filesystem::path(a.study.study).parent_path();
  io::MatchStudyFile file = io::match_study_from_json(doc, io::relative_to(base));
  studies::MatchStudy& study = file.study;
  if (a.method) study.method = studies::match_method_from_name(*a.method, "--method");
  const studies::CurvatureMatch match(study.setup);
  const InterruptGuard guard;  // Ctrl-C ends the GA with its best so far, as --time does
  const studies::MatchResult result = studies::run_curvature_match(match, study, a.study.log.has_value());
  if (a.study.log) write_run_log(result.log, *a.study.log);
  if (a.study.svg) write_figures(*a.study.svg, match, result, study);
  Json out = io::match_result_to_json(match, file, result);
  if (a.occt) {
    // Open CASCADE's fairing baselines with the ends of the best curve (the direct route's NURBS, else the spline
    // through the best points), measured against the best points.
    if (study.setup.dimension != 2)
      throw Error(Errc::InvalidArgument, "--occt compares planar curves: the study's points are 3-D",
                  {.field = "--occt"});
    const std::size_t n = study.setup.points.size();
    std::vector<Vec3> start(n), best(n);
    match.points_from(result.start, start);
    match.points_from(result.best, best);
    const nurbs::NurbsCurve start_curve = match.sampler().curve(start);
    const nurbs::NurbsCurve best_curve =
        result.direct && result.direct->nurbs ? result.direct->nurbs->curve : match.sampler().curve(best);
    const std::vector<Vec3>& measured = result.direct ? result.direct_points : best;
    out["occt"] = occt_baselines(measured, best_curve, {{"start", &start_curve}, {"best", &best_curve}}, a.study.svg);
  }
  for (const auto& w : out["warnings"]) std::cerr << "hula: warning: " << w.get<std::string>() << "\n";
  print_json(out);
  return kExitOk;
}

std::vector<double> torsion_samples(const studies::CurvatureMatch& match, std::span<const double> x) {
  studies::SplineProfileSampler::Workspace ws;
  std::vector<Vec3> points(match.setup().points.size());
  const std::size_t n = match.sampler().abscissae().size();
  std::vector<double> kappa(n), tau(n);
  match.points_from(x, points);
  (void)match.sampler().sample(points, ws, kappa, tau);
  return tau;
}

void write_torsion_figures(const std::filesystem::path& dir, const studies::CurvatureMatch& match,
                           const studies::TorsionMatchResult& r, const studies::TorsionMatchSettings& settings) {
  const std::size_t n = match.setup().points.size();
  const std::vector<double> start = match.start_variables();
  const std::vector<double>& best = r.front.empty() ? start : r.front[r.compromise].variables;
  if (r.map) {
    write_map_figure(dir, "fitness_map", "mean |k - k*|", *settings.map, *r.map, 0, 2, start, best, r.variables);
    write_map_figure(dir, "torsion_map", "mean |tau - tau*|", *settings.map, *r.map, 1, 2, start, best, r.variables);
    const std::vector<std::string> names{"curvature", "torsion"};
    io::write_file_atomically(dir / "fitness_map.csv", io::match_map_csv(*r.map, names));
  }
  std::vector<Vec3> before(n), after(n);
  match.points_from(start, before);
  match.points_from(best, after);
  const io::SvgStyle grey{"#888888", 1.5, {}, "6 4"}, blue{"#1f5fbf", 2.0, {}, {}}, red{"#c03030", 2.0, {}, "3 3"};
  for (const bool is_after : {false, true}) {
    io::SvgFigure fig;
    fig.set_equal_aspect(true);
    fig.set_title(is_after ? "Best compromise (x-y view)" : "Start curve (x-y view)");
    if (is_after) add_curve(fig, match.sampler().curve(before), before, grey, "start", false);
    add_curve(fig, match.sampler().curve(is_after ? after : before), is_after ? after : before, blue,
              is_after ? "best compromise" : "start", true);
    write_svg(dir, is_after ? "curve_after" : "curve_before", fig);
  }
  const auto& u = match.sampler().abscissae();
  {
    io::SvgFigure fig;
    fig.set_title("Curvature profile");
    fig.set_axes("u", "curvature");
    fig.add_polyline(u, match.curvature_samples(start), grey, "start");
    fig.add_polyline(u, match.target_samples(), red, "target");
    fig.add_polyline(u, match.curvature_samples(best), blue, "best compromise");
    write_svg(dir, "profile", fig);
  }
  {
    io::SvgFigure fig;
    fig.set_title("Torsion profile");
    fig.set_axes("u", "torsion");
    fig.add_polyline(u, torsion_samples(match, start), grey, "start");
    fig.add_polyline(u, match.torsion_target_samples(), red, "target");
    fig.add_polyline(u, torsion_samples(match, best), blue, "best compromise");
    write_svg(dir, "torsion_profile", fig);
  }
  {
    io::SvgFigure fig;
    fig.set_title("Pareto set: mean curvature error vs mean torsion error");
    fig.set_axes("mean |k - k*|", "mean |tau - tau*|");
    std::vector<double> ek, et, pk, pt;
    for (const auto& m : r.front) {
      (m.polished ? pk : ek).push_back(m.curvature);
      (m.polished ? pt : et).push_back(m.torsion);
    }
    fig.add_points(ek, et, blue, 3.0, "NSGA-II front");
    if (!pk.empty()) fig.add_points(pk, pt, io::SvgStyle{"#c03030", 1.5, {}, {}}, 5.0, "polished");
    write_svg(dir, "pareto", fig);
  }
  {
    io::SvgFigure fig;
    fig.set_title("Convergence: best errors in the population");
    fig.set_axes("generation", "mean error");
    fig.set_log_y(true);
    std::vector<double> g(r.best_curvature.size());
    for (std::size_t i = 0; i < g.size(); ++i) g[i] = static_cast<double>(i);
    fig.add_polyline(g, r.best_curvature, blue, "curvature");
    fig.add_polyline(g, r.best_torsion, io::SvgStyle{"#2a9d4a", 2.0, {}, {}}, "torsion");
    write_svg(dir, "convergence", fig);
  }
}

int run_match_torsion(const StudyArgs& a) {
  const io::StudyDocument doc = load_study(a, "match-curvature-torsion");
  const std::filesystem::path base = std::filesystem::path(a.study).parent_path();
  io::TorsionMatchStudyFile file = io::torsion_match_study_from_json(doc, io::relative_to(base));
  studies::TorsionMatchStudy& study = file.study;
  study.settings.wall_time_seconds = doc.header.wall_time_seconds;
  study.settings.cancel = doc.header.cancel;
  const InterruptGuard guard;  // Ctrl-C ends NSGA-II with its front so far, as --time does
  const studies::CurvatureMatch match(study.setup);
  const studies::TorsionMatchResult result = studies::run_curvature_torsion_match(
      match, study.settings, study.header.seed, study.header.threads, a.log.has_value());
  if (a.log) write_run_log(result.log, *a.log);
  if (a.svg) write_torsion_figures(*a.svg, match, result, study.settings);
  const Json out = io::torsion_match_result_to_json(match, file, result);
  if (out.contains("warnings"))
    for (const auto& w : out["warnings"]) std::cerr << "hula: warning: " << w.get<std::string>() << "\n";
  print_json(out);
  return kExitOk;
}

}  // namespace

Command add_match_curvature_torsion(CLI::App& app) {
  auto a = std::make_shared<StudyArgs>();
  CLI::App* sub = app.add_subcommand(
      "match-curvature-torsion",
      "Match prescribed curvature and torsion profiles as two objectives (NSGA-II, optional LM polish)");
  add_study_options(sub, *a);
  sub->footer(
      "--svg DIR writes curve_before.svg, curve_after.svg, profile.svg, torsion_profile.svg, pareto.svg, "
      "convergence.svg, and with a \"map\" fitness_map.svg, torsion_map.svg and fitness_map.csv.");
  return {sub, [a] { return run_match_torsion(*a); }};
}

Command add_match_curvature(CLI::App& app) {
  auto a = std::make_shared<MatchArgs>();
  CLI::App* sub = app.add_subcommand(
      "match-curvature",
      "Match a prescribed curvature profile by moving data points (GA, or GA + Levenberg-Marquardt)");
  add_study_options(sub, a->study);
  sub->footer(
      "--svg DIR writes curve_before.svg, curve_after.svg, profile.svg, convergence.svg, and with a \"map\" "
      "fitness_map.svg and fitness_map.csv.");
  sub->add_option("--method", a->method, "ga | hybrid | direct (overrides the study file's \"method\")");
  sub->add_option("--abscissa", a->abscissa,
                  "arclength | parameter: what the target's u measures (overrides the study file's \"abscissa\"; "
                  "direct converts a parameter target to arc length through the start spline)");
  sub->add_flag("--occt", a->occt,
                "Add Open CASCADE's fairing baselines between the best curve's ends with its end tangents and "
                "curvatures: \"occt\" in the output, baselines.svg under --svg (planar studies)");
  return {sub, [a] { return run_match(*a); }};
}

}  // namespace hula::cli
