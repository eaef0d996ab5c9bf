// SPDX-License-Identifier: MIT
// Printer of the law text form. Precedence levels (lowest first): 0 comparison,
// 1 additive, 2 multiplicative, 3 unary minus, 4 power, 5 primary. An operand
// is parenthesised when its level is below the level its position requires,
// which mirrors the parser's grammar exactly (left-associative + − × ÷,
// right-associative ^ whose base is a primary and whose exponent is a unary).
#include <cmath>
#include <cstdio>
#include <unordered_map>

#include "hula/law/detail/graph.hpp"
#include "hula/law/detail/names.hpp"
#include "hula/law/parser.hpp"

namespace hula::law {

namespace {

std::string number(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

int level(const Node& n) {
  switch (n.op) {
    case Op::Less:
    case Op::LessEqual:
      return 0;
    case Op::Add:
    case Op::Sub:
      return 1;
    case Op::Mul:
    case Op::Div:
      return 2;
    case Op::Neg:
      return 3;
    case Op::Pow:
      return 4;
    case Op::Constant:
      return std::signbit(n.value) ? 3 : 5;
    default:
      return 5;
  }
}

class Printer {
 public:
  explicit Printer(const Law& root) : ctx_(root.context()) {}

  void emit(const Law& e, int required, std::string& out) {
    const Node& n = e.node();
    const bool paren = level(n) < required;
    if (paren) out += '(';
    body(e, n, out);
    if (paren) out += ')';
  }

 private:
  void call(const char* name, const Law& e, std::size_t arity, std::string& out) {
    out += name;
    out += '(';
    for (std::size_t i = 0; i < arity; ++i) {
      if (i > 0) out += ", ";
      emit(e.arg(i), 0, out);
    }
    out += ')';
  }

  void binary(const Law& e, const char* op, int left, int right, std::string& out) {
    emit(e.arg(0), left, out);
    out += op;
    emit(e.arg(1), right, out);
  }

  void body(const Law& e, const Node& n, std::string& out) {
    switch (n.op) {
      case Op::Constant:
        out += number(n.value);
        return;
      case Op::Parameter:
        out += ctx_.parameter_name(n.index);
        return;
      case Op::Neg:
        out += '-';
        emit(e.arg(0), 3, out);
        return;
      case Op::Add:
        binary(e, " + ", 1, 2, out);
        return;
      case Op::Sub:
        binary(e, " - ", 1, 2, out);
        return;
      case Op::Mul:
        binary(e, "*", 2, 3, out);
        return;
      case Op::Div:
        binary(e, "/", 2, 3, out);
        return;
      case Op::Pow:
        binary(e, "^", 5, 3, out);
        return;
      case Op::Less:
        binary(e, " < ", 1, 1, out);
        return;
      case Op::LessEqual:
        binary(e, " <= ", 1, 1, out);
        return;
      case Op::Term:
        out += "term(";
        emit(e.arg(0), 0, out);
        out += ", " + std::to_string(n.index) + ")";
        return;
      case Op::Curve:
        out += ctx_.curve_name(n.index);
        out += '(';
        emit(e.arg(0), 0, out);
        if (n.order > 0) out += ", " + std::to_string(n.order);
        out += ')';
        return;
      default:
        call(detail::function_name(n.op), e, n.arity, out);
        return;
    }
  }

  Context ctx_;
};

}  // namespace

std::string print(const Law& expression) {
  Printer p(expression);
  std::string out;
  p.emit(expression, 0, out);
  return out;
}

}  // namespace hula::law
