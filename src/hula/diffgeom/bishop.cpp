// SPDX-License-Identifier: MIT
// Double-reflection rotation-minimising frames (Wang et al. 2008, Algorithm 1);
// see bishop.hpp for the notation.
#include "hula/diffgeom/bishop.hpp"

#include <cmath>
#include <limits>

#include "hula/core/error.hpp"
#include "hula/core/nan.hpp"

namespace hula::diffgeom {

namespace {

// u rotated about the unit axis a by angle θ (u ⟂ a): u cos θ + (a × u) sin θ.
Vec3 rotate_about(const Vec3& u, const Vec3& a, double theta) {
  return u * std::cos(theta) + cross(a, u) * std::sin(theta);
}

// A unit vector normal to the unit vector T: the coordinate axis least aligned with T, made normal.
Vec3 any_normal(const Vec3& T) {
  const double ax = std::fabs(T.x), ay = std::fabs(T.y), az = std::fabs(T.z);
  const Vec3 e = ax <= ay && ax <= az ? Vec3{1, 0, 0} : (ay <= az ? Vec3{0, 1, 0} : Vec3{0, 0, 1});
  return normalized(e - T * dot(e, T));
}
}  // namespace

void BishopOptions::validate() const {
  frenet.validate();
  if (initial_u && (!is_finite(*initial_u) || norm(*initial_u) == 0.0))
    throw Error(Errc::InvalidOption, "initial_u must be finite and non-zero", {.field = "initial_u"});
}

BishopResult bishop_frame(std::span<const FrenetPoint> samples, const BishopOptions& options) {
  options.validate();
  if (samples.size() < 2)
    throw Error(Errc::InvalidArgument,
                "the Bishop frame needs at least 2 samples, got " + std::to_string(samples.size()), {.field = "t"});
  for (std::size_t i = 1; i < samples.size(); ++i)
    if (!(samples[i].t > samples[i - 1].t))
      throw Error(Errc::InvalidArgument,
                  "t[" + std::to_string(i) + "] = " + format_number(samples[i].t) + " must be greater than t[" +
                      std::to_string(i - 1) + "] = " + format_number(samples[i - 1].t),
                  {.field = "t", .index = i});
  BishopResult result;
  result.frames.resize(samples.size());
  const Vec3 nan_vec{kNaN, kNaN, kNaN};
  double s = 0.0;
  std::size_t prev = samples.size();  // index of the last sample with a frame
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const FrenetPoint& p = samples[i];
    BishopFrame& f = result.frames[i];
    if (i > 0 && is_finite(p.position) && is_finite(samples[i - 1].position))
      s += distance(p.position, samples[i - 1].position);
    f.t = p.t;
    f.s = s;
    f.position = p.position;
    f.tangent = f.u = f.v = nan_vec;
    if (!p.tangent_defined) continue;
    const Vec3& t1 = p.tangent;
    Vec3 r1;
    if (prev == samples.size()) {
      // Step 0: the initial reference vector (BishopOptions::initial_u).
      if (options.initial_u) {
        const Vec3 w = *options.initial_u - t1 * dot(*options.initial_u, t1);
        if (!(norm(w) > options.frenet.tolerance.angular * norm(*options.initial_u)))
          throw Error(Errc::InvalidOption, "initial_u is parallel to the tangent at t = " + format_number(p.t),
                      {.field = "initial_u"});
        r1 = normalized(w);
      } else if (p.frame_defined) {
        r1 = p.normal;
      } else if (norm(p.signed_normal) > 1e-3) {
        r1 = normalized(p.signed_normal);  // |n × T| = sin of the angle between n and T
      } else {
        r1 = any_normal(t1);
      }
    } else {
      const BishopFrame& q = result.frames[prev];
      const Vec3& x0 = q.position;
      const Vec3& t0 = q.tangent;
      const Vec3& r0 = q.u;
      // Step 1: reflect r0 and t0 in the bisecting plane of x0, x1 (normal v1).
      const Vec3 v1 = p.position - x0;
      const double c1 = dot(v1, v1);
      Vec3 rL = r0, tL = t0;
      if (c1 > 0.0) {
        rL = r0 - v1 * (2.0 / c1 * dot(v1, r0));
        tL = t0 - v1 * (2.0 / c1 * dot(v1, t0));
      }
      // Step 2: reflect again so tL goes to t1 (normal v2); c2 = 0 means tL = t1 already.
      const Vec3 v2 = t1 - tL;
      const double c2 = dot(v2, v2);
      r1 = c2 > 0.0 ? rL - v2 * (2.0 / c2 * dot(v2, rL)) : rL;
      // Remove the rounding drift out of the normal plane, so the frame stays orthonormal.
      r1 = normalized(r1 - t1 * dot(r1, t1));
    }
    f.tangent = t1;
    f.u = r1;
    f.v = cross(t1, r1);
    f.defined = true;
    prev = i;
  }
  if (options.close) {
    const BishopFrame& a = result.frames.front();
    const BishopFrame& b = result.frames.back();
    const double gap = distance(a.position, b.position);
    const double size = s > 0.0 ? s : 1.0;
    if (!a.defined || !b.defined || !(gap <= resolution_for_size(options.frenet.tolerance, size)) ||
        !(norm(cross(a.tangent, b.tangent)) <= 1e3 * options.frenet.tolerance.angular + 1e-12) ||
        dot(a.tangent, b.tangent) < 0.0)
      throw Error(
          Errc::InvalidArgument,
          "close: the first and last samples must coincide with parallel tangents (gap " + format_number(gap) + ")",
          {.field = "close"});
    // Angle from the propagated U at the end to U at the start, about the common tangent.
    const double phi = std::atan2(dot(cross(b.u, a.u), b.tangent), dot(b.u, a.u));
    result.closing_angle = phi;
    for (BishopFrame& f : result.frames) {
      if (!f.defined) continue;
      f.u = rotate_about(f.u, f.tangent, phi * f.s / size);
      f.v = cross(f.tangent, f.u);
    }
  }
  return result;
}

BishopResult bishop_frame(const nurbs::NurbsCurve& curve, std::span<const double> ts, const BishopOptions& options) {
  options.validate();
  std::vector<FrenetPoint> samples(ts.size());
  frenet(curve, ts, samples, options.frenet);
  return bishop_frame(samples, options);
}

BishopResult bishop_frame(const LawFrenet& curve, std::span<const double> ts, const BishopOptions& options) {
  options.validate();
  std::vector<FrenetPoint> samples(ts.size());
  curve.at(ts, samples);
  return bishop_frame(samples, options);
}

}  // namespace hula::diffgeom
