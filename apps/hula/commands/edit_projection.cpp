// SPDX-License-Identifier: MIT
// `hula edit-projection STUDY`: replace one projection of a 3-D curve by an
// edited planar curve and rebuild the 3-D curve (thesis 8.1), matching the two
// curves by normalised parameter. JSON out: the curve, the measured deviation
// of the construction and the largest change of each coordinate; --svg DIR
// draws the three projections before and after.
#include <memory>
#include <string>

#include "commands/common.hpp"
#include "commands/editing_common.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/editing_study_file.hpp"
#include "hula/io/json_curve.hpp"

namespace hula::cli {

namespace {

struct EditProjectionArgs {
  StudyArgs study;
  std::string output;
};

int run_edit_projection(const EditProjectionArgs& a) {
  if (!a.output.empty()) io::check_output_path(a.output, "--output");
  const io::StudyDocument doc = load_study(a.study, "edit-projection");
  const io::EditProjectionStudy s = io::read_edit_projection_study(doc);
  const studies::ProjectionEditResult r = studies::edit_projection(s.curve.nurbs(), s.edited.nurbs(), s.plane);
  Json out = io::edit_projection_result_to_json(s, r);
  if (!a.output.empty()) io::write_curve_file(a.output, r.curve);
  if (a.study.svg) {
    for (diffgeom::Plane plane : {diffgeom::Plane::XY, diffgeom::Plane::YZ, diffgeom::Plane::ZX}) {
      const std::string name(diffgeom::plane_name(plane));
      io::SvgFigure f = plane_figure("projection on " + name + (plane == s.plane ? " (edited)" : ""), plane);
      draw_curve(f, s.curve.nurbs(), plane, {.stroke = "#999999", .dash = "6 4"}, "original");
      if (plane == s.plane) draw_curve(f, s.edited.nurbs(), plane, {.stroke = "#1f77b4", .width = 4.0}, "edited");
      draw_curve(f, r.curve, plane, {.stroke = "#d62728"}, "rebuilt");
      write_svg(*a.study.svg, "projection-" + name, f);
    }
  }
  record_run(out, s.header, a.study);
  print_result(out, a.output);
  return kExitOk;
}

}  // namespace

Command add_edit_projection(CLI::App& app) {
  auto args = std::make_shared<EditProjectionArgs>();
  CLI::App* sub = app.add_subcommand("edit-projection",
                                     "Replace one projection of a 3-D curve by an edited planar curve (thesis 8.1)");
  add_study_options(sub, args->study, false);
  sub->add_option("-o,--output", args->output, "Write the rebuilt curve file, atomically");
  return {sub, [args] { return run_edit_projection(*args); }};
}

}  // namespace hula::cli
