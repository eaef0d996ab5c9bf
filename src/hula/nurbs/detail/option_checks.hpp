// SPDX-License-Identifier: MIT
// Option checks shared by the interpolation and approximation entry points,
// so both name the field and value the same way.
#pragma once

#include "hula/nurbs/interpolate.hpp"

namespace hula::nurbs::detail {

/// @throws hula::Error(Errc::InvalidOption) unless dimension is 2 or 3.
void check_dimension_option(int dimension);
/// @throws hula::Error(Errc::InvalidOption) unless rule is a Parameterisation enumerator.
void check_parameterisation_option(Parameterisation rule);

}  // namespace hula::nurbs::detail
