// SPDX-License-Identifier: MIT
// Argument checks the Kernel interface adds to the nurbs functions, shared by
// both backends so they refuse the same inputs with the same error codes.
#pragma once

#include <span>

#include "hula/core/vec.hpp"
#include "hula/nurbs/nurbs_curve.hpp"
#include "hula/oli/kernel/kernel.hpp"

namespace hula::oli::detail {

/// @throws hula::Error(Errc::InvalidArgument) naming "order" unless 0 ≤ order ≤ 3
void check_derivative_order(int order);
/// @throws hula::Error(Errc::InvalidArgument) naming "times" unless times ≥ 1
void check_times(int times);
/// @throws hula::Error(Errc::InvalidArgument) if only one end tangent is given (names the missing one)
void check_interpolation(std::span<const Vec3> points, const KernelInterpolation& options);
/// The parameter check of NurbsCurve::evaluate: finite and inside the domain.
/// @throws hula::Error(Errc::NonFiniteInput / OutOfDomain) naming `field`
void check_parameter(const nurbs::NurbsCurve& curve, double t, const char* field = "t");

}  // namespace hula::oli::detail
