// SPDX-License-Identifier: MIT
// Fin polylines (thesis 6.3.2); see fins.hpp for the conventions.
#include "hula/diffgeom/fins.hpp"

#include <cmath>
#include <limits>
#include <string>

#include "hula/core/error.hpp"
#include "hula/core/nan.hpp"
#include "hula/diffgeom/bishop.hpp"
#include "hula/diffgeom/combescure.hpp"
#include "hula/diffgeom/frenet_law.hpp"
#include "hula/law/derive.hpp"

namespace hula::diffgeom {

namespace {

Fins build(std::span<const FrenetPoint> pts, const FinOptions& o) {
  Fins f;
  const std::size_t n = pts.size();
  f.t.resize(n);
  f.base.resize(n);
  f.tip.assign(n, Vec3{kNaN, kNaN, kNaN});
  f.defined.assign(n, 0);
  BishopResult bishop;
  if (o.kind == FinKind::BishopU || o.kind == FinKind::BishopV) {
    BishopOptions bo;
    bo.frenet = o.frenet;
    bishop = bishop_frame(pts, bo);
  }
  auto length = [&](double q) {
    const double l = o.scale * q;
    return o.log_scale ? std::copysign(std::log1p(std::fabs(l)), l) : l;
  };
  for (std::size_t i = 0; i < n; ++i) {
    const FrenetPoint& p = pts[i];
    f.t[i] = p.t;
    f.base[i] = p.position;
    Vec3 dir;
    double q = 1.0;
    bool ok = p.frame_defined;
    switch (o.kind) {
      case FinKind::Curvature:
        // The curvature vector κN is 0 (not undefined) where κ = 0, so the fin has length 0 there.
        ok = p.tangent_defined;
        dir = p.frame_defined ? p.normal * -1.0 : Vec3{};
        q = p.frame_defined ? p.curvature : 0.0;
        break;
      case FinKind::Torsion:
        dir = p.binormal;
        q = p.torsion;
        break;
      case FinKind::Normal:
        dir = p.normal * -1.0;
        break;
      case FinKind::Binormal:
        dir = p.binormal * -1.0;
        break;
      case FinKind::BishopU:
        ok = bishop.frames[i].defined;
        dir = bishop.frames[i].u * -1.0;
        break;
      case FinKind::BishopV:
        ok = bishop.frames[i].defined;
        dir = bishop.frames[i].v * -1.0;
        break;
      case FinKind::Combescure: {
        // Q − P = s (τ/κ T + B) (eq. 44 with C = s) as a fin: the unit direction of τ/κ T + B with the
        // quantity |τ/κ T + B| = √(1 + (τ/κ)²), so the log scale applies to its length like to the
        // other fins. Defined where combescure() is (not at planar points).
        ok = combescure(p, 1.0, o.frenet.tolerance.angular).defined;
        if (ok) {
          const Vec3 r = p.tangent * (p.torsion / p.curvature) + p.binormal;
          q = norm(r);
          dir = r * (1.0 / q);
        }
        break;
      }
    }
    if (!ok) continue;
    f.tip[i] = p.position + dir * length(q);
    f.defined[i] = 1;
  }
  return f;
}

}  // namespace

std::vector<double> parameter_grid(nurbs::Interval d, int n) {
  if (n < 1) return {};
  if (n == 1) return {d.start};
  std::vector<double> ts(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) ts[static_cast<std::size_t>(i)] = d.start + d.length() * i / (n - 1);
  ts.back() = d.end;
  return ts;
}

std::string_view fin_kind_name(FinKind kind) noexcept {
  switch (kind) {
    case FinKind::Curvature:
      return "curvature";
    case FinKind::Torsion:
      return "torsion";
    case FinKind::Normal:
      return "normal";
    case FinKind::Binormal:
      return "binormal";
    case FinKind::BishopU:
      return "bishop-u";
    case FinKind::BishopV:
      return "bishop-v";
    case FinKind::Combescure:
      return "combescure";
  }
  return "unknown";
}

std::optional<FinKind> fin_kind_from_name(std::string_view name) noexcept {
  for (const FinKind k : kFinKinds)
    if (fin_kind_name(k) == name) return k;
  return std::nullopt;
}

void FinOptions::validate() const {
  frenet.validate();
  if (!std::isfinite(scale))
    throw Error(Errc::InvalidOption, "scale = " + format_number(scale) + " must be finite", {.field = "scale"});
  if (density < 2 || density > 1000000)
    throw Error(Errc::InvalidOption, "density = " + std::to_string(density) + " must be in [2, 1000000]",
                {.field = "density"});
}

Fins fins(const nurbs::NurbsCurve& curve, const FinOptions& options) {
  options.validate();
  const std::vector<double> ts = parameter_grid(curve.domain(), options.density);
  std::vector<FrenetPoint> pts(ts.size());
  frenet(curve, ts, pts, options.frenet);
  return build(pts, options);
}

Fins fins(std::span<const FrenetPoint> frames, const FinOptions& options) {
  options.validate();
  return build(frames, options);
}

Fins fins(const curve::Curve& curve, const FinOptions& options) {
  options.validate();
  if (curve.natural_evaluator() != nullptr) {
    const std::vector<double> ts = parameter_grid(curve.domain(), options.density);
    std::vector<FrenetPoint> pts(ts.size());
    CurveFrenet(curve, options.frenet).at(ts, pts);
    return build(pts, options);
  }
  if (!curve.law()) return fins(curve.nurbs(), options);
  const std::vector<double> ts = parameter_grid(curve.domain(), options.density);
  std::vector<FrenetPoint> pts(ts.size());
  LawFrenet(*curve.law_evaluator(3), curve.domain(), options.frenet).at(ts, pts);
  return build(pts, options);
}

law::Law fin_law(const law::Law& curve, std::string_view parameter, const FinOptions& options) {
  options.validate();
  if (!curve.valid() || (curve.dimension() != 2 && curve.dimension() != 3))
    throw Error(Errc::InvalidArgument, "the curve law must be a 2- or 3-vector", {.field = "law"});
  if (options.log_scale) throw Error(Errc::InvalidOption, "log_scale fins have no law form", {.field = "log_scale"});
  const law::Law r = curve.dimension() == 3
                         ? curve
                         : law::vec(law::term(curve, 1), law::term(curve, 2), curve.context().constant(0.0));
  const double s = options.scale;
  switch (options.kind) {
    case FinKind::Curvature: {
      const law::Law r1 = law::derivative(r, parameter, 1);
      const law::Law r2 = law::derivative(r, parameter, 2);
      const law::Law v2 = law::dot(r1, r1);
      const law::Law kn = (v2 * r2 - law::dot(r1, r2) * r1) / (v2 * v2);  // κN
      return r - s * kn;
    }
    case FinKind::Torsion: {
      const FrenetLaws f = frenet_laws(r, parameter);
      return r + s * (f.torsion * f.binormal);
    }
    case FinKind::Normal:
      return r - s * frenet_laws(r, parameter).normal;
    case FinKind::Binormal:
      return r - s * frenet_laws(r, parameter).binormal;
    case FinKind::Combescure:
      return combescure_law(r, parameter, s);
    case FinKind::BishopU:
    case FinKind::BishopV:
      break;
  }
  throw Error(
      Errc::InvalidOption,
      "the " + std::string(fin_kind_name(options.kind)) + " fin has no law form (the Bishop frame is integrated)",
      {.field = "kind"});
}

law::ToNurbsResult fin_nurbs(const law::Law& curve, std::string_view parameter, nurbs::Interval domain,
                             const FinOptions& options, const law::ToNurbsOptions& fit) {
  return law::to_nurbs(fin_law(curve, parameter, options), parameter, domain.start, domain.end, fit);
}

}  // namespace hula::diffgeom
