// SPDX-License-Identifier: MIT
// Curves derived by law constructions; see derived_curve.hpp.
#include "hula/diffgeom/detail/derived_curve.hpp"

#include <exception>
#include <utility>
#include <variant>

#include "hula/core/error.hpp"
#include "hula/law/convert.hpp"
#include "hula/law/parser.hpp"

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

DerivedCurve derived_curve(const law::Law& l, const ParentLaw& p, bool printable, Interval domain, double tolerance) {
  if (p.printable && printable && law::printed_length(l) <= law::ParseOptions{}.max_length) {
    curve::Curve c = curve::Curve::from_law(law::print(l), p.parameter, domain, tolerance);
    const double deviation = c.approximation_deviation();
    return {std::move(c), true, deviation};
  }
  law::ToNurbsOptions fit;
  fit.tolerance = tolerance;
  law::ToNurbsResult n = law::to_nurbs(l, p.parameter, domain.start, domain.end, fit);
  return {curve::Curve(std::move(n.curve)), false, n.max_deviation};
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
