// SPDX-License-Identifier: MIT
// The answer of `hula law EXPR`: a law expression parsed, evaluated with its
// derivatives (law_values.hpp, as POST /api/law answers), and on request its
// printed N-th derivative, roots, extrema, integral, singularities and its
// NURBS within a tolerance, in one JSON document (docs/cli.md "hula law").
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "hula/io/json_curve.hpp"

namespace hula::io {

/// What to ask about a law. Intervals are [a, b] with a < b; the integral's ends may be ±inf.
struct LawQuery {
  std::string expression;
  std::string parameter = "t";
  std::vector<double> at;     ///< parameters of the values (none: no "results")
  int derivatives = 0;        ///< highest derivative at `at`, 0..16
  int print_derivative = -1;  ///< print this derivative's expression (-1: none)
  std::optional<std::pair<double, double>> roots, extrema, integrate, singularities, to_nurbs;
  /// The intervals as the caller typed them, quoted in the errors of roots and integrate.
  std::string roots_text, integrate_text;
  /// Answer a non-converged integral or unresolved roots instead of failing.
  bool allow_unconverged = false;
  double to_nurbs_tolerance = 1e-6;  ///< largest distance law–NURBS
  std::string to_nurbs_output;       ///< the file the NURBS goes to, named in "nurbs"
};

/// The JSON document and, with `to_nurbs`, the NURBS curve to write.
struct LawAnswer {
  /// law_evaluation_json, then "derivative"? {"order", "expression", "definitions"?, "printed_length"?},
  /// "roots"? {"interval", "roots", "unresolved", "converged"}, "extrema"? {"interval", "points", "minimum",
  /// "maximum"}, "integral"? {"interval", "value", "error_estimate", "method", "converged", "divergent",
  /// "antiderivative"? | "numeric_reason"?, "singular_points"}, "singularities"? {"interval", "points",
  /// "undefined", "smooth"}, "nurbs"? {"output", "domain", "tolerance", "max_deviation", "degree",
  /// "control_points", "segments"}.
  Json json;
  std::optional<curve::Curve> curve;
};

/// @throws hula::Error(Errc::ParseError) at the expression's line and column; Errc::InvalidArgument naming the
///   option for a vector law where a scalar one is needed; Errc::NumericalFailure for an unresolved root or a
///   divergent or non-converged integral (unless allow_unconverged); as law_derivatives and law::to_nurbs
[[nodiscard]] LawAnswer law_answer(const LawQuery& query);

}  // namespace hula::io
