// SPDX-License-Identifier: MIT
// Curvature combs for the study figures and Open CASCADE's fairing baselines
// (oli/kernel/occt_fairing.hpp) beside a study's curves, shared by
// `hula fair-knots --occt` and `hula match-curvature --occt`: the JSON block
// "occt" and the figure baselines.svg. The combs are the curves' analysis
// (diffgeom::analyse_curve, its automatic fin scale); the baselines and their
// measurements come from oli_kernel.
#include "commands/fairing_baselines.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "commands/study_common.hpp"
#include "hula/diffgeom/analysis.hpp"
#include "hula/io/json_curve.hpp"
#ifdef HULA_WITH_OCCT
#include "hula/oli/kernel/occt_fairing.hpp"
#endif

namespace hula::cli {

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

double fin_scale(const nurbs::NurbsCurve& curve) { return curvature_comb(curve, std::nullopt).scale; }

// The curvature fins of `curve` (segments in `fin_colour`) and the comb line through their tips.
void add_fins(io::SvgFigure& fig, const nurbs::NurbsCurve& curve, double scale, const char* fin_colour,
              const char* comb_colour, const std::string& legend) {
  const diffgeom::Fins f = curvature_comb(curve, scale).fins;
  std::vector<double> x0, y0, x1, y1, tx, ty;
  for (std::size_t i = 0; i < f.t.size(); ++i) {
    tx.push_back(f.defined[i] ? f.tip[i].x : std::numeric_limits<double>::quiet_NaN());
    ty.push_back(f.defined[i] ? f.tip[i].y : std::numeric_limits<double>::quiet_NaN());
    if (!f.defined[i]) continue;
    x0.push_back(f.base[i].x);
    y0.push_back(f.base[i].y);
    x1.push_back(f.tip[i].x);
    y1.push_back(f.tip[i].y);
  }
  fig.add_segments(x0, y0, x1, y1, io::SvgStyle{.stroke = fin_colour, .width = 0.8});
  fig.add_polyline(tx, ty, io::SvgStyle{.stroke = comb_colour, .width = 1.0}, legend);
}

#ifdef HULA_WITH_OCCT
// Open CASCADE's baselines with the end tangents and curvatures of `reference` (the best curve): their energies
// and deviations under "occt", and their curves with combs beside the study's in baselines.svg.
Json occt_baselines(std::span<const Vec3> points, const nurbs::NurbsCurve& reference,
                    const std::vector<std::pair<std::string, const nurbs::NurbsCurve*>>& studied,
                    const std::optional<std::filesystem::path>& svg) {
  const auto dom = reference.domain();
  std::vector<diffgeom::FrenetPoint> ends(2);
  const double ts[2] = {dom.start, dom.end};
  diffgeom::frenet(reference, ts, ends);
  const oli::FairingEnds e{.p1 = points.front(),
                           .p2 = points.back(),
                           .t1 = ends[0].tangent,
                           .t2 = ends[1].tangent,
                           .k1 = ends[0].tangent_defined ? ends[0].signed_curvature : 0.0,
                           .k2 = ends[1].tangent_defined ? ends[1].signed_curvature : 0.0};
  const std::vector<oli::FairingBaseline> b = oli::occt_fairing_baselines(e, points);
  auto num = [](double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); };
  Json out = Json::object();
  out["ends"] = Json{{"tangent_angles", Json::array({std::atan2(e.t1.y, e.t1.x), std::atan2(e.t2.y, e.t2.x)})},
                     {"curvatures", Json::array({e.k1, e.k2})}};
  out["curves"] = Json::array();
  for (const oli::FairingBaseline& c : b)
    out["curves"].push_back(Json{{"name", c.name},
                                 {"status", c.status},
                                 {"bending", num(c.bending)},
                                 {"variation", num(c.variation)},
                                 {"max_deviation", num(c.max_deviation)},
                                 {"mean_deviation", num(c.mean_deviation)},
                                 {"tangent_error", num(c.tangent_error)},
                                 {"curve", c.curve ? io::curve_to_json(*c.curve) : Json(nullptr)}});
  if (svg) {
    io::SvgFigure fig(900, 700);
    fig.set_title("fairing baselines: the studies' curves and Open CASCADE's, with curvature combs");
    fig.set_equal_aspect(true);
    const double scale = fin_scale(reference);
    const char* colours[] = {"#000000", "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e"};
    std::size_t k = 0;
    auto draw = [&](const nurbs::NurbsCurve& c, const std::string& name) {
      const char* colour = colours[k++ % 6];
      add_fins(fig, c, scale, colour, colour, name + " comb");
      std::vector<double> x, y;
      for (int i = 0; i <= 600; ++i) {
        const Vec3 p = c.evaluate(c.domain().start + c.domain().length() * i / 600.0);
        x.push_back(p.x);
        y.push_back(p.y);
      }
      fig.add_polyline(x, y, io::SvgStyle{.stroke = colour, .width = 2.0}, name);
    };
    for (const auto& [name, c] : studied) draw(*c, name);
    for (const oli::FairingBaseline& c : b)
      if (c.curve) draw(*c.curve, "OCCT " + c.name);
    std::vector<double> px, py;
    for (const Vec3& q : points) {
      px.push_back(q.x);
      py.push_back(q.y);
    }
    fig.add_points(px, py, io::SvgStyle{.stroke = "#444444", .fill = "#444444"}, 4.0, "data points");
    write_svg(*svg, "baselines", fig);
  }
  return out;
}
#else
Json occt_baselines(std::span<const Vec3>, const nurbs::NurbsCurve&,
                    const std::vector<std::pair<std::string, const nurbs::NurbsCurve*>>&,
                    const std::optional<std::filesystem::path>&) {
  throw Error(Errc::Unsupported, "--occt needs a build with Open CASCADE (HULA_WITH_OCCT)", {.field = "--occt"});
}
#endif

}  // namespace hula::cli
