// SPDX-License-Identifier: MIT
// Matching setups seeded from a curve: its points, end tangents and profiles
// by normalised arc length (see the header).
#include "hula/studies/match_seed.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <variant>

#include "hula/core/error.hpp"
#include "hula/diffgeom/frenet.hpp"
#include "hula/nurbs/arc_length.hpp"
#include "hula/studies/curvature_edit.hpp"
#include "hula/studies/detail/curve_plane.hpp"

namespace hula::studies {
namespace {

[[noreturn]] void invalid_seed_option(const std::string& field, double value, const std::string& range) {
  throw Error(Errc::InvalidOption, "MatchSeedOptions." + field + " = " + format_number(value) + " is outside " + range,
              ErrorWhere{.field = field});
}

// The parameters of n points at uniform arc length (ends exact).
std::vector<double> uniform_length_parameters(const nurbs::NurbsCurve& c, std::size_t n, double length) {
  std::vector<double> t(n);
  const Interval dom = c.domain();
  for (std::size_t i = 0; i < n; ++i)
    t[i] = i == 0       ? dom.start
           : i + 1 == n ? dom.end
                        : nurbs::parameter_at_length(c, length * static_cast<double>(i) / static_cast<double>(n - 1));
  return t;
}

// Fills the NaN entries (torsion where κ = 0) by linear interpolation between defined neighbours, constant past
// the first and last; false when none is defined.
bool fill_undefined(std::vector<double>& v) {
  std::vector<std::size_t> defined;
  for (std::size_t i = 0; i < v.size(); ++i)
    if (std::isfinite(v[i])) defined.push_back(i);
  if (defined.empty()) return false;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (std::isfinite(v[i])) continue;
    const auto next = std::lower_bound(defined.begin(), defined.end(), i);
    if (next == defined.begin())
      v[i] = v[*next];
    else if (next == defined.end())
      v[i] = v[defined.back()];
    else {
      const std::size_t a = *(next - 1), b = *next;
      const double f = static_cast<double>(i - a) / static_cast<double>(b - a);
      v[i] = v[a] + f * (v[b] - v[a]);
    }
  }
  return true;
}

}  // namespace

void MatchSeedOptions::validate() const {
  if (points == 1 || points > 1000) invalid_seed_option("points", static_cast<double>(points), "0 or [2, 1000]");
  if (!(bound > 0.0 && bound <= 10.0)) invalid_seed_option("bound", bound, "(0, 10]");
  if (samples < 2 || samples > 100'000) invalid_seed_option("samples", static_cast<double>(samples), "[2, 100000]");
  if (profile_samples < 2 || profile_samples > 100'000)
    invalid_seed_option("profile_samples", static_cast<double>(profile_samples), "[2, 100000]");
}

MatchSeed seed_match_setup(const curve::Curve& curve, const MatchSeedOptions& options) {
  options.validate();
  const nurbs::NurbsCurve& c = curve.nurbs();
  const std::optional<Vec3> plane = detail::plane_normal(c);
  const bool planar = plane.has_value();
  const double length = nurbs::arc_length(c);
  if (!(length > 0.0)) throw Error(Errc::InvalidArgument, "the curve has zero length", ErrorWhere{.field = "curve"});
  MatchSeed seed;
  CurvatureMatchSetup& s = seed.setup;
  // The setups' planar case is the X-Y plane (z = 0); a planar curve elsewhere is matched as a 3-D one.
  const auto in_xy = [&] {
    const std::span<const Vec3> p = c.control_points();
    return std::all_of(p.begin(), p.end(), [](const Vec3& q) { return q.z == 0.0; });
  };
  s.dimension = c.dimension() == 2 || (planar && in_xy()) ? 2 : 3;

  // The points: an interpolated or Hermite curve's own, else points at uniform arc length.
  const auto own = std::visit(
      [](const auto& data) -> std::vector<Vec3> {
        using T = std::decay_t<decltype(data)>;
        if constexpr (std::is_same_v<T, curve::InterpolatedData> || std::is_same_v<T, curve::HermiteData>)
          return data.points;
        else
          return {};
      },
      curve.data());
  if (options.points == 0 && !own.empty()) {
    s.points = own;
  } else {
    const std::size_t n = options.points != 0 ? options.points : std::max<std::size_t>(4, handle_count(curve) + 2);
    for (const double t : uniform_length_parameters(c, n, length)) s.points.push_back(c.evaluate(t));
  }
  if (s.dimension == 2)
    for (Vec3& p : s.points) p.z = 0.0;

  // The end tangents.
  const Interval dom = c.domain();
  const Vec3 t0 = c.derivatives(dom.start, 1)[1];
  const Vec3 t1 = c.derivatives(dom.end, 1, {.side = nurbs::Side::Left})[1];
  if (!(norm(t0) > 0.0) || !(norm(t1) > 0.0))
    throw Error(Errc::InvalidArgument, "the curve has zero speed at an end: no end tangent to hold",
                ErrorWhere{.field = "curve"});
  s.start_tangent = normalized(t0);
  s.end_tangent = normalized(t1);

  // Bounds: ± bound × size on every coordinate but the first point's (and z of a planar setup).
  const double reach = options.bound * std::max(c.model_size(), 1e-300);
  s.lower.assign(s.points.size(), Vec3{});
  s.upper.assign(s.points.size(), Vec3{});
  for (std::size_t i = 1; i < s.points.size(); ++i) {
    const Vec3 box{reach, reach, s.dimension == 2 ? 0.0 : reach};
    s.lower[i] = box;
    s.upper[i] = box;
  }

  // The profiles by normalised arc length.
  const std::size_t m = options.profile_samples;
  seed.u.resize(m);
  const std::vector<double> ts = uniform_length_parameters(c, m, length);
  for (std::size_t i = 0; i < m; ++i) seed.u[i] = static_cast<double>(i) / static_cast<double>(m - 1);
  std::vector<diffgeom::FrenetPoint> f(m);
  diffgeom::FrenetOptions fo;
  if (plane) fo.plane_normal = *plane;
  diffgeom::frenet(c, ts, f, fo);
  seed.curvature.resize(m);
  for (std::size_t i = 0; i < m; ++i) seed.curvature[i] = f[i].tangent_defined ? f[i].curvature : 0.0;
  s.target = Profile::from_samples(seed.u, seed.curvature);
  if (s.dimension == 3) {
    seed.torsion.resize(m);
    for (std::size_t i = 0; i < m; ++i) seed.torsion[i] = f[i].torsion_defined ? f[i].torsion : std::nan("");
    if (planar) std::fill(seed.torsion.begin(), seed.torsion.end(), 0.0);
    if (!fill_undefined(seed.torsion))
      throw Error(Errc::InvalidArgument, "the curve's curvature vanishes everywhere: it has no torsion profile",
                  ErrorWhere{.field = "curve"});
    s.torsion_target = Profile::from_samples(seed.u, seed.torsion);
  }
  s.samples = options.samples;
  s.abscissa = ProfileAbscissa::ArcLength;
  s.validate();
  return seed;
}

}  // namespace hula::studies
