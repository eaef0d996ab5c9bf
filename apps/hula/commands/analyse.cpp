// SPDX-License-Identifier: MIT
// `hula analyse`: the differential geometry of a curve file at parameters or
// arc lengths (thesis 6.1–6.4), as
//   {"points": [{"t", "s", "position", "T", "N", "B", "kappa", "tau",
//                "kappa_prime", "speed", "bishop": {"U", "V"}}]}
// with null where a quantity is undefined (hula::diffgeom::FrenetPoint rules).
// Law curves are analysed exactly from the law; NURBS from the kernel.
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>

#include "commands/common.hpp"
#include "commands/study_common.hpp"
#include "hula/core/error.hpp"
#include "hula/diffgeom/bishop.hpp"
#include "hula/diffgeom/continuity.hpp"
#include "hula/diffgeom/features.hpp"
#include "hula/diffgeom/fins.hpp"
#include "hula/diffgeom/monotonicity.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/io/curve_figures.hpp"
#include "hula/io/intersection_json.hpp"
#include "hula/nurbs/intersect.hpp"

namespace hula::cli {

namespace {
// Uniform samples in the Bishop propagation grid: the double-reflection error is O(h⁴), so
// 4096 steps keep U within ~1e-12 rad of the exact RMF on curves of moderate total turning.
constexpr int kBishopGrid = 4096;

struct AnalyseArgs {
  std::string curve;
  std::string at;
  int samples = 0;
  std::string by = "parameter";
  bool features = false;
  std::string svg;
  std::optional<std::string> fins;
  std::optional<double> fin_scale;
  std::optional<int> fin_density;
  std::string view = "auto";
};

Json number_or_null(double x, bool defined) { return defined && std::isfinite(x) ? Json(x) : Json(nullptr); }
Json vec_or_null(const Vec3& v, bool defined) {
  return defined && is_finite(v) ? Json::array({v.x, v.y, v.z}) : Json(nullptr);
}

// {"inflections", "curvature_extrema", "knots"}: inflections only for planar curves (about their
// plane's normal; [] for space curves), extrema of κ, and the continuity at every interior knot
// (NURBS only; a law has no knots).
Json features_to_json(const curve::Curve& c) {
  const Planarity plane = planarity(c.nurbs());
  diffgeom::FeatureOptions fo;
  if (plane.normal) fo.frenet.plane_normal = *plane.normal;
  std::vector<diffgeom::Feature> infl;
  if (plane.planar) infl = diffgeom::inflections(c, fo);
  const std::vector<diffgeom::Feature> ext = diffgeom::curvature_extrema(c, fo);
  auto vec = [](const Vec3& v) { return Json::array({v.x, v.y, v.z}); };
  Json j = Json::object();
  Json ji = Json::array();
  for (const auto& f : infl) ji.push_back(Json{{"t", f.t}, {"position", vec(f.position)}});
  Json je = Json::array();
  for (const auto& f : ext)
    je.push_back(Json{{"t", f.t},
                      {"kind", f.kind == diffgeom::FeatureKind::CurvatureMaximum ? "maximum" : "minimum"},
                      {"kappa", f.curvature},
                      {"position", vec(f.position)}});
  Json jt = Json::array();
  for (const auto& f : diffgeom::torsion_extrema(c, fo))
    jt.push_back(Json{{"t", f.t},
                      {"kind", f.kind == diffgeom::FeatureKind::TorsionMaximum ? "maximum" : "minimum"},
                      {"tau", f.torsion},
                      {"position", vec(f.position)}});
  Json jk = Json::array();
  // Knots are features of the exact NURBS kinds only (a law has none; a natural curve's are its fit's).
  if (c.kind() != curve::Kind::Law && c.kind() != curve::Kind::Natural) {
    for (const diffgeom::Continuity& k : diffgeom::knot_continuity(c.nurbs())) {
      Json left = Json::array(), right = Json::array();
      for (const Vec3& v : k.left) left.push_back(vec(v));
      for (const Vec3& v : k.right) right.push_back(vec(v));
      jk.push_back(Json{{"t", k.t},
                        {"multiplicity", k.multiplicity},
                        {"parametric", k.parametric < 0 ? Json(nullptr) : Json("C" + std::to_string(k.parametric))},
                        {"geometric", k.geometric < 0 ? Json(nullptr) : Json("G" + std::to_string(k.geometric))},
                        {"tangent_angle", std::isfinite(k.tangent_angle) ? Json(k.tangent_angle) : Json(nullptr)},
                        {"left", std::move(left)},
                        {"right", std::move(right)}});
    }
  }
  j["inflections"] = std::move(ji);
  j["curvature_extrema"] = std::move(je);
  j["torsion_extrema"] = std::move(jt);
  j["knots"] = std::move(jk);
  // Pieces of monotone curvature (signed for planar curves) and the extrema that break monotonicity.
  const diffgeom::CurvatureMonotonicity mono = diffgeom::curvature_monotonicity(c, plane.planar, fo);
  Json jp = Json::array(), jv = Json::array();
  for (const auto& p : mono.pieces)
    jp.push_back(Json{{"t0", p.t0},
                      {"t1", p.t1},
                      {"kappa0", p.kappa0},
                      {"kappa1", p.kappa1},
                      {"trend", std::string(diffgeom::curvature_trend_name(p.trend))}});
  for (const auto& f : mono.violations)
    jv.push_back(Json{{"t", f.t}, {"kind", std::string(diffgeom::feature_kind_name(f.kind))}, {"kappa", f.curvature}});
  j["curvature_monotonicity"] =
      Json{{"monotone", mono.monotone()}, {"pieces", std::move(jp)}, {"violations", std::move(jv)}};
  // Where the curve meets itself (thesis ch. 10: a curve that doubles back is not a valid solution).
  j["self_intersections"] = io::intersection_to_json(nurbs::self_intersect(c.nurbs()), c.nurbs().dimension());
  return j;
}

// The figures (io::curve_figures, thesis figures 32–48), each written atomically as DIR/<name>.svg.
void write_svgs(const std::filesystem::path& dir, const io::CurveFigures& figures) {
  for (const io::NamedFigure& f : figures.figures) write_svg(dir, f.name, f.figure);
}

// {"kind", "scale", "t": [...], "base": [[x, y, z], ...], "tip": [... or null where undefined]} per fin kind.
Json fins_to_json(const io::CurveFigures& figures) {
  Json out = Json::array();
  for (const io::FigureFins& f : figures.fins) {
    Json base = Json::array(), tip = Json::array();
    for (std::size_t i = 0; i < f.fins.t.size(); ++i) {
      base.push_back(vec_or_null(f.fins.base[i], true));
      tip.push_back(vec_or_null(f.fins.tip[i], f.fins.defined[i] != 0));
    }
    out.push_back(Json{{"kind", diffgeom::fin_kind_name(f.kind)},
                       {"scale", f.scale},
                       {"t", f.fins.t},
                       {"base", std::move(base)},
                       {"tip", std::move(tip)}});
  }
  return out;
}

int run_analyse(const AnalyseArgs& a) {
  if (!a.svg.empty()) check_svg_directory(a.svg);  // before the computation, not after
  io::CurveFigureOptions figure_options;
  if (a.fins) figure_options.fins = io::parse_fin_kinds(*a.fins, "--fins");
  figure_options.fin_scale = a.fin_scale;
  if (a.fin_density) figure_options.fin_density = *a.fin_density;
  figure_options.view = io::parse_curve_view(a.view, "--view");
  const curve::Curve subject = io::read_curve_file(a.curve);
  const Interval dom = subject.domain();
  const bool by_length = a.by == "arclength";
  // The requested abscissae, in parameter or arc length.
  std::vector<double> xs;
  if (!a.at.empty()) {
    xs = parse_number_list(a.at, by_length ? "s" : "t");
  } else {
    const double end = by_length ? subject.length() : dom.end;
    const double start = by_length ? 0.0 : dom.start;
    for (int i = 0; i < a.samples; ++i)
      xs.push_back(a.samples == 1 ? start : start + (end - start) * i / (a.samples - 1));
  }
  std::vector<double> ts(xs.size()), ss(xs.size());
  if (by_length) {
    const double total = subject.length();
    for (std::size_t i = 0; i < xs.size(); ++i) {
      if (!(xs[i] >= 0.0 && xs[i] <= total * (1 + 1e-14)))
        throw Error(
            Errc::OutOfDomain,
            "s[" + std::to_string(i) + "] = " + format_number(xs[i]) + " is outside [0, " + format_number(total) + "]",
            ErrorWhere{.field = "s", .index = i});
      ss[i] = xs[i];
      ts[i] = subject.parameter_at_length(std::min(xs[i], total));
    }
  } else {
    ts = xs;
  }
  std::vector<diffgeom::FrenetPoint> points(ts.size());
  diffgeom::frenet(subject, ts, points);  // validates the parameters (names t[i])
  if (!by_length)
    for (std::size_t i = 0; i < ts.size(); ++i) ss[i] = subject.length_to(ts[i]);

  // Bishop frame propagated from the domain start over a dense grid that contains every requested t.
  std::vector<double> grid;
  for (int i = 0; i <= kBishopGrid; ++i) grid.push_back(dom.start + dom.length() * i / kBishopGrid);
  grid.back() = dom.end;
  grid.insert(grid.end(), ts.begin(), ts.end());
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  std::vector<diffgeom::FrenetPoint> grid_points(grid.size());
  diffgeom::frenet(subject, grid, grid_points);
  const diffgeom::BishopResult bishop = diffgeom::bishop_frame(grid_points);

  Json list = Json::array();
  for (std::size_t i = 0; i < ts.size(); ++i) {
    const diffgeom::FrenetPoint& p = points[i];
    const auto g = static_cast<std::size_t>(std::lower_bound(grid.begin(), grid.end(), ts[i]) - grid.begin());
    const diffgeom::BishopFrame& f = bishop.frames[g];
    Json j = Json::object();
    j["t"] = p.t;
    j["s"] = ss[i];
    j["position"] = vec_or_null(p.position, true);
    j["T"] = vec_or_null(p.tangent, p.tangent_defined);
    j["N"] = vec_or_null(p.normal, p.frame_defined);
    j["B"] = vec_or_null(p.binormal, p.frame_defined);
    j["kappa"] = number_or_null(p.curvature, p.tangent_defined);
    j["tau"] = number_or_null(p.torsion, p.torsion_defined);
    j["kappa_prime"] = number_or_null(p.curvature_derivative, p.frame_defined);
    j["speed"] = number_or_null(p.speed, p.reason != diffgeom::Undefined::NonFinite);
    Json b = Json::object();
    b["U"] = vec_or_null(f.u, f.defined);
    b["V"] = vec_or_null(f.v, f.defined);
    j["bishop"] = std::move(b);
    list.push_back(std::move(j));
  }
  Json doc = Json::object();
  doc["points"] = std::move(list);
  if (a.features) doc["features"] = features_to_json(subject);
  if (a.fins || !a.svg.empty()) {
    const io::CurveFigures figures = io::curve_figures(subject, figure_options);
    if (a.fins) doc["fins"] = fins_to_json(figures);
    if (!a.svg.empty()) write_svgs(a.svg, figures);
  }
  print_json(doc);
  return kExitOk;
}
}  // namespace

Command add_analyse(CLI::App& app) {
  auto args = std::make_shared<AnalyseArgs>();
  CLI::App* sub = app.add_subcommand(
      "analyse", "Differential geometry of a curve file: Frenet and Bishop frames, curvature, torsion, speed");
  sub->add_option("curve", args->curve, "Curve file (JSON)")->required();
  auto* at = sub->add_option("--at", args->at, "Parameters (or arc lengths with --by arclength) x0,x1,...");
  auto* n = sub->add_option("--samples", args->samples, "N equally spaced samples over the domain, N in [1, 1000000]")
                ->check(CLI::Range(1, 1000000));
  at->excludes(n);
  sub->add_option("--by", args->by, "Abscissa of --at / --samples: parameter | arclength (default parameter)")
      ->check(CLI::IsMember({"parameter", "arclength"}));
  sub->add_flag(
      "--features", args->features,
      "Add \"features\": inflections (planar curves), curvature extrema, knot continuity, curvature monotonicity, "
      "self-intersections");
  sub->add_option("--svg", args->svg,
                  "Write curve.svg (the curve and its fins, curvature and torsion unless --fins), kappa.svg, tau.svg, "
                  "radius.svg (range-limited radius of curvature), speed.svg and logcurvature.svg into this directory");
  sub->add_option("--fins", args->fins,
                  "Fin kinds, comma-separated: curvature, torsion, normal, binormal, bishop (U and V), bishop-u, "
                  "bishop-v, combescure (the Combescure compound P + s(tau/kappa T + B)); adds \"fins\" to the "
                  "output and draws them in curve.svg");
  add_real_option(sub, "--fin-scale", args->fin_scale, 0.0, std::numeric_limits<double>::max(), true,
                  "Fin scale s > 0 for every kind (default: the longest fin a fifth of the curve's size)");
  add_integer_option(sub, "--fin-density", args->fin_density, 2, 100000, "Fins per kind, in [2, 100000] (default 120)");
  sub->add_option("--view", args->view, "View of curve.svg: auto | xy | yz | zx | isometric (default auto)")
      ->check(CLI::IsMember({"auto", "xy", "yz", "zx", "isometric"}));
  return {sub, [args, sub] {
            if (sub->count("--at") == 0 && sub->count("--samples") == 0)
              throw Error(Errc::InvalidArgument, "give --at or --samples", {.field = "at"});
            return run_analyse(*args);
          }};
}

}  // namespace hula::cli
