// SPDX-License-Identifier: MIT
#include "hula/nurbs/detail/option_checks.hpp"

#include <string>

#include "hula/core/error.hpp"

namespace hula::nurbs::detail {

void check_dimension_option(int dimension) {
  if (dimension != 2 && dimension != 3)
    throw Error(Errc::InvalidOption, "dimension = " + std::to_string(dimension) + " must be 2 or 3",
                {.field = "dimension"});
}

void check_parameterisation_option(Parameterisation rule) {
  switch (rule) {
    case Parameterisation::Uniform:
    case Parameterisation::ChordLength:
    case Parameterisation::Centripetal:
    case Parameterisation::Foley:
      return;
  }
  throw Error(Errc::InvalidOption,
              "parameterisation = " + std::to_string(static_cast<int>(rule)) + " is not a Parameterisation value",
              {.field = "parameterisation"});
}

}  // namespace hula::nurbs::detail
