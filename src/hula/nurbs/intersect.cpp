// SPDX-License-Identifier: MIT
// Curve–curve intersection, self-intersection and distance (see the header).
//
// Notation: A(s), B(t) the two curves, D = A(s) − B(t), tol the resolution,
// a piece = one Bézier piece of a curve on the global parameter interval
// [t0, t1] (its local parameter u ∈ [0, 1] maps linearly onto it).
#include "hula/nurbs/intersect.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <numeric>
#include <optional>
#include <queue>
#include <string>
#include <utility>

#include "hula/core/error.hpp"
#include "hula/nurbs/bezier.hpp"
#include "hula/nurbs/closest_point.hpp"
#include "hula/nurbs/refine.hpp"

namespace hula::nurbs {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
// Halvings of one Bézier piece before it is a leaf: 2^-60 of a span is below
// the resolution of its parameter.
constexpr int kMaxSubdivisionDepth = 60;
// Work limits. Curves that run within a few tolerances of each other (not
// within one) over a stretch of length ℓ need about ℓ / (8 tol / κ)^½ pieces
// before the hull bounds separate them: harmless at the default 1e-6, but
// ~10⁷ for a 1e-14 relative tolerance. Beyond these counts intersect refuses
// (NumericalFailure) and curve_distance returns its best with the bound it proved.
constexpr std::size_t kMaxPairs = 1'000'000;
constexpr std::size_t kMaxDistancePairs = 300'000;

// ---- pieces ---------------------------------------------------------------

struct Piece {
  std::vector<Vec3> P;    // control points
  std::vector<double> w;  // weights (empty: polynomial)
  double t0 = 0.0, t1 = 0.0;
  int depth = 0;
  Box3 box;
  double size = 0.0;       // box diagonal
  double thickness = 0.0;  // max distance of a control point from the chord segment P0 Pn
  Vec3 axis{};             // unit chord direction (zero when the chord vanishes)
  bool monotone = false;   // every tangent has a positive component along axis
  double alpha = 0.0;      // half-angle of the tangent cone about axis (when monotone)
};

double point_segment_distance(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 d = b - a;
  const double dd = dot(d, d);
  const double u = dd > 0.0 ? std::clamp(dot(p - a, d) / dd, 0.0, 1.0) : 0.0;
  return distance(p, a + u * d);
}

// The tangent cone of a piece about `axis`: every derivative of a rational
// Bézier curve is a non-negative combination of P_j − P_i (j > i)
// (C' = Σ_{i>j} w_i w_j B_i B_j (i − j) / (u (1 − u) W²) (P_i − P_j)); of a
// polynomial one, of the consecutive differences. Zero differences add
// nothing. `cosine` is the smallest cosine to the axis (-1 when every
// difference is zero); `angle` the largest angle, from atan2 so that it is
// accurate near 0 (acos of a cosine near 1 loses half the digits).
struct Cone {
  double cosine = 2.0;
  double angle = 0.0;
};
Cone cone_of(std::span<const Vec3> P, bool rational, const Vec3& axis) {
  Cone c;
  const std::size_t n = P.size();
  for (std::size_t i = 0; i + 1 < n; ++i)
    for (std::size_t j = i + 1; j < (rational ? n : i + 2); ++j) {
      const Vec3 d = P[j] - P[i];
      const double len = norm(d);
      if (!(len > 0.0)) continue;
      c.cosine = std::fmin(c.cosine, dot(d, axis) / len);
      c.angle = std::fmax(c.angle, std::atan2(norm(cross(d, axis)), dot(d, axis)));
    }
  if (c.cosine > 1.0) c.cosine = -1.0;
  return c;
}
double cone_cosine(std::span<const Vec3> P, bool rational, const Vec3& axis) {
  return cone_of(P, rational, axis).cosine;
}

Piece make_piece(std::vector<Vec3> P, std::vector<double> w, double t0, double t1, int depth) {
  Piece p;
  p.P = std::move(P);
  p.w = std::move(w);
  p.t0 = t0;
  p.t1 = t1;
  p.depth = depth;
  for (const Vec3& q : p.P) p.box.add(q);
  p.size = p.box.diagonal();
  const Vec3 chord = p.P.back() - p.P.front();
  for (const Vec3& q : p.P) p.thickness = std::fmax(p.thickness, point_segment_distance(q, p.P.front(), p.P.back()));
  const double len = norm(chord);
  if (len > 0.0) {
    p.axis = chord / len;
    const Cone c = cone_of(p.P, !p.w.empty(), p.axis);
    p.monotone = c.cosine > 0.0;
    p.alpha = p.monotone ? c.angle : 0.0;
  }
  return p;
}

std::pair<Piece, Piece> split(const Piece& p) {
  DeCasteljauResult r = de_casteljau(p.P, p.w, 0.5);
  const double tm = 0.5 * (p.t0 + p.t1);
  return {make_piece(std::move(r.left), std::move(r.left_weights), p.t0, tm, p.depth + 1),
          make_piece(std::move(r.right), std::move(r.right_weights), tm, p.t1, p.depth + 1)};
}

std::vector<Piece> pieces_of(const NurbsCurve& c) {
  std::vector<Piece> out;
  for (const NurbsCurve& seg : decompose_to_bezier(c)) {
    const Interval d = seg.domain();
    out.push_back(make_piece({seg.control_points().begin(), seg.control_points().end()},
                             {seg.weights().begin(), seg.weights().end()}, d.start, d.end, 0));
  }
  return out;
}

bool splittable(const Piece& p, double tol) {
  return p.size > tol && p.depth < kMaxSubdivisionDepth &&
         p.t1 - p.t0 > 8.0 * kEps * std::fmax(1.0, std::fmax(std::fabs(p.t0), std::fabs(p.t1)));
}

// ---- bounds -------------------------------------------------------------

struct SegmentClosest {
  double u = 0.0, v = 0.0, distance = 0.0;
};

// Closest points of segments p0 p1 and q0 q1 (Ericson, Real-Time Collision Detection 5.1.9).
SegmentClosest closest_segments(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r);
  double u = 0.0, v = 0.0;
  if (a <= 0.0 && e <= 0.0) {
  } else if (a <= 0.0) {
    v = std::clamp(f / e, 0.0, 1.0);
  } else {
    const double c = dot(d1, r);
    if (e <= 0.0) {
      u = std::clamp(-c / a, 0.0, 1.0);
    } else {
      const double b = dot(d1, d2);
      const double denom = a * e - b * b;
      u = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
      v = (b * u + f) / e;
      if (v < 0.0) {
        v = 0.0;
        u = std::clamp(-c / a, 0.0, 1.0);
      } else if (v > 1.0) {
        v = 1.0;
        u = std::clamp((b - c) / a, 0.0, 1.0);
      }
    }
  }
  return {u, v, distance(p0 + u * d1, q0 + v * d2)};
}

// A lower bound on the distance between the curves of two pieces: each lies
// in its control box and within `thickness` of its chord (convex hull).
double lower_bound(const Piece& a, const Piece& b) {
  double g2 = 0.0;
  for (std::size_t c = 0; c < 3; ++c) {
    const double gap = std::fmax(0.0, std::fmax(a.box.min[c] - b.box.max[c], b.box.min[c] - a.box.max[c]));
    g2 += gap * gap;
  }
  const SegmentClosest sc = closest_segments(a.P.front(), a.P.back(), b.P.front(), b.P.back());
  return std::fmax(std::sqrt(g2), sc.distance - a.thickness - b.thickness);
}

// Angle between the lines of two unit axes, in [0, π/2] (atan2: accurate near 0).
double line_angle(const Vec3& u, const Vec3& v) { return std::atan2(norm(cross(u, v)), std::fabs(dot(u, v))); }

// No tangent of a is parallel to a tangent of b: then the pieces meet at most
// once (A(s2) − A(s1) lies in a's cone, B(t2) − B(t1) in ±b's cone). The
// margin of 1e-9 rad keeps rounding in the cone angles from proving it for
// parallel pieces.
bool separated(const Piece& a, const Piece& b) {
  return a.monotone && b.monotone && line_angle(a.axis, b.axis) > a.alpha + b.alpha + 1e-9;
}

// ---- local solvers --------------------------------------------------------

struct Root {
  double s = 0.0, t = 0.0;
  double dist = HUGE_VAL;
  bool converged = false;
};

struct Eval {
  std::array<Vec3, 3> d;
};

Eval derivs(const NurbsCurve& c, double t, int order) {
  Eval e;
  c.derivatives(t, order, std::span<Vec3>(e.d.data(), static_cast<std::size_t>(order) + 1));
  return e;
}

// C(u) with u clamped to the domain: interpolated parameters (t0 + (t1 − t0) k / 4) may round past an end.
Vec3 at(const NurbsCurve& c, double u) { return c.evaluate(u, {.domain = Domain::Clamp}); }

Interval widened(double t0, double t1, const Interval& dom) {
  const double w = t1 - t0;
  return {std::fmax(dom.start, t0 - w), std::fmin(dom.end, t1 + w)};
}

struct Solver {
  const NurbsCurve& A;
  const NurbsCurve& B;
  double eps0;      // rounding level of a distance
  double eps_root;  // the largest |D| that is a meeting point rather than a near miss
  int max_iterations;

  // Gauss–Newton on D(s, t) = A(s) − B(t) = 0 (J = [A', −B']), a step that
  // leaves the box being clipped and the other variable re-solved alone (a
  // root on a domain end). Returns the best iterate, converged when it is a
  // meeting point: |D| at rounding level (eps_root), or a domain end whose
  // foot on the other curve was reached (then |D| may be anything; the caller
  // compares it with tol). A minimum of |D| > eps_root inside the domain is a
  // near miss of nearly parallel curves: not converged.
  Root crossing(double s, double t, const Interval& bs, const Interval& bt) const {
    Root best{s, t, HUGE_VAL, false};
    const auto finish = [&](Root r) {
      const Interval da = A.domain(), db = B.domain();
      const bool at_end = r.s == da.start || r.s == da.end || r.t == db.start || r.t == db.end;
      r.converged = r.dist <= eps_root || at_end;
      return r;
    };
    for (int it = 0; it < max_iterations; ++it) {
      const Eval a = derivs(A, s, 1), b = derivs(B, t, 1);
      const Vec3 D = a.d[0] - b.d[0];
      const double dist = norm(D);
      if (dist < best.dist) best = {s, t, dist, false};
      if (dist <= eps0) return {s, t, dist, true};
      const double aa = dot(a.d[1], a.d[1]), bb = dot(b.d[1], b.d[1]), ab = dot(a.d[1], b.d[1]);
      const double ga = dot(a.d[1], D), gb = -dot(b.d[1], D);
      const double det = aa * bb - ab * ab;  // |A' × B'|²
      if (!(det > 1e-24 * aa * bb)) break;   // parallel tangents: not a transversal point
      double ns = s - (bb * ga + ab * gb) / det;
      double nt = t - (ab * ga + aa * gb) / det;
      const bool cs = ns < bs.start || ns > bs.end, ct = nt < bt.start || nt > bt.end;
      ns = std::clamp(ns, bs.start, bs.end);
      nt = std::clamp(nt, bt.start, bt.end);
      if (cs && !ct && bb > 0.0) nt = std::clamp(t + dot(b.d[1], D + (ns - s) * a.d[1]) / bb, bt.start, bt.end);
      if (ct && !cs && aa > 0.0) ns = std::clamp(s - dot(a.d[1], D - (nt - t) * b.d[1]) / aa, bs.start, bs.end);
      const double step = std::fabs(ns - s) * std::sqrt(aa) + std::fabs(nt - t) * std::sqrt(bb);
      s = ns;
      t = nt;
      if (step <= eps0) {
        const double d = distance(A.evaluate(s), B.evaluate(t));
        if (d <= best.dist) best = {s, t, d, false};
        return finish(best);
      }
    }
    best.converged = best.dist <= eps_root;
    return best;
  }

  // Gauss–Newton on the tangency system r = (A'·D / |A'|, L (A' × B') / (|A'| |B'|)) = 0
  // (the foot of B(t) on A and parallel tangents; L the model size makes both
  // rows lengths). Its Jacobian, exact at a solution, is regular where the
  // relative curvature of the curves is not zero; `regular` reports it.
  Root tangent(double s, double t, const Interval& bs, const Interval& bt, double L, bool* regular) const {
    *regular = false;
    Root best{s, t, HUGE_VAL, false};
    double last_step = HUGE_VAL;
    for (int it = 0; it < max_iterations; ++it) {
      const Eval a = derivs(A, s, 2), b = derivs(B, t, 2);
      const Vec3 D = a.d[0] - b.d[0];
      const double na = norm(a.d[1]), nb = norm(b.d[1]);
      if (!(na > 0.0 && nb > 0.0)) return best;
      const double dist = norm(D);
      if (dist < best.dist) best = {s, t, dist, false};
      const double k = L / (na * nb);
      const double r1 = dot(a.d[1], D) / na;
      const Vec3 r2 = k * cross(a.d[1], b.d[1]);
      const double j1s = (dot(a.d[2], D) + na * na) / na, j1t = -dot(a.d[1], b.d[1]) / na;
      const Vec3 j2s = k * cross(a.d[2], b.d[1]), j2t = k * cross(a.d[1], b.d[2]);
      const double h00 = j1s * j1s + dot(j2s, j2s), h01 = j1s * j1t + dot(j2s, j2t), h11 = j1t * j1t + dot(j2t, j2t);
      const double g0 = j1s * r1 + dot(j2s, r2), g1 = j1t * r1 + dot(j2t, r2);
      const double det = h00 * h11 - h01 * h01, tr = h00 + h11;
      if (!(det > 1e-16 * tr * tr)) return best;  // σ_min / σ_max < 1e-8: no isolated contact
      const double ns = std::clamp(s - (h11 * g0 - h01 * g1) / det, bs.start, bs.end);
      const double nt = std::clamp(t - (h00 * g1 - h01 * g0) / det, bt.start, bt.end);
      const double step = std::fabs(ns - s) * na + std::fabs(nt - t) * nb;
      s = ns;
      t = nt;
      if (step <= eps0 || (it > 2 && step >= last_step && step <= 1e-9 * L)) {
        const double d = distance(A.evaluate(s), B.evaluate(t));
        best = {s, t, d, true};
        *regular = true;
        return best;
      }
      last_step = step;
    }
    return best;
  }

  // Newton on g = |D|² / 2: gradient (A'·D, −B'·D), Hessian [[A'·A' + A''·D, −A'·B'], [−A'·B', B'·B' − B''·D]];
  // Gauss–Newton (the Hessian without the D terms) where it is not positive
  // definite; a variable on a bound of the box with the gradient pushing out
  // is held there and the other solved alone; steps halved until |D| falls.
  Root nearest(double s, double t, const Interval& bs, const Interval& bt) const {
    Eval a = derivs(A, s, 2), b = derivs(B, t, 2);
    Vec3 D = a.d[0] - b.d[0];
    double dist = norm(D);
    for (int it = 0; it < max_iterations; ++it) {
      if (dist <= eps0) return {s, t, dist, true};
      const double aa = dot(a.d[1], a.d[1]), bb = dot(b.d[1], b.d[1]), ab = dot(a.d[1], b.d[1]);
      const double g0 = dot(a.d[1], D), g1 = -dot(b.d[1], D);
      double h00 = aa + dot(a.d[2], D), h11 = bb - dot(b.d[2], D), h01 = -ab;
      if (!(h00 > 0.0 && h11 > 0.0 && h00 * h11 - h01 * h01 > 1e-14 * (h00 + h11) * (h00 + h11))) {
        h00 = aa * (1.0 + 1e-10);
        h11 = bb * (1.0 + 1e-10);
      }
      const bool hold_s = (s <= bs.start && g0 > 0.0) || (s >= bs.end && g0 < 0.0);
      const bool hold_t = (t <= bt.start && g1 > 0.0) || (t >= bt.end && g1 < 0.0);
      double ds = 0.0, dt = 0.0;
      if (hold_s && hold_t) return {s, t, dist, true};
      if (hold_s) {
        dt = h11 > 0.0 ? -g1 / h11 : 0.0;
      } else if (hold_t) {
        ds = h00 > 0.0 ? -g0 / h00 : 0.0;
      } else {
        const double det = h00 * h11 - h01 * h01;
        if (!(det > 0.0)) return {s, t, dist, false};
        ds = -(h11 * g0 - h01 * g1) / det;
        dt = -(h00 * g1 - h01 * g0) / det;
      }
      bool accepted = false;
      double lam = 1.0;
      for (int k = 0; k < 40 && !accepted; ++k, lam *= 0.5) {
        const double ns = std::clamp(s + lam * ds, bs.start, bs.end), nt = std::clamp(t + lam * dt, bt.start, bt.end);
        const Eval na = derivs(A, ns, 2), nb = derivs(B, nt, 2);
        const Vec3 ND = na.d[0] - nb.d[0];
        const double nd = norm(ND);
        if (nd <= dist) {
          const double step = std::fabs(ns - s) * std::sqrt(aa) + std::fabs(nt - t) * std::sqrt(bb);
          // Near a minimum |D| changes by O(step²): once a step gains only
          // rounding, the distance is as exact as it will get.
          const bool flat = dist - nd <= 8.0 * kEps * dist;
          s = ns;
          t = nt;
          a = na;
          b = nb;
          D = ND;
          dist = nd;
          accepted = true;
          if (step <= eps0 || flat) return {s, t, dist, true};
        }
      }
      if (!accepted) return {s, t, dist, true};  // no descent left: a minimum to rounding
    }
    return {s, t, dist, false};
  }
};

// Local foot of point p on curve C near parameter t inside [lo, hi]: Newton on
// f = C'·(C − p) (The NURBS Book eq. 6.3), clipped to the bounds, the best
// iterate kept. Returns {t, distance}.
std::pair<double, double> local_foot(const NurbsCurve& C, const Vec3& p, double t, const Interval& bounds, double eps0,
                                     int max_iterations) {
  t = std::clamp(t, bounds.start, bounds.end);
  double best_t = t, best_d = HUGE_VAL;
  for (int it = 0; it < max_iterations; ++it) {
    const Eval e = derivs(C, t, 2);
    const Vec3 D = e.d[0] - p;
    const double d = norm(D);
    if (d < best_d) {
      best_d = d;
      best_t = t;
    }
    if (d <= eps0) break;
    const double f = dot(e.d[1], D);
    double df = dot(e.d[2], D) + dot(e.d[1], e.d[1]);
    if (!(df > 0.0)) df = dot(e.d[1], e.d[1]);
    if (!(df > 0.0)) break;
    const double nt = std::clamp(t - f / df, bounds.start, bounds.end);
    if (std::fabs(nt - t) * norm(e.d[1]) <= eps0) break;
    t = nt;
  }
  return {best_t, best_d};
}

// ---- the intersection engine ---------------------------------------------

// Both curves lie in one plane z = c (2-D curves, or 3-D ones with equal z).
bool in_one_plane_z(const NurbsCurve& a, const NurbsCurve& b) {
  const Box3 x = a.control_box(), y = b.control_box();
  return x.min.z == x.max.z && y.min.z == y.max.z && x.min.z == y.min.z;
}

struct ZonePiece {
  double s0, s1, t0, t1;
  int orientation;  // +1: the curves run the same way, -1: opposite, 0: unknown (a leaf)
  double gs, gt;    // parameter gaps that are 2 tol along each curve: pieces this close touch
};

class Engine {
 public:
  Engine(const NurbsCurve& a, const NurbsCurve& b, double tol, double eps0, double model, int max_iterations, bool self,
         bool closed)
      : planar_(in_one_plane_z(a, b)),
        closed_(closed),
        A_(a),
        B_(b),
        tol_(tol),
        model_(model),
        self_(self),
        solver_{a, b, eps0, 64.0 * eps0, max_iterations},
        eps0_(eps0),
        max_iterations_(max_iterations) {}

  // Two pieces of A and B (self: of the same curve, a's parameters below b's).
  void pair(const Piece& a, const Piece& b) {
    count_pair();
    if (lower_bound(a, b) > tol_) return;
    const bool sa = splittable(a, tol_), sb = splittable(b, tol_);
    const SegmentClosest seed = closest_segments(a.P.front(), a.P.back(), b.P.front(), b.P.back());
    const double s0 = a.t0 + seed.u * (a.t1 - a.t0), t0 = b.t0 + seed.v * (b.t1 - b.t0);
    if (!sa && !sb) {  // a leaf: the subdivision cannot tell more
      if (distance(A_.evaluate(s0), B_.evaluate(t0)) <= tol_) zones_.push_back(zone_of(a, b));
      return;
    }
    bool found = false;
    if (separated(a, b)) {
      const Root r = solver_.crossing(s0, t0, widened(a.t0, a.t1, A_.domain()), widened(b.t0, b.t1, B_.domain()));
      if (r.converged && r.dist <= tol_) {
        roots_.push_back(r);
        const double ma = 1e-9 * (a.t1 - a.t0), mb = 1e-9 * (b.t1 - b.t0);
        // The pair's only common point is found.
        found = r.s >= a.t0 - ma && r.s <= a.t1 + ma && r.t >= b.t0 - mb && r.t <= b.t1 + mb;
      }
    }
    // Flat pieces within tol of each other are part of a contact zone (with or
    // without the crossing just found: zones have no holes).
    if (a.monotone && b.monotone && a.alpha <= 0.35 && b.alpha <= 0.35) {
      if (const std::optional<ZonePiece> z = within(a, b)) {
        zones_.push_back(*z);
        return;
      }
    }
    if (found) return;
    if (sa && (!sb || a.size >= b.size)) {
      const auto [l, r] = split(a);
      pair(l, b);
      pair(r, b);
    } else {
      const auto [l, r] = split(b);
      pair(a, l);
      pair(a, r);
    }
  }

  void count_pair() {
    if (++pairs_ > kMaxPairs)
      throw Error(Errc::NumericalFailure,
                  "the curves stay within a few tolerances (tol = " + format_number(tol_) + ") of each other " +
                      "over a stretch too long to resolve at this tolerance (" + std::to_string(kMaxPairs) +
                      " piece pairs examined); give a larger tolerance",
                  {.field = "tolerance"});
  }

  // One piece against itself.
  void self(const Piece& p) {
    count_pair();
    if (p.monotone || !splittable(p, tol_)) return;
    const auto [l, r] = split(p);
    self(l);
    self(r);
    adjacent(l, r);
  }

  // Two pieces of one curve where l ends at r's start: they meet there, and
  // only there when the curve is monotone along one direction over both.
  void adjacent(const Piece& l, const Piece& r) {
    count_pair();
    Vec3 u = r.P.back() - l.P.front();
    if (!(norm(u) > 0.0)) u = l.axis + r.axis;
    const double len = norm(u);
    if (len > 0.0) {
      u = u / len;
      if (cone_cosine(l.P, !l.w.empty(), u) > 0.0 && cone_cosine(r.P, !r.w.empty(), u) > 0.0) return;
    }
    const bool sl = splittable(l, tol_), sr = splittable(r, tol_);
    if (!sl && !sr) return;  // only the shared point is left
    if (sl && sr) {
      const auto [l1, l2] = split(l);
      const auto [r1, r2] = split(r);
      adjacent(l2, r1);
      pair(l1, r1);
      pair(l1, r2);
      pair(l2, r2);
    } else if (sl) {
      const auto [l1, l2] = split(l);
      adjacent(l2, r);
      pair(l1, r);
    } else {
      const auto [r1, r2] = split(r);
      adjacent(l, r1);
      pair(l, r2);
    }
  }

  [[nodiscard]] IntersectionResult finish() {
    IntersectionResult out;
    out.tolerance = tol_;
    std::vector<CurveIntersection> points;
    // Zones explained as a whole (overlaps, tangential contacts) absorb the
    // Gauss–Newton roots inside them: near a tangency |D| falls below rounding
    // level well away from the contact point.
    std::vector<Zone> absorbing;
    for (const Zone& z : merge_zones()) classify(z, points, out.overlaps, absorbing);
    for (const Root& r : roots_) {
      bool absorbed = false;
      for (const Zone& z : absorbing) absorbed = absorbed || inside(z, r, 1.0);
      if (!absorbed) add_point(points, make_point(r, IntersectionKind::Crossing));
    }
    if (self_) {
      // Pieces met across the closure of a closed curve come with s > t.
      for (CurveIntersection& p : points)
        if (p.s > p.t) std::swap(p.s, p.t);
      for (CurveOverlap& o : out.overlaps)
        if (o.s0 > std::fmin(o.t0, o.t1)) {
          const bool up = o.t0 < o.t1;
          o = {std::fmin(o.t0, o.t1), std::fmax(o.t0, o.t1), up ? o.s0 : o.s1, up ? o.s1 : o.s0, {}, {}};
          o.start = A_.evaluate(o.s0);
          o.end = A_.evaluate(o.s1);
        }
      for (CurveOverlap& o : out.overlaps) snap_fold(o);
      std::erase_if(points, [&](const CurveIntersection& p) { return trivial(p.s, p.t); });
      std::erase_if(out.overlaps, [&](const CurveOverlap& o) { return trivial(o.s0, o.s1) && trivial(o.t0, o.t1); });
    }
    std::sort(points.begin(), points.end(), [](const auto& x, const auto& y) { return x.s < y.s; });
    std::sort(out.overlaps.begin(), out.overlaps.end(), [](const auto& x, const auto& y) { return x.s0 < y.s0; });
    out.points = std::move(points);
    return out;
  }

  void add_root(const Root& r) { roots_.push_back(r); }

 private:
  struct Zone {
    double s0, s1, t0, t1;
    int orientation;
  };

  // A leaf's zone piece: its pieces are too small for their chords to tell the orientation.
  ZonePiece zone_of(const Piece& a, const Piece& b) const { return {a.t0, a.t1, b.t0, b.t1, 0, slack(a), slack(b)}; }

  // The parameter step of a piece that moves its point by 2 tol (its chord speed; the box when the chord vanishes).
  double slack(const Piece& p) const {
    const double len = std::fmax(distance(p.P.front(), p.P.back()), p.size);
    return len > 0.0 ? 2.0 * tol_ * (p.t1 - p.t0) / len : p.t1 - p.t0;
  }

  // The smaller piece lies within tol of the other (at five samples, feet
  // sought inside the other piece): the zone piece is its interval and the
  // span of its feet. (Asking it of both pieces would fail wherever the two
  // curves are subdivided out of step, which is almost everywhere.)
  std::optional<ZonePiece> within(const Piece& a, const Piece& b) const {
    const bool a_small = a.size <= b.size;
    const Piece& p = a_small ? a : b;
    const Piece& q = a_small ? b : a;
    const NurbsCurve& C = a_small ? A_ : B_;
    const NurbsCurve& D = a_small ? B_ : A_;
    const Vec3 chord = q.P.back() - q.P.front();
    const double cc = dot(chord, chord);
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (int k = 0; k <= 4; ++k) {
      const Vec3 x = at(C, p.t0 + (p.t1 - p.t0) * k / 4.0);
      const double lam = cc > 0.0 ? std::clamp(dot(x - q.P.front(), chord) / cc, 0.0, 1.0) : 0.5;
      const auto [t, d] = local_foot(D, x, q.t0 + lam * (q.t1 - q.t0), {q.t0, q.t1}, eps0_, max_iterations_);
      if (d > tol_) return std::nullopt;
      lo = std::fmin(lo, t);
      hi = std::fmax(hi, t);
    }
    const int o = dot(a.axis, b.axis) < 0.0 ? -1 : 1;
    return a_small ? ZonePiece{a.t0, a.t1, lo, hi, o, slack(a), slack(b)}
                   : ZonePiece{lo, hi, b.t0, b.t1, o, slack(a), slack(b)};
  }

  // Connected groups of zone pieces (rectangles of (s, t) that overlap or
  // come within 2 tol of each other along both curves: feet found inside a
  // piece stop at its end, so neighbours may leave such gaps).
  std::vector<Zone> merge_zones() const {
    const std::size_t n = zones_.size();
    std::vector<std::size_t> parent(n);
    std::iota(parent.begin(), parent.end(), std::size_t{0});
    const auto find = [&](std::size_t i) {
      while (parent[i] != i) i = parent[i] = parent[parent[i]];
      return i;
    };
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return zones_[i].s0 < zones_[j].s0; });
    double gs_max = 0.0;
    for (const ZonePiece& z : zones_) gs_max = std::fmax(gs_max, z.gs);
    for (std::size_t x = 0; x < n; ++x) {
      const ZonePiece& zi = zones_[order[x]];
      for (std::size_t y = x + 1; y < n; ++y) {
        const ZonePiece& zj = zones_[order[y]];
        if (zj.s0 > zi.s1 + 2.0 * gs_max) break;
        const double gs = std::fmax(zi.gs, zj.gs), gt = std::fmax(zi.gt, zj.gt);
        const bool same_way = zj.orientation == zi.orientation || zi.orientation == 0 || zj.orientation == 0;
        if (same_way && zj.s0 <= zi.s1 + gs && zj.t0 <= zi.t1 + gt && zi.t0 <= zj.t1 + gt)
          parent[find(order[x])] = find(order[y]);
      }
    }
    std::vector<Zone> out;
    std::vector<std::size_t> index(n, n);
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t root = find(i);
      const ZonePiece& z = zones_[i];
      if (index[root] == n) {
        index[root] = out.size();
        out.push_back({z.s0, z.s1, z.t0, z.t1, z.orientation});
      } else {
        Zone& m = out[index[root]];
        if (m.orientation == 0) m.orientation = z.orientation;
        m.s0 = std::fmin(m.s0, z.s0);
        m.s1 = std::fmax(m.s1, z.s1);
        m.t0 = std::fmin(m.t0, z.t0);
        m.t1 = std::fmax(m.t1, z.t1);
      }
    }
    for (Zone& z : out)
      if (z.orientation == 0) z.orientation = 1;
    return out;
  }

  // A zone where the curves stay together (their distance at its quarter
  // points is below tol / 16) is an overlap; one where they separate again is
  // a contact: its crossings, or else its one tangential contact point
  // (Newton on the tangency system, or the nearest pair of points of the zone
  // where that system is singular, e.g. at an inflection). A contact of
  // relative curvature Δκ keeps the curves within tol over a stretch about
  // 2 (2 tol / Δκ)^½ long, at tol / 4 halfway to its ends; a zone no longer
  // than 8 tol is a point.
  static bool inside(const Zone& z, const Root& r, double grow) {
    const double ms = grow * (1e-9 * (z.s1 - z.s0) + 1e-300), mt = grow * (1e-9 * (z.t1 - z.t0) + 1e-300);
    return r.s >= z.s0 - ms && r.s <= z.s1 + ms && r.t >= z.t0 - mt && r.t <= z.t1 + mt;
  }

  void classify(const Zone& z, std::vector<CurveIntersection>& points, std::vector<CurveOverlap>& overlaps,
                std::vector<Zone>& absorbing) const {
    const Interval bs = widened(z.s0, z.s1, A_.domain()), bt = widened(z.t0, z.t1, B_.domain());
    // The zone's extent: how far its points get from its start (a closed curve returns to it).
    double len = 0.0;
    const Vec3 a0 = A_.evaluate(z.s0), b0 = B_.evaluate(z.t0);
    for (int k = 1; k <= 4; ++k) {
      len = std::fmax(len, distance(a0, at(A_, z.s0 + (z.s1 - z.s0) * k / 4.0)));
      len = std::fmax(len, distance(b0, at(B_, z.t0 + (z.t1 - z.t0) * k / 4.0)));
    }
    if (len > 8.0 * tol_) {
      double sep = 0.0;
      for (const double f : {0.25, 0.5, 0.75}) {
        const double s = z.s0 + f * (z.s1 - z.s0);
        const double t = z.orientation > 0 ? z.t0 + f * (z.t1 - z.t0) : z.t1 - f * (z.t1 - z.t0);
        sep = std::fmax(sep, local_foot(B_, at(A_, s), t, bt, eps0_, max_iterations_).second);
      }
      if (sep < tol_ / 16.0) {
        overlaps.push_back(overlap_of(z, bt, bs, std::fmax(4.0 * sep, 64.0 * eps0_)));
        absorbing.push_back(z);
        return;
      }
    }
    // Self: the two branches of a spike (the curve turning back by nearly π
    // at a corner or cusp) stay within tol of each other near its tip; the
    // zone then reaches the diagonal s = t through the tip's short arc. The
    // tip is where the curve turns, not where it meets itself.
    if (self_ && z.orientation < 0 && z.s1 <= z.t0 && arc_within(A_, z.s1, z.t0, 2.0 * len + 2.0 * tol_)) {
      absorbing.push_back(z);
      return;
    }
    const double sc = 0.5 * (z.s0 + z.s1), tc = 0.5 * (z.t0 + z.t1);
    bool regular = false;
    const Root tr = solver_.tangent(sc, tc, bs, bt, model_, &regular);
    if (regular && tr.dist <= tol_ && inside(z, tr, 1e8)) {
      add_point(points, make_point(tr, IntersectionKind::Tangent));
      absorbing.push_back(z);
      return;
    }
    // Planar curves crossing with parallel tangents (an inflection on the
    // contact): |D| vanishes to third order there, so Gauss–Newton stops
    // (rounding)^⅓ away; the sign of the gap across B locates it to rounding.
    if (planar_) {
      const auto t_of = [&](double s) {
        const double f = (s - z.s0) / (z.s1 - z.s0);
        return z.orientation > 0 ? z.t0 + f * (z.t1 - z.t0) : z.t1 - f * (z.t1 - z.t0);
      };
      const auto gap = [&](double s) {
        const Vec3 p = at(A_, s);
        const double t = local_foot(B_, p, t_of(s), bt, eps0_, max_iterations_).first;
        const Eval b = derivs(B_, t, 1);
        return std::pair{cross(b.d[1], p - b.d[0]).z, t};
      };
      double lo = z.s0, hi = z.s1;
      const double glo = gap(lo).first, ghi = gap(hi).first;
      if ((glo < 0.0 && ghi > 0.0) || (glo > 0.0 && ghi < 0.0)) {
        for (int k = 0; k < 200 && lo < hi; ++k) {
          const double m = 0.5 * (lo + hi);
          if (m == lo || m == hi) break;
          ((gap(m).first < 0.0) == (glo < 0.0) ? lo : hi) = m;
        }
        const double sm = 0.5 * (lo + hi), tm = gap(sm).second;
        const double d = distance(A_.evaluate(sm), B_.evaluate(tm));
        if (d <= tol_) {
          add_point(points, make_point({sm, tm, d, true}, IntersectionKind::Tangent));
          absorbing.push_back(z);
          return;
        }
      }
    }
    for (const Root& r : roots_)
      if (inside(z, r, 1.0)) return;  // the zone's crossings are reported as such
    const Root nr = solver_.nearest(sc, tc, bs, bt);
    if (nr.dist <= tol_) add_point(points, make_point(nr, IntersectionKind::Tangent));
  }

  // The overlap's ends: from each end of the zone, bisection towards its
  // quarter point for the last parameter where A is within `delta` of B (the
  // curves' gap inside the overlap, so exact overlaps end to rounding level,
  // not to tol), then snapped to an end of either curve within 2 tol.
  CurveOverlap overlap_of(const Zone& z, const Interval& bt, const Interval& bs, double delta) const {
    const Interval ds = A_.domain(), dt = B_.domain();
    const auto t_of = [&](double s) {  // the zone's linear s → t correspondence
      const double f = (s - z.s0) / (z.s1 - z.s0);
      return z.orientation > 0 ? z.t0 + f * (z.t1 - z.t0) : z.t1 - f * (z.t1 - z.t0);
    };
    const auto gap = [&](double s) { return local_foot(B_, at(A_, s), t_of(s), bt, eps0_, max_iterations_).second; };
    const auto end_pair = [&](double s_out, double s_in) {
      double s = s_out;
      if (gap(s_out) > delta) {
        for (int k = 0; k < 64 && s_out != s_in; ++k) {
          const double m = 0.5 * (s_out + s_in);
          if (m == s_out || m == s_in) break;
          (gap(m) <= delta ? s_in : s_out) = m;
        }
        s = s_in;
      }
      const Vec3 p = A_.evaluate(s);
      for (const double e : {ds.start, ds.end})
        if (distance(p, A_.evaluate(e)) <= 2.0 * tol_ && std::fabs(e - s) <= 0.5 * (z.s1 - z.s0)) s = e;
      double t = local_foot(B_, A_.evaluate(s), t_of(s), bt, eps0_, max_iterations_).first;
      const Vec3 q = B_.evaluate(t);
      for (const double e : {dt.start, dt.end})
        if (distance(q, B_.evaluate(e)) <= 2.0 * tol_ && std::fabs(e - t) <= 0.5 * (z.t1 - z.t0)) {
          t = e;
          s = local_foot(A_, B_.evaluate(t), s, bs, eps0_, max_iterations_).first;
        }
      return std::pair{s, t};
    };
    const auto [s0, t0] = end_pair(z.s0, z.s0 + 0.25 * (z.s1 - z.s0));
    const auto [s1, t1] = end_pair(z.s1, z.s1 - 0.25 * (z.s1 - z.s0));
    CurveOverlap o;
    o.s0 = std::fmin(s0, s1);
    o.s1 = std::fmax(s0, s1);
    o.t0 = s0 <= s1 ? t0 : t1;
    o.t1 = s0 <= s1 ? t1 : t0;
    o.start = A_.evaluate(o.s0);
    o.end = A_.evaluate(o.s1);
    return o;
  }

  CurveIntersection make_point(const Root& r, IntersectionKind kind) const {
    const Eval a = derivs(A_, r.s, 1), b = derivs(B_, r.t, 1);
    CurveIntersection p;
    p.s = r.s;
    p.t = r.t;
    p.point = 0.5 * (a.d[0] + b.d[0]);
    p.distance = distance(a.d[0], b.d[0]);
    const double na = norm(a.d[1]), nb = norm(b.d[1]);
    p.angle = na > 0.0 && nb > 0.0 ? std::atan2(norm(cross(a.d[1], b.d[1])), std::fabs(dot(a.d[1], b.d[1]))) : 0.0;
    p.kind = kind;
    return p;
  }

  // Adds a point unless one within 2 tol along both curves is there (the
  // tangent one, then the nearer one, is kept).
  void add_point(std::vector<CurveIntersection>& points, const CurveIntersection& p) const {
    for (CurveIntersection& q : points)
      if (same_place(A_, p.s, q.s) && same_place(B_, p.t, q.t)) {
        const bool better = (p.kind == IntersectionKind::Tangent && q.kind != IntersectionKind::Tangent) ||
                            (p.kind == q.kind && p.distance < q.distance);
        if (better) q = p;
        return;
      }
    points.push_back(p);
  }

  // Parameters u and v of C are one place: the arc between them stays within 2 tol.
  bool same_place(const NurbsCurve& C, double u, double v) const {
    if (u == v) return true;
    const Vec3 cu = C.evaluate(u);
    for (int k = 1; k <= 4; ++k)
      if (distance(cu, at(C, k == 4 ? v : u + (v - u) * k / 4.0)) > 2.0 * tol_) return false;
    return true;
  }

  // Self: an overlap whose end (s1, t1) meets the diagonal (the curve runs
  // back over itself from a fold: a cusp or a reversing corner) ends at the
  // fold, the point of the arc between s1 and t1 farthest along the overlap's
  // direction (golden-section search; the subdivision stops short of it).
  void snap_fold(CurveOverlap& o) const {
    if (!(o.t1 < o.t0) || !same_place(A_, o.s1, o.t1)) return;
    const Vec3 dir = A_.evaluate(o.s1) - at(A_, o.s0 + 0.75 * (o.s1 - o.s0));
    const auto reach = [&](double u) { return dot(at(A_, u), dir); };
    constexpr double kInvPhi = 0.6180339887498949;
    double lo = std::fmin(o.s1, o.t1), hi = std::fmax(o.s1, o.t1);
    for (int k = 0; k < 200 && hi - lo > 4.0 * kEps * std::fmax(1.0, std::fabs(hi)); ++k) {
      const double m1 = hi - kInvPhi * (hi - lo), m2 = lo + kInvPhi * (hi - lo);
      (reach(m1) < reach(m2) ? lo : hi) = reach(m1) < reach(m2) ? m1 : m2;
    }
    o.s1 = o.t1 = 0.5 * (lo + hi);
    o.end = A_.evaluate(o.s1);
  }

  // The arc of C between u and v stays within r of C(u) (at 8 samples).
  static bool arc_within(const NurbsCurve& C, double u, double v, double r) {
    const Vec3 cu = C.evaluate(u);
    for (int k = 1; k <= 8; ++k)
      if (distance(cu, at(C, k == 8 ? v : u + (v - u) * k / 8.0)) > r) return false;
    return true;
  }

  // Self: s and t are one place of the curve, or a loop or spike tip below the
  // resolution: the arc between them (for a closed curve, the arc through its
  // ends) stays within 8 tol, the length below which a zone is one point.
  bool trivial(double s, double t) const {
    if (arc_within(A_, s, t, 8.0 * tol_)) return true;
    const Interval d = A_.domain();
    return closed_ && arc_within(A_, s, d.start, 8.0 * tol_) && arc_within(A_, t, d.end, 8.0 * tol_);
  }

  bool planar_;  // both curves lie in one plane z = const
  bool closed_;
  const NurbsCurve& A_;
  const NurbsCurve& B_;
  double tol_;
  double model_;
  bool self_;
  Solver solver_;
  double eps0_;
  int max_iterations_;
  std::vector<Root> roots_;
  std::vector<ZonePiece> zones_;
  std::size_t pairs_ = 0;
};

struct Scale {
  double tol;
  double eps0;
  double model;
};

Scale scale_of(const NurbsCurve& a, const NurbsCurve& b, const IntersectOptions& options) {
  Box3 box = a.control_box();
  box.add(b.control_box().min);
  box.add(b.control_box().max);
  const double model = std::fmax(a.model_size(), b.model_size());
  const double magnitude = std::fmax(box.extent(), model);
  return {resolution_for_size(options.tolerance, model), 16.0 * kEps * magnitude, model > 0.0 ? model : 1.0};
}

// Ends of one curve lying on the other (touching at an end), found by the global closest point.
void end_roots(const NurbsCurve& a, const NurbsCurve& b, double tol, Engine& engine, bool a_first) {
  for (const double e : {a.domain().start, a.domain().end}) {
    const ClosestPointResult cp = closest_point(b, a.evaluate(e));
    if (cp.distance <= tol)
      engine.add_root(a_first ? Root{e, cp.t, cp.distance, true} : Root{cp.t, e, cp.distance, true});
  }
}

// Pairs of pieces in the order of their distance lower bounds (best first).
struct PairItem {
  double bound;
  std::size_t a, b;
  bool operator<(const PairItem& o) const { return bound > o.bound; }
};

}  // namespace

const char* intersection_kind_name(IntersectionKind kind) noexcept {
  return kind == IntersectionKind::Tangent ? "tangent" : "crossing";
}

void IntersectOptions::validate() const {
  tolerance.validate();
  if (max_iterations < 1 || max_iterations > 1000)
    throw Error(Errc::InvalidOption,
                "options.max_iterations = " + std::to_string(max_iterations) + " must be in [1, 1000]",
                {.field = "max_iterations"});
}

namespace {

IntersectionResult intersect_scaled(const NurbsCurve& a, const NurbsCurve& b, const Scale& sc,
                                    const IntersectOptions& options) {
  Engine engine(a, b, sc.tol, sc.eps0, sc.model, options.max_iterations, false, false);
  end_roots(a, b, sc.tol, engine, true);
  end_roots(b, a, sc.tol, engine, false);
  const std::vector<Piece> pa = pieces_of(a), pb = pieces_of(b);
  for (const Piece& x : pa)
    for (const Piece& y : pb) engine.pair(x, y);
  return engine.finish();
}

IntersectionResult self_intersect_scaled(const NurbsCurve& curve, const Scale& sc, const IntersectOptions& options) {
  const Interval d = curve.domain();
  const bool closed = distance(curve.evaluate(d.start), curve.evaluate(d.end)) <= sc.tol;
  Engine engine(curve, curve, sc.tol, sc.eps0, sc.model, options.max_iterations, true, closed);
  const std::vector<Piece> p = pieces_of(curve);
  for (std::size_t i = 0; i < p.size(); ++i) {
    engine.self(p[i]);
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      if (j == i + 1)
        engine.adjacent(p[i], p[j]);
      else if (closed && i == 0 && j + 1 == p.size())
        engine.adjacent(p[j], p[i]);
      else
        engine.pair(p[i], p[j]);
    }
  }
  return engine.finish();
}

struct DistanceFound {
  Root best;
  double bound = 0.0;  // no pair of points is closer (scaled units)
};

DistanceFound curve_distance_scaled(const NurbsCurve& a, const NurbsCurve& b, const Scale& sc,
                                    const IntersectOptions& options) {
  const Solver solver{a, b, sc.eps0, 64.0 * sc.eps0, options.max_iterations};
  // Start from the ends of each curve against the other (a minimum may sit on a domain end).
  Root best;
  const auto offer = [&](const Root& r) {
    if (r.dist < best.dist) best = r;
  };
  for (const double e : {a.domain().start, a.domain().end}) {
    const ClosestPointResult cp = closest_point(b, a.evaluate(e));
    offer({e, cp.t, cp.distance, true});
  }
  for (const double e : {b.domain().start, b.domain().end}) {
    const ClosestPointResult cp = closest_point(a, b.evaluate(e));
    offer({cp.t, e, cp.distance, true});
  }
  // Branch and bound: a pair of pieces is dropped once its lower bound is
  // within tol of the best distance found; the queue gives the most promising first.
  // Pieces live in two arenas; a piece split once keeps its halves (it meets many partners).
  struct Arena {
    std::deque<Piece> pieces;              // a deque: pieces never move
    std::vector<std::size_t> first_child;  // 0: not split yet
    std::size_t children(std::size_t i) {
      if (first_child[i] == 0) {
        auto [l, r] = split(pieces[i]);
        first_child[i] = pieces.size();
        pieces.push_back(std::move(l));
        pieces.push_back(std::move(r));
        first_child.resize(pieces.size(), 0);
      }
      return first_child[i];
    }
  };
  const std::vector<Piece> ea = pieces_of(a), eb = pieces_of(b);
  Arena pa{{ea.begin(), ea.end()}, {}}, pb{{eb.begin(), eb.end()}, {}};
  pa.first_child.assign(pa.pieces.size(), 0);
  pb.first_child.assign(pb.pieces.size(), 0);
  std::priority_queue<PairItem> queue;
  for (std::size_t i = 0; i < pa.pieces.size(); ++i)
    for (std::size_t j = 0; j < pb.pieces.size(); ++j) queue.push({lower_bound(pa.pieces[i], pb.pieces[j]), i, j});
  std::size_t visits = 0;
  while (!queue.empty() && best.dist > sc.eps0) {
    const PairItem item = queue.top();
    if (item.bound >= best.dist - sc.tol || ++visits > kMaxDistancePairs) break;
    queue.pop();
    const bool sx = splittable(pa.pieces[item.a], sc.tol), sy = splittable(pb.pieces[item.b], sc.tol);
    {
      // Newton from the chords' closest points where they promise a better
      // distance (and on leaves): the bounds, not Newton, make the result
      // global, so a pair that cannot improve on the best only gets split.
      const Piece& x = pa.pieces[item.a];
      const Piece& y = pb.pieces[item.b];
      const SegmentClosest seed = closest_segments(x.P.front(), x.P.back(), y.P.front(), y.P.back());
      const double s0 = x.t0 + seed.u * (x.t1 - x.t0), t0 = y.t0 + seed.v * (y.t1 - y.t0);
      if ((!sx && !sy) || distance(a.evaluate(s0), b.evaluate(t0)) < best.dist)
        offer(solver.nearest(s0, t0, widened(x.t0, x.t1, a.domain()), widened(y.t0, y.t1, b.domain())));
    }
    if (!sx && !sy) continue;
    const auto push = [&](std::size_t i, std::size_t j) {
      const double lb = lower_bound(pa.pieces[i], pb.pieces[j]);
      if (lb < best.dist - sc.tol) queue.push({lb, i, j});
    };
    if (sx && (!sy || pa.pieces[item.a].size >= pb.pieces[item.b].size)) {
      const std::size_t c = pa.children(item.a);
      push(c, item.b);
      push(c + 1, item.b);
    } else {
      const std::size_t c = pb.children(item.b);
      push(item.a, c);
      push(item.a, c + 1);
    }
  }
  // The queue's smallest bound is the proof; an empty queue (or a meeting) proves the best itself, to tol.
  const double bound = queue.empty() || best.dist <= sc.eps0 ? best.dist - sc.tol : queue.top().bound;
  return {best, std::fmax(0.0, std::fmin(best.dist, bound))};
}

// Curves whose coordinates are far from 1 are solved on copies scaled by a
// power of two (exact), so that the squared lengths of the solvers neither
// overflow nor underflow; parameters are unchanged, and points and distances
// are evaluated on the curves as given.
int scale_exponent(const NurbsCurve& a, const NurbsCurve& b) {
  const double magnitude = std::fmax(a.control_box().extent(), b.control_box().extent());
  return magnitude > 1e100 || (magnitude > 0.0 && magnitude < 1e-100) ? -std::ilogb(magnitude) : 0;
}

NurbsCurve scaled(const NurbsCurve& c, int exponent) {
  std::vector<Vec3> P(c.control_points().begin(), c.control_points().end());
  for (Vec3& p : P) p = {std::ldexp(p.x, exponent), std::ldexp(p.y, exponent), std::ldexp(p.z, exponent)};
  return {c.knots(), std::move(P), {c.weights().begin(), c.weights().end()}, c.dimension()};
}

Scale scaled(Scale sc, const NurbsCurve& a, const NurbsCurve& b, int exponent) {
  const Box3 x = a.control_box(), y = b.control_box();
  sc.tol = std::ldexp(sc.tol, exponent);
  sc.model = std::ldexp(sc.model, exponent);
  sc.eps0 = 16.0 * kEps * std::fmax(std::fmax(x.extent(), y.extent()), sc.model);
  return sc;
}

// The result's points and distances on the curves as given.
IntersectionResult restored(IntersectionResult r, const NurbsCurve& a, const NurbsCurve& b, int exponent) {
  r.tolerance = std::ldexp(r.tolerance, -exponent);
  for (CurveIntersection& p : r.points) {
    const Vec3 pa = a.evaluate(p.s), pb = b.evaluate(p.t);
    p.point = 0.5 * pa + 0.5 * pb;
    p.distance = distance(pa, pb);
  }
  for (CurveOverlap& o : r.overlaps) {
    o.start = a.evaluate(o.s0);
    o.end = a.evaluate(o.s1);
  }
  return r;
}

}  // namespace

IntersectionResult intersect(const NurbsCurve& a, const NurbsCurve& b, const IntersectOptions& options) {
  options.validate();
  const Scale sc = scale_of(a, b, options);
  const int e = scale_exponent(a, b);
  if (e == 0) return intersect_scaled(a, b, sc, options);
  const NurbsCurve sa = scaled(a, e), sb = scaled(b, e);
  return restored(intersect_scaled(sa, sb, scaled(sc, sa, sb, e), options), a, b, e);
}

IntersectionResult self_intersect(const NurbsCurve& curve, const IntersectOptions& options) {
  options.validate();
  const Scale sc = scale_of(curve, curve, options);
  const int e = scale_exponent(curve, curve);
  if (e == 0) return self_intersect_scaled(curve, sc, options);
  const NurbsCurve s = scaled(curve, e);
  return restored(self_intersect_scaled(s, scaled(sc, s, s, e), options), curve, curve, e);
}

CurveDistanceResult curve_distance(const NurbsCurve& a, const NurbsCurve& b, const IntersectOptions& options) {
  options.validate();
  const Scale sc = scale_of(a, b, options);
  const int e = scale_exponent(a, b);
  DistanceFound found;
  if (e == 0) {
    found = curve_distance_scaled(a, b, sc, options);
  } else {
    const NurbsCurve sa = scaled(a, e), sb = scaled(b, e);
    found = curve_distance_scaled(sa, sb, scaled(sc, sa, sb, e), options);
    found.bound = std::ldexp(found.bound, -e);
  }
  const Root& best = found.best;
  CurveDistanceResult out;
  out.s = best.s;
  out.t = best.t;
  out.point_a = a.evaluate(best.s);
  out.point_b = b.evaluate(best.t);
  out.distance = distance(out.point_a, out.point_b);
  out.lower_bound = std::fmin(found.bound, out.distance);
  return out;
}

}  // namespace hula::nurbs
