// SPDX-License-Identifier: MIT
// Match (end poles from the clamped-end derivative formulas) and Blend (scaled
// Hermite with a golden-section search of ∫κ'² ds); see match_blend.hpp.
#include "hula/diffgeom/match_blend.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "hula/core/error.hpp"
#include "hula/diffgeom/features.hpp"
#include "hula/nurbs/elevate.hpp"
#include "hula/nurbs/interpolate.hpp"
#include "hula/nurbs/refine.hpp"
#include "hula/nurbs/reparam.hpp"

namespace hula::diffgeom {

namespace {

using Table = std::array<Vec3, 4>;

Table table(const nurbs::NurbsCurve& c, double t, nurbs::Side side) {
  Table d{};
  nurbs::EvalOptions o;
  o.side = side;
  c.derivatives(t, 3, d, o);
  return d;
}

double model_size(const nurbs::NurbsCurve& a, const nurbs::NurbsCurve& b) {
  return std::max(a.model_size(), b.model_size());
}

double step(const nurbs::NurbsCurve& a, const nurbs::NurbsCurve& b) {
  return std::max(a.domain().length(), b.domain().length());
}

// N_i^(j) at the end of the domain (from below), j = 0 … 3, as the x component of the curve whose only
// non-zero pole is the unit x vector at index i.
std::array<double, 4> end_basis(const nurbs::NurbsCurve& c, std::size_t i) {
  std::vector<Vec3> poles(c.control_points().size(), Vec3{});
  poles[i] = Vec3{1.0, 0.0, 0.0};
  const nurbs::NurbsCurve unit(c.knots(), std::move(poles), {}, 3);
  const Table d = table(unit, c.domain().end, nurbs::Side::Left);
  return {d[0].x, d[1].x, d[2].x, d[3].x};
}

// Inserts knots at the middle of the longest span until A has at least `poles` control points.
nurbs::NurbsCurve with_poles(nurbs::NurbsCurve c, std::size_t poles, int& inserted) {
  while (c.control_points().size() < poles) {
    const std::vector<double> bp = c.knots().breakpoints();
    std::size_t widest = 0;
    for (std::size_t i = 1; i + 1 < bp.size(); ++i)
      if (bp[i + 1] - bp[i] > bp[widest + 1] - bp[widest]) widest = i;
    c = nurbs::insert_knot(c, 0.5 * (bp[widest] + bp[widest + 1]));
    ++inserted;
  }
  return c;
}

}  // namespace

void MatchOptions::validate() const {
  if (continuity < 0 || continuity > 3)
    throw Error(Errc::InvalidOption, "continuity = G" + std::to_string(continuity) + " must be G0 … G3",
                {.field = "continuity"});
  if (!std::isfinite(at)) throw Error(Errc::NonFiniteInput, "at must be finite", {.field = "at"});
  if (!(tangent_scale > 0.0 && tangent_scale <= 1e3))
    throw Error(Errc::InvalidOption, "tangent_scale = " + format_number(tangent_scale) + " must be in (0, 1e3]",
                {.field = "tangent_scale"});
}

MatchResult match_end(const nurbs::NurbsCurve& a_in, const nurbs::NurbsCurve& b, const MatchOptions& options) {
  options.validate();
  if (a_in.is_rational())
    throw Error(Errc::Unsupported, "match needs a non-rational curve A (its end poles are solved linearly)",
                {.field = "a"});
  if (!a_in.knots().is_clamped()) throw Error(Errc::Unsupported, "match needs a clamped curve A", {.field = "a"});
  const int k = options.continuity;
  const bool at_start = options.end == CurveEnd::Start;
  nurbs::NurbsCurve a = at_start ? nurbs::reverse(a_in) : a_in;

  // The target on B, and the direction A runs into it: s = +1 (B continues A) or −1 (B runs back).
  double u = options.target_end == CurveEnd::Start ? b.domain().start : b.domain().end;
  if (options.use_parameter) {
    if (!b.domain().contains(options.at))
      throw Error(Errc::OutOfDomain,
                  "at = " + format_number(options.at) + " is outside B's domain [" + format_number(b.domain().start) +
                      ", " + format_number(b.domain().end) + "]",
                  {.field = "at"});
    u = options.at;
  }
  const nurbs::Side b_side = u >= b.domain().end ? nurbs::Side::Left : nurbs::Side::Right;
  const Table bd = table(b, u, b_side);
  const Table ad0 = table(a, a.domain().end, nurbs::Side::Left);
  double s = 1.0;
  if (options.use_parameter)
    s = dot(ad0[1], bd[1]) < 0.0 ? -1.0 : 1.0;
  else if (options.target_end == CurveEnd::End)
    s = -1.0;
  Table target{};
  for (std::size_t j = 0; j < 4; ++j) target[j] = bd[j] * std::pow(s, static_cast<double>(j));

  int inserted = 0;
  int elevation = 0;
  if (k >= 1) {
    const double vb = norm(bd[1]);
    const double va = norm(ad0[1]);
    if (!(vb > 0.0)) throw Error(Errc::InvalidArgument, "B has zero speed at the target: no tangent", {.field = "b"});
    if (!(va > 0.0)) throw Error(Errc::InvalidArgument, "A has zero speed at its end: no tangent", {.field = "a"});
  }
  // Enough degree for the order, and enough poles that A's other end pole stays.
  if (a.degree() < k) {
    elevation = k - a.degree();
    a = nurbs::elevate_degree(a, elevation);
  }
  a = with_poles(a, static_cast<std::size_t>(k) + 2, inserted);

  const Table ad = table(a, a.domain().end, nurbs::Side::Left);
  const double lambda = k >= 1 ? options.tangent_scale * norm(ad[1]) / norm(target[1]) : 1.0;
  std::vector<Vec3> poles(a.control_points().begin(), a.control_points().end());
  const std::size_t n = poles.size() - 1;
  std::array<std::array<double, 4>, 4> c{};  // c[i][j] = N_{n−i}^(j)(end)
  for (std::size_t i = 0; i <= static_cast<std::size_t>(k); ++i) c[i] = end_basis(a, n - i);
  for (std::size_t j = 0; j <= static_cast<std::size_t>(k); ++j) {
    Vec3 rhs = target[j] * std::pow(lambda, static_cast<double>(j));
    for (std::size_t i = 0; i < j; ++i) rhs = rhs - poles[n - i] * c[i][j];
    poles[n - j] = rhs / c[j][j];
  }
  const int dim = std::max(a.dimension(), b.dimension());
  a = nurbs::NurbsCurve(a.knots(), std::move(poles), {}, dim);
  std::vector<int> moved;
  for (int i = 0; i <= k; ++i) moved.push_back(static_cast<int>(n) - i);

  const Table left = table(a, a.domain().end, nurbs::Side::Left);
  const Continuity reached = compare_sides(a.domain().end, left, target, model_size(a, b), step(a, b), {});
  if (at_start) {
    a = nurbs::reverse(a);
    for (int& i : moved) i = static_cast<int>(n) - i;
  }
  std::sort(moved.begin(), moved.end());
  return MatchResult{std::move(a), std::move(moved), inserted, elevation, u, reached};
}

void BlendOptions::validate() const {
  if (continuity < 1 || continuity > 3)
    throw Error(Errc::InvalidOption, "continuity = G" + std::to_string(continuity) + " must be G1 … G3",
                {.field = "continuity"});
  if (!(min_scale > 0.0 && min_scale < max_scale && max_scale <= 10.0))
    throw Error(Errc::InvalidOption, "the scale bracket must satisfy 0 < min_scale < max_scale ≤ 10",
                {.field = "min_scale"});
  if (iterations < 1 || iterations > 200)
    throw Error(Errc::InvalidOption, "iterations = " + std::to_string(iterations) + " must be in 1 … 200",
                {.field = "iterations"});
}

BlendResult blend(const nurbs::NurbsCurve& a, const nurbs::NurbsCurve& b, const BlendOptions& options) {
  options.validate();
  if (options.end == CurveEnd::Start || options.target_end == CurveEnd::End) {
    // The blend leaves the chosen end outwards and reaches the other inwards: the reversed curves' end and start.
    BlendOptions forward = options;
    forward.end = CurveEnd::End;
    forward.target_end = CurveEnd::Start;
    return blend(options.end == CurveEnd::Start ? nurbs::reverse(a) : a,
                 options.target_end == CurveEnd::End ? nurbs::reverse(b) : b, forward);
  }
  const Table ad = table(a, a.domain().end, nurbs::Side::Left);
  const Table bd = table(b, b.domain().start, nurbs::Side::Right);
  const double va = norm(ad[1]);
  const double vb = norm(bd[1]);
  if (!(va > 0.0)) throw Error(Errc::InvalidArgument, "A has zero speed at its end: no tangent", {.field = "a"});
  if (!(vb > 0.0)) throw Error(Errc::InvalidArgument, "B has zero speed at its start: no tangent", {.field = "b"});
  const double chord = distance(ad[0], bd[0]);
  if (!(chord > 1e-12 * model_size(a, b)))
    throw Error(Errc::InvalidArgument, "A's end and B's start coincide: nothing to blend", {.field = "b"});
  const int dim = std::max(a.dimension(), b.dimension());
  const std::array<double, 2> params{0.0, 1.0};

  auto make = [&](double m) {
    const double la = m * chord / va;
    const double lb = m * chord / vb;
    const std::array<Vec3, 2> p{ad[0], bd[0]};
    const std::array<Vec3, 2> d1{ad[1] * la, bd[1] * lb};
    const std::array<Vec3, 2> d2{ad[2] * (la * la), bd[2] * (lb * lb)};
    const std::array<Vec3, 2> d3{ad[3] * (la * la * la), bd[3] * (lb * lb * lb)};
    if (options.continuity == 1) return nurbs::hermite_cubic(p, d1, params, dim);
    if (options.continuity == 2) return nurbs::hermite_quintic(p, d1, d2, params, dim);
    return nurbs::hermite_septic(p, d1, d2, d3, params, dim);
  };
  EnergyOptions search;
  search.relative_tolerance = 1e-6;
  search.max_depth = 10;
  auto energy = [&](double m) { return curvature_variation_energy(make(m), search).value; };

  // Golden-section search of the common scale m on [min_scale, max_scale].
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double lo = options.min_scale, hi = options.max_scale;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
  double f1 = energy(x1), f2 = energy(x2);
  for (int i = 0; i < options.iterations; ++i) {
    if (f1 <= f2) {
      hi = x2;
      x2 = x1;
      f2 = f1;
      x1 = hi - g * (hi - lo);
      f1 = energy(x1);
    } else {
      lo = x1;
      x1 = x2;
      f1 = f2;
      x2 = lo + g * (hi - lo);
      f2 = energy(x2);
    }
  }
  const double scale = f1 <= f2 ? x1 : x2;
  nurbs::NurbsCurve curve = make(scale);
  const EnergyResult energy_value = curvature_variation_energy(curve);
  const int extrema = static_cast<int>(curvature_extrema(curve).size());
  const double size = model_size(a, b);
  const Continuity start =
      compare_sides(a.domain().end, ad, table(curve, 0.0, nurbs::Side::Right), size, step(a, curve), {});
  const Continuity end = compare_sides(1.0, table(curve, 1.0, nurbs::Side::Left), bd, size, step(curve, b), {});
  return BlendResult{std::move(curve), scale, energy_value, extrema, start, end};
}

}  // namespace hula::diffgeom
