// SPDX-License-Identifier: MIT
// `hula fin-compound STUDY`: prescribed compound fins (thesis 8.3). Method
// "projection": the normal fin compound of a projection and, given an edited
// compound, the projection whose compound it is and the 3-D curve rebuilt from
// it; method "combescure": the Combescure compound of a parent curve, or the
// parent of a prescribed compound. JSON out (curves as "nurbs" curve
// documents, measured deviations); --svg DIR writes before/after figures.
#include <memory>
#include <optional>
#include <string>

#include "commands/common.hpp"
#include "commands/editing_common.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/editing_study_file.hpp"
#include "hula/io/json_curve.hpp"

namespace hula::cli {

namespace {

struct FinCompoundArgs {
  StudyArgs study;
  std::string output;
};

constexpr int kFins = 60;  // fins drawn per curve in the figures

// P(t_i) and Q(t_i) at kFins + 1 parameters of P's domain (Q on the same parameterisation).
void fin_points(const nurbs::NurbsCurve& p, const nurbs::NurbsCurve& q, std::vector<Vec3>& base,
                std::vector<Vec3>& tip) {
  for (int i = 0; i <= kFins; ++i) {
    const double u = static_cast<double>(i) / kFins;
    base.push_back(p.evaluate(p.domain().start * (1 - u) + p.domain().end * u));
    tip.push_back(q.evaluate(q.domain().start * (1 - u) + q.domain().end * u));
  }
}

// The figures of the projection technique (before; after, given a prescribed compound).
void projection_figures(const io::FinCompoundStudy& s, const io::FinCompoundRun& run, const std::string& dir) {
  const studies::NormalCompoundOptions& o = s.projection;
  const nurbs::NurbsCurve& curve = s.curve->nurbs();
  const nurbs::NurbsCurve& projection = *run.projection;
  const studies::LawCurveFit& compound = *run.compound;
  const std::optional<studies::CompoundEditResult>& edit = run.edit;
  std::vector<Vec3> base, tip;
  fin_points(projection, compound.curve, base, tip);
  io::SvgFigure before = plane_figure("normal fin compound of the projection (before)", o.plane);
  draw_segments(before, base, tip, o.plane, {.stroke = "#999999", .width = 0.8}, "fins");
  draw_curve(before, projection, o.plane, {.stroke = "black"}, "projection");
  draw_curve(before, compound.curve, o.plane, {.stroke = "#1f77b4"}, "compound");
  write_svg(dir, "before", before);
  if (edit) {
    base.clear();
    tip.clear();
    fin_points(edit->planar.curve, s.compound->nurbs(), base, tip);
    io::SvgFigure after = plane_figure("prescribed compound and its curve (after)", o.plane);
    draw_curve(after, projection, o.plane, {.stroke = "#999999", .dash = "6 4"}, "original projection");
    draw_segments(after, base, tip, o.plane, {.stroke = "#bbbbbb", .width = 0.8}, "fins");
    draw_curve(after, edit->planar.curve, o.plane, {.stroke = "#d62728"}, "new projection");
    draw_curve(after, s.compound->nurbs(), o.plane, {.stroke = "#1f77b4"}, "prescribed compound");
    write_svg(dir, "after", after);
    for (diffgeom::Plane other : {diffgeom::Plane::XY, diffgeom::Plane::YZ, diffgeom::Plane::ZX}) {
      if (other == o.plane) continue;
      io::SvgFigure f = plane_figure(std::string("3-D curve seen on ") + std::string(diffgeom::plane_name(other)) +
                                         " (the unchanged coordinate is kept)",
                                     other);
      draw_curve(f, curve, other, {.stroke = "#999999", .dash = "6 4"}, "original");
      draw_curve(f, edit->curve, other, {.stroke = "#d62728"}, "rebuilt");
      write_svg(dir, "rebuilt-" + std::string(diffgeom::plane_name(other)), f);
    }
  }
}

// The figures of the Combescure transform: parent, compound and fins on XY and ZX.
void combescure_figures(const io::FinCompoundStudy& s, const io::FinCompoundRun& run, const std::string& dir) {
  const bool forward = s.curve.has_value();
  const nurbs::NurbsCurve& input = forward ? s.curve->nurbs() : s.compound->nurbs();
  const nurbs::NurbsCurve& result = run.result_curve();
  const nurbs::NurbsCurve& p = forward ? input : result;
  const nurbs::NurbsCurve& q = forward ? result : input;
  std::vector<Vec3> base, tip;
  fin_points(p, q, base, tip);
  for (diffgeom::Plane plane : {diffgeom::Plane::XY, diffgeom::Plane::ZX}) {
    io::SvgFigure f = plane_figure(std::string("Combescure compound Q = P + C (tau/kappa T + B), seen on ") +
                                       std::string(diffgeom::plane_name(plane)),
                                   plane);
    draw_segments(f, base, tip, plane, {.stroke = "#999999", .width = 0.8}, "R = Q - P");
    draw_curve(f, p, plane, {.stroke = "black"}, "parent P");
    draw_curve(f, q, plane, {.stroke = "#1f77b4"}, "compound Q");
    write_svg(dir, "combescure-" + std::string(diffgeom::plane_name(plane)), f);
  }
}

int run_fin_compound(const FinCompoundArgs& a) {
  if (!a.output.empty()) io::check_output_path(a.output, "--output");
  const io::StudyDocument doc = load_study(a.study, "fin-compound");
  const io::FinCompoundStudy s = io::read_fin_compound_study(doc);
  const io::FinCompoundRun run = io::run_fin_compound_study(s);
  Json out = io::fin_compound_result_to_json(s, run);
  if (!a.output.empty()) io::write_curve_file(a.output, run.result_curve());
  if (a.study.svg) {
    if (s.method == io::FinCompoundMethod::Projection)
      projection_figures(s, run, *a.study.svg);
    else
      combescure_figures(s, run, *a.study.svg);
  }
  record_run(out, s.header, a.study);
  print_result(out, a.output);
  return kExitOk;
}

}  // namespace

Command add_fin_compound(CLI::App& app) {
  auto args = std::make_shared<FinCompoundArgs>();
  CLI::App* sub = app.add_subcommand(
      "fin-compound", "Prescribed compound fins (thesis 8.3): projection technique or Combescure transform");
  add_study_options(sub, args->study, false);
  sub->add_option("-o,--output", args->output,
                  "Write the resulting curve file (rebuilt 3-D curve, compound, or parent), atomically");
  return {sub, [args] { return run_fin_compound(*args); }};
}

}  // namespace hula::cli
