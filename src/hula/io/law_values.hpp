// SPDX-License-Identifier: MIT
// Values and derivatives of a law expression at parameters, and their JSON
// shape ({"t", "derivatives": [[value], [first], ...]}, scalars as
// one-element arrays), shared by `hula law`, `hula eval` on law curve files
// and the HTTP API's POST /api/law.
#pragma once

#include <span>
#include <string>
#include <vector>

#include "hula/io/json_curve.hpp"
#include "hula/law/expr.hpp"

namespace hula::io {

/// Values and derivatives 0..order of a law at parameters: result[i][k * dimension + c].
/// @param law any law of `parameter`
/// @param ts the parameter values
/// @param order highest derivative order
/// @throws hula::Error(Errc::OutOfDomain) naming `parameter[i]` where a value is undefined, with the
///   innermost undefined subexpression
[[nodiscard]] std::vector<std::vector<double>> law_derivatives(const law::Law& law, const std::string& parameter,
                                                               std::span<const double> ts, int order);

/// {"t", "derivatives": [[...], ...]} entries (the `hula eval` shape; scalars as one-element arrays).
[[nodiscard]] Json law_results_to_json(std::span<const double> ts, const std::vector<std::vector<double>>& values,
                                       int dimension, int order);

}  // namespace hula::io
