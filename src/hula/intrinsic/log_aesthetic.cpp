// SPDX-License-Identifier: MIT
// Log-aesthetic curves as exact curvature laws (see the header).
#include "hula/intrinsic/log_aesthetic.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "hula/core/error.hpp"
#include "hula/law/parser.hpp"

namespace hula::intrinsic {

double LogAestheticCurve::radius(double s) const noexcept {
  if (alpha == 0.0) return rho0 * std::exp(lambda * s);
  const double base = std::pow(rho0, alpha) + alpha * lambda * s;
  return base > 0.0 ? std::pow(base, 1.0 / alpha) : std::numeric_limits<double>::quiet_NaN();
}

double LogAestheticCurve::curvature(double s) const noexcept { return 1.0 / radius(s); }

double LogAestheticCurve::curvature_rate(double s) const noexcept {
  // dρ/ds = λ ρ^{1−α} (from ρ^α = ρ0^α + αλs), so dκ/ds = −ρ'/ρ² = −λ ρ^{−1−α}.
  return -lambda * std::pow(radius(s), -1.0 - alpha);
}

double LogAestheticCurve::max_length() const noexcept {
  if (alpha * lambda < 0.0) return -std::pow(rho0, alpha) / (alpha * lambda);
  return std::numeric_limits<double>::infinity();
}

law::Law LogAestheticCurve::curvature_law(const law::Context& context, std::string_view parameter) const {
  const law::Law s = context.parameter(parameter);
  if (alpha == 0.0) return law::exp(-lambda * s) * (1.0 / rho0);
  return law::pow(std::pow(rho0, alpha) + (alpha * lambda) * s, -1.0 / alpha);
}

void LogAestheticCurve::validate() const {
  for (const auto& [v, name] :
       {std::pair{alpha, "alpha"}, std::pair{rho0, "rho0"}, std::pair{lambda, "lambda"}, std::pair{length, "length"}})
    if (!std::isfinite(v))
      throw Error(Errc::NonFiniteInput, std::string(name) + " = " + format_number(v) + " is not finite",
                  ErrorWhere{.field = name});
  if (!(rho0 > 0.0))
    throw Error(Errc::InvalidArgument, "rho0 = " + format_number(rho0) + " must be positive",
                ErrorWhere{.field = "rho0"});
  if (!(length > 0.0))
    throw Error(Errc::InvalidArgument, "length = " + format_number(length) + " must be positive",
                ErrorWhere{.field = "length"});
  if (!(length < max_length()))
    throw Error(Errc::InvalidArgument,
                "length = " + format_number(length) +
                    " reaches the end of the curve (radius 0 or infinite at s = " + format_number(max_length()) +
                    " for alpha = " + format_number(alpha) + ", lambda = " + format_number(lambda) + ")",
                ErrorWhere{.field = "length"});
  if (!std::isfinite(radius(length)) || !(radius(length) > 0.0))
    throw Error(Errc::InvalidArgument, "the radius of curvature overflows before s = length = " + format_number(length),
                ErrorWhere{.field = "length"});
}

IntrinsicCurve LogAestheticCurve::to_intrinsic(const StartFrame& start, const ReconstructionOptions& options) const {
  validate();
  const law::Context ctx;
  return reconstruct_planar(curvature_law(ctx), "s", length, start, options);
}

curve::NaturalData LogAestheticCurve::natural_data(const StartFrame& start, double tolerance) const {
  validate();
  const law::Context ctx;
  curve::NaturalData d;
  d.curvature = law::print(curvature_law(ctx, "s"));
  d.torsion = "0";
  d.parameter = "s";
  d.length = length;
  d.start_point = start.point;
  d.start_tangent = start.tangent;
  d.start_normal = start.normal;
  d.tolerance = tolerance;
  return d;
}

}  // namespace hula::intrinsic
