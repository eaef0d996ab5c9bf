// SPDX-License-Identifier: MIT
#include "hula/core/tolerance.hpp"

#include <algorithm>
#include <cmath>

#include "hula/core/error.hpp"

namespace hula {

void Tolerance::validate() const {
  if (!(std::isfinite(resabs) && resabs > 0.0))
    throw Error(Errc::InvalidOption, "tolerance.resabs = " + format_number(resabs) + " must be finite and > 0",
                {.field = "resabs"});
  if (!(std::isfinite(angular) && angular > 0.0))
    throw Error(Errc::InvalidOption, "tolerance.angular = " + format_number(angular) + " must be finite and > 0",
                {.field = "angular"});
}

double resolution_for_size(const Tolerance& tol, double model_size) {
  // Models much smaller than resabs would collapse to a point under an absolute
  // test; for them resabs is scaled down with the model (1e-6 relative to a
  // unit-sized model), and no resolution is ever below rounding noise.
  const double size = std::isfinite(model_size) ? std::fabs(model_size) : 0.0;
  const double absolute = std::min(tol.resabs, tol.resabs * size);
  return std::max(absolute, kRelativeResolution * size);
}

}  // namespace hula
