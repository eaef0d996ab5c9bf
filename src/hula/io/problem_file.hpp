// SPDX-License-Identifier: MIT
// Optimisation problem files (JSON, docs/formats.md "Problem files"): design
// variables with bounds and an optional binary-coding precision, objectives
// and constraints written as law expressions of the variable names
// (thesis 10.1: the user states the problem, Flexo solves it). The
// expressions are parsed with the law parser and compiled together into one
// Tape, which evaluates a point with no allocation and may run on several
// threads at once, as optim::Problem::evaluate requires.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

#include "hula/io/json_read.hpp"
#include "hula/optim/problem.hpp"

namespace hula::io {

/// What a problem file declares.
struct ProblemFile {
  /// The problem, ready for a Flexo algorithm: values are the objectives,
  /// then the inequality constraints g <= 0, then the equality constraints h = 0.
  optim::Problem problem{};
  /// The hypervolume reference point of the file's "reference" member (one
  /// value per objective); unset when the file has none.
  std::optional<std::vector<double>> reference{};
};

/// Reads a problem from JSON text.
/// @param text the file's contents
/// @returns the problem (validated with optim::Problem::validate) and the optional reference
/// @throws hula::Error(Errc::ParseError) for JSON syntax (line, column), a missing or mistyped
///   member (naming its JSON path, e.g. `variables[2].upper`), a variable name that is not an
///   identifier or repeats one, an unknown constraint type, or an expression the law parser
///   refuses or that is not scalar: the message starts with the member (`objectives[1]: ...`)
///   and `where` holds field ("objectives", "constraints"), index and the parser's line/column
///   inside the expression string
/// @throws hula::Error(Errc::NonFiniteInput) for a number literal that overflows a double
/// @throws hula::Error(Errc::InvalidOption) from optim::Problem::validate (e.g. inverted bounds,
///   naming `variables[i].lower`), or a reference whose size differs from the objective count
[[nodiscard]] ProblemFile parse_problem_json(std::string_view text);

/// Reads a problem from a JSON value (a request body's "problem" member): the codec of
/// parse_problem_json without the text.
/// @throws as parse_problem_json, but for JSON syntax
[[nodiscard]] ProblemFile problem_from_json(const json::Json& document);

/// Reads a problem file.
/// @throws hula::Error(Errc::IoError) if the file cannot be read; otherwise as parse_problem_json
[[nodiscard]] ProblemFile read_problem_file(const std::filesystem::path& path);

}  // namespace hula::io
