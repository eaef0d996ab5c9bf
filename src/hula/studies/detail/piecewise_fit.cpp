// SPDX-License-Identifier: MIT
#include "hula/studies/detail/piecewise_fit.hpp"

#include <algorithm>
#include <string>

#include "hula/core/error.hpp"

namespace hula::studies::detail {

std::vector<double> breakpoints(const nurbs::NurbsCurve& curve) {
  const nurbs::Interval d = curve.domain();
  std::vector<double> out{d.start};
  for (const double u : curve.knots().values())
    if (u > out.back() && u < d.end) out.push_back(u);
  out.push_back(d.end);
  return out;
}

law::ToNurbsResult fit_on_spans(const law::Law& law, std::string_view parameter, std::span<const double> breaks,
                                const law::ToNurbsOptions& options, std::string_view field) {
  HULA_ASSERT(breaks.size() >= 2, "fit_on_spans needs two breakpoints");
  std::vector<nurbs::NurbsCurve> pieces;
  double deviation = 0.0;
  std::size_t segments = 0;
  for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
    law::ToNurbsResult r = law::to_nurbs(law, parameter, breaks[i], breaks[i + 1], options);
    deviation = std::max(deviation, r.max_deviation);
    segments += r.segments;
    pieces.push_back(std::move(r.curve));
  }
  if (pieces.size() == 1) {
    const std::size_t n = pieces[0].control_points().size();
    return {std::move(pieces[0]), deviation, n, segments};
  }
  // Join: each piece is a clamped quintic {b_i^6, interior, b_{i+1}^6}; the joint keeps one copy of
  // the shared end point and knot multiplicity 5 (C0; the law fixes the two sides' derivatives).
  // The pieces must meet: the law is continuous only if the input is smooth enough at the breakpoint.
  for (std::size_t i = 0; i + 1 < pieces.size(); ++i) {
    const Vec3 a = pieces[i].control_points().back(), b = pieces[i + 1].control_points().front();
    const double gap = distance(a, b);
    if (gap > 10.0 * options.tolerance)
      throw Error(Errc::InvalidArgument,
                  std::string(field) + ": the result jumps by " + format_number(gap) +
                      " at the knot t = " + format_number(breaks[i + 1]) +
                      " (the input's tangent or a higher derivative it depends on is discontinuous there)",
                  {.field = std::string(field), .index = i + 1});
  }
  const int p = pieces[0].degree();
  std::vector<double> knots(static_cast<std::size_t>(p + 1), breaks.front());
  std::vector<Vec3> points;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const auto U = pieces[i].knots().values();
    HULA_ASSERT(pieces[i].degree() == p, "to_nurbs pieces share one degree");
    knots.insert(knots.end(), U.begin() + p + 1, U.end() - (p + 1));
    if (i + 1 < pieces.size()) knots.insert(knots.end(), static_cast<std::size_t>(p), breaks[i + 1]);
    const auto P = pieces[i].control_points();
    points.insert(points.end(), P.begin() + (i == 0 ? 0 : 1), P.end());
  }
  knots.insert(knots.end(), static_cast<std::size_t>(p + 1), breaks.back());
  const std::size_t n = points.size();
  return {nurbs::NurbsCurve(p, std::move(knots), std::move(points), {}, pieces[0].dimension()), deviation, n, segments};
}

}  // namespace hula::studies::detail
