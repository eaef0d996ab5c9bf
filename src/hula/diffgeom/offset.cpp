// SPDX-License-Identifier: MIT
// Planar offsets with cusp and loop trimming; see offset.hpp.
#include "hula/diffgeom/offset.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/diffgeom/detail/derived_curve.hpp"
#include "hula/diffgeom/frenet_law.hpp"
#include "hula/diffgeom/planarity.hpp"
#include "hula/law/convert.hpp"
#include "hula/law/derive.hpp"
#include "hula/law/integrate.hpp"
#include "hula/law/parser.hpp"
#include "hula/law/roots.hpp"
#include "hula/law/tape.hpp"
#include "hula/nurbs/closest_point.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/nurbs/reparam.hpp"

namespace hula::diffgeom {

using detail::parent_law;
using detail::ParentLaw;

namespace {

// Samples of the independent deviation check of the raw offset.
constexpr int kVerifySamples = 1000;

// Component k (1-based) of a 2- or 3-vector law.
law::Law component(const law::Law& v, int k) { return law::term(v, k); }

// The cusps of the offset by d, increasing: |C'|³ − d (x'y'' − y'x'') = 0 ⇔ dκ = 1. A sign change that is no
// root is a curvature jump across 1/d at a knot, where the offset turns back as sharply: a cusp too.
std::vector<double> offset_cusps(const ParentLaw& p, Interval dom, double distance) {
  const law::Law dx = law::derivative(component(p.r, 1), p.parameter);
  const law::Law dy = law::derivative(component(p.r, 2), p.parameter);
  const law::Law ddx = law::derivative(dx, p.parameter);
  const law::Law ddy = law::derivative(dy, p.parameter);
  const law::Law speed2 = dx * dx + dy * dy;
  const law::Law g = speed2 * law::sqrt(speed2) - distance * (dx * ddy - dy * ddx);
  const law::RootReport roots = law::find_roots(g, p.parameter, dom.start, dom.end);
  std::vector<double> out = roots.roots;
  out.insert(out.end(), roots.unresolved.begin(), roots.unresolved.end());
  std::sort(out.begin(), out.end());
  return out;
}

// The breaks of an offset's NURBS fit, increasing: the knots where it is below C2 and its cusps (where a fit
// across the turn would crawl). A cusp within 1e-9 of the domain of a knot or of another break is that break
// (a curvature jump at a knot is found as a sign change beside it; the knot is the exact place).
std::vector<double> fit_breaks(const curve::Curve& curve, const ParentLaw& p, std::span<const double> cusps) {
  const Interval dom = curve.domain();
  const double min_span = 1e-9 * (dom.end - dom.start);
  std::vector<double> out = p.printable ? std::vector<double>{} : detail::low_continuity_knots(curve.nurbs(), 1);
  for (double c : cusps) {
    const bool near = c - dom.start <= min_span || dom.end - c <= min_span ||
                      std::any_of(out.begin(), out.end(), [&](double b) { return std::abs(b - c) <= min_span; });
    if (!near) out.push_back(c);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// The point C + d n and its parameter derivative (1 − dκ) C' of the planar offset by d, κ signed.
std::array<Vec3, 2> offset_point(const curve::Curve& c, double d, double t) {
  const std::vector<Vec3> D = c.derivatives(t, 2);
  const double speed = std::hypot(D[1].x, D[1].y);
  const double kappa = (D[1].x * D[2].y - D[1].y * D[2].x) / (speed * speed * speed);
  return {D[0] + d * Vec3{-D[1].y, D[1].x, 0.0} / speed, (1.0 - d * kappa) * D[1]};
}

// Newton on C(s) + d n(s) = C(u) − d n(u) from a crossing of the two fitted offsets; s and u are left as they
// are unless the iteration converges inside the domain.
void refine_crossing(const curve::Curve& c, double d, Interval dom, double& s, double& u) {
  double a = s;
  double b = u;
  for (int it = 0; it < 20; ++it) {
    const auto [P, dP] = offset_point(c, d, a);
    const auto [Q, dQ] = offset_point(c, -d, b);
    const Vec3 f = P - Q;
    // [dP −dQ] (δa, δb) = −f in x, y.
    const double det = -dP.x * dQ.y + dQ.x * dP.y;
    if (!(std::abs(det) > 0.0)) return;
    const double da = (f.x * dQ.y - f.y * dQ.x) / det;
    const double db = (dP.x * f.y - dP.y * f.x) / det;
    a += da;
    b -= db;
    if (!dom.contains(a) || !dom.contains(b)) return;
    if (std::abs(da) + std::abs(db) <= 1e-15 * (dom.end - dom.start)) break;
  }
  const auto P = offset_point(c, d, a)[0];
  const auto Q = offset_point(c, -d, b)[0];
  if (norm(P - Q) <= 1e-9 * (1.0 + std::abs(d))) {
    s = a;
    u = b;
  }
}

}  // namespace

void OffsetOptions::validate() const {
  if (!(tolerance >= 1e-12 && tolerance <= 1e-2))
    throw Error(Errc::InvalidOption, "tolerance = " + format_number(tolerance) + " must lie in [1e-12, 1e-2]",
                {.field = "tolerance"});
}

law::Law planar_offset_law(const law::Law& curve, std::string_view parameter, double distance) {
  if (!curve.valid() || curve.dimension() == 1)
    throw Error(Errc::InvalidArgument, "a planar offset needs a 2- or 3-vector law, got a scalar", {.field = "law"});
  const law::Law x = component(curve, 1);
  const law::Law y = component(curve, 2);
  const law::Law dx = law::derivative(x, parameter);
  const law::Law dy = law::derivative(y, parameter);
  // n = (−y', x') / |C'|: T turned by +90°, so d > 0 offsets to the left.
  const law::Law k = distance / law::sqrt(dx * dx + dy * dy);
  if (curve.dimension() == 3) return law::vec(x - k * dy, y + k * dx, component(curve, 3));
  return law::vec(x - k * dy, y + k * dx);
}

PlanarOffset planar_offset(const curve::Curve& curve, double distance, const OffsetOptions& options) {
  options.validate();
  // A 3-D curve in a plane z = constant is offset in that plane.
  detail::require_xy_plane(curve, "a planar offset");
  if (!std::isfinite(distance))
    throw Error(Errc::InvalidArgument, "distance = " + format_number(distance) + " must be finite",
                {.field = "distance"});
  const Interval dom = curve.domain();
  ParentLaw p = parent_law(curve);
  const law::Law r = detail::plane_law(p, curve);
  const law::Law offset = planar_offset_law(r, p.parameter, distance);

  const std::vector<double> cusps = offset_cusps(p, dom, distance);
  // A law curve's offset is a law curve (exact) when its text stays within the parser's limit.
  detail::DerivedCurve derived = [&] {
    try {
      // The offset of a NURBS is one derivative less smooth than it: fit it span by span where that is below C2,
      // and on either side of its cusps.
      return detail::derived_curve(offset, p, true, dom, options.tolerance, fit_breaks(curve, p, cusps));
    } catch (const Error&) {
      detail::rethrow_undefined("curve", "the planar offset", " (C' = 0 there)");
    }
  }();
  PlanarOffset out{.raw = std::move(derived.curve), .exact = derived.exact};
  const nurbs::NurbsCurve& raw = out.raw.nurbs();

  // Independent check against C + d n from the input's own exact derivatives.
  for (int i = 0; i <= kVerifySamples; ++i) {
    const double t = i == kVerifySamples ? dom.end : dom.start + (dom.end - dom.start) * i / kVerifySamples;
    const std::vector<Vec3> d = curve.derivatives(t, 1);
    const Vec3 n = Vec3{-d[1].y, d[1].x, 0.0} / norm(d[1]);
    out.deviation = std::max(out.deviation, norm(raw.evaluate(t) - (d[0] + distance * n)));
  }
  if (!options.trim) return out;
  out.cusps = cusps;

  // An open curve's offset also changes from valid to invalid where it crosses the circle of radius |d| about an
  // end point (beyond it the end is nearer than d): roots of |O − C(end)|² − d².
  std::vector<double> end_crossings;
  const Vec3 c0 = curve.point(dom.start);
  const Vec3 c1 = curve.point(dom.end);
  if (norm(c0 - c1) > 100.0 * options.tolerance) {
    for (const Vec3& e : {c0, c1}) {
      const law::Law w = offset - p.context.constant(e, offset.dimension());
      const std::vector<double> hits =
          law::roots(law::dot(w, w) - distance * distance, p.parameter, dom.start, dom.end);
      end_crossings.insert(end_crossings.end(), hits.begin(), hits.end());
    }
  }

  nurbs::IntersectOptions io;
  io.tolerance.resabs = 4.0 * options.tolerance;
  const nurbs::IntersectionResult self = nurbs::self_intersect(raw, io);
  out.loops = self.points;

  // A point of the offset also becomes nearer than |d| to the curve where a part of the curve that bends back
  // reaches it from the other side: there it lies on the opposite offset C − d n too. Those crossings of the
  // raw offset with the opposite one (fitted the same way) split it as well; without them a piece running into
  // the other side's reach of a curled open curve (or a self-crossing closed one) was kept whole.
  // The opposite offset only locates the crossings (refined on the exact offsets below), so where its cusps keep
  // the fit from reaching the tolerance a coarser fit does.
  const law::Law opposite_law = planar_offset_law(r, p.parameter, -distance);
  const std::vector<double> breaks = fit_breaks(curve, p, offset_cusps(p, dom, -distance));
  std::optional<detail::DerivedCurve> opposite;
  for (double tol = options.tolerance; !opposite; tol *= 10.0) {
    try {
      opposite = detail::derived_curve(opposite_law, p, true, dom, tol, breaks);
    } catch (const Error& e) {
      if (e.code() != Errc::NumericalFailure || tol >= 1e-3) throw;
    }
  }
  nurbs::IntersectOptions across_options;
  across_options.tolerance.resabs = 4.0 * std::max(options.tolerance, opposite->deviation);
  nurbs::IntersectionResult across = nurbs::intersect(raw, opposite->curve.nurbs(), across_options);
  for (nurbs::CurveIntersection& x : across.points) refine_crossing(curve, distance, dom, x.s, x.t);

  // Split points: cusps, end-circle crossings, both parameters of every self-intersection and the ends of overlaps,
  // and the crossings of the opposite offset.
  std::vector<double> cuts{dom.start, dom.end};
  cuts.insert(cuts.end(), out.cusps.begin(), out.cusps.end());
  cuts.insert(cuts.end(), end_crossings.begin(), end_crossings.end());
  for (const auto& x : self.points) cuts.insert(cuts.end(), {x.s, x.t});
  for (const auto& o : self.overlaps) cuts.insert(cuts.end(), {o.s0, o.s1, o.t0, o.t1});
  for (const auto& x : across.points) cuts.push_back(x.s);
  for (const auto& o : across.overlaps) cuts.insert(cuts.end(), {o.s0, o.s1});
  std::sort(cuts.begin(), cuts.end());
  const double min_span = 1e-12 * (dom.end - dom.start);
  std::vector<double> unique;
  for (double c : cuts)
    if (unique.empty() || c - unique.back() > min_span) unique.push_back(c);
  unique.back() = dom.end;

  // Keep a piece when its midpoint lies |d| from the curve: nearer means another part of the curve
  // is closer than d, so the piece belongs to a loop or runs backwards past a cusp.
  const double margin = 10.0 * (options.tolerance + curve.approximation_deviation()) + 1e-9 * std::abs(distance);
  std::vector<Interval> kept;
  for (std::size_t i = 0; i + 1 < unique.size(); ++i) {
    const Interval piece{unique[i], unique[i + 1]};
    const Vec3 mid = raw.evaluate(0.5 * (piece.start + piece.end));
    if (nurbs::closest_point(curve.nurbs(), mid).distance < std::abs(distance) - margin) continue;
    if (!kept.empty() && kept.back().end == piece.start)
      kept.back().end = piece.end;  // both sides of a split point kept: one span
    else
      kept.push_back(piece);
  }
  if (kept.empty()) return out;

  // Spans whose ends meet (the two parameters of one self-intersection) form one piece with a corner.
  const double gap = 100.0 * options.tolerance;
  auto meets = [&](double a, double b) { return norm(raw.evaluate(a) - raw.evaluate(b)) <= gap; };
  std::vector<std::vector<Interval>> groups{{kept.front()}};
  for (std::size_t i = 1; i < kept.size(); ++i) {
    if (meets(groups.back().back().end, kept[i].start))
      groups.back().push_back(kept[i]);
    else
      groups.push_back({kept[i]});
  }
  // A closed curve's offset runs on through the closure: the last group continues into the first.
  const bool wraps =
      groups.front().front().start == dom.start && groups.back().back().end == dom.end && meets(dom.end, dom.start);
  if (wraps && groups.size() > 1) {
    std::vector<Interval> last = std::move(groups.back());
    groups.pop_back();
    last.insert(last.end(), groups.front().begin(), groups.front().end());
    groups.front() = std::move(last);
  }
  for (auto& spans : groups) {
    nurbs::NurbsCurve c = nurbs::segment(raw, spans.front());
    for (std::size_t i = 1; i < spans.size(); ++i) c = nurbs::join(c, nurbs::segment(raw, spans[i]), gap);
    // Closed when the piece ends where it starts: through the closure, or round to the same loop's corner.
    const bool closed = meets(spans.back().end, spans.front().start);
    out.trimmed.push_back({std::move(spans), std::move(c), closed});
  }
  return out;
}

namespace {

// Values of a scalar law and its first derivative at t (an evaluator of order 1).
std::array<double, 2> scalar_values(const law::CurveEvaluator& e, double t) {
  std::array<Vec3, 2> out{};
  (void)e.derivatives(t, out);
  return {out[0].x, out[1].x};
}

// The Bishop angle φ(t) = −∫_a^t τ|C'| as a quintic Hermite NURBS (x = φ) on dom, with exact φ' and φ'' at its
// breakpoints and φ from adaptive quadrature; segments double until φ at every segment's midpoint agrees with
// the quadrature within `tol`. The torsion of a NURBS jumps at its knots of continuity below C3 (`breaks`):
// φ is fitted piece by piece between them, with one-sided derivatives at their ends, and the pieces are joined
// C0 — integrated across a jump, the quadrature and the Hermite fit would refine without end. Returns the curve
// and the largest disagreement.
std::pair<nurbs::NurbsCurve, double> bishop_angle(const law::Law& dphi, const std::string& parameter, Interval dom,
                                                  std::span<const double> breaks, double tol) {
  const law::CurveEvaluator e(dphi, parameter, 1);
  // τ|C'| of a NURBS carries rounding noise near 1e-12 of its size, so a tighter relative target (or one
  // relative to a piece whose angle nearly cancels) cannot be met and Gauss–Kronrod would bisect 2^20 times;
  // the depth cap bounds the work, and φ is checked against `tol` below in any case.
  law::IntegrationOptions io;
  io.relative_tolerance = 1e-11;
  io.max_depth = 8;
  auto integral = [&](double a, double b) {
    const law::IntegrationResult r = law::integrate(dphi, parameter, a, b, io);
    if (r.divergent || !std::isfinite(r.value))
      throw Error(Errc::NumericalFailure,
                  "the Bishop angle cannot be integrated on [" + format_number(a) + ", " + format_number(b) +
                      "] (the torsion is undefined there: κ = 0?)",
                  {.field = "frame"});
    return r.value;
  };
  // One piece [a, b] starting at angle phi0: φ', φ'' taken inside the piece at its ends.
  auto piece = [&](double a, double b, double phi0) -> std::pair<nurbs::NurbsCurve, double> {
    const double L = b - a;
    for (std::size_t m = 8; m <= 4096; m *= 2) {
      std::vector<double> ts(m + 1), us(m + 1);
      std::vector<Vec3> P(m + 1), D1(m + 1), D2(m + 1);
      double phi = phi0;
      for (std::size_t i = 0; i <= m; ++i) {
        ts[i] = i == m ? b : a + L * static_cast<double>(i) / static_cast<double>(m);
        us[i] = static_cast<double>(i) / static_cast<double>(m);
        if (i > 0) phi += integral(ts[i - 1], ts[i]);
        const double at = i == m ? std::nextafter(b, a) : ts[i];
        const std::array<double, 2> v = scalar_values(e, at);
        if (!std::isfinite(v[0]) || !std::isfinite(v[1]))
          throw Error(Errc::NumericalFailure,
                      "the Bishop frame of this space curve is undefined at " + parameter + " = " +
                          format_number(ts[i]) + " (κ = 0 or C' = 0 there)",
                      {.field = "frame"});
        // Hermite data in u = (t − a) / L: dφ/du = L φ', d²φ/du² = L² φ''.
        P[i] = {phi, 0.0, 0.0};
        D1[i] = {L * v[0], 0.0, 0.0};
        D2[i] = {L * L * v[1], 0.0, 0.0};
      }
      const nurbs::NurbsCurve c = nurbs::reparameterise(nurbs::hermite_quintic(P, D1, D2, us, 2), {a, b});
      double err = 0.0;
      for (std::size_t i = 1; i <= m; ++i) {
        const double mid = 0.5 * (ts[i - 1] + ts[i]);
        err = std::max(err, std::abs(c.evaluate(mid).x - (P[i - 1].x + integral(ts[i - 1], mid))));
      }
      if (err <= tol) return {c, err};
    }
    throw Error(Errc::NumericalFailure,
                "the Bishop angle did not reach " + format_number(tol) + " radians with 4096 segments on [" +
                    format_number(a) + ", " + format_number(b) + "]",
                {.field = "tolerance"});
  };
  std::vector<double> cuts{dom.start};
  for (const double t : breaks)
    if (t > cuts.back() && t < dom.end) cuts.push_back(t);
  cuts.push_back(dom.end);
  auto [curve, err] = piece(cuts[0], cuts[1], 0.0);
  for (std::size_t k = 1; k + 1 < cuts.size(); ++k) {
    auto [next, e_k] = piece(cuts[k], cuts[k + 1], curve.evaluate(cuts[k]).x);
    curve = nurbs::join(curve, next, 1e-9 * (1.0 + std::abs(curve.evaluate(cuts[k]).x)));
    err = std::max(err, e_k);
  }
  return {std::move(curve), err};
}

}  // namespace

std::string_view offset_frame_name(OffsetFrame frame) noexcept {
  return frame == OffsetFrame::Frenet ? "frenet" : "bishop";
}

std::optional<OffsetFrame> offset_frame_from_name(std::string_view name) noexcept {
  if (name == "frenet") return OffsetFrame::Frenet;
  if (name == "bishop") return OffsetFrame::Bishop;
  return std::nullopt;
}

void HelicalOffsetOptions::validate() const {
  if (!(tolerance >= 1e-12 && tolerance <= 1e-2))
    throw Error(Errc::InvalidOption, "tolerance = " + format_number(tolerance) + " must lie in [1e-12, 1e-2]",
                {.field = "tolerance"});
}

law::Law helical_offset_law(const law::Law& curve, const law::Law& distance, const law::Law& twist, const law::Law& u,
                            const law::Law& v) {
  if (curve.dimension() != 3 || u.dimension() != 3 || v.dimension() != 3 || distance.dimension() != 1 ||
      twist.dimension() != 1)
    throw Error(Errc::InvalidArgument, "a helical offset needs 3-vector curve and frame laws and scalar d and θ",
                {.field = "law"});
  return curve + distance * (law::cos(twist) * u + law::sin(twist) * v);
}

HelicalOffset helical_offset(const curve::Curve& curve, std::string_view distance, std::string_view twist,
                             const HelicalOffsetOptions& options) {
  options.validate();
  const Interval dom = curve.domain();
  ParentLaw p = parent_law(curve);
  const law::Law d = detail::scalar_option(distance, p, "distance");
  const law::Law theta = detail::scalar_option(twist, p, "twist");
  const law::Law r =
      p.r.dimension() == 3 ? p.r : law::vec(component(p.r, 1), component(p.r, 2), p.context.constant(0.0));
  HelicalOffset out{.curve = curve};
  law::Law u, v;
  double angle_error = 0.0;
  bool leaf = false;  // the law holds a NURBS leaf (not printable as a law curve)
  const Planarity plane = options.frame == OffsetFrame::Bishop ? planarity(curve.nurbs()) : Planarity{};
  if (options.frame == OffsetFrame::Frenet) {
    const FrenetLaws f = frenet_laws(r, p.parameter);
    u = f.normal;
    v = f.binormal;
  } else if (plane.planar) {
    // A plane curve's Bishop frame: U = n × T turns only with T (U' = n × T' ∥ T), V = n is constant.
    Vec3 n{0.0, 0.0, 1.0};
    if (plane.normal) {
      n = *plane.normal;
    } else {
      // Collinear control points (a straight line): any plane through the line; the one containing the
      // coordinate axis least aligned with it.
      const Vec3 dir = curve.point(dom.end) - curve.point(dom.start);
      const Vec3 axis = std::abs(dir.x) <= std::abs(dir.y) && std::abs(dir.x) <= std::abs(dir.z) ? Vec3{1, 0, 0}
                        : std::abs(dir.y) <= std::abs(dir.z)                                     ? Vec3{0, 1, 0}
                                                                                                 : Vec3{0, 0, 1};
      n = cross(dir, axis) / norm(cross(dir, axis));
    }
    out.plane_normal = n;
    const law::Law nl = p.context.constant(n);
    u = law::cross(nl, law::normalize(law::derivative(r, p.parameter)));
    v = nl;
  } else {
    const FrenetLaws f = frenet_laws(r, p.parameter);
    const law::Law dphi = -(f.torsion * f.speed);
    double dmax = 0.0;
    const law::CurveEvaluator de(d, p.parameter, 0);
    for (int i = 0; i <= 200; ++i) {
      std::array<Vec3, 1> o{};
      (void)de.derivatives(dom.start + (dom.end - dom.start) * i / 200.0, o);
      dmax = std::max(dmax, std::abs(o[0].x));
    }
    const std::vector<double> breaks =
        p.printable ? std::vector<double>{} : detail::low_continuity_knots(curve.nurbs(), 3);
    auto [phi_curve, err] = bishop_angle(dphi, p.parameter, dom, breaks, 0.1 * options.tolerance / std::max(1.0, dmax));
    angle_error = err * dmax;
    const law::Law phi = law::term(p.context.curve(phi_curve, p.context.parameter(p.parameter), "bishop_angle"), 1);
    u = law::cos(phi) * f.normal + law::sin(phi) * f.binormal;
    v = law::cos(phi) * f.binormal - law::sin(phi) * f.normal;
    leaf = true;
  }
  const law::Law h = helical_offset_law(r, d, theta, u, v);
  try {
    // The frames take up to the third derivative of a NURBS: fit span by span where that leaves less than C2.
    detail::DerivedCurve c =
        detail::derived_curve(h, p, !leaf, dom, options.tolerance,
                              p.printable ? std::vector<double>{} : detail::low_continuity_knots(curve.nurbs(), 3));
    out.curve = std::move(c.curve);
    out.exact = c.exact;
    out.deviation = c.deviation + angle_error;
  } catch (const Error&) {
    detail::rethrow_undefined(
        "frame", "the " + std::string(offset_frame_name(options.frame)) + " frame",
        options.frame == OffsetFrame::Frenet ? " (κ = 0 there: the Bishop frame is defined)" : "");
  }
  return out;
}

}  // namespace hula::diffgeom
