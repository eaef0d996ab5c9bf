// SPDX-License-Identifier: MIT
// The function names of the law text form, shared by the parser, the printer
// and the parameter-name check (a parameter may not shadow a function).
#pragma once

#include <string_view>

#include "hula/law/expr.hpp"

namespace hula::law::detail {

/// A named function of the grammar: its op and the accepted argument counts.
struct FunctionInfo {
  std::string_view name;
  Op op;
  int min_args;
  int max_args;
};

/// The function table (Op::Vec covers vec(x, y) and vec(x, y, z); Op::Term takes (v, integer)).
inline constexpr FunctionInfo kFunctions[] = {
    {"sqrt", Op::Sqrt, 1, 1},
    {"exp", Op::Exp, 1, 1},
    {"log", Op::Log, 1, 1},
    {"sin", Op::Sin, 1, 1},
    {"cos", Op::Cos, 1, 1},
    {"tan", Op::Tan, 1, 1},
    {"asin", Op::Asin, 1, 1},
    {"acos", Op::Acos, 1, 1},
    {"atan", Op::Atan, 1, 1},
    {"atan2", Op::Atan2, 2, 2},
    {"sinh", Op::Sinh, 1, 1},
    {"cosh", Op::Cosh, 1, 1},
    {"tanh", Op::Tanh, 1, 1},
    {"abs", Op::Abs, 1, 1},
    {"sign", Op::Sign, 1, 1},
    {"min", Op::Min, 2, 2},
    {"max", Op::Max, 2, 2},
    {"pow", Op::Pow, 2, 2},
    {"piecewise", Op::Piecewise, 3, 3},
    {"vec", Op::Vec, 2, 3},
    {"term", Op::Term, 2, 2},
    {"dot", Op::Dot, 2, 2},
    {"cross", Op::Cross, 2, 2},
    {"norm", Op::Norm, 1, 1},
    {"normalize", Op::Normalize, 1, 1},
};

/// The entry for `name`, or nullptr.
inline const FunctionInfo* find_function(std::string_view name) {
  for (const auto& f : kFunctions)
    if (f.name == name) return &f;
  return nullptr;
}

/// The printed name of a function op (nullptr for operators and leaves).
inline const char* function_name(Op op) {
  for (const auto& f : kFunctions)
    if (f.op == op) return f.name.data();
  return nullptr;
}

/// True for function names and the constants `pi` and `e`.
inline bool is_reserved_name(std::string_view name) {
  return name == "pi" || name == "e" || find_function(name) != nullptr;
}

}  // namespace hula::law::detail
