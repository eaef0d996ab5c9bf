// SPDX-License-Identifier: MIT
// `hula fin-compound STUDY`: prescribed compound fins (thesis 8.3). Method
// "projection": the normal fin compound of a projection and, given an edited
// compound, the projection whose compound it is and the 3-D curve rebuilt from
// it; method "combescure": the Combescure compound of a parent curve, or the
// parent of a prescribed compound. JSON out (curves as "nurbs" curve
// documents, measured deviations); --svg DIR writes before/after figures.
#include <memory>
#include <string>

#include "commands/common.hpp"
#include "commands/editing_common.hpp"
#include "hula/core/error.hpp"
#include "hula/diffgeom/combescure.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/editing_study_file.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/law/tape.hpp"

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

Json fit_json(const studies::LawCurveFit& f) {
  Json j = Json::object();
  j["curve"] = io::curve_to_json(f.curve);
  j["fit_deviation"] = f.fit_deviation;
  return j;
}

// max |a(t) − b(t)| of two laws of `parameter` at 1001 parameters of `domain`.
double law_deviation(const law::Law& a, const law::Law& b, const std::string& parameter, nurbs::Interval domain) {
  law::CurveEvaluator ea(a, parameter, 0), eb(b, parameter, 0);
  double d = 0.0;
  for (int i = 0; i <= 1000; ++i) {
    const double u = i / 1000.0;
    Vec3 va[1], vb[1];
    const double t = domain.start * (1 - u) + domain.end * u;
    if (!ea.derivatives(t, va) || !eb.derivatives(t, vb))
      throw Error(Errc::NumericalFailure, "the transform is undefined at t = " + format_number(t), {.field = "curve"});
    d = std::max(d, distance(va[0], vb[0]));
  }
  return d;
}

int run_projection(const io::FinCompoundStudy& s, const FinCompoundArgs& a, Json& out) {
  const studies::NormalCompoundOptions& o = s.projection;
  const nurbs::NurbsCurve& curve = s.curve->nurbs();
  out["plane"] = std::string(diffgeom::plane_name(o.plane));
  out["scale"] = o.scale;
  const nurbs::NurbsCurve projection = diffgeom::project(curve, o.plane);
  const studies::LawCurveFit compound = studies::normal_compound(curve, o);
  out["projection"] = io::curve_to_json(projection);
  out["compound"] = fit_json(compound);
  std::optional<studies::CompoundEditResult> edit;
  if (s.compound) {
    edit = studies::edit_normal_compound(curve, s.compound->nurbs(), o);
    Json e = Json::object();
    e["planar"] = fit_json(edit->planar);
    e["curve"] = io::curve_to_json(edit->curve);
    e["min_stretch"] = edit->stretch.min_stretch;
    e["min_stretch_at"] = edit->stretch.at;
    e["forward_deviation"] = edit->forward_deviation;
    e["assembly_deviation"] = edit->assembly_deviation;
    // Largest change of each coordinate against the original (normalised parameters): the dropped
    // coordinate must not change.
    Json changed = Json::array();
    for (std::size_t k = 0; k < 3; ++k) {
      double m = 0.0;
      for (int i = 0; i <= 1000; ++i) {
        const double u = i / 1000.0;
        const nurbs::Interval dr = edit->curve.domain(), dc = curve.domain();
        m = std::max(m, std::abs(edit->curve.evaluate(dr.start * (1 - u) + dr.end * u)[k] -
                                 curve.evaluate(dc.start * (1 - u) + dc.end * u)[k]));
      }
      changed.push_back(m);
    }
    e["max_change"] = std::move(changed);
    out["edit"] = std::move(e);
    if (!a.output.empty()) io::write_curve_file(a.output, edit->curve);
  } else if (!a.output.empty()) {
    io::write_curve_file(a.output, compound.curve);
  }
  if (a.study.svg) {
    std::vector<Vec3> base, tip;
    fin_points(projection, compound.curve, base, tip);
    io::SvgFigure before = plane_figure("normal fin compound of the projection (before)", o.plane);
    draw_segments(before, base, tip, o.plane, {.stroke = "#999999", .width = 0.8}, "fins");
    draw_curve(before, projection, o.plane, {.stroke = "black"}, "projection");
    draw_curve(before, compound.curve, o.plane, {.stroke = "#1f77b4"}, "compound");
    write_svg(*a.study.svg, "before", before);
    if (edit) {
      base.clear();
      tip.clear();
      fin_points(edit->planar.curve, s.compound->nurbs(), base, tip);
      io::SvgFigure after = plane_figure("prescribed compound and its curve (after)", o.plane);
      draw_curve(after, projection, o.plane, {.stroke = "#999999", .dash = "6 4"}, "original projection");
      draw_segments(after, base, tip, o.plane, {.stroke = "#bbbbbb", .width = 0.8}, "fins");
      draw_curve(after, edit->planar.curve, o.plane, {.stroke = "#d62728"}, "new projection");
      draw_curve(after, s.compound->nurbs(), o.plane, {.stroke = "#1f77b4"}, "prescribed compound");
      write_svg(*a.study.svg, "after", after);
      for (diffgeom::Plane other : {diffgeom::Plane::XY, diffgeom::Plane::YZ, diffgeom::Plane::ZX}) {
        if (other == o.plane) continue;
        io::SvgFigure f = plane_figure(std::string("3-D curve seen on ") + std::string(diffgeom::plane_name(other)) +
                                           " (the unchanged coordinate is kept)",
                                       other);
        draw_curve(f, curve, other, {.stroke = "#999999", .dash = "6 4"}, "original");
        draw_curve(f, edit->curve, other, {.stroke = "#d62728"}, "rebuilt");
        write_svg(*a.study.svg, "rebuilt-" + std::string(diffgeom::plane_name(other)), f);
      }
    }
  }
  return kExitOk;
}

int run_combescure(const io::FinCompoundStudy& s, const FinCompoundArgs& a, Json& out) {
  const studies::CombescureOptions& o = s.combescure;
  out["c"] = o.c;
  const bool forward = s.curve.has_value();
  const curve::Curve& input = forward ? *s.curve : *s.compound;
  // Law curves are transformed exactly; NURBS curves as laws of "t".
  const std::string parameter = input.law() ? input.law_parameter() : std::string("t");
  const Interval domain = input.domain();
  const law::Law input_law = input.law() ? *input.law() : law::from_nurbs(input.nurbs(), law::Context(), "t");
  const studies::LawCurveFit result =
      input.law()
          ? (forward ? studies::combescure_compound(input_law, parameter, domain, o)
                     : studies::combescure_parent(input_law, parameter, domain, o))
          : (forward ? studies::combescure_compound(input.nurbs(), o) : studies::combescure_parent(input.nurbs(), o));
  // The check: transforming back (with −C, resp. +C) must give the input.
  const law::Law back = diffgeom::combescure_law(result.law, parameter, forward ? -o.c : o.c);
  Json r = fit_json(result);
  r["round_trip_deviation"] = law_deviation(back, input_law, parameter, domain);
  out[forward ? "compound" : "parent"] = std::move(r);
  if (!a.output.empty()) io::write_curve_file(a.output, result.curve);
  if (a.study.svg) {
    const nurbs::NurbsCurve& p = forward ? input.nurbs() : result.curve;
    const nurbs::NurbsCurve& q = forward ? result.curve : input.nurbs();
    std::vector<Vec3> base, tip;
    fin_points(p, q, base, tip);
    for (diffgeom::Plane plane : {diffgeom::Plane::XY, diffgeom::Plane::ZX}) {
      io::SvgFigure f = plane_figure(std::string("Combescure compound Q = P + C (tau/kappa T + B), seen on ") +
                                         std::string(diffgeom::plane_name(plane)),
                                     plane);
      draw_segments(f, base, tip, plane, {.stroke = "#999999", .width = 0.8}, "R = Q - P");
      draw_curve(f, p, plane, {.stroke = "black"}, "parent P");
      draw_curve(f, q, plane, {.stroke = "#1f77b4"}, "compound Q");
      write_svg(*a.study.svg, "combescure-" + std::string(diffgeom::plane_name(plane)), f);
    }
  }
  return kExitOk;
}

int run_fin_compound(const FinCompoundArgs& a) {
  if (!a.output.empty()) io::check_output_path(a.output, "--output");
  const io::StudyDocument doc = load_study(a.study, "fin-compound");
  const io::FinCompoundStudy s = io::read_fin_compound_study(doc);
  Json out = Json::object();
  out["study"] = "fin-compound";
  out["method"] = s.method == io::FinCompoundMethod::Projection ? "projection" : "combescure";
  const int code =
      s.method == io::FinCompoundMethod::Projection ? run_projection(s, a, out) : run_combescure(s, a, out);
  record_run(out, s.header, a.study);
  print_result(out, a.output);
  return code;
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
