// SPDX-License-Identifier: MIT
// The one curve analysis (analysis.hpp).
#include "hula/diffgeom/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <variant>

#include "hula/core/error.hpp"

namespace hula::diffgeom {

namespace {

// Uniform steps of the Bishop propagation grid: the double-reflection error is O(h⁴), so 4096 steps
// keep U within ~1e-12 rad of the exact rotation-minimising frame on curves of moderate total turning.
constexpr int kBishopGrid = 4096;

// The kinds whose NURBS is the curve itself, so its knots are the curve's (a law's or a natural
// curve's stand-in NURBS has knots of its fit, not of the curve).
bool has_knots(const curve::Curve& c) { return c.kind() != curve::Kind::Law && c.kind() != curve::Kind::Natural; }

// The parameters of the samples, with their arc lengths when asked or sampled by arc length.
void sample_parameters(const curve::Curve& c, const AnalysisOptions& o, std::vector<double>& ts,
                       std::vector<double>& ss) {
  const Interval dom = c.domain();
  if (o.by == SampleBy::Parameter) {
    ts = o.at.empty() ? parameter_grid(dom, o.samples) : o.at;
    if (o.arc_lengths) {
      ss.resize(ts.size());
      for (std::size_t i = 0; i < ts.size(); ++i) {
        // frenet() below names a parameter outside the domain; length_to would name it "t" without index.
        if (!(ts[i] >= dom.start && ts[i] <= dom.end)) {
          ss.clear();
          return;
        }
        ss[i] = c.length_to(ts[i]);
      }
    }
    return;
  }
  const double total = c.length();
  if (o.at.empty()) {
    const auto n = static_cast<std::size_t>(o.samples);
    ss.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      ss[i] = n == 1 ? 0.0 : i + 1 == n ? total : total * static_cast<double>(i) / static_cast<double>(n - 1);
  } else {
    ss = o.at;
    for (std::size_t i = 0; i < ss.size(); ++i)
      if (!(ss[i] >= 0.0 && ss[i] <= total * (1 + 1e-14)))
        throw Error(
            Errc::OutOfDomain,
            "s[" + std::to_string(i) + "] = " + format_number(ss[i]) + " is outside [0, " + format_number(total) + "]",
            ErrorWhere{.field = "s", .index = i});
  }
  ts.resize(ss.size());
  for (std::size_t i = 0; i < ss.size(); ++i) {
    // The ends exactly: parameter_at_length inverts an integral to a tolerance.
    ts[i] = ss[i] == 0.0 ? dom.start : ss[i] >= total ? dom.end : c.parameter_at_length(ss[i]);
  }
}

// The Bishop frame at the samples: propagated over a dense grid that contains every sample.
std::vector<BishopFrame> bishop_at(const curve::Curve& c, std::span<const FrenetPoint> samples,
                                   const FrenetOptions& fo) {
  std::vector<double> grid = parameter_grid(c.domain(), kBishopGrid + 1);
  for (const FrenetPoint& p : samples) grid.push_back(p.t);
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  std::vector<FrenetPoint> points(grid.size());
  frenet(c, grid, points, fo);
  BishopOptions bo;
  bo.frenet = fo;
  const BishopResult b = bishop_frame(points, bo);
  std::vector<BishopFrame> out;
  out.reserve(samples.size());
  for (const FrenetPoint& p : samples)
    out.push_back(b.frames[static_cast<std::size_t>(std::lower_bound(grid.begin(), grid.end(), p.t) - grid.begin())]);
  return out;
}

MaximumCurvature maximum_curvature(std::span<const FrenetPoint> ends, const CurveFeatures& f) {
  MaximumCurvature m;
  const auto offer = [&m](double kappa, double t) {
    if (std::isfinite(kappa) && !(kappa <= m.value)) {
      m.value = kappa;
      m.t = t;
    }
  };
  for (const FrenetPoint& p : ends)
    if (p.tangent_defined) offer(p.curvature, p.t);
  for (const Feature& e : f.curvature_extrema)
    if (e.kind == FeatureKind::CurvatureMaximum) offer(e.curvature, e.t);
  for (const Continuity& k : f.knots) {
    offer(k.curvature_left, k.t);
    offer(k.curvature_right, k.t);
  }
  return m;
}

CurveFeatures find_features(const curve::Curve& c, const Planarity& plane, const FeatureOptions& fo) {
  CurveFeatures f;
  if (plane.planar) f.inflections = inflections(c, fo);
  f.curvature_extrema = curvature_extrema(c, fo);
  f.torsion_extrema = torsion_extrema(c, fo);
  if (has_knots(c)) f.knots = knot_continuity(c.nurbs());
  f.monotonicity = curvature_monotonicity(c, plane.planar, f.curvature_extrema, f.inflections, fo);
  const Interval dom = c.domain();
  const std::array<double, 2> ends_t{dom.start, dom.end};
  std::array<FrenetPoint, 2> ends;
  frenet(c, ends_t, ends, fo.frenet);
  f.maximum_curvature = maximum_curvature(ends, f);
  f.self_intersections = nurbs::self_intersect(c.nurbs());
  return f;
}

}  // namespace

std::string_view sample_by_name(SampleBy by) noexcept { return by == SampleBy::ArcLength ? "arclength" : "parameter"; }

std::optional<SampleBy> sample_by_from_name(std::string_view name) noexcept {
  if (name == "parameter") return SampleBy::Parameter;
  if (name == "arclength") return SampleBy::ArcLength;
  return std::nullopt;
}

void AnalysisOptions::validate() const {
  if (samples < 1 || samples > kMaxAnalysisSamples)
    throw Error(Errc::InvalidOption,
                "samples = " + std::to_string(samples) + " must be in [1, " + std::to_string(kMaxAnalysisSamples) + "]",
                {.field = "samples"});
  if (at.size() > static_cast<std::size_t>(kMaxAnalysisSamples))
    throw Error(Errc::InvalidOption,
                "at has " + std::to_string(at.size()) + " abscissae, more than " + std::to_string(kMaxAnalysisSamples),
                {.field = "at"});
  for (std::size_t i = 0; i < at.size(); ++i)
    if (!std::isfinite(at[i]))
      throw Error(Errc::NonFiniteInput, "at[" + std::to_string(i) + "] is not a finite number",
                  {.field = "at", .index = i});
  if (fin_scale && !(std::isfinite(*fin_scale) && *fin_scale != 0.0))
    throw Error(Errc::InvalidOption, "fin_scale = " + format_number(*fin_scale) + " must be finite and non-zero",
                {.field = "fin_scale"});
  if (fin_density != 0 && (fin_density < 2 || fin_density > kMaxAnalysisSamples))
    throw Error(Errc::InvalidOption,
                "fin_density = " + std::to_string(fin_density) + " must be 0 or in [2, " +
                    std::to_string(kMaxAnalysisSamples) + "]",
                {.field = "fin_density"});
  feature.validate();
}

double auto_fin_scale(std::span<const FrenetPoint> pts, FinKind kind) {
  Box3 box;
  double qmax = 0.0, turning = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const FrenetPoint& p = pts[i];
    if (is_finite(p.position)) box.add(p.position);
    switch (kind) {
      case FinKind::Curvature:
        if (p.tangent_defined) qmax = std::max(qmax, p.curvature);
        break;
      case FinKind::Torsion:
        if (p.torsion_defined) qmax = std::max(qmax, std::fabs(p.torsion));
        break;
      case FinKind::Combescure:  // |τ/κ T + B| = √(1 + (τ/κ)²)
        if (p.torsion_defined && p.curvature > 0.0) qmax = std::max(qmax, std::hypot(1.0, p.torsion / p.curvature));
        break;
      default:
        qmax = 1.0;
    }
    if (i > 0 && pts[i - 1].tangent_defined && p.tangent_defined)
      turning += std::acos(std::clamp(dot(pts[i - 1].tangent, p.tangent), -1.0, 1.0));
  }
  if (!(qmax > 0.0) || box.empty()) return 1.0;
  const double size = std::max(box.diagonal(), 1e-300);
  const double fraction = 0.2 / std::max(1.0, turning / (2.0 * std::numbers::pi) / 2.0);
  double thin = HUGE_VAL;
  for (const double e : {box.max.x - box.min.x, box.max.y - box.min.y, box.max.z - box.min.z})
    if (e > 1e-9 * size) thin = std::min(thin, e);
  return std::min(fraction * size, 0.5 * thin) / qmax;
}

CurveAnalysis analyse_curve(const curve::Curve& c, const AnalysisOptions& options) {
  options.validate();
  CurveAnalysis a;
  a.by = options.by;
  a.planarity = planarity(c.nurbs());
  FeatureOptions fo = options.feature;
  if (a.planarity.normal) fo.frenet.plane_normal = *a.planarity.normal;

  std::vector<double> ts;
  sample_parameters(c, options, ts, a.s);
  a.samples.resize(ts.size());
  frenet(c, ts, a.samples, fo.frenet);  // names a parameter outside the domain, t[i]
  if (options.by == SampleBy::Parameter && options.arc_lengths && a.s.size() != ts.size()) {
    a.s.resize(ts.size());
    for (std::size_t i = 0; i < ts.size(); ++i) a.s[i] = c.length_to(ts[i]);
  }
  if (options.bishop) a.bishop = bishop_at(c, a.samples, fo.frenet);

  if (!options.fins.empty()) {
    const int density = options.fin_density != 0 ? options.fin_density : std::max(2, options.samples);
    // Sampled on the parameter grid with as many fins as samples, the fins stand at the samples: the
    // frames already evaluated there serve (the same parameters, bit for bit).
    const bool at_samples = options.by == SampleBy::Parameter && options.at.empty() && density == options.samples;
    std::vector<FrenetPoint> grid_frames;
    if (!at_samples) {
      const std::vector<double> grid = parameter_grid(c.domain(), density);
      grid_frames.resize(grid.size());
      frenet(c, grid, grid_frames, fo.frenet);
    }
    const std::span<const FrenetPoint> frames = at_samples ? std::span<const FrenetPoint>(a.samples) : grid_frames;
    for (const FinKind kind : options.fins) {
      FinOptions fin;
      fin.kind = kind;
      fin.frenet = fo.frenet;
      fin.scale = options.fin_scale ? *options.fin_scale : auto_fin_scale(frames, kind);
      a.fins.push_back({kind, fin.scale, fins(frames, fin)});
    }
  }
  if (options.features) a.features = find_features(c, a.planarity, fo);
  return a;
}

}  // namespace hula::diffgeom
