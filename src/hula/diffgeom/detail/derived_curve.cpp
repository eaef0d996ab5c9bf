// SPDX-License-Identifier: MIT
// Curves derived by law constructions; see derived_curve.hpp.
#include "hula/diffgeom/detail/derived_curve.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>
#include <utility>
#include <variant>

#include "hula/core/error.hpp"
#include "hula/diffgeom/planarity.hpp"
#include "hula/law/convert.hpp"
#include "hula/law/parser.hpp"
#include "hula/nurbs/reparam.hpp"

namespace hula::diffgeom::detail {

ParentLaw parent_law(const curve::Curve& c) {
  ParentLaw p;
  if (const auto* data = std::get_if<curve::LawData>(&c.data())) {
    law::ParseOptions po;
    po.parameters = {data->parameter};
    p.r = law::parse(data->expression, p.context, po);
    p.parameter = data->parameter;
    p.printable = true;
  } else {
    p.parameter = "t";
    p.r = law::from_nurbs(c.nurbs(), p.context, p.parameter);
  }
  return p;
}

void require_xy_plane(const curve::Curve& c, const char* what) {
  if (c.dimension() == 2) return;
  const Planarity pl = planarity(c.nurbs());
  const Box3 box = c.nurbs().control_box();
  const bool flat =
      pl.planar && (pl.normal ? std::abs(pl.normal->z) >= 1.0 - 1e-12 : box.max.z - box.min.z <= pl.tolerance);
  if (!flat)
    throw Error(
        Errc::InvalidArgument,
        std::string(what) + " needs a plane curve in the XY plane (2-D, or 3-D with constant z); this one is not",
        {.field = "curve"});
}

law::Law plane_law(const ParentLaw& p, const curve::Curve& c) {
  if (c.dimension() == 2 && p.r.dimension() == 3) return law::vec(law::term(p.r, 1), law::term(p.r, 2));
  return p.r;
}

law::Law scalar_option(std::string_view text, const ParentLaw& p, const char* field) {
  law::ParseOptions po;
  po.parameters = {p.parameter};
  try {
    const law::Law l = law::parse(text, p.context, po);
    if (l.dimension() != 1)
      throw Error(Errc::ParseError, "a scalar law is needed, got a " + std::to_string(l.dimension()) + "-vector",
                  {.field = field});
    return l;
  } catch (const Error& e) {
    ErrorWhere where = e.where();
    where.field = field;
    throw Error(Errc::ParseError, std::string(field) + ": " + e.message(), where);
  }
}

DerivedCurve derived_curve(const law::Law& l, const ParentLaw& p, bool printable, Interval domain, double tolerance,
                           std::span<const double> breaks) {
  if (p.printable && printable && law::printed_length(l) <= law::ParseOptions{}.max_length) {
    curve::Curve c = curve::Curve::from_law(law::print(l), p.parameter, domain, tolerance);
    const double deviation = c.approximation_deviation();
    return {std::move(c), true, deviation};
  }
  law::ToNurbsOptions fit;
  fit.tolerance = tolerance;
  // Fit span by span between the breaks (where the law is less than C2 the quintic fit would crawl), joined C0.
  std::vector<double> cuts{domain.start};
  for (double b : breaks)
    if (b > cuts.back() && b < domain.end) cuts.push_back(b);
  cuts.push_back(domain.end);
  std::optional<nurbs::NurbsCurve> joined;
  double deviation = 0.0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    law::ToNurbsResult n = law::to_nurbs(l, p.parameter, cuts[i], cuts[i + 1], fit);
    deviation = std::max(deviation, n.max_deviation);
    joined = joined ? nurbs::join(*joined, n.curve, 2.0 * tolerance) : std::move(n.curve);
  }
  return {curve::Curve(std::move(*joined)), false, deviation};
}

std::vector<double> low_continuity_knots(const nurbs::NurbsCurve& c, int order) {
  std::vector<double> out;
  const Interval d = c.domain();
  for (double u : c.knots().values())
    if (u > d.start && u < d.end && (out.empty() || out.back() != u) &&
        c.degree() - c.knots().multiplicity(u) - order < 2)
      out.push_back(u);
  return out;
}

void rethrow_undefined(const char* field, const std::string& what, const std::string& why) {
  try {
    throw;
  } catch (const Error& e) {
    if (e.message().find("undefined") == std::string::npos) throw;
    throw Error(Errc::NumericalFailure, what + " is undefined on this curve: " + e.message() + why, {.field = field});
  }
}

}  // namespace hula::diffgeom::detail
