// SPDX-License-Identifier: MIT
// Printer of the law text form. Precedence levels (lowest first): 0 comparison,
// 1 additive, 2 multiplicative, 3 unary minus, 4 power, 5 primary. An operand
// is parenthesised when its level is below the level its position requires,
// which mirrors the parser's grammar exactly (left-associative + − × ÷,
// right-associative ^ whose base is a primary and whose exponent is a unary).
//
// One walker serves three outputs: the text (print), its length without the
// text (printed_length: memoised per node and required level, so O(DAG) even
// when the text is exponential), and the text with named shared
// subexpressions (print_shared: a named node prints as its name, a primary).
#include <cmath>
#include <cstdio>
#include <limits>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>

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

/// Text output: appends.
struct TextOut {
  std::string text;
  void put(std::string_view s) { text += s; }
};

/// Length output: counts, saturating.
struct LengthOut {
  std::size_t length = 0;
  void put(std::string_view s) { add(s.size()); }
  void add(std::size_t n) {
    length =
        length > std::numeric_limits<std::size_t>::max() - n ? std::numeric_limits<std::size_t>::max() : length + n;
  }
};

template <class Out>
class Printer {
 public:
  explicit Printer(const Law& root, const std::unordered_map<NodeId, std::string>* names = nullptr)
      : ctx_(root.context()), names_(names) {}

  void emit(const Law& e, int required, Out& out) {
    if (names_ != nullptr) {
      if (auto it = names_->find(e.id()); it != names_->end() && e.id() != defining_) {
        out.put(it->second);
        return;
      }
    }
    if constexpr (std::is_same_v<Out, LengthOut>) {
      // Memoised: the length of a node at a required level does not depend on where it sits.
      const std::uint64_t key = (static_cast<std::uint64_t>(e.id()) << 3) | static_cast<std::uint64_t>(required);
      if (auto it = memo_.find(key); it != memo_.end()) {
        out.add(it->second);
        return;
      }
      LengthOut sub;
      emit_node(e, required, sub);
      memo_.emplace(key, sub.length);
      out.add(sub.length);
    } else {
      emit_node(e, required, out);
    }
  }

  /// The node printed in full even if it is named (the right-hand side of its definition).
  void define(const Law& e, Out& out) {
    defining_ = e.id();
    emit(e, 0, out);
    defining_ = kNoNode;
  }

 private:
  void emit_node(const Law& e, int required, Out& out) {
    const Node& n = e.node();
    const bool paren = level(n) < required;
    if (paren) out.put("(");
    body(e, n, out);
    if (paren) out.put(")");
  }

  void call(const char* name, const Law& e, std::size_t arity, Out& out) {
    out.put(name);
    out.put("(");
    for (std::size_t i = 0; i < arity; ++i) {
      if (i > 0) out.put(", ");
      emit(e.arg(i), 0, out);
    }
    out.put(")");
  }

  void binary(const Law& e, const char* op, int left, int right, Out& out) {
    emit(e.arg(0), left, out);
    out.put(op);
    emit(e.arg(1), right, out);
  }

  void body(const Law& e, const Node& n, Out& out) {
    switch (n.op) {
      case Op::Constant:
        out.put(number(n.value));
        return;
      case Op::Parameter:
        out.put(ctx_.parameter_name(n.index));
        return;
      case Op::Neg:
        out.put("-");
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
        out.put("term(");
        emit(e.arg(0), 0, out);
        out.put(", " + std::to_string(n.index) + ")");
        return;
      case Op::Curve:
        out.put(ctx_.curve_name(n.index));
        out.put("(");
        emit(e.arg(0), 0, out);
        if (n.order > 0) out.put(", " + std::to_string(n.order));
        out.put(")");
        return;
      default:
        call(detail::function_name(n.op), e, n.arity, out);
        return;
    }
  }

  Context ctx_;
  const std::unordered_map<NodeId, std::string>* names_;
  NodeId defining_ = kNoNode;
  std::unordered_map<std::uint64_t, std::size_t> memo_;
};

/// Threshold of print_shared: a shared node is named when its own text is longer than this.
constexpr std::size_t kNameAbove = 24;

}  // namespace

std::string print(const Law& expression) {
  Printer<TextOut> p(expression);
  TextOut out;
  p.emit(expression, 0, out);
  return std::move(out.text);
}

std::size_t printed_length(const Law& expression) {
  Printer<LengthOut> p(expression);
  LengthOut out;
  p.emit(expression, 0, out);
  return out.length;
}

SharedPrint print_shared(const Law& expression) {
  // Post-order of the DAG (iterative) and the number of parents of each node.
  std::vector<Law> order;
  std::unordered_map<NodeId, std::size_t> uses;
  std::unordered_set<NodeId> seen;
  std::vector<std::pair<Law, bool>> stack{{expression, false}};
  while (!stack.empty()) {
    auto [e, expanded] = stack.back();
    stack.pop_back();
    if (expanded) {
      order.push_back(e);
      continue;
    }
    if (!seen.insert(e.id()).second) continue;
    stack.push_back({e, true});
    for (std::size_t i = 0; i < e.node().arity; ++i) {
      ++uses[e.node().args[i]];
      stack.push_back({e.arg(i), false});
    }
  }
  Printer<LengthOut> sizer(expression);
  std::unordered_map<NodeId, std::string> names;
  SharedPrint out;
  Printer<TextOut> printer(expression, &names);
  for (const Law& e : order) {
    if (e == expression || uses[e.id()] < 2 || e.node().arity == 0) continue;
    LengthOut len;
    sizer.emit(e, 0, len);
    if (len.length <= kNameAbove) continue;
    TextOut text;
    printer.define(e, text);
    std::string name = "_q" + std::to_string(out.definitions.size() + 1);
    names.emplace(e.id(), name);
    out.definitions.push_back({std::move(name), std::move(text.text)});
  }
  TextOut text;
  printer.emit(expression, 0, text);
  out.expression = std::move(text.text);
  return out;
}

}  // namespace hula::law
