// SPDX-License-Identifier: MIT
// curve::NaturalData resolved by integration and a verified NURBS fit (natural_curve.hpp).
#include "hula/intrinsic/natural_curve.hpp"

#include <cmath>
#include <string>

#include "hula/core/error.hpp"
#include "hula/intrinsic/natural_equations.hpp"
#include "hula/law/parser.hpp"

namespace hula::intrinsic {

namespace {
law::Law parse_scalar(const std::string& text, const law::Context& ctx, const std::string& parameter,
                      const char* field) {
  law::ParseOptions options;
  options.parameters = {parameter};
  law::Law l;
  try {
    options.validate();
    l = law::parse(text, ctx, options);
  } catch (const Error& e) {
    ErrorWhere where = e.where();
    where.field = field;
    throw Error(Errc::ParseError, std::string(field) + ": " + e.message(), where);
  }
  if (l.dimension() != 1)
    throw Error(Errc::ParseError,
                std::string(field) + ": must be a scalar law of " + parameter + ", got a " +
                    std::to_string(l.dimension()) + "-vector",
                {.field = field});
  return l;
}
}  // namespace

curve::Curve natural_curve(const curve::NaturalData& data, double tolerance) {
  if (!(tolerance >= 1e-9 && tolerance <= 0.1))
    throw Error(Errc::InvalidArgument, "tolerance = " + format_number(tolerance) + " is outside [1e-9, 0.1]",
                {.field = "tolerance"});
  // The laws live in a context private to this construction (docs/architecture.md).
  const law::Context ctx;
  const law::Law kappa = parse_scalar(data.curvature, ctx, data.parameter, "curvature");
  const law::Law tau = parse_scalar(data.torsion, ctx, data.parameter, "torsion");
  ReconstructionOptions ro;
  ro.tolerance = tolerance / 10.0;
  const IntrinsicCurve r = reconstruct(kappa, tau, data.parameter, data.length,
                                       StartFrame{data.start_point, data.start_tangent, data.start_normal}, ro);
  NurbsFitOptions fo;
  fo.tolerance = tolerance;
  NurbsFitResult fit = fit_nurbs(r, fo);
  if (!fit.converged)
    throw Error(Errc::NumericalFailure,
                "tolerance = " + format_number(tolerance) + " not met by the NURBS fit of the natural curve within " +
                    std::to_string(fo.max_segments) + " segments (reached " + format_number(fit.max_deviation) + ")",
                {.field = "tolerance"});
  return curve::Curve::natural(curve::NaturalKey{}, data, std::move(fit.curve), fit.max_deviation);
}

}  // namespace hula::intrinsic
