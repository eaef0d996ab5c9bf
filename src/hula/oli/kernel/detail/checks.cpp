// SPDX-License-Identifier: MIT
#include "hula/oli/kernel/detail/checks.hpp"

#include <cmath>
#include <string>

#include "hula/core/error.hpp"

namespace hula::oli::detail {

void check_derivative_order(int order) {
  if (order < 0 || order > 3)
    throw Error(Errc::InvalidArgument,
                "derivative order " + std::to_string(order) + " is not in [0, 3] (the kernel interface's range)",
                {.field = "order"});
}

void check_times(int times) {
  if (times < 1)
    throw Error(Errc::InvalidArgument, "times = " + std::to_string(times) + " must be ≥ 1", {.field = "times"});
}

void check_interpolation(std::span<const Vec3> /*points*/, const KernelInterpolation& options) {
  if (options.start_tangent.has_value() != options.end_tangent.has_value()) {
    const char* missing = options.start_tangent ? "end_tangent" : "start_tangent";
    throw Error(Errc::InvalidArgument, std::string("give both end tangents or neither: ") + missing + " is missing",
                {.field = missing});
  }
}

void check_parameter(const nurbs::NurbsCurve& curve, double t, const char* field) {
  if (!std::isfinite(t))
    throw Error(Errc::NonFiniteInput, std::string(field) + " = " + format_number(t) + " is not finite",
                {.field = field});
  const auto d = curve.domain();
  if (t < d.start || t > d.end)
    throw Error(Errc::OutOfDomain,
                std::string(field) + " = " + format_number(t) + " is outside the curve domain [" +
                    format_number(d.start) + ", " + format_number(d.end) + "]",
                {.field = field});
}

}  // namespace hula::oli::detail
