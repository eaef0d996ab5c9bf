// SPDX-License-Identifier: MIT
// Open CASCADE's fairing baselines beside a study run's curves (fairing_baselines.hpp).
#include "hula/oli/fairing_baselines.hpp"

#include <cmath>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/diffgeom/frenet.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/study_figures.hpp"
#ifdef HULA_WITH_OCCT
#include "hula/oli/kernel/occt_fairing.hpp"
#endif

namespace hula::oli {

namespace {

// What the baselines are measured against and drawn beside.
struct Studied {
  std::vector<Vec3> points;                                         // the data the deviations are measured from
  nurbs::NurbsCurve reference;                                      // the curve whose ends the baselines take
  std::vector<std::pair<std::string, nurbs::NurbsCurve>> curves{};  // the run's curves, drawn first
};

Studied studied(const StudyOutcome& outcome) {
  if (const auto* f = std::get_if<FairKnotsValues>(&outcome.values)) {
    const studies::FairKnotsOutcome& o = f->outcome;
    const studies::FairingResult* best = o.best();
    Studied s{f->study.setup.points, best != nullptr ? best->best.curve : o.chord_length.curve};
    s.curves.emplace_back("chord length", o.chord_length.curve);
    if (o.ga) s.curves.emplace_back("GA", o.ga->best.curve);
    if (o.deterministic) s.curves.emplace_back("Nelder-Mead", o.deterministic->best.curve);
    return s;
  }
  if (const auto* m = std::get_if<MatchValues>(&outcome.values)) {
    const studies::CurvatureMatch& match = *m->match;
    const studies::MatchResult& r = m->result;
    if (match.setup().dimension != 2)
      throw Error(Errc::InvalidArgument,
                  "Open CASCADE's fairing baselines compare planar curves: the study's points are 3-D",
                  {.field = "occt"});
    const std::size_t n = match.setup().points.size();
    std::vector<Vec3> start(n), best(n);
    match.points_from(r.start, start);
    match.points_from(r.best, best);
    const nurbs::NurbsCurve start_curve = match.sampler().curve(start);
    nurbs::NurbsCurve best_curve = r.direct && r.direct->nurbs ? r.direct->nurbs->curve : match.sampler().curve(best);
    Studied s{r.direct ? r.direct_points : best, best_curve};
    s.curves.emplace_back("start", start_curve);
    s.curves.emplace_back("best", std::move(best_curve));
    return s;
  }
  throw Error(Errc::InvalidArgument,
              "Open CASCADE's fairing baselines compare fair-knots and match-curvature runs, not " + outcome.kind,
              {.field = "occt"});
}

}  // namespace

#ifdef HULA_WITH_OCCT
FairingBaselines fairing_baselines(const StudyOutcome& outcome) {
  const Studied s = studied(outcome);
  const nurbs::Interval dom = s.reference.domain();
  std::vector<diffgeom::FrenetPoint> ends(2);
  const double ts[2] = {dom.start, dom.end};
  diffgeom::frenet(s.reference, ts, ends);
  const FairingEnds e{.p1 = s.points.front(),
                      .p2 = s.points.back(),
                      .t1 = ends[0].tangent,
                      .t2 = ends[1].tangent,
                      .k1 = ends[0].tangent_defined ? ends[0].signed_curvature : 0.0,
                      .k2 = ends[1].tangent_defined ? ends[1].signed_curvature : 0.0};
  const std::vector<FairingBaseline> baselines = occt_fairing_baselines_in_plugin(e, s.points);
  const auto num = [](double v) { return std::isfinite(v) ? io::Json(v) : io::Json(nullptr); };
  FairingBaselines out;
  out.json["ends"] =
      io::Json{{"tangent_angles", io::Json::array({std::atan2(e.t1.y, e.t1.x), std::atan2(e.t2.y, e.t2.x)})},
               {"curvatures", io::Json::array({e.k1, e.k2})}};
  out.json["curves"] = io::Json::array();
  for (const FairingBaseline& c : baselines)
    out.json["curves"].push_back(io::Json{{"name", c.name},
                                          {"status", c.status},
                                          {"bending", num(c.bending)},
                                          {"variation", num(c.variation)},
                                          {"max_deviation", num(c.max_deviation)},
                                          {"mean_deviation", num(c.mean_deviation)},
                                          {"tangent_error", num(c.tangent_error)},
                                          {"curve", c.curve ? io::curve_to_json(*c.curve) : io::Json(nullptr)}});
  io::SvgFigure& fig = out.figure;
  fig.set_title("fairing baselines: the studies' curves and Open CASCADE's, with curvature combs");
  fig.set_equal_aspect(true);
  const double scale = io::curvature_comb_scale(s.reference);
  const char* colours[] = {"#000000", "#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e"};
  std::size_t k = 0;
  const auto draw = [&](const nurbs::NurbsCurve& c, const std::string& name) {
    const std::string colour = colours[k++ % 6];
    io::add_curvature_comb(fig, c, scale, colour, colour, name + " comb");
    std::vector<double> x, y;
    for (int i = 0; i <= 600; ++i) {
      const Vec3 p = c.evaluate(i == 600 ? c.domain().end : c.domain().start + c.domain().length() * i / 600.0);
      x.push_back(p.x);
      y.push_back(p.y);
    }
    fig.add_polyline(x, y, io::SvgStyle{.stroke = colour, .width = 2.0}, name);
  };
  for (const auto& [name, c] : s.curves) draw(c, name);
  for (const FairingBaseline& c : baselines)
    if (c.curve) draw(*c.curve, "OCCT " + c.name);
  std::vector<double> px, py;
  for (const Vec3& q : s.points) {
    px.push_back(q.x);
    py.push_back(q.y);
  }
  fig.add_points(px, py, io::SvgStyle{.stroke = "#444444", .fill = "#444444"}, 4.0, "data points");
  return out;
}
#else
FairingBaselines fairing_baselines(const StudyOutcome& outcome) {
  (void)studied(outcome);
  throw Error(Errc::Unsupported, "Open CASCADE's fairing baselines need a build with Open CASCADE (HULA_WITH_OCCT)",
              {.field = "occt"});
}
#endif

}  // namespace hula::oli
