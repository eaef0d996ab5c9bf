// SPDX-License-Identifier: MIT
// The text form of laws: a recursive-descent parser with positioned errors
// and documented limits, and a printer such that parse(print(x)) returns the
// very same hash-consed node. The grammar is documented in docs/formats.md
// ("Law expressions"). Nothing in a law string is ever executed as code.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "hula/law/expr.hpp"

namespace hula::law {

/// Options of parse().
struct ParseOptions {
  /// Names accepted as parameters. Any other identifier that is not a function, a curve or a
  /// constant (`pi`, `e`) is an error. Default {"t"}.
  std::vector<std::string> parameters{"t"};
  /// Largest accepted input in bytes. Default 65536; valid 1 … 16 MiB. Raise it only for
  /// machine-generated laws.
  std::size_t max_length = 65536;
  /// Largest nesting depth of parentheses, calls, unary signs and powers. Default 200;
  /// valid 1 … 1000 (deeper recursion risks the stack of worker threads).
  std::size_t max_depth = 200;
  /// Largest number of new DAG nodes one parse may create. Default 100000; valid ≥ 1.
  std::size_t max_nodes = 100000;

  /// @throws hula::Error(Errc::InvalidOption) naming the field out of range or a bad parameter name
  void validate() const;
};

/// Parses a law. NURBS leaves already registered in the context (Context::curve) are callable
/// by name: `name(u)` is C(u), `name(u, k)` its k-th derivative.
/// @param text the expression (ASCII; grammar in docs/formats.md)
/// @param context where the nodes are created
/// @returns the expression's node (scalar or vector)
/// @throws hula::Error(Errc::ParseError) with ErrorWhere{field "expression", line, column} (1-based)
///   and a message saying what was expected and what was found: empty input, unexpected character,
///   malformed or out-of-range number, unknown identifier or function, wrong argument count,
///   dimension mismatch (naming the operation), trailing input, or a limit exceeded
/// @throws hula::Error(Errc::InvalidOption) if options are invalid
[[nodiscard]] Law parse(std::string_view text, const Context& context, const ParseOptions& options = {});

/// Prints a law in the grammar of parse(): minimal parentheses, constants with 17 significant
/// digits (so they read back bit-exact), NURBS leaves by their curve names.
/// @note The text writes a shared subexpression once per use: its length can grow exponentially
///   with the DAG (high derivatives). Check printed_length() first, or use print_shared().
[[nodiscard]] std::string print(const Law& expression);

/// The length in characters of print(expression), computed on the DAG (each node once per
/// parenthesisation level) without building the text; saturates at SIZE_MAX.
/// Complexity O(DAG size).
[[nodiscard]] std::size_t printed_length(const Law& expression);

/// A law printed with its shared subexpressions named (the DAG as a list of definitions).
struct SharedPrint {
  /// Named subexpression: `name` stands for `expression`, which may use earlier names.
  struct Definition {
    std::string name;
    std::string expression;
  };
  /// In dependency order (each uses only names defined before it). Names are _q1, _q2, ….
  std::vector<Definition> definitions;
  /// The law, using the names.
  std::string expression;
};

/// Prints a law with every subexpression that is used more than once and whose own text
/// (print() of it) is longer than 24 characters named once: the text is then O(DAG size).
/// Substituting the definitions back (last first, parenthesised where the grammar needs it)
/// gives the law.
[[nodiscard]] SharedPrint print_shared(const Law& expression);

}  // namespace hula::law
