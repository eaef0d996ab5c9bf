// SPDX-License-Identifier: MIT
#include "hula/optim/solution.hpp"

#include <cmath>

#include "hula/core/error.hpp"

namespace hula::optim {

void RunSettings::validate() const {
  if (!std::isfinite(penalty) || penalty < 0.0) {
    throw Error(Errc::InvalidOption, "run.penalty = " + format_number(penalty) + " must be finite and >= 0",
                {.field = "run.penalty"});
  }
  stop.validate();
}

}  // namespace hula::optim
