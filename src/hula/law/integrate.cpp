// SPDX-License-Identifier: MIT
// Adaptive Gauss–Kronrod integration of compiled laws (see integrate.hpp).
#include "hula/law/integrate.hpp"

#include <boost/math/quadrature/gauss_kronrod.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/law/singularities.hpp"
#include "hula/law/tape.hpp"

namespace hula::law {

void IntegrationOptions::validate() const {
  if (!(relative_tolerance >= 1e-15 && relative_tolerance <= 0.1))
    throw Error(
        Errc::InvalidOption,
        "IntegrationOptions::relative_tolerance must be in [1e-15, 0.1], got " + format_number(relative_tolerance),
        ErrorWhere{.field = "relative_tolerance"});
  if (max_depth < 1 || max_depth > 40)
    throw Error(Errc::InvalidOption,
                "IntegrationOptions::max_depth must be in [1, 40], got " + std::to_string(max_depth),
                ErrorWhere{.field = "max_depth"});
}

IntegrationResult integrate(const Law& f, std::string_view parameter, double a, double b,
                            const IntegrationOptions& options) {
  options.validate();
  if (!f.valid() || f.dimension() != 1) throw Error(Errc::InvalidArgument, "integrate: expects a scalar law");
  if (!std::isfinite(a) || !std::isfinite(b))
    throw Error(Errc::InvalidArgument,
                "integrate: bounds must be finite, got [" + format_number(a) + ", " + format_number(b) + "]");
  IntegrationResult r;
  if (a == b) {
    r.converged = true;
    return r;
  }
  const double sign = a < b ? 1.0 : -1.0;
  const double lo = std::min(a, b);
  const double hi = std::max(a, b);
  const std::string in[1] = {std::string(parameter)};
  const Law outs[1] = {f};
  const Tape tape = Tape::compile(outs, in);
  Workspace w = tape.make_workspace();
  auto g = [&](double t) {
    double v = 0.0;
    if (!tape.evaluate(std::span<const double>(&t, 1), std::span<double>(&v, 1), w))
      throw Error(Errc::NumericalFailure,
                  "integrate: the integrand is undefined at " + std::string(parameter) + " = " + format_number(t));
    return v;
  };
  std::vector<double> cuts{lo};
  if (options.split_at_singularities) {
    for (const Singularity& s : singularities(f, parameter, lo, hi).points)
      if (s.t > cuts.back() && s.t < hi) cuts.push_back(s.t);
  }
  cuts.push_back(hi);
  using Rule = boost::math::quadrature::gauss_kronrod<double, 61>;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    double err = 0.0;
    double l1 = 0.0;
    const double v = Rule::integrate(g, cuts[i], cuts[i + 1], static_cast<unsigned>(options.max_depth),
                                     options.relative_tolerance, &err, &l1);
    r.value += v;
    r.error_estimate += err;
    r.l1_norm += l1;
    ++r.pieces;
  }
  r.value *= sign;
  r.converged = r.error_estimate <= options.relative_tolerance * r.l1_norm || r.l1_norm == 0.0;
  return r;
}

}  // namespace hula::law
