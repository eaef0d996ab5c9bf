// SPDX-License-Identifier: MIT
// Frenet quantities from derivative formulas (thesis 6.1, eq. 5, 11, 17); see
// frenet.hpp for the notation. Batches evaluate derivatives in fixed-size
// blocks on the stack, so no allocation happens per point.
#include "hula/diffgeom/frenet.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/core/nan.hpp"

namespace hula::diffgeom {

namespace {
constexpr Vec3 kNaNVec{kNaN, kNaN, kNaN};
// Points per block in the batch forms: 4 derivatives × 64 points = 6 KiB of stack.
constexpr std::size_t kBlock = 64;

void check_sizes(std::size_t a, std::size_t b, const char* what) {
  if (a != b)
    throw Error(Errc::InvalidArgument,
                std::string(what) + ": " + std::to_string(b) + " outputs for " + std::to_string(a) + " parameters",
                {.field = what});
}
// Derivatives to order 3 of ts[i0, i0 + m); an error names the absolute index of the bad parameter
// (the kernel's batch form counts from the start of the block).
void block_derivatives(const nurbs::NurbsCurve& curve, std::span<const double> ts, std::size_t i0, std::size_t m,
                       std::span<Vec3> d, const nurbs::EvalOptions& eval) {
  try {
    curve.derivatives(ts.subspan(i0, m), 3, d, eval);
  } catch (const Error& e) {
    ErrorWhere where = e.where();
    if (!where.index) throw;
    const std::size_t index = i0 + *where.index;
    where.index = index;
    where.field = "t";
    throw Error(e.code(), "t[" + std::to_string(index) + "] = " + format_number(ts[index]) + ": " + e.message(), where);
  }
}
}  // namespace

std::string_view undefined_name(Undefined reason) noexcept {
  switch (reason) {
    case Undefined::None:
      return "none";
    case Undefined::ZeroSpeed:
      return "zero-speed";
    case Undefined::ZeroCurvature:
      return "zero-curvature";
    case Undefined::NonFinite:
      return "non-finite";
  }
  return "unknown";
}

void FrenetOptions::validate() const {
  tolerance.validate();
  if (!is_finite(plane_normal) || norm(plane_normal) == 0.0)
    throw Error(Errc::InvalidOption, "plane_normal must be finite and non-zero", {.field = "plane_normal"});
}

FrenetScale frenet_scale(double model_size, double domain_length, const Tolerance& tolerance) {
  if (!std::isfinite(model_size) || model_size < 0.0)
    throw Error(Errc::InvalidArgument, "model_size = " + format_number(model_size) + " must be finite and >= 0",
                {.field = "model_size"});
  if (!std::isfinite(domain_length) || domain_length <= 0.0)
    throw Error(Errc::InvalidArgument, "domain length = " + format_number(domain_length) + " must be finite and > 0",
                {.field = "domain"});
  FrenetScale s;
  s.model_size = model_size > 0.0 ? model_size : 1.0;
  s.zero_speed = resolution_for_size(tolerance, s.model_size) / domain_length;
  return s;
}

FrenetScale frenet_scale(const nurbs::NurbsCurve& curve, const Tolerance& tolerance) {
  return frenet_scale(curve.model_size(), curve.domain().length(), tolerance);
}

FrenetPoint frenet_from_derivatives(double t, std::span<const Vec3, 4> d, const FrenetScale& scale,
                                    const FrenetOptions& options) {
  FrenetPoint p;
  p.t = t;
  p.position = d[0];
  p.tangent = p.normal = p.binormal = p.signed_normal = kNaNVec;
  p.curvature = p.torsion = p.curvature_derivative = p.signed_curvature = kNaN;
  if (!is_finite(d[1]) || !is_finite(d[2]) || !is_finite(d[3]) || !is_finite(d[0])) {
    p.speed = kNaN;
    p.reason = Undefined::NonFinite;
    return p;
  }
  // Scale the derivatives by 1/m, m = max|r'_i|, so that |r'|² and |a| neither underflow (a curve at
  // 1e-200) nor overflow (1e200). The formulas are homogeneous: with r^(k) → r^(k)/m, κ and τ are
  // multiplied by m, dκ/ds by m², the speed by 1/m; the results are scaled back below.
  const double m = max_abs(d[1]);
  if (!(m > scale.zero_speed)) {
    p.speed = std::sqrt(dot(d[1], d[1]));
    p.reason = Undefined::ZeroSpeed;
    return p;
  }
  const double inv_m = 1.0 / m;
  const Vec3 r1 = d[1] * inv_m;
  const Vec3 r2 = d[2] * inv_m;
  const Vec3 r3 = d[3] * inv_m;
  const double v2 = dot(r1, r1);
  const double v = std::sqrt(v2);
  p.speed = v * m;
  if (!(p.speed > scale.zero_speed)) {
    p.reason = Undefined::ZeroSpeed;
    return p;
  }
  p.tangent_defined = true;
  const Vec3 T = r1 / v;
  p.tangent = T;
  const Vec3 a = cross(r1, r2);
  const double a2 = dot(a, a);
  const double an = std::sqrt(a2);
  const double v3 = v2 * v;
  // Signed curvature about the plane normal n: κ_s = (a · n) / v³, normal n × T.
  const Vec3 n = options.plane_normal / norm(options.plane_normal);
  p.signed_normal = cross(n, T);
  // Zero-curvature test (see FrenetOptions::tolerance), in the scaled units: r'' parallel to r'
  // within the angular resolution, or a radius of curvature beyond model_size / angular. Both bounds
  // sit far above the rounding noise of a (≈ 1e-16 |r'| |r''|), so what passes is a real frame.
  const double bound = options.tolerance.angular * v * std::max(std::sqrt(dot(r2, r2)), v2 * m / scale.model_size);
  const bool straight = !(an > bound);
  p.curvature = straight ? 0.0 : an / v3 * inv_m;
  p.signed_curvature = straight ? 0.0 : dot(a, n) / v3 * inv_m;
  if (straight) {
    p.reason = Undefined::ZeroCurvature;
    return p;
  }
  p.frame_defined = p.torsion_defined = true;
  const Vec3 B = a / an;
  p.binormal = B;
  p.normal = cross(B, T);
  p.torsion = dot(a, r3) / a2 * inv_m;
  // dκ/dt = (a · a')/(|a| v³) − 3|a|(r'·r'')/v⁵, a' = r' × r'''; dκ/ds = (dκ/dt)/v.
  const Vec3 a1 = cross(r1, r3);
  const double dkdt = dot(a, a1) / (an * v3) - 3.0 * an * dot(r1, r2) / (v3 * v2);
  p.curvature_derivative = dkdt / v * (inv_m * inv_m);
  return p;
}

FrenetPoint frenet(const nurbs::NurbsCurve& curve, double t, const FrenetOptions& options) {
  options.validate();
  std::array<Vec3, 4> d;
  curve.derivatives(t, 3, d, options.eval);
  return frenet_from_derivatives(t, d, frenet_scale(curve, options.tolerance), options);
}

void frenet(const nurbs::NurbsCurve& curve, std::span<const double> ts, std::span<FrenetPoint> out,
            const FrenetOptions& options) {
  options.validate();
  check_sizes(ts.size(), out.size(), "out");
  const FrenetScale scale = frenet_scale(curve, options.tolerance);
  std::array<Vec3, 4 * kBlock> d;
  for (std::size_t i0 = 0; i0 < ts.size(); i0 += kBlock) {
    const std::size_t m = std::min(kBlock, ts.size() - i0);
    block_derivatives(curve, ts, i0, m, std::span<Vec3>(d.data(), 4 * m), options.eval);
    for (std::size_t i = 0; i < m; ++i)
      out[i0 + i] = frenet_from_derivatives(ts[i0 + i], std::span<const Vec3, 4>(d.data() + 4 * i, 4), scale, options);
  }
}

void curvature_torsion(const nurbs::NurbsCurve& curve, std::span<const double> ts, std::span<double> kappa,
                       std::span<double> tau, const FrenetOptions& options) {
  options.validate();
  check_sizes(ts.size(), kappa.size(), "kappa");
  check_sizes(ts.size(), tau.size(), "tau");
  const FrenetScale scale = frenet_scale(curve, options.tolerance);
  const double angular = options.tolerance.angular;
  const double inv_size = 1.0 / scale.model_size;
  const double angular2 = angular * angular;
  const double zero_speed2 = scale.zero_speed * scale.zero_speed;
  std::array<Vec3, 4 * kBlock> d;
  for (std::size_t i0 = 0; i0 < ts.size(); i0 += kBlock) {
    const std::size_t m = std::min(kBlock, ts.size() - i0);
    block_derivatives(curve, ts, i0, m, std::span<Vec3>(d.data(), 4 * m), options.eval);
    for (std::size_t i = 0; i < m; ++i) {
      // The tests of frenet_from_derivatives without the frame vectors and, while |r'|² and |r''|² sit
      // in [1e-50, 1e50] (so |r' × r''|² can neither overflow nor underflow), without its 1/m
      // rescaling; other points take the general kernel.
      const Vec3& r1 = d[4 * i + 1];
      const Vec3& r2 = d[4 * i + 2];
      const Vec3& r3 = d[4 * i + 3];
      const double v2 = dot(r1, r1);
      const double r22 = dot(r2, r2);
      if (!(v2 >= 1e-50 && v2 <= 1e50 && r22 <= 1e50)) {
        const FrenetPoint p =
            frenet_from_derivatives(ts[i0 + i], std::span<const Vec3, 4>(d.data() + 4 * i, 4), scale, options);
        kappa[i0 + i] = p.curvature;
        tau[i0 + i] = p.torsion;
        continue;
      }
      const Vec3 a = cross(r1, r2);
      const double a2 = dot(a, a);
      const double big = v2 * inv_size;
      const bool moving = v2 > zero_speed2;
      const bool curved = a2 > angular2 * v2 * std::max(r22, big * big);
      // One division for both: q = 1/(|a|^2 v^6), kappa = |a|^2 sqrt(q), tau = (a . r''') v^6 q. With |r'|^2
      // and |r''|^2 in [1e-50, 1e50] and a curved point, |a|^2 v^6 stays in range.
      const double v6 = v2 * v2 * v2;
      const double q = 1.0 / (curved ? a2 * v6 : 1.0);
      kappa[i0 + i] = moving ? (curved ? a2 * std::sqrt(q) : 0.0) : kNaN;
      tau[i0 + i] = moving && curved ? dot(a, r3) * v6 * q : kNaN;
    }
  }
}

LawFrenet::LawFrenet(const law::Law& curve, const std::string& parameter, nurbs::Interval domain,
                     const FrenetOptions& options)
    : LawFrenet(law::CurveEvaluator(curve, parameter, 3), domain, options) {}

LawFrenet::LawFrenet(law::CurveEvaluator evaluator, Interval domain, const FrenetOptions& options)
    : evaluator_(std::move(evaluator)), options_(options) {
  options_.validate();
  if (evaluator_.order() < 3)
    throw Error(Errc::InvalidArgument,
                "the curve law is compiled to order " + std::to_string(evaluator_.order()) + "; Frenet needs 3",
                {.field = "law"});
  if (evaluator_.dimension() < 2)
    throw Error(Errc::InvalidArgument, "the curve law must be a 2- or 3-vector, not a scalar", {.field = "law"});
  if (!std::isfinite(domain.start) || !std::isfinite(domain.end) || !(domain.start < domain.end))
    throw Error(Errc::InvalidArgument,
                "domain [" + format_number(domain.start) + ", " + format_number(domain.end) +
                    "] must be finite with start < end",
                {.field = "domain"});
  // Model size: diagonal of the box of 33 positions (a law has no control polygon).
  Box3 box;
  std::array<Vec3, 4> d;
  for (int i = 0; i <= 32; ++i) {
    const double t = domain.start + domain.length() * i / 32.0;
    if (evaluator_.derivatives(t, d)) box.add(d[0]);
  }
  scale_ = frenet_scale(box.diagonal(), domain.length(), options_.tolerance);
}

FrenetPoint LawFrenet::at(double t) const {
  std::array<Vec3, 4> d;
  evaluator_.derivatives(t, d);
  return frenet_from_derivatives(t, d, scale_, options_);
}

void LawFrenet::at(std::span<const double> ts, std::span<FrenetPoint> out) const {
  check_sizes(ts.size(), out.size(), "out");
  std::array<Vec3, 4 * kBlock> d;
  for (std::size_t i0 = 0; i0 < ts.size(); i0 += kBlock) {
    const std::size_t m = std::min(kBlock, ts.size() - i0);
    evaluator_.derivatives(ts.subspan(i0, m), std::span<Vec3>(d.data(), 4 * m));
    for (std::size_t i = 0; i < m; ++i)
      out[i0 + i] =
          frenet_from_derivatives(ts[i0 + i], std::span<const Vec3, 4>(d.data() + 4 * i, 4), scale_, options_);
  }
}

CurveFrenet::CurveFrenet(curve::Curve curve, const FrenetOptions& options)
    : curve_(std::move(curve)), options_(options) {
  options_.validate();
  const Interval d = curve_.domain();
  // Model size: diagonal of the box of 33 positions.
  std::array<double, 33> ts;
  for (std::size_t i = 0; i < ts.size(); ++i) ts[i] = d.start + d.length() * static_cast<double>(i) / 32.0;
  ts.back() = d.end;
  std::array<Vec3, 33> p;
  curve_.derivatives(ts, 0, p);
  Box3 box;
  for (const Vec3& x : p)
    if (std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z)) box.add(x);
  scale_ = frenet_scale(box.diagonal(), d.length(), options_.tolerance);
}

FrenetPoint CurveFrenet::at(double t) const {
  const std::vector<Vec3> d = curve_.derivatives(t, 3, options_.eval);
  return frenet_from_derivatives(t, std::span<const Vec3, 4>(d.data(), 4), scale_, options_);
}

void CurveFrenet::at(std::span<const double> ts, std::span<FrenetPoint> out) const {
  check_sizes(ts.size(), out.size(), "out");
  std::array<Vec3, 4 * kBlock> d;
  for (std::size_t i0 = 0; i0 < ts.size(); i0 += kBlock) {
    const std::size_t m = std::min(kBlock, ts.size() - i0);
    try {
      curve_.derivatives(ts.subspan(i0, m), 3, std::span<Vec3>(d.data(), 4 * m), options_.eval);
    } catch (const Error& e) {
      // Name the index in ts, not in the block.
      if (e.code() != Errc::OutOfDomain || !e.where().index) throw;
      const std::size_t i = i0 + *e.where().index;
      const Interval dom = curve_.domain();
      throw Error(Errc::OutOfDomain,
                  "t[" + std::to_string(i) + "] = " + format_number(ts[i]) + " is outside the curve domain [" +
                      format_number(dom.start) + ", " + format_number(dom.end) + "]",
                  {.field = "t", .index = i});
    }
    for (std::size_t i = 0; i < m; ++i)
      out[i0 + i] =
          frenet_from_derivatives(ts[i0 + i], std::span<const Vec3, 4>(d.data() + 4 * i, 4), scale_, options_);
  }
}

void frenet(const curve::Curve& curve, std::span<const double> ts, std::span<FrenetPoint> out,
            const FrenetOptions& options) {
  if (curve.natural_evaluator() != nullptr) {
    CurveFrenet(curve, options).at(ts, out);
    return;
  }
  if (!curve.law()) {
    frenet(curve.nurbs(), ts, out, options);
    return;
  }
  check_sizes(ts.size(), out.size(), "out");
  const Interval d = curve.domain();
  for (std::size_t i = 0; i < ts.size(); ++i)
    if (!d.contains(ts[i]))
      throw Error(Errc::OutOfDomain,
                  "t[" + std::to_string(i) + "] = " + format_number(ts[i]) + " is outside the curve domain [" +
                      format_number(d.start) + ", " + format_number(d.end) + "]",
                  {.field = "t", .index = i});
  LawFrenet(*curve.law_evaluator(3), d, options).at(ts, out);
}

}  // namespace hula::diffgeom
