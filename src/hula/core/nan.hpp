// SPDX-License-Identifier: MIT
// The quiet NaN that marks an undefined value (a curvature at a cusp, a sample outside a domain): one
// definition for every module, so their sources can share a unity translation unit (HULA_UNITY_BUILD).
#pragma once

#include <limits>

namespace hula {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace hula
