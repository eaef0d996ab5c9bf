// scratch
#include <gtest/gtest.h>

#include <Geom2dAPI_InterCurveCurve.hxx>
#include <Geom2dInt_GInter.hxx>
#include <IntRes2d_IntersectionPoint.hxx>
#include <GeomAPI_ExtremaCurveCurve.hxx>
#include <cstdio>

#include "hula/core/rng.hpp"
#include "hula/nurbs/intersect.hpp"
#include "hula/testing/curve_generators.hpp"
#include "hula/testing/occt_curve.hpp"

namespace hula::nurbs {
namespace {

NurbsCurve planar(const NurbsCurve& c) {
  std::vector<Vec3> P(c.control_points().begin(), c.control_points().end());
  for (Vec3& p : P) p.z = 0.0;
  return NurbsCurve(c.knots(), P, {c.weights().begin(), c.weights().end()}, 2);
}

TEST(Scratch, Random2d) {
  Rng rng(7);
  int occ_total = 0, ours_total = 0, missed = 0, extra = 0, segs = 0;
  double worst = 0;
  for (int i = 0; i < 200; ++i) {
    const NurbsCurve a = planar(testing::random_curve(rng, {.degree = 1 + static_cast<int>(rng.below(5)), .rational = i % 2 == 0, .extra_points = static_cast<int>(rng.below(6))}));
    const NurbsCurve b = planar(testing::random_curve(rng, {.degree = 1 + static_cast<int>(rng.below(5)), .rational = i % 3 == 0, .extra_points = static_cast<int>(rng.below(6))}));
    Geom2dAPI_InterCurveCurve inter(testing::to_occt_2d(a), testing::to_occt_2d(b), 1e-9);
    const IntersectionResult r = intersect(a, b);
    occ_total += inter.NbPoints();
    ours_total += static_cast<int>(r.points.size());
    segs += inter.NbSegments();
    for (int k = 1; k <= inter.NbPoints(); ++k) {
      const Vec3 q = testing::to_vec3(inter.Point(k));
      double best = HUGE_VAL;
      for (const auto& p : r.points) best = std::min(best, distance(p.point, q));
      if (best > 1e-10) { ++missed; std::printf("pair %d occt point %d (%g,%g) nearest ours %g\n", i, k, q.x, q.y, best); }
      worst = std::max(worst, best < 1e-6 ? best : 0.0);
    }
    for (const auto& p : r.points) {
      double best = HUGE_VAL;
      for (int k = 1; k <= inter.NbPoints(); ++k) best = std::min(best, distance(p.point, testing::to_vec3(inter.Point(k))));
      const auto ca = testing::to_occt_2d(a); const auto cb = testing::to_occt_2d(b);
      const double check = testing::to_vec3(ca->Value(p.s)).x - testing::to_vec3(cb->Value(p.t)).x + 0*ca->Continuity();
      const double check2 = ca->Value(p.s).Distance(cb->Value(p.t));
      if (best > 1e-10) { ++extra; std::printf("occtdist %g cont %d %d  ", check2, static_cast<int>(ca->Continuity()), static_cast<int>(cb->Continuity())); (void)check; std::printf("pair %d ours s=%.17g t=%.17g dist=%g kind=%s angle=%g nearest occt %g\n", i, p.s, p.t, p.distance, intersection_kind_name(p.kind), p.angle, best); }
    }
    {
      const int N = 3000;
      if (i != 11 && i != 48) continue;
      std::vector<Vec3> pa(N + 1), pb(N + 1);
      for (int k = 0; k <= N; ++k) {
        pa[k] = a.evaluate(k == N ? a.domain().end : a.domain().start + a.domain().length() * k / N);
        pb[k] = b.evaluate(k == N ? b.domain().end : b.domain().start + b.domain().length() * k / N);
      }
      for (int x = 0; x < N; ++x)
        for (int y = 0; y < N; ++y) {
          const Vec3 d1 = pa[x + 1] - pa[x], d2 = pb[y + 1] - pb[y], r0 = pb[y] - pa[x];
          const double den = d1.x * d2.y - d1.y * d2.x;
          if (den == 0) continue;
          const double u = (r0.x * d2.y - r0.y * d2.x) / den, v = (r0.x * d1.y - r0.y * d1.x) / den;
          if (u < 0 || u > 1 || v < 0 || v > 1) continue;
          const Vec3 q = pa[x] + u * d1;
          if (i == 11 && distance(q, {-3.80223,3.1498,0}) < 0.01) std::printf("  seg x=%d y=%d u=%g v=%g q=(%.9g,%.9g)\n", x, y, u, v, q.x, q.y);
          double best = HUGE_VAL;
          for (const auto& p : r.points) best = std::min(best, distance(p.point, q));
          if (best > 1e-3) for (const auto& p : r.points) if (distance(p.point, q) < 0.05) std::printf("  near: (%.9g,%.9g) s=%.12g t=%.12g kind %s ang %g\n", p.point.x, p.point.y, p.s, p.t, intersection_kind_name(p.kind), p.angle);
          if (best > 1e-3) std::printf("POLY pair %d polyline crossing (%g,%g) nearest ours %g\n", i, q.x, q.y, best);
        }
    }
    if (!r.overlaps.empty()) std::printf("pair %d overlaps %zu\n", i, r.overlaps.size());
  }
  std::printf("occt %d ours %d missed %d extra %d segs %d worst matched %g\n", occ_total, ours_total, missed, extra, segs, worst);
}

}  // namespace
}  // namespace hula::nurbs
