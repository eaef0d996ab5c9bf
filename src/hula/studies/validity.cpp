// SPDX-License-Identifier: MIT
// Validity requirements of design curves (see the header).
#include "hula/studies/validity.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "hula/core/error.hpp"
#include "hula/curve/curve.hpp"
#include "hula/diffgeom/monotonicity.hpp"
#include "hula/nurbs/intersect.hpp"

namespace hula::studies {

namespace {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

std::string where(const Vec3& p, int dimension) {
  return "(" + num(p.x) + ", " + num(p.y) + (dimension == 3 ? ", " + num(p.z) : std::string()) + ")";
}

// Lowest speed over the samples relative to their mean (trapezoidal in t): 32 per knot span, each span's
// ends evaluated from inside it, so a knot where the speed jumps is seen from both sides.
void measure_speed(const nurbs::NurbsCurve& c, ValidityCheck& check) {
  constexpr int kPerSpan = 32;
  const std::vector<double> breaks = c.knots().breakpoints();
  double integral = 0.0, lowest = HUGE_VAL;
  std::array<Vec3, 2> d{};
  for (std::size_t s = 0; s + 1 < breaks.size(); ++s) {
    const double a = breaks[s], b = breaks[s + 1], h = (b - a) / kPerSpan;
    double previous = 0.0;
    for (int k = 0; k <= kPerSpan; ++k) {
      const double t = k == kPerSpan ? b : a + h * k;
      c.derivatives(t, 1, d, {.side = k == kPerSpan ? nurbs::Side::Left : nurbs::Side::Right});
      const double speed = norm(d[1]);
      if (k > 0) integral += 0.5 * h * (previous + speed);
      previous = speed;
      if (speed < lowest) {
        lowest = speed;
        check.slowest_at = t;
      }
    }
  }
  const double mean = integral / c.domain().length();
  check.speed_ratio = mean > 0.0 ? lowest / mean : 0.0;
}

}  // namespace

std::size_t ValidityRequirements::count() const noexcept {
  return static_cast<std::size_t>(no_self_intersection) + static_cast<std::size_t>(min_speed > 0.0) +
         static_cast<std::size_t>(monotone_curvature);
}

void ValidityRequirements::validate() const {
  if (!(min_speed >= 0.0 && min_speed < 1.0))
    throw Error(Errc::InvalidArgument,
                "validity.min_speed = " + format_number(min_speed) +
                    " must be in [0, 1): the lowest speed allowed as a fraction of the mean speed",
                {.field = "validity.min_speed"});
  if (!(std::isfinite(penalty) && penalty >= 0.0))
    throw Error(Errc::InvalidArgument, "validity.penalty = " + format_number(penalty) + " must be finite and >= 0",
                {.field = "validity.penalty"});
}

void ValidityRequirements::apply(optim::RunSettings& run) const {
  run.constraints = handling;
  run.penalty = penalty;
}

ValidityCheck check_validity(const nurbs::NurbsCurve& curve, const ValidityRequirements& requirements) {
  requirements.validate();
  ValidityCheck check;
  const int dim = curve.dimension();
  if (requirements.no_self_intersection) {
    const nurbs::IntersectionResult r = nurbs::self_intersect(curve);
    check.self_intersections = r.points.size() + r.overlaps.size();
    if (!r.points.empty()) {
      const nurbs::CurveIntersection& p = r.points.front();
      check.reasons.push_back(
          "the curve meets itself at " + where(p.point, dim) + " (t = " + num(p.s) + " and " + num(p.t) + ")" +
          (check.self_intersections > 1 ? " and at " + std::to_string(check.self_intersections - 1) + " more place(s)"
                                        : std::string()));
    } else if (!r.overlaps.empty()) {
      const nurbs::CurveOverlap& o = r.overlaps.front();
      check.reasons.push_back("the curve runs back over itself from " + where(o.start, dim) + " to " +
                              where(o.end, dim) + " (t = " + num(o.s0) + " to " + num(o.s1) + ")");
    }
  }
  if (requirements.min_speed > 0.0) {
    measure_speed(curve, check);
    if (check.speed_ratio < requirements.min_speed)
      check.reasons.push_back("cusp: the speed falls to " + num(100.0 * check.speed_ratio) + " % of its mean at t = " +
                              num(check.slowest_at) + " " + where(curve.evaluate(check.slowest_at), dim) +
                              ", below validity.min_speed = " + num(requirements.min_speed));
  }
  if (requirements.monotone_curvature) {
    const diffgeom::CurvatureMonotonicity m = diffgeom::curvature_monotonicity(curve::Curve(curve), dim == 2);
    check.curvature_extrema = m.violations.size();
    if (!m.monotone()) {
      const diffgeom::Feature& f = m.violations.front();
      check.reasons.push_back("the curvature is not monotone: " + std::to_string(m.violations.size()) +
                              " curvature extremum(s), the first at t = " + num(f.t) + " " + where(f.position, dim));
    }
  }
  return check;
}

void validity_constraints(const ValidityCheck& check, const ValidityRequirements& requirements, std::span<double> out) {
  std::size_t k = 0;
  if (requirements.no_self_intersection) out[k++] = static_cast<double>(check.self_intersections);
  if (requirements.min_speed > 0.0) out[k++] = requirements.min_speed - check.speed_ratio;
  if (requirements.monotone_curvature) out[k++] = static_cast<double>(check.curvature_extrema);
}

}  // namespace hula::studies
