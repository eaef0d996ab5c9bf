// SPDX-License-Identifier: MIT
// Exact symbolic differentiation of laws (the thesis's law::derivative,
// 10.2.4), of any order with respect to any parameter. Each rule is written
// in derive.cpp as a formula. Derivatives are memoised per (node, parameter)
// in the Context and built through the simplifying builders, so the k-th
// derivative of an expression shares everything it can with the (k−1)-th and
// grows polynomially, not exponentially, with k.
#pragma once

#include <string_view>
#include <vector>

#include "hula/law/expr.hpp"

namespace hula::law {

/// The `order`-th derivative of `expression` with respect to parameter `parameter`.
/// A parameter the expression does not use gives a zero of the expression's dimension.
/// Where the expression is not differentiable (abs at 0, sign, min/max ties, piecewise
/// switches, comparisons) the result is the one-sided rule of derive.cpp, documented there.
/// @param order ≥ 0 (0 returns the expression)
/// @throws hula::Error(Errc::InvalidArgument) if order < 0, the parameter name is not an
///   identifier, or the derivative graph exceeds kMaxNodes
[[nodiscard]] Law derivative(const Law& expression, std::string_view parameter, int order = 1);

/// {f, f', …, f^(order)} with respect to `parameter`.
/// @throws as derivative
[[nodiscard]] std::vector<Law> derivatives(const Law& expression, std::string_view parameter, int order);

}  // namespace hula::law
