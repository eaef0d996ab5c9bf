// SPDX-License-Identifier: MIT
#include "hula/io/curve_figures.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "hula/core/error.hpp"
#include "hula/core/vec.hpp"
#include "hula/diffgeom/analysis.hpp"
#include "hula/diffgeom/frenet.hpp"

namespace hula::io {

namespace {

constexpr int kMaxFigureSamples = 100000;
// A coordinate within this fraction of the box diagonal of a constant counts as in that plane
// (the analyse figures' planarity rule).
constexpr double kFlatFraction = 1e-12;

struct FinStyle {
  const char* colour;
  const char* label;
};

FinStyle fin_style(diffgeom::FinKind kind) {
  switch (kind) {
    case diffgeom::FinKind::Curvature:
      return {"#1f5fbf", "curvature fins P - s\u03BAN"};
    case diffgeom::FinKind::Torsion:
      return {"#c0392b", "torsion fins P + s\u03C4B"};
    case diffgeom::FinKind::Normal:
      return {"#27ae60", "normal fins P - sN"};
    case diffgeom::FinKind::Binormal:
      return {"#8e44ad", "binormal fins P - sB"};
    case diffgeom::FinKind::BishopU:
      return {"#d35400", "Bishop fins P - sU"};
    case diffgeom::FinKind::BishopV:
      return {"#16a085", "Bishop fins P - sV"};
    case diffgeom::FinKind::Combescure:
      return {"#b7950b", "Combescure fins P + s(\u03C4/\u03BA T + B)"};
  }
  return {"#000000", ""};
}

std::string short_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

// The page coordinates of a point in a resolved view.
struct Projector {
  CurveView view;
  bool tall = false;  // Auto space curves: from −Y 20° above (tall) or from +Z tilted 35° (flat)
  bool oblique = false;
  std::array<double, 2> operator()(const Vec3& p) const {
    if (oblique) {
      const double a = (tall ? 20.0 : 35.0) * std::numbers::pi / 180.0;
      return tall ? std::array{p.x, p.z * std::cos(a) + p.y * std::sin(a)}
                  : std::array{p.x, p.y * std::cos(a) + p.z * std::sin(a)};
    }
    switch (view) {
      case CurveView::Yz:
        return {p.y, p.z};
      case CurveView::Zx:
        return {p.z, p.x};
      case CurveView::Isometric:
        return {(p.y - p.x) / std::numbers::sqrt2, (2.0 * p.z - p.x - p.y) / std::sqrt(6.0)};
      default:
        return {p.x, p.y};
    }
  }
};

std::string view_description(const Projector& v) {
  if (v.oblique) return v.tall ? "seen from -Y, 20 degrees above" : "seen from +Z, tilted 35 degrees towards -Y";
  switch (v.view) {
    case CurveView::Yz:
      return "YZ, seen from +X";
    case CurveView::Zx:
      return "ZX, seen from +Y";
    case CurveView::Isometric:
      return "isometric, seen from (1, 1, 1)";
    default:
      return "XY, seen from +Z";
  }
}

Projector resolve_view(CurveView view, const Box3& box) {
  Projector v{view};
  if (view != CurveView::Auto) return v;
  const Vec3 e = box.max - box.min;
  const double flat = kFlatFraction * std::max(box.diagonal(), 1e-300);
  if (e.z <= flat) {
    v.view = CurveView::Xy;
  } else if (e.x <= flat) {
    v.view = CurveView::Yz;
  } else if (e.y <= flat) {
    v.view = CurveView::Zx;
  } else {
    v.view = CurveView::Auto;
    v.oblique = true;
    v.tall = e.z > 0.5 * std::max(e.x, e.y);
  }
  return v;
}

void add_line(SvgFigure& f, const Projector& view, std::span<const Vec3> points, const SvgStyle& style,
              std::string legend) {
  std::vector<double> x, y;
  x.reserve(points.size());
  y.reserve(points.size());
  for (const Vec3& p : points) {
    const auto [a, b] = is_finite(p) ? view(p) : std::array{std::nan(""), std::nan("")};
    x.push_back(a);
    y.push_back(b);
  }
  f.add_polyline(x, y, style, std::move(legend));
}

}  // namespace

std::string_view curve_view_name(CurveView view) noexcept {
  switch (view) {
    case CurveView::Auto:
      return "auto";
    case CurveView::Xy:
      return "xy";
    case CurveView::Yz:
      return "yz";
    case CurveView::Zx:
      return "zx";
    case CurveView::Isometric:
      return "isometric";
  }
  return "auto";
}

CurveView parse_curve_view(std::string_view name, std::string_view field) {
  for (const CurveView v : {CurveView::Auto, CurveView::Xy, CurveView::Yz, CurveView::Zx, CurveView::Isometric})
    if (name == curve_view_name(v)) return v;
  throw Error(
      Errc::InvalidOption,
      std::string(field) + " = '" + std::string(name.substr(0, 32)) + "': expected auto, xy, yz, zx or isometric",
      {.field = std::string(field)});
}

std::vector<diffgeom::FinKind> parse_fin_kinds(std::string_view list, std::string_view field) {
  using diffgeom::FinKind;
  std::vector<FinKind> out;
  auto add = [&](FinKind k) {
    if (std::find(out.begin(), out.end(), k) == out.end()) out.push_back(k);
  };
  std::size_t index = 0;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string_view name = list.substr(start, comma - start);
    bool known = false;
    if (const std::optional<FinKind> k = diffgeom::fin_kind_from_name(name)) add(*k), known = true;
    if (name == "bishop") add(FinKind::BishopU), add(FinKind::BishopV), known = true;
    if (!known)
      throw Error(Errc::InvalidOption,
                  std::string(field) + "[" + std::to_string(index) + "] = '" + std::string(name.substr(0, 32)) +
                      "': expected curvature, torsion, normal, binormal, bishop, bishop-u, bishop-v or combescure",
                  {.field = std::string(field), .index = index});
    start = comma + 1;
    ++index;
  }
  return out;
}

void CurveFigureOptions::validate() const {
  if (fin_scale && !(std::isfinite(*fin_scale) && *fin_scale != 0.0))
    throw Error(Errc::InvalidOption, "fin_scale = " + short_number(*fin_scale) + ": must be finite and non-zero",
                {.field = "fin_scale"});
  if (fin_density < 2 || fin_density > kMaxFigureSamples)
    throw Error(
        Errc::InvalidOption,
        "fin_density = " + std::to_string(fin_density) + ": must be in [2, " + std::to_string(kMaxFigureSamples) + "]",
        {.field = "fin_density"});
  if (samples < 2 || samples > kMaxFigureSamples)
    throw Error(Errc::InvalidOption,
                "samples = " + std::to_string(samples) + ": must be in [2, " + std::to_string(kMaxFigureSamples) + "]",
                {.field = "samples"});
}

CurveFigures curve_figures(const curve::Curve& subject, const CurveFigureOptions& options) {
  options.validate();
  // The samples and the fins are the curve's analysis (diffgeom::analyse_curve), the one every door
  // reports: the fins drawn are those `hula analyse --fins` and POST .../analysis answer.
  diffgeom::AnalysisOptions ao;
  ao.samples = options.samples;
  ao.fins = options.fins;
  ao.fin_scale = options.fin_scale;
  ao.fin_density = options.fin_density;
  diffgeom::CurveAnalysis analysis = diffgeom::analyse_curve(subject, ao);
  const std::vector<diffgeom::FrenetPoint>& pts = analysis.samples;
  const std::size_t n = pts.size();

  Box3 box;
  for (const auto& p : pts) box.add(p.position);
  const double size = std::max(box.diagonal(), 1e-300);

  CurveFigures out;
  const Projector view = resolve_view(options.view, box);
  out.view = view.oblique ? CurveView::Auto : view.view;
  out.view_description = view_description(view);

  SvgFigure curve_fig(800, 800);
  curve_fig.set_equal_aspect(true);
  std::string kinds;
  for (const diffgeom::AnalysedFins& comb : analysis.fins) {
    const diffgeom::Fins& f = comb.fins;
    const FinStyle style = fin_style(comb.kind);
    std::vector<double> x0, y0, x1, y1;
    for (std::size_t i = 0; i < f.tip.size(); ++i) {
      if (!f.defined[i]) continue;
      const auto [a, b] = view(f.base[i]);
      const auto [c, d] = view(f.tip[i]);
      x0.push_back(a), y0.push_back(b), x1.push_back(c), y1.push_back(d);
    }
    curve_fig.add_segments(x0, y0, x1, y1, SvgStyle{.stroke = style.colour, .width = 0.5});
    add_line(curve_fig, view, f.tip, SvgStyle{.stroke = style.colour, .width = 1.0},
             std::string(style.label) + ", s = " + short_number(comb.scale));
    kinds += (kinds.empty() ? "" : ", ") + std::string(diffgeom::fin_kind_name(comb.kind));
  }
  std::vector<Vec3> positions(n);
  for (std::size_t i = 0; i < n; ++i) positions[i] = pts[i].position;
  add_line(curve_fig, view, positions, SvgStyle{.stroke = "#000000", .width = 2.0}, "curve");
  curve_fig.set_title("curve (" + out.view_description + ")" + (kinds.empty() ? "" : " with " + kinds + " fins"));
  out.figures.push_back({"curve", std::move(curve_fig)});
  out.fins = std::move(analysis.fins);

  // Graphs against t. Their y range contains 0 (a dashed zero line), so a constant profile is a flat line
  // and not magnified rounding noise. Curves in a plane z = const get signed curvature about +Z.
  const bool planar = box.max.z - box.min.z <= kFlatFraction * size;
  auto graph = [&](const std::string& name, const std::string& label, const std::string& x_label, const char* colour,
                   auto abscissa, auto value, bool with_zero) {
    SvgFigure g(800, 600);
    g.set_title(label + " against " + x_label);
    g.set_axes(x_label, label);
    std::vector<double> x(n), y(n);
    double xlo = HUGE_VAL, xhi = -HUGE_VAL;
    for (std::size_t i = 0; i < n; ++i) {
      x[i] = abscissa(pts[i]);
      y[i] = value(pts[i]);
      if (!std::isfinite(x[i]) || !std::isfinite(y[i])) {
        x[i] = y[i] = std::nan("");
        continue;
      }
      xlo = std::min(xlo, x[i]), xhi = std::max(xhi, x[i]);
    }
    if (with_zero && xlo <= xhi) {
      const std::array<double, 2> zx{xlo, xhi}, zy{0.0, 0.0};
      g.add_polyline(zx, zy, SvgStyle{.stroke = "#888888", .width = 1.0, .dash = "6 4"});
    }
    g.add_polyline(x, y, SvgStyle{.stroke = colour, .width = 2.0}, label);
    out.figures.push_back({name, std::move(g)});
  };
  const auto by_t = [](const diffgeom::FrenetPoint& p) { return p.t; };
  graph(
      "kappa", planar ? "signed curvature \u03BA" : "curvature \u03BA", "t", "#1f5fbf", by_t,
      [planar](const diffgeom::FrenetPoint& p) {
        return p.tangent_defined ? (planar ? p.signed_curvature : p.curvature) : std::nan("");
      },
      true);
  graph(
      "tau", "torsion \u03C4", "t", "#c0392b", by_t,
      [](const diffgeom::FrenetPoint& p) { return p.torsion_defined ? p.torsion : std::nan(""); }, true);
  const double radius_limit = 10.0 * size;
  graph(
      "radius", "radius of curvature \u03C1", "t", "#27ae60", by_t,
      [radius_limit](const diffgeom::FrenetPoint& p) {
        const double r = p.tangent_defined && p.curvature > 0 ? 1.0 / p.curvature : std::nan("");
        return r <= radius_limit ? r : std::nan("");
      },
      true);
  graph(
      "speed", "speed |C'(t)|", "t", "#8e44ad", by_t,
      [](const diffgeom::FrenetPoint& p) { return std::isfinite(p.speed) ? p.speed : std::nan(""); }, true);
  // Logarithmic curvature graph (log-aesthetic analysis): x = log10 ρ, y = log10(κ / |dκ/ds|).
  graph(
      "logcurvature", "log10(\u03BA / |d\u03BA/ds|)", "log10 \u03C1", "#d35400",
      [](const diffgeom::FrenetPoint& p) { return p.frame_defined ? -std::log10(p.curvature) : std::nan(""); },
      [](const diffgeom::FrenetPoint& p) {
        return p.frame_defined && p.curvature_derivative != 0.0
                   ? std::log10(p.curvature / std::fabs(p.curvature_derivative))
                   : std::nan("");
      },
      false);
  return out;
}

}  // namespace hula::io
