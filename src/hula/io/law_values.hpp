// SPDX-License-Identifier: MIT
// Values and derivatives of a law expression at parameters, and their JSON
// shape ({"t", "derivatives": [[value], [first], ...]}, scalars as
// one-element arrays), shared by `hula law`, `hula eval` on law curve files
// and the HTTP API's POST /api/law.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include "hula/io/json_curve.hpp"
#include "hula/law/expr.hpp"
#include "hula/law/singularities.hpp"

namespace hula::io {

/// Values and derivatives of a law at parameters (law_derivatives()).
struct LawValues {
  /// values[i][k * dimension + c]: component c of derivative k at ts[i]; NaN from kink->order on.
  std::vector<std::vector<double>> values;
  /// Per point: where the derivatives stop existing (law::nonsmooth_at), if they do.
  std::vector<std::optional<law::NonSmoothPoint>> kinks;
};
/// Values and derivatives 0..order of a law at parameters. Derivatives at a kink, jump or join
/// that law::nonsmooth_at reports are NaN, with the reason in `kinks`.
/// @throws hula::Error(Errc::OutOfDomain) naming `parameter[i]` where a value is undefined
/// @throws hula::Error(Errc::NumericalFailure) naming `parameter[i]` and the subexpression that overflows
[[nodiscard]] LawValues law_derivatives(const law::Law& law, const std::string& parameter, std::span<const double> ts,
                                        int order);
/// {"t", "derivatives": [[...], ...]} entries (the `hula eval` shape; scalars as one-element arrays;
/// undefined derivatives null, with "undefined": {"order", "kind", "expression", "reason"}).
[[nodiscard]] Json law_results_to_json(std::span<const double> ts, const LawValues& values, int dimension, int order);

/// {"expression" (as the law printer writes it), "parameter", "dimension"} and, when `ts` is not empty,
/// "results" (law_results_to_json of derivatives 0..order): what `hula law EXPR --at ...` prints first and
/// POST /api/law answers.
/// @throws as law_derivatives
[[nodiscard]] Json law_evaluation_json(const law::Law& law, const std::string& parameter, std::span<const double> ts,
                                       int order);

/// Answers a law request {"expression", "parameter"? ("t"), "at"?, "derivatives"? (0..16)}: the law parsed
/// and law_evaluation_json of it (POST /api/law).
/// @throws hula::Error(Errc::ParseError) naming the member or the expression's line and column; as
///   law_derivatives
[[nodiscard]] Json law_request_json(const Json& body);

}  // namespace hula::io
