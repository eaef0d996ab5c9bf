// SPDX-License-Identifier: MIT
// `hula analyse`: the differential geometry of a curve file at parameters or
// arc lengths (thesis 6.1–6.4), as
//   {"points": [{"t", "s", "position", "T", "N", "B", "kappa", "tau",
//                "kappa_prime", "speed", "bishop": {"U", "V"}}]}
// with null where a quantity is undefined (hula::diffgeom::FrenetPoint rules).
// Law curves are analysed exactly from the law; NURBS from the kernel.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>

#include "commands/common.hpp"
#include "commands/study_common.hpp"
#include "hula/core/error.hpp"
#include "hula/diffgeom/bishop.hpp"
#include "hula/diffgeom/continuity.hpp"
#include "hula/diffgeom/features.hpp"
#include "hula/diffgeom/fins.hpp"
#include "hula/diffgeom/monotonicity.hpp"
#include "hula/io/atomic_file.hpp"

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
  return j;
}

// --- SVG figures (thesis figures 32–48): the curve seen from +Z with its curvature fins (blue) and
// torsion fins (red), and κ(t), τ(t) plots. Written with io::write_file_atomically.
struct Polyline {
  std::vector<Vec3> points;  // NaN points break the line
  std::string colour;
  double width = 1.0;
};

std::string svg_document(const std::vector<Polyline>& lines, const std::string& title) {
  Box3 box;
  for (const Polyline& l : lines)
    for (const Vec3& p : l.points)
      if (is_finite(p)) box.add(p);
  if (box.empty()) box.add(Vec3{0, 0, 0});
  const double w = std::max(box.max.x - box.min.x, 1e-300), h = std::max(box.max.y - box.min.y, 1e-300);
  const double size = 800.0, margin = 20.0;
  const double k = (size - 2 * margin) / std::max(w, h);
  // Centred in the square: the shorter side gets equal margins on both ends.
  const double ox = margin + 0.5 * (size - 2 * margin - w * k), oy = margin + 0.5 * (size - 2 * margin - h * k);
  auto X = [&](double x) { return ox + (x - box.min.x) * k; };
  auto Y = [&](double y) { return size - oy - (y - box.min.y) * k; };  // SVG y points down
  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"800\" viewBox=\"0 0 800 800\">\n";
  out += "<title>" + title + "</title>\n<rect width=\"800\" height=\"800\" fill=\"white\"/>\n";
  for (const Polyline& l : lines) {
    std::string d;
    bool pen = false;
    for (const Vec3& p : l.points) {
      if (!is_finite(p)) {
        pen = false;
        continue;
      }
      d += (pen ? " L" : " M") + format_number(X(p.x)) + " " + format_number(Y(p.y));
      pen = true;
    }
    if (!d.empty())
      out += "<path fill=\"none\" stroke=\"" + l.colour + "\" stroke-width=\"" + format_number(l.width) + "\" d=\"" +
             d + "\"/>\n";
  }
  return out + "</svg>\n";
}

void write_svgs(const std::filesystem::path& dir, const curve::Curve& subject) {
  std::filesystem::create_directories(dir);
  const Interval dom = subject.domain();
  constexpr int kSamples = 400;
  std::vector<double> ts(kSamples);
  for (int i = 0; i < kSamples; ++i) ts[static_cast<std::size_t>(i)] = dom.start + dom.length() * i / (kSamples - 1);
  ts.back() = dom.end;
  std::vector<diffgeom::FrenetPoint> pts(ts.size());
  diffgeom::frenet(subject, ts, pts);
  // Fin scale: the largest fin is a fifth of the curve's size (less for coiling curves, below).
  Box3 box;
  double kmax = 0.0, tmax = 0.0;
  for (const auto& p : pts) {
    box.add(p.position);
    if (p.tangent_defined) kmax = std::max(kmax, p.curvature);
    if (p.torsion_defined) tmax = std::max(tmax, std::fabs(p.torsion));
  }
  const double size = std::max(box.diagonal(), 1e-300);
  // Total turning of the tangent in turns: curves that coil many times (toroidal helices) get proportionally
  // shorter fins, fraction 0.2 / (turns / 2), so neighbouring coils' fins do not cover each other.
  double turning = 0.0;
  for (std::size_t i = 1; i < pts.size(); ++i)
    if (pts[i - 1].tangent_defined && pts[i].tangent_defined)
      turning += std::acos(std::clamp(dot(pts[i - 1].tangent, pts[i].tangent), -1.0, 1.0));
  const double fraction = 0.2 / std::max(1.0, turning / (2.0 * std::numbers::pi) / 2.0);
  // And no fin longer than half the smallest extent of the box (ignoring a flat direction), so the fins of a
  // slender helix stay of the size of its diameter instead of its height.
  double thin = HUGE_VAL;
  for (const double e : {box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z})
    if (e > 1e-9 * size) thin = std::min(thin, e);
  const double longest = std::min(fraction * size, 0.5 * thin);
  auto comb = [&](diffgeom::FinKind kind, double qmax, const std::string& colour, std::vector<Polyline>& out) {
    diffgeom::FinOptions fo;
    fo.kind = kind;
    fo.density = 120;
    fo.scale = qmax > 0 ? longest / qmax : 1.0;
    const diffgeom::Fins f = diffgeom::fins(subject, fo);
    for (std::size_t i = 0; i < f.tip.size(); ++i)
      if (f.defined[i]) out.push_back({{f.base[i], f.tip[i]}, colour, 0.5});
    out.push_back({f.tip, colour, 1.0});
  };
  std::vector<Polyline> curve;
  comb(diffgeom::FinKind::Curvature, kmax, "#1f5fbf", curve);
  comb(diffgeom::FinKind::Torsion, tmax, "#c0392b", curve);
  Polyline c{{}, "black", 2.0};
  for (const auto& p : pts) c.points.push_back(p.position);
  curve.push_back(c);
  // Planar curves in XY are drawn seen from +Z. Space curves are drawn in an oblique view chosen by their
  // shape: a tall curve (z extent > half its x or y extent: helices) from −Y, 20° above the XY plane
  // (X = x, Y = z cos 20° + y sin 20°); a flat one (S-bends, toroidal helices) from +Z tilted 35° towards
  // −Y (X = x, Y = y cos 35° + z sin 35°). Either way the torsion fins along B are visible.
  bool planar = true;
  for (const Polyline& l : curve)
    for (const Vec3& p : l.points)
      if (is_finite(p) && std::fabs(p.z) > 1e-12 * size) planar = false;
  std::string view = "seen from +Z";
  if (!planar) {
    const bool tall = box.max.z - box.min.z > 0.5 * std::max(box.max.x - box.min.x, box.max.y - box.min.y);
    const double a = (tall ? 20.0 : 35.0) * std::numbers::pi / 180.0;
    view = tall ? "seen from -Y, 20 degrees above" : "seen from +Z, tilted 35 degrees towards -Y";
    for (Polyline& l : curve)
      for (Vec3& p : l.points)
        p = tall ? Vec3{p.x, p.z * std::cos(a) + p.y * std::sin(a), 0.0}
                 : Vec3{p.x, p.y * std::cos(a) + p.z * std::sin(a), 0.0};
  }
  io::write_file_atomically(dir / "curve.svg",
                            svg_document(curve, "curve (" + view + ") with curvature and torsion fins"));
  // Plots: y = the quantity on a range that contains 0 when `with_zero` (so a constant profile is a flat line,
  // not magnified rounding noise), padded by 8 %; x = the abscissa over its finite range. Framed, with the
  // values of the range ends, the zero line and the abscissa ends written as text. NaN breaks the line.
  auto graph = [&](auto abscissa, auto value, const std::string& name, const std::string& label,
                   const std::string& xlabel, const std::string& colour, bool with_zero) {
    double lo = with_zero ? 0.0 : HUGE_VAL, hi = with_zero ? 0.0 : -HUGE_VAL, xlo = HUGE_VAL, xhi = -HUGE_VAL;
    for (const auto& p : pts) {
      const double v = value(p);
      const double x = abscissa(p);
      if (std::isfinite(v) && std::isfinite(x)) lo = std::min(lo, v), hi = std::max(hi, v);
      if (std::isfinite(v) && std::isfinite(x)) xlo = std::min(xlo, x), xhi = std::max(xhi, x);
    }
    if (!(lo <= hi)) lo = 0.0, hi = 1.0;  // nothing finite to draw: an empty frame
    if (!(xlo < xhi)) xlo = std::isfinite(xlo) ? xlo - 0.5 : 0.0, xhi = xlo + 1.0;
    const double pad = hi > lo ? 0.08 * (hi - lo) : 1.0;
    if (with_zero) {
      lo = lo < 0.0 ? lo - pad : lo;
      hi = hi > 0.0 ? hi + pad : (lo < 0.0 ? hi : hi + pad);
      if (lo >= 0.0 && hi <= 0.0) hi = 1.0;
    } else {
      lo -= pad;
      hi += pad;
    }
    const double left = 130, right = 770, top = 60, bottom = 740;
    auto X = [&](double x) { return left + (x - xlo) / (xhi - xlo) * (right - left); };
    auto Y = [&](double v) { return bottom - (v - lo) / (hi - lo) * (bottom - top); };
    std::string d;
    bool pen = false;
    for (const auto& p : pts) {
      const double v = value(p);
      const double x = abscissa(p);
      if (!std::isfinite(v) || !std::isfinite(x)) {
        pen = false;
        continue;
      }
      d += (pen ? " L" : " M") + format_number(X(x)) + " " + format_number(Y(v));
      pen = true;
    }
    auto text = [](double x, double y, const std::string& anchor, const std::string& body) {
      return "<text x=\"" + format_number(x) + "\" y=\"" + format_number(y) + "\" text-anchor=\"" + anchor +
             "\" font-family=\"sans-serif\" font-size=\"20\">" + body + "</text>\n";
    };
    auto value_text = [](double v) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.4g", v);
      return std::string(buf);
    };
    std::string out =
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"800\" height=\"800\" viewBox=\"0 0 800 800\">\n";
    out += "<title>" + label + " against " + xlabel + "</title>\n<rect width=\"800\" height=\"800\" fill=\"white\"/>\n";
    out += "<rect x=\"" + format_number(left) + "\" y=\"" + format_number(top) + "\" width=\"" +
           format_number(right - left) + "\" height=\"" + format_number(bottom - top) +
           "\" fill=\"none\" stroke=\"#888888\" stroke-width=\"1\"/>\n";
    if (lo < 0.0 && hi > 0.0)
      out += "<path fill=\"none\" stroke=\"#888888\" stroke-width=\"1\" stroke-dasharray=\"6 4\" d=\"M" +
             format_number(left) + " " + format_number(Y(0.0)) + " L" + format_number(right) + " " +
             format_number(Y(0.0)) + "\"/>\n";
    if (!d.empty()) out += "<path fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"2.5\" d=\"" + d + "\"/>\n";
    out += text(400, 35, "middle", label + " against " + xlabel);
    out += text(left - 8, top + 7, "end", value_text(hi)) + text(left - 8, bottom + 7, "end", value_text(lo));
    if (lo < 0.0 && hi > 0.0) out += text(left - 8, Y(0.0) + 7, "end", "0");
    out += text(left, bottom + 30, "middle", xlabel + " = " + value_text(xlo)) +
           text(right, bottom + 30, "end", value_text(xhi));
    io::write_file_atomically(dir / (name + ".svg"), out + "</svg>\n");
  };
  const auto by_t = [](const diffgeom::FrenetPoint& p) { return p.t; };
  auto plot = [&](auto value, const std::string& name, const std::string& label, const std::string& colour) {
    graph(by_t, value, name, label, "t", colour, true);
  };
  // Signed curvature (about +Z) for planar curves, so it crosses zero at inflections; κ ≥ 0 for space curves.
  plot(
      [planar](const diffgeom::FrenetPoint& p) {
        return p.tangent_defined ? (planar ? p.signed_curvature : p.curvature) : std::nan("");
      },
      "kappa", planar ? "signed curvature \u03BA" : "curvature \u03BA", "#1f5fbf");
  plot([](const diffgeom::FrenetPoint& p) { return p.torsion_defined ? p.torsion : std::nan(""); }, "tau",
       "torsion \u03C4", "#c0392b");
  // Radius of curvature limited to ten times the curve's size (nearly straight pieces would squash the rest).
  const double radius_limit = 10.0 * size;
  plot(
      [&](const diffgeom::FrenetPoint& p) {
        const double r = p.tangent_defined && p.curvature > 0 ? 1.0 / p.curvature : std::nan("");
        return r <= radius_limit ? r : std::nan("");
      },
      "radius", "radius of curvature \u03C1", "#27ae60");
  plot([](const diffgeom::FrenetPoint& p) { return std::isfinite(p.speed) ? p.speed : std::nan(""); }, "speed",
       "speed |C'(t)|", "#8e44ad");
  // Logarithmic curvature graph (log-aesthetic analysis): x = log10 ρ, y = log10(κ / |dκ/ds|).
  graph([](const diffgeom::FrenetPoint& p) { return p.frame_defined ? -std::log10(p.curvature) : std::nan(""); },
        [](const diffgeom::FrenetPoint& p) {
          return p.frame_defined && p.curvature_derivative != 0.0
                     ? std::log10(p.curvature / std::fabs(p.curvature_derivative))
                     : std::nan("");
        },
        "logcurvature", "log10(\u03BA / |d\u03BA/ds|)", "log10 \u03C1", "#d35400", false);
}

int run_analyse(const AnalyseArgs& a) {
  if (!a.svg.empty()) check_svg_directory(a.svg);  // before the computation, not after
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
  if (!a.svg.empty()) write_svgs(a.svg, subject);
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
      "Add \"features\": inflections (planar curves), curvature extrema, knot continuity, curvature monotonicity");
  sub->add_option(
      "--svg", args->svg,
      "Write curve.svg (curvature and torsion fins), kappa.svg, tau.svg, radius.svg (range-limited radius of "
      "curvature), speed.svg and logcurvature.svg into this directory");
  return {sub, [args, sub] {
            if (sub->count("--at") == 0 && sub->count("--samples") == 0)
              throw Error(Errc::InvalidArgument, "give --at or --samples", {.field = "at"});
            return run_analyse(*args);
          }};
}

}  // namespace hula::cli
