// SPDX-License-Identifier: MIT
// `hula fair-knots STUDY`: the knot-vector studies of thesis 7.2–7.4 from a
// "fair-knots" study file — chord-length start, the given parameters,
// the energy map, GA and/or deterministic fairing — as JSON, with the
// before/after curves (curvature fins), the energy map and the convergence
// graphs as SVG and the map as CSV under --svg DIR. `--occt` adds Open
// CASCADE's fairing baselines (oli/kernel/occt_fairing.hpp: FairCurve_Batten
// fixed and sliding, FairCurve_MinimalVariation) with the best curve's end
// tangents and curvatures, their energies and deviations from the data points
// under "occt", and `baselines.svg` with every curve and its curvature comb.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "commands/common.hpp"
#include "commands/fairing_baselines.hpp"
#include "commands/study_common.hpp"
#include "hula/diffgeom/fins.hpp"
#include "hula/diffgeom/frenet.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/fair_knots_study_file.hpp"
#include "hula/io/json_curve.hpp"

namespace hula::cli {

namespace {

// The curve with its curvature fins (Figures 59, 63, 65–67), the data points,
// and optionally a reference curve dashed.
io::SvgFigure curve_figure(const studies::KnotFairingSetup& setup, const studies::ParameterEvaluation& e,
                           const std::string& title, const studies::ParameterEvaluation* reference) {
  io::SvgFigure fig(800, 700);
  fig.set_title(title);
  fig.set_equal_aspect(true);
  auto sample = [](const nurbs::NurbsCurve& c, std::vector<double>& x, std::vector<double>& y) {
    const int n = 600;
    for (int i = 0; i <= n; ++i) {
      const Vec3 p = c.evaluate(static_cast<double>(i) / n);
      x.push_back(p.x);
      y.push_back(p.y);
    }
  };
  add_fins(fig, e.curve, fin_scale(e.curve), "#9ecae1", "#3182bd", "curvature fins");
  if (reference != nullptr) {
    std::vector<double> rx, ry;
    sample(reference->curve, rx, ry);
    fig.add_polyline(rx, ry, io::SvgStyle{.stroke = "#888888", .width = 1.2, .dash = "6,4"}, "chord length");
  }
  std::vector<double> cx, cy;
  sample(e.curve, cx, cy);
  fig.add_polyline(cx, cy, io::SvgStyle{.stroke = "#000000", .width = 2.0}, "curve");
  std::vector<double> px, py;
  for (const Vec3& q : setup.points) {
    px.push_back(q.x);
    py.push_back(q.y);
  }
  fig.add_points(px, py, io::SvgStyle{.stroke = "#d62728", .fill = "#d62728"}, 4.0, "data points");
  return fig;
}

std::string energy_label(studies::FairingEnergy e) {
  return e == studies::FairingEnergy::Bending ? "∫κ² ds" : "∫(dκ/ds)² ds";
}

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

int run_fair_knots(const StudyArgs& args, bool occt) {
  const io::StudyDocument doc = load_study(args, "fair-knots");
  studies::FairKnotsStudy study = io::fair_knots_study_from_json(doc);
  // --time and Ctrl-C end each optimiser with its best so far ("stopped": true).
  for (optim::StopCriteria* stop : {&study.ga.binary.run.stop, &study.ga.real.run.stop}) {
    stop->wall_time_seconds = doc.header.wall_time_seconds;
    stop->cancel = doc.header.cancel;
  }
  study.deterministic.wall_time_seconds = doc.header.wall_time_seconds;
  study.deterministic.cancel = doc.header.cancel;
  const InterruptGuard guard;
  const studies::KnotFairingSetup& setup = study.setup;

  const std::vector<double> chord = studies::chord_length_parameters(setup);
  const studies::ParameterEvaluation before = studies::evaluate_parameters(setup, chord);
  Json out = Json::object();
  out["study"] = io::fair_knots_study_to_json(study);
  out["energy"] = studies::fairing_energy_name(setup.energy);
  out["chord_length"] = io::fairing_evaluation_to_json(before);
  if (study.parameters)
    out["given"] = io::fairing_evaluation_to_json(studies::evaluate_parameters(setup, *study.parameters));

  // The map and its sections first: they are evaluations of the setup, and
  // their errors should come before the optimisers run.
  std::optional<studies::EnergyMap> map;
  std::vector<studies::MapSection> sections;
  if (study.map) {
    map = studies::energy_map(setup, chord, *study.map);
    out["map"] = Json{{"knots", Json::array({map->first, map->second})},
                      {"grid", study.map->grid},
                      {"min", Json{{"energy", map->min_energy}, {"k1", map->min_k1}, {"k2", map->min_k2}}}};
    for (const double k1 : study.sections) {
      sections.push_back(studies::map_section(setup, chord, *study.map, k1, 201));
      const studies::MapSection& sec = sections.back();
      Json energies = Json::array();
      for (const double e : sec.energy) energies.push_back(std::isfinite(e) ? Json(e) : Json(nullptr));
      out["map"]["sections"].push_back(Json{{"k1", sec.k1}, {"k2", sec.k2}, {"energy", energies}});
    }
  }

  optim::RunLog log;
  std::optional<studies::FairingResult> ga;
  std::optional<studies::FairingResult> det;
  const bool run_ga = study.method == studies::FairingMethod::Ga || study.method == studies::FairingMethod::Both;
  const bool run_det =
      study.method == studies::FairingMethod::Deterministic || study.method == studies::FairingMethod::Both;
  if (run_ga) {
    ga = studies::fair_knots_ga(setup, chord, study.ga, args.log ? &log : nullptr);
    out["ga"] = io::fairing_result_to_json(*ga, before.energy);
  }
  if (run_det) {
    det = studies::fair_knots_deterministic(setup, chord, study.deterministic);
    out["deterministic"] = io::fairing_result_to_json(*det, before.energy);
  }
  if (ga && det) {
    double dp = 0.0;
    for (std::size_t i = 0; i < chord.size(); ++i)
      dp = std::max(dp, std::abs(ga->best.parameters[i] - det->best.parameters[i]));
    out["agreement"] = Json{{"relative_energy", ga->best.energy / det->best.energy - 1.0}, {"max_parameter", dp}};
  }
  if (occt) {
    const nurbs::NurbsCurve* reference = &before.curve;
    if (ga) reference = &ga->best.curve;
    if (det && (!ga || det->best.energy < ga->best.energy)) reference = &det->best.curve;
    std::vector<std::pair<std::string, const nurbs::NurbsCurve*>> studied{{"chord length", &before.curve}};
    if (ga) studied.emplace_back("GA", &ga->best.curve);
    if (det) studied.emplace_back("Nelder-Mead", &det->best.curve);
    out["occt"] = occt_baselines(setup.points, *reference, studied, args.svg);
  }
  if (args.log && run_ga) write_run_log(log, *args.log);
  if (args.svg) {
    const std::filesystem::path dir = *args.svg;
    write_svg(dir, "curve_before",
              curve_figure(setup, before, "chord length: " + energy_label(setup.energy) + " = " + fmt(before.energy),
                           nullptr));
    const studies::FairingResult* best = nullptr;
    if (ga) best = &*ga;
    if (det && (best == nullptr || det->best.energy < best->best.energy)) best = &*det;
    if (best != nullptr) {
      write_svg(dir, "curve_after",
                curve_figure(setup, best->best,
                             std::string(best == &*det ? "deterministic" : "GA") +
                                 " optimum: " + energy_label(setup.energy) + " = " + fmt(best->best.energy),
                             &before));
      io::SvgFigure conv(800, 500);
      conv.set_title("convergence: best " + energy_label(setup.energy));
      conv.set_axes("generation (GA) / iteration (Nelder-Mead)", energy_label(setup.energy));
      auto add = [&](const studies::FairingResult& r, const char* colour, const char* legend) {
        std::vector<double> x(r.convergence.size());
        for (std::size_t i = 0; i < x.size(); ++i) x[i] = static_cast<double>(i);
        conv.add_polyline(x, r.convergence, io::SvgStyle{.stroke = colour, .width = 1.5}, legend);
      };
      if (ga) add(*ga, "#d62728", "GA (all rounds)");
      if (det) add(*det, "#1f77b4", "Nelder-Mead");
      write_svg(dir, "convergence", conv);
    }
    if (map) {
      io::SvgFigure fig(800, 700);
      fig.set_title("energy map " + energy_label(setup.energy) + " over parameters " + std::to_string(map->first) +
                    " and " + std::to_string(map->second));
      fig.set_axes("k" + std::to_string(map->first), "k" + std::to_string(map->second));
      // log10: the energy rises by decades towards the edges of the triangle,
      // which would leave the region of the minimum in one colour.
      std::vector<double> shown(map->energy.size());
      for (std::size_t i = 0; i < shown.size(); ++i) shown[i] = std::log10(map->energy[i]);
      fig.add_heatmap(map->k1, map->k2, shown, "log10 " + energy_label(setup.energy));
      const std::vector<double> cx{chord[map->first]}, cy{chord[map->second]};
      fig.add_points(cx, cy, io::SvgStyle{.stroke = "#ffffff", .fill = "#ffffff"}, 5.0, "chord length");
      if (best != nullptr) {
        const std::vector<double> bx{best->best.parameters[map->first]}, by{best->best.parameters[map->second]};
        fig.add_points(bx, by, io::SvgStyle{.stroke = "#d62728", .fill = "#d62728"}, 5.0, "optimum");
      }
      write_svg(dir, "energy_map", fig);
      if (!sections.empty()) {
        io::SvgFigure sec_fig(800, 500);
        sec_fig.set_title("energy map cross sections (Figures 56-57)");
        sec_fig.set_axes("k" + std::to_string(map->second), energy_label(setup.energy));
        sec_fig.set_log_y(true);
        const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e"};
        for (std::size_t i = 0; i < sections.size(); ++i) {
          sec_fig.add_polyline(sections[i].k2, sections[i].energy, io::SvgStyle{.stroke = colours[i % 5], .width = 1.5},
                               "k" + std::to_string(map->first) + " = " + fmt(sections[i].k1));
        }
        write_svg(dir, "energy_sections", sec_fig);
      }
      io::write_file_atomically(dir / "energy_map.csv", io::energy_map_csv(*map));
    }
  }
  print_json(out);
  return kExitOk;
}

}  // namespace

Command add_fair_knots(CLI::App& app) {
  auto args = std::make_shared<StudyArgs>();
  CLI::App* sub = app.add_subcommand(
      "fair-knots",
      "Knot-vector studies (thesis 7.2-7.4): chord-length start, evaluation of given parameters, energy map, "
      "GA and deterministic fairing of the data parameters of a cubic spline");
  add_study_options(sub, *args);
  sub->footer(
      "--svg DIR writes curve_before.svg, curve_after.svg (curves with curvature fins), convergence.svg, and with "
      "a \"map\" energy_map.svg, energy_map.csv and (with map.sections) energy_sections.svg. --log writes the GA's run "
      "log (all rounds).");
  auto occt = std::make_shared<bool>(false);
  sub->add_flag("--occt", *occt,
                "Add Open CASCADE's fairing baselines (FairCurve_Batten fixed and sliding, FairCurve_MinimalVariation) "
                "with the best curve's end tangents and curvatures: \"occt\" in the output, baselines.svg under --svg");
  return {sub, [args, occt] { return run_fair_knots(*args, *occt); }};
}

}  // namespace hula::cli
