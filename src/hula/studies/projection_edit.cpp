// SPDX-License-Identifier: MIT
// Projection editing (thesis 8.1); see projection_edit.hpp.
#include "hula/studies/projection_edit.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/nurbs/elevate.hpp"
#include "hula/nurbs/refine.hpp"
#include "hula/nurbs/reparam.hpp"

namespace hula::studies {

namespace {

// Distinct interior knot values of a clamped knot vector with their multiplicities.
std::vector<std::pair<double, int>> interior_knots(const nurbs::NurbsCurve& curve) {
  std::vector<std::pair<double, int>> out;
  const auto U = curve.knots().values();
  const nurbs::Interval dom = curve.domain();
  for (const double u : U) {
    if (u <= dom.start || u >= dom.end) continue;
    if (!out.empty() && out.back().first == u)
      ++out.back().second;
    else
      out.emplace_back(u, 1);
  }
  return out;
}

// The knots of `from` (with multiplicity) that `into` lacks.
std::vector<double> missing_knots(const nurbs::NurbsCurve& into, const nurbs::NurbsCurve& from) {
  const auto have = interior_knots(into);
  std::vector<double> add;
  for (const auto& [u, m] : interior_knots(from)) {
    int present = 0;
    for (const auto& [v, k] : have)
      if (v == u) present = k;  // exact: knot values are combinatorial (STYLE.md)
    for (int i = present; i < m; ++i) add.push_back(u);
  }
  return add;
}

constexpr int kCheckSamples = 1001;  // dense check of the construction's rounding error

// Knots of the two curves closer than this on the unit domain are one knot: the affine maps to
// [0, 1] round the same breakpoint differently (0.7734375 vs 0.77343749999999989), and a span of
// width 1e-17 would make the basis functions meaningless. Moving a knot by δ moves the curve by
// O(δ |C'|), far below resabs.
constexpr double kKnotSnap = 1e-12;

// `curve` with each knot within kKnotSnap of a knot of `reference` replaced by that knot.
nurbs::NurbsCurve snap_knots(const nurbs::NurbsCurve& curve, const nurbs::NurbsCurve& reference) {
  std::vector<double> U(curve.knots().values().begin(), curve.knots().values().end());
  const auto R = reference.knots().values();
  bool changed = false;
  for (double& u : U) {
    const auto it = std::lower_bound(R.begin(), R.end(), u);
    for (auto c : {it, it == R.begin() ? it : it - 1}) {
      if (c != R.end() && *c != u && std::abs(*c - u) <= kKnotSnap) {
        u = *c;
        changed = true;
        break;
      }
    }
  }
  if (!changed) return curve;
  return nurbs::NurbsCurve(curve.degree(), std::move(U),
                           std::vector<Vec3>(curve.control_points().begin(), curve.control_points().end()),
                           std::vector<double>(curve.weights().begin(), curve.weights().end()), curve.dimension());
}

}  // namespace

std::size_t dropped_coordinate(diffgeom::Plane plane) noexcept {
  return plane == diffgeom::Plane::XY ? 2 : (plane == diffgeom::Plane::YZ ? 0 : 1);
}

Vec3 plane_normal(diffgeom::Plane plane) noexcept {
  switch (plane) {
    case diffgeom::Plane::XY:
      return {0.0, 0.0, 1.0};
    case diffgeom::Plane::YZ:
      return {1.0, 0.0, 0.0};
    case diffgeom::Plane::ZX:
      return {0.0, 1.0, 0.0};
  }
  return {0.0, 0.0, 1.0};
}

diffgeom::Plane plane_from_name(std::string_view name, std::string_view field) {
  if (name == "xy") return diffgeom::Plane::XY;
  if (name == "yz") return diffgeom::Plane::YZ;
  if (name == "zx") return diffgeom::Plane::ZX;
  throw Error(Errc::InvalidArgument,
              std::string(field) + " = \"" + std::string(name) + "\" is not a plane (expected xy, yz or zx)",
              {.field = std::string(field)});
}

void require_planar(const nurbs::NurbsCurve& curve, diffgeom::Plane plane, std::string_view field,
                    const Tolerance& tolerance) {
  const std::size_t k = dropped_coordinate(plane);
  const auto P = curve.control_points();
  const double tol = resolution_for_size(tolerance, curve.model_size());
  static constexpr const char* kAxis[] = {"x", "y", "z"};
  for (std::size_t i = 1; i < P.size(); ++i) {
    if (std::abs(P[i][k] - P[0][k]) > tol)
      throw Error(Errc::InvalidArgument,
                  std::string(field) + " is not planar in " + std::string(diffgeom::plane_name(plane)) +
                      ": control_points[" + std::to_string(i) + "]." + kAxis[k] + " = " + format_number(P[i][k]) +
                      " differs from control_points[0]." + kAxis[k] + " = " + format_number(P[0][k]) +
                      " by more than " + format_number(tol),
                  {.field = std::string(field), .index = i, .component = k});
  }
}

CommonStructure common_structure(const nurbs::NurbsCurve& first, const nurbs::NurbsCurve& second) {
  nurbs::NurbsCurve a = nurbs::reparameterise(first, {0.0, 1.0});
  nurbs::NurbsCurve b = nurbs::reparameterise(second, {0.0, 1.0});
  if (a.degree() < b.degree()) a = nurbs::elevate_degree(a, b.degree() - a.degree());
  if (b.degree() < a.degree()) b = nurbs::elevate_degree(b, a.degree() - b.degree());
  b = snap_knots(b, a);
  const std::vector<double> add_a = missing_knots(a, b);
  const std::vector<double> add_b = missing_knots(b, a);
  if (!add_a.empty()) a = nurbs::refine_knots(a, add_a);
  if (!add_b.empty()) b = nurbs::refine_knots(b, add_b);
  return {std::move(a), std::move(b)};
}

ProjectionEditResult edit_projection(const nurbs::NurbsCurve& original, const nurbs::NurbsCurve& edited,
                                     diffgeom::Plane plane, const Tolerance& tolerance) {
  require_planar(edited, plane, "edited", tolerance);
  ProjectionEditResult result{original, 0.0};
  const bool same = edited.degree() == original.degree() && edited.knots() == original.knots() &&
                    std::equal(edited.weights().begin(), edited.weights().end(), original.weights().begin(),
                               original.weights().end()) &&
                    edited.control_points().size() == original.control_points().size();
  if (same) {
    result.curve = diffgeom::reconstruct_from_projection(original, edited, plane);
  } else {
    CommonStructure c = common_structure(original, edited);
    const auto wa = c.first.weights(), wb = c.second.weights();
    // Exact combination needs one set of weights; a shared scale factor is not enough because the
    // refinement already fixed the weights of both, so compare them as they are.
    if (!std::equal(wa.begin(), wa.end(), wb.begin(), wb.end(),
                    [](double x, double y) { return std::abs(x - y) <= 1e-12 * std::max(1.0, std::abs(x)); }))
      throw Error(Errc::InvalidArgument,
                  "the edited projection's weights differ from the original's after refinement to a common "
                  "knot vector, so the curves cannot be combined exactly (use a non-rational edited curve)",
                  {.field = "weights"});
    // reconstruct_from_projection compares weights exactly; give the edited curve the original's.
    nurbs::NurbsCurve second(c.first.knots(),
                             std::vector<Vec3>(c.second.control_points().begin(), c.second.control_points().end()),
                             std::vector<double>(wa.begin(), wa.end()), 3);
    result.curve = diffgeom::reconstruct_from_projection(c.first, second, plane);
  }
  // Measure the construction against its definition at normalised parameters.
  const std::size_t k = dropped_coordinate(plane);
  const nurbs::Interval dr = result.curve.domain(), de = edited.domain(), dorig = original.domain();
  for (int i = 0; i < kCheckSamples; ++i) {
    const double u = static_cast<double>(i) / (kCheckSamples - 1);
    auto at = [u](nurbs::Interval d) { return d.start * (1.0 - u) + d.end * u; };
    Vec3 expect = edited.evaluate(at(de));
    expect[k] = original.evaluate(at(dorig))[k];
    result.max_deviation = std::max(result.max_deviation, distance(result.curve.evaluate(at(dr)), expect));
  }
  return result;
}

}  // namespace hula::studies
