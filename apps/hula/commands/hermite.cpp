// SPDX-License-Identifier: MIT
// `hula hermite STUDY`: Hermite editing (thesis 7.5.2). The C2 cubic spline
// through the points, its tangent and normal handles at the knots, the edits
// (rotations in degrees, scales) applied to P' and P'', and the curve rebuilt
// by the quintic (C2) or cubic (C1) Hermite. JSON out: both curves and the
// handles per knot; --svg DIR draws the spline and the edited curve with their
// handles (cf. thesis figures 69–71).
#include <algorithm>
#include <memory>
#include <string>

#include "commands/common.hpp"
#include "commands/editing_common.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/editing_study_file.hpp"
#include "hula/io/json_curve.hpp"

namespace hula::cli {

namespace {

struct HermiteArgs {
  StudyArgs study;
  std::string output;
};

// The handles drawn at a common display scale (the derivatives are per unit of t ∈ [0, 1], so about
// the curve's length: scaled so the longest handle is a fifth of the curve's size).
void draw_handles(io::SvgFigure& f, const studies::HermiteHandles& h, double scale_first, double scale_second) {
  std::vector<Vec3> tip1, tip2;
  for (std::size_t i = 0; i < h.points.size(); ++i) {
    tip1.push_back(h.points[i] + scale_first * h.first[i]);
    tip2.push_back(h.points[i] + scale_second * h.normal_handle[i]);
  }
  draw_segments(f, h.points, tip1, diffgeom::Plane::XY, {.stroke = "#2ca02c", .width = 2.0}, "T|P'|");
  draw_segments(f, h.points, tip2, diffgeom::Plane::XY, {.stroke = "#9467bd", .width = 2.0}, "N|P''|");
  std::vector<double> x, y;
  for (const Vec3& p : h.points) {
    x.push_back(p.x);
    y.push_back(p.y);
  }
  f.add_points(x, y, {.stroke = "black"}, 3.0, "points");
}

int run_hermite(const HermiteArgs& a) {
  if (!a.output.empty()) io::check_output_path(a.output, "--output");
  const io::StudyDocument doc = load_study(a.study, "hermite");
  const io::HermiteStudy s = io::read_hermite_study(doc);
  const studies::HermiteEditResult r = studies::hermite_edit(s.spline.points, s.edits, s.options);
  Json out = io::hermite_result_to_json(s, r);
  if (!a.output.empty()) io::write_curve_file(a.output, r.curve);
  if (a.study.svg) {
    double m1 = 0.0, m2 = 0.0;
    for (const auto* h : {&r.before, &r.after})
      for (std::size_t i = 0; i < h->points.size(); ++i) {
        m1 = std::max(m1, norm(h->first[i]));
        m2 = std::max(m2, norm(h->normal_handle[i]));
      }
    const double size = r.spline.model_size();
    const double s1 = m1 > 0 ? 0.2 * size / m1 : 0.0, s2 = m2 > 0 ? 0.2 * size / m2 : 0.0;
    io::SvgFigure before = plane_figure("cubic spline and its handles (before)", diffgeom::Plane::XY);
    draw_curve(before, r.spline, diffgeom::Plane::XY, {.stroke = "black"}, "C2 cubic spline");
    draw_handles(before, r.before, s1, s2);
    write_svg(*a.study.svg, "before", before);
    io::SvgFigure after = plane_figure("Hermite curve from the edited handles (after)", diffgeom::Plane::XY);
    draw_curve(after, r.spline, diffgeom::Plane::XY, {.stroke = "#999999", .dash = "6 4"}, "spline");
    draw_curve(after, r.curve, diffgeom::Plane::XY, {.stroke = "#d62728"}, "edited");
    draw_handles(after, r.after, s1, s2);
    write_svg(*a.study.svg, "after", after);
  }
  record_run(out, s.header, a.study);
  print_result(out, a.output);
  return kExitOk;
}

}  // namespace

Command add_hermite(CLI::App& app) {
  auto args = std::make_shared<HermiteArgs>();
  CLI::App* sub = app.add_subcommand(
      "hermite", "Hermite editing (thesis 7.5.2): rotate and scale the tangent/normal handles of a spline");
  add_study_options(sub, args->study, false);
  sub->add_option("-o,--output", args->output, "Write the edited curve file, atomically");
  return {sub, [args] { return run_hermite(*args); }};
}

}  // namespace hula::cli
