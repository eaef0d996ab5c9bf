// SPDX-License-Identifier: MIT
// Sampled curve-to-curve distance (see deviation.hpp).
#include "hula/nurbs/deviation.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/nurbs/closest_point.hpp"

namespace hula::nurbs {

void DeviationOptions::validate() const {
  if (samples < 2)
    throw Error(Errc::InvalidOption, "DeviationOptions::samples = " + std::to_string(samples) + " must be >= 2",
                ErrorWhere{.field = "samples"});
  if (mode != DeviationMode::Parameter && mode != DeviationMode::Closest)
    throw Error(Errc::InvalidOption, "DeviationOptions::mode is not a DeviationMode value",
                ErrorWhere{.field = "mode"});
}

namespace {
// Parameter of curve c at normalised s; the ends are the exact domain ends.
double at_fraction(const Interval& d, std::size_t i, std::size_t n) {
  if (i == 0) return d.start;
  if (i + 1 == n) return d.end;
  const double s = static_cast<double>(i) / static_cast<double>(n - 1);
  return d.start + s * (d.end - d.start);
}
}  // namespace

DeviationResult deviation(const NurbsCurve& a, const NurbsCurve& b, const DeviationOptions& options) {
  options.validate();
  const std::size_t n = options.samples;
  std::vector<double> ta(n), tb(n);
  for (std::size_t i = 0; i < n; ++i) {
    ta[i] = at_fraction(a.domain(), i, n);
    tb[i] = at_fraction(b.domain(), i, n);
  }
  std::vector<Vec3> pa(n), pb(n);
  a.evaluate(ta, pa);
  if (options.mode == DeviationMode::Parameter) {
    b.evaluate(tb, pb);
  } else {
    for (std::size_t i = 0; i < n; ++i) pb[i] = closest_point(b, pa[i]).point;
  }
  DeviationResult r;
  r.samples = n;
  double sum = 0.0, sum2 = 0.0;
  Vec3 axis_sum{};
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 d = pa[i] - pb[i];
    const double len = norm(d);
    sum += len;
    sum2 += len * len;
    const Vec3 ad{std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)};
    axis_sum += ad;
    for (std::size_t c = 0; c < 3; ++c) r.max_axis[c] = std::max(r.max_axis[c], ad[c]);
    if (len > r.max) {
      r.max = len;
      r.at = static_cast<double>(i) / static_cast<double>(n - 1);
    }
  }
  const double inv = 1.0 / static_cast<double>(n);
  r.mean = sum * inv;
  r.rms = std::sqrt(sum2 * inv);
  r.mean_axis = axis_sum * inv;
  return r;
}

}  // namespace hula::nurbs
