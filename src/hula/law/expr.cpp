// SPDX-License-Identifier: MIT
// Hash-consed construction and value-preserving simplification of law nodes.
// Every builder checks dimensions, then tries the identities listed in
// expr.hpp, then interns the node. Because a node is only ever created in its
// simplified form by a deterministic function of (op, arguments), rebuilding
// the same operation on the same arguments returns the same node: this is
// what makes parse(print(x)) == x hold.
#include "hula/law/expr.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <unordered_map>
#include <utility>

#include "hula/core/error.hpp"
#include "hula/law/detail/graph.hpp"
#include "hula/law/detail/names.hpp"
#include "hula/law/detail/scalar_ops.hpp"

namespace hula::law {

using namespace detail;  // scalar semantics (op_div, op_pow, ...)

namespace {

std::string dim_name(int d) {
  if (d == 1) return "a scalar";
  return "a " + std::to_string(d) + "-vector";
}

[[noreturn]] void fail(const std::string& message) { throw Error(Errc::InvalidArgument, message); }

const std::shared_ptr<Graph>& graph_of(const Law& a, const char* op) {
  if (!a.valid()) fail(std::string("'") + op + "': empty law operand");
  return Graph::of(a);
}

const std::shared_ptr<Graph>& same_graph(const Law& a, const Law& b, const char* op) {
  const auto& g = graph_of(a, op);
  if (graph_of(b, op) != g) fail(std::string("'") + op + "': operands belong to different law contexts");
  return g;
}

void require_scalar(const Law& a, const char* op) {
  if (a.dimension() != 1) fail(std::string("'") + op + "': expects a scalar argument, got " + dim_name(a.dimension()));
}

bool is_const(const Law& a, double v) { return a.op() == Op::Constant && a.node().value == v; }

Law make(const std::shared_ptr<Graph>& g, Op op, int dim, std::initializer_list<NodeId> args, double value = 0.0,
         std::uint32_t index = 0, std::uint32_t order = 0) {
  Node n;
  n.op = op;
  n.dimension = static_cast<std::uint8_t>(dim);
  n.arity = static_cast<std::uint8_t>(args.size());
  std::size_t i = 0;
  for (NodeId a : args) n.args[i++] = a;
  n.value = value;
  n.index = index;
  n.order = order;
  return Graph::handle(g, g->intern(n));
}

Law constant_in(const std::shared_ptr<Graph>& g, double v) { return make(g, Op::Constant, 1, {}, v); }

Law zero_of(const std::shared_ptr<Graph>& g, int dim) {
  Law z = constant_in(g, 0.0);
  if (dim == 1) return z;
  if (dim == 2) return make(g, Op::Vec, 2, {z.id(), z.id()});
  return make(g, Op::Vec, 3, {z.id(), z.id(), z.id()});
}

/// Folds a scalar operation on constants when the result is finite.
bool fold(const std::shared_ptr<Graph>& g, Op op, const Law& a, const Law* b, Law& out) {
  if (!a.is_constant() || (b != nullptr && !b->is_constant())) return false;
  const double r = detail::apply(op, a.node().value, b != nullptr ? b->node().value : 0.0);
  if (!std::isfinite(r)) return false;  // keep 1/0 symbolic so evaluation reports it
  out = constant_in(g, r);
  return true;
}

Law unary_scalar(const Law& a, Op op, const char* name) {
  const auto& g = graph_of(a, name);
  require_scalar(a, name);
  Law out;
  if (fold(g, op, a, nullptr, out)) return out;
  return make(g, op, 1, {a.id()});
}

Law binary_scalar(const Law& a, const Law& b, Op op, const char* name) {
  const auto& g = same_graph(a, b, name);
  require_scalar(a, name);
  require_scalar(b, name);
  Law out;
  if (fold(g, op, a, &b, out)) return out;
  return make(g, op, 1, {a.id(), b.id()});
}

bool is_identifier(std::string_view s) {
  if (s.empty()) return false;
  auto alpha = [](char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; };
  if (!alpha(s[0])) return false;
  for (char c : s)
    if (!alpha(c) && !(c >= '0' && c <= '9')) return false;
  return true;
}

}  // namespace

// ---------------------------------------------------------------- Graph

std::size_t NodeHash::operator()(const Node& n) const noexcept {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &n.value, sizeof bits);
  std::uint64_t h = static_cast<std::uint64_t>(n.op) * 0x9E3779B97F4A7C15ULL ^ n.dimension;
  auto mix = [&h](std::uint64_t v) { h = (h ^ v) * 0x100000001B3ULL + (h >> 29); };
  mix(n.args[0]);
  mix(n.args[1]);
  mix(n.args[2]);
  mix(bits);
  mix(n.index);
  mix(n.order);
  return static_cast<std::size_t>(h);
}

bool NodeEqual::operator()(const Node& a, const Node& b) const noexcept {
  return a.op == b.op && a.dimension == b.dimension && a.arity == b.arity && a.args == b.args &&
         std::memcmp(&a.value, &b.value, sizeof(double)) == 0 && a.index == b.index && a.order == b.order;
}

NodeId Graph::intern(Node n) {
  std::uint32_t height = 0;
  bool total = true;
  for (std::size_t i = 0; i < n.arity; ++i) {
    const Node& arg = nodes[n.args[i]];
    height = std::max(height, arg.height + 1);
    total = total && arg.total;
  }
  switch (n.op) {
    case Op::Div:
    case Op::Sqrt:
    case Op::Log:
    case Op::Tan:
    case Op::Asin:
    case Op::Acos:
    case Op::Atan2:
    case Op::Normalize:
    case Op::Curve:
      total = false;
      break;
    case Op::Pow: {
      // a ^ k with a constant non-negative integer k is a polynomial: total.
      const Node& e = nodes[n.args[1]];
      const bool int_exp = e.op == Op::Constant && e.value >= 0 && e.value == std::floor(e.value);
      total = total && int_exp;
      break;
    }
    default:
      break;
  }
  n.height = height;
  n.total = total;
  if (auto it = table.find(n); it != table.end()) return it->second;
  if (height > kMaxHeight)
    throw Error(Errc::InvalidArgument,
                "law expression nested deeper than the limit of " + std::to_string(kMaxHeight) + " levels");
  if (nodes.size() >= kMaxNodes)
    throw Error(Errc::InvalidArgument,
                "law expression graph exceeds the limit of " + std::to_string(kMaxNodes) + " nodes");
  const auto id = static_cast<NodeId>(nodes.size());
  nodes.push_back(n);
  table.emplace(n, id);
  return id;
}

// ---------------------------------------------------------------- Law

const Node& Law::node() const {
  if (!graph_) throw Error(Errc::InvalidArgument, "empty law handle");
  return graph_->nodes[id_];
}

Law Law::arg(std::size_t i) const {
  const Node& n = node();
  HULA_ASSERT(i < n.arity, "law argument index out of range");
  return Law(graph_, n.args[i]);
}

bool Law::is_zero() const {
  const Node& n = node();
  if (n.op == Op::Constant) return n.value == 0.0;
  if (n.op != Op::Vec) return false;
  for (std::size_t i = 0; i < n.arity; ++i)
    if (!arg(i).is_zero()) return false;
  return true;
}

Context Law::context() const {
  if (!graph_) throw Error(Errc::InvalidArgument, "empty law handle");
  return Context(graph_);
}

// ---------------------------------------------------------------- Context

Context::Context() : graph_(std::make_shared<Graph>()) {}

Law Context::constant(double value) const {
  if (!std::isfinite(value))
    throw Error(Errc::NonFiniteInput, "law constant must be finite, got " + format_number(value));
  return constant_in(graph_, value);
}

Law Context::constant(const Vec3& value, int dimension) const {
  if (dimension == 2) return vec(constant(value.x), constant(value.y));
  if (dimension != 3) fail("constant vector dimension must be 2 or 3, got " + std::to_string(dimension));
  return vec(constant(value.x), constant(value.y), constant(value.z));
}

Law Context::parameter(std::string_view name) const {
  if (!is_identifier(name)) fail("parameter name '" + std::string(name) + "' is not an identifier");
  if (detail::is_reserved_name(name))
    fail("parameter name '" + std::string(name) + "' is reserved (function or constant name)");
  auto& names = graph_->parameter_names;
  std::uint32_t index = 0;
  while (index < names.size() && names[index] != name) ++index;
  if (index == names.size()) {
    if (graph_->curve_names.end() != std::find(graph_->curve_names.begin(), graph_->curve_names.end(), name))
      fail("parameter name '" + std::string(name) + "' already names a curve");
    names.emplace_back(name);
  }
  return make(graph_, Op::Parameter, 1, {}, 0.0, index);
}

Law Context::curve(const nurbs::NurbsCurve& c, const Law& argument, std::string_view name, int order) const {
  if (!argument.valid() || Graph::of(argument) != graph_) fail("curve: argument belongs to another law context");
  require_scalar(argument, "curve");
  if (order < 0) fail("curve: derivative order must be >= 0, got " + std::to_string(order));
  auto& g = *graph_;
  std::uint32_t index = 0;
  while (index < g.curves.size() && !(g.curves[index] == c && (name.empty() || g.curve_names[index] == name))) ++index;
  if (index == g.curves.size()) {
    std::string n = name.empty() ? "curve" + std::to_string(index + 1) : std::string(name);
    if (!is_identifier(n) || detail::is_reserved_name(n))
      fail("curve name '" + n + "' is not an identifier or is reserved");
    if (std::find(g.curve_names.begin(), g.curve_names.end(), n) != g.curve_names.end())
      fail("curve name '" + n + "' already names another curve");
    if (std::find(g.parameter_names.begin(), g.parameter_names.end(), n) != g.parameter_names.end())
      fail("curve name '" + n + "' already names a parameter");
    g.curves.push_back(c);
    g.curve_names.push_back(std::move(n));
  }
  return make(graph_, Op::Curve, 3, {argument.id()}, 0.0, index, static_cast<std::uint32_t>(order));
}

std::size_t Context::node_count() const { return graph_->nodes.size(); }

std::size_t Context::size(const Law& root) {
  const auto& g = *Graph::of(root);
  std::vector<char> seen(g.nodes.size(), 0);
  std::vector<NodeId> stack{root.id()};
  std::size_t count = 0;
  while (!stack.empty()) {
    const NodeId id = stack.back();
    stack.pop_back();
    if (seen[id]) continue;
    seen[id] = 1;
    ++count;
    const Node& n = g.nodes[id];
    for (std::size_t i = 0; i < n.arity; ++i) stack.push_back(n.args[i]);
  }
  return count;
}

std::vector<std::string> Context::parameter_names() const { return graph_->parameter_names; }
const std::string& Context::parameter_name(std::uint32_t index) const { return graph_->parameter_names.at(index); }
const nurbs::NurbsCurve& Context::curve_at(std::uint32_t index) const { return graph_->curves.at(index); }
const std::string& Context::curve_name(std::uint32_t index) const { return graph_->curve_names.at(index); }
int Context::find_curve(std::string_view name) const {
  for (std::size_t i = 0; i < graph_->curve_names.size(); ++i)
    if (graph_->curve_names[i] == name) return static_cast<int>(i);
  return -1;
}

// ---------------------------------------------------------------- scalar semantics

double detail::apply(Op op, double a, double b) {
  switch (op) {
    case Op::Neg:
      return -a;
    case Op::Add:
      return a + b;
    case Op::Sub:
      return a - b;
    case Op::Mul:
      return a * b;
    case Op::Div:
      return op_div(a, b);
    case Op::Pow:
      return op_pow(a, b);
    case Op::Sqrt:
      return op_sqrt(a);
    case Op::Exp:
      return std::exp(a);
    case Op::Log:
      return op_log(a);
    case Op::Sin:
      return std::sin(a);
    case Op::Cos:
      return std::cos(a);
    case Op::Tan:
      return std::tan(a);
    case Op::Asin:
      return op_asin(a);
    case Op::Acos:
      return op_acos(a);
    case Op::Atan:
      return std::atan(a);
    case Op::Atan2:
      return op_atan2(a, b);
    case Op::Sinh:
      return std::sinh(a);
    case Op::Cosh:
      return std::cosh(a);
    case Op::Tanh:
      return std::tanh(a);
    case Op::Abs:
      return std::fabs(a);
    case Op::Sign:
      return op_sign(a);
    case Op::Min:
      return op_min(a, b);
    case Op::Max:
      return op_max(a, b);
    case Op::Less:
      return op_less(a, b);
    case Op::LessEqual:
      return op_less_equal(a, b);
    case Op::Norm:
      return std::fabs(a);
    default:
      break;
  }
  throw InternalError("law apply: not a scalar operation");
}

// ---------------------------------------------------------------- builders

Law operator-(const Law& a) {
  const auto& g = graph_of(a, "-");
  if (a.op() == Op::Neg) return a.arg(0);  // −(−x) = x
  if (a.dimension() > 1 && a.is_zero()) return a;
  // −(c·x) = (−c)·x: exact (negation only flips the sign bit).
  if (a.op() == Op::Mul && a.arg(0).is_constant()) return constant_in(g, -a.arg(0).node().value) * a.arg(1);
  Law out;
  if (a.dimension() == 1 && fold(g, Op::Neg, a, nullptr, out)) return out;
  return make(g, Op::Neg, a.dimension(), {a.id()});
}

Law operator+(const Law& a, const Law& b) {
  const auto& g = same_graph(a, b, "+");
  if (a.dimension() != b.dimension())
    fail("'+': cannot add " + dim_name(a.dimension()) + " and " + dim_name(b.dimension()));
  if (a.is_zero()) return b;
  if (b.is_zero()) return a;
  if (b.op() == Op::Neg) return a - b.arg(0);  // a + (−b) = a − b (exact)
  if (a == b) return constant_in(g, 2.0) * a;  // x + x = 2·x (exact: doubling does not round)
  Law out;
  if (a.dimension() == 1 && fold(g, Op::Add, a, &b, out)) return out;
  return make(g, Op::Add, a.dimension(), {a.id(), b.id()});
}

Law operator-(const Law& a, const Law& b) {
  const auto& g = same_graph(a, b, "-");
  if (a.dimension() != b.dimension())
    fail("'-': cannot subtract " + dim_name(b.dimension()) + " from " + dim_name(a.dimension()));
  if (b.is_zero()) return a;
  if (a.is_zero()) return -b;
  if (a == b && a.node().total) return zero_of(g, a.dimension());
  if (b.op() == Op::Neg) return a + b.arg(0);  // a − (−b) = a + b (exact)
  Law out;
  if (a.dimension() == 1 && fold(g, Op::Sub, a, &b, out)) return out;
  return make(g, Op::Sub, a.dimension(), {a.id(), b.id()});
}

Law operator*(const Law& a, const Law& b) {
  const auto& g = same_graph(a, b, "*");
  const int da = a.dimension();
  const int db = b.dimension();
  if (da > 1 && db > 1) fail("'*': cannot multiply " + dim_name(da) + " by " + dim_name(db) + " (use dot or cross)");
  const int d = std::max(da, db);
  if (is_const(a, 1.0)) return b;
  if (is_const(b, 1.0)) return a;
  if (a.is_zero() && b.node().total) return zero_of(g, d);
  if (b.is_zero() && a.node().total) return zero_of(g, d);
  if (is_const(a, -1.0)) return -b;
  if (is_const(b, -1.0)) return -a;
  Law out;
  if (d == 1 && fold(g, Op::Mul, a, &b, out)) return out;
  // Normal form of products (each step exact or one rounding of a constant, so values stay
  // within an ulp): signs outside, (−a)·b = −(a·b); constants first, x·c = c·x; constants
  // collected, c1·(c2·x) = (c1 c2)·x when finite; repeated factors as powers, x·x = x²,
  // x^m·x^n = x^(m+n) for positive integers m, n (total for finite x, like the product).
  if (a.op() == Op::Neg) return -(a.arg(0) * b);
  if (b.op() == Op::Neg) return -(a * b.arg(0));
  if (b.is_constant() && !a.is_constant()) return b * a;
  if (a.is_constant() && b.op() == Op::Mul && b.arg(0).is_constant()) {
    const double k = a.node().value * b.arg(0).node().value;
    if (std::isfinite(k)) return constant_in(g, k) * b.arg(1);
  }
  if (d == 1) {
    auto power_of = [](const Law& e) -> std::pair<Law, double> {
      if (e.op() == Op::Pow && e.arg(1).is_constant()) {
        const double m = e.arg(1).node().value;
        if (m >= 1.0 && m <= 64.0 && m == std::floor(m)) return {e.arg(0), m};
      }
      return {e, 1.0};
    };
    const auto [base_a, m] = power_of(a);
    const auto [base_b, n] = power_of(b);
    if (base_a == base_b && !base_a.is_constant() && m + n <= 64.0) return pow(base_a, constant_in(g, m + n));
  }
  return make(g, Op::Mul, d, {a.id(), b.id()});
}

Law operator/(const Law& a, const Law& b) {
  const auto& g = same_graph(a, b, "/");
  if (b.dimension() != 1) fail("'/': cannot divide by " + dim_name(b.dimension()));
  if (is_const(b, 1.0)) return a;
  if (is_const(b, -1.0)) return -a;
  if (a.is_zero() && b.is_constant() && b.node().value != 0.0) return a;
  Law out;
  if (a.dimension() == 1 && fold(g, Op::Div, a, &b, out)) return out;
  return make(g, Op::Div, a.dimension(), {a.id(), b.id()});
}

Law operator+(const Law& a, double b) { return a + a.context().constant(b); }
Law operator+(double a, const Law& b) { return b.context().constant(a) + b; }
Law operator-(const Law& a, double b) { return a - a.context().constant(b); }
Law operator-(double a, const Law& b) { return b.context().constant(a) - b; }
Law operator*(const Law& a, double b) { return a * a.context().constant(b); }
Law operator*(double a, const Law& b) { return b.context().constant(a) * b; }
Law operator/(const Law& a, double b) { return a / a.context().constant(b); }
Law operator/(double a, const Law& b) { return b.context().constant(a) / b; }

Law pow(const Law& a, const Law& b) {
  const auto& g = same_graph(a, b, "^");
  require_scalar(a, "^");
  require_scalar(b, "^");
  if (is_const(b, 1.0)) return a;
  if (is_const(b, 0.0) && a.node().total) return constant_in(g, 1.0);
  Law out;
  if (fold(g, Op::Pow, a, &b, out)) return out;
  return make(g, Op::Pow, 1, {a.id(), b.id()});
}
Law pow(const Law& a, double b) { return pow(a, a.context().constant(b)); }

Law sqrt(const Law& a) { return unary_scalar(a, Op::Sqrt, "sqrt"); }
Law exp(const Law& a) { return unary_scalar(a, Op::Exp, "exp"); }
Law log(const Law& a) { return unary_scalar(a, Op::Log, "log"); }
Law sin(const Law& a) { return unary_scalar(a, Op::Sin, "sin"); }
Law cos(const Law& a) { return unary_scalar(a, Op::Cos, "cos"); }
Law tan(const Law& a) { return unary_scalar(a, Op::Tan, "tan"); }
Law asin(const Law& a) { return unary_scalar(a, Op::Asin, "asin"); }
Law acos(const Law& a) { return unary_scalar(a, Op::Acos, "acos"); }
Law atan(const Law& a) { return unary_scalar(a, Op::Atan, "atan"); }
Law atan2(const Law& y, const Law& x) { return binary_scalar(y, x, Op::Atan2, "atan2"); }
Law sinh(const Law& a) { return unary_scalar(a, Op::Sinh, "sinh"); }
Law cosh(const Law& a) { return unary_scalar(a, Op::Cosh, "cosh"); }
Law tanh(const Law& a) { return unary_scalar(a, Op::Tanh, "tanh"); }
Law abs(const Law& a) { return unary_scalar(a, Op::Abs, "abs"); }
Law sign(const Law& a) { return unary_scalar(a, Op::Sign, "sign"); }
Law min(const Law& a, const Law& b) {
  if (a == b && a.valid() && a.dimension() == 1) return a;
  return binary_scalar(a, b, Op::Min, "min");
}
Law max(const Law& a, const Law& b) {
  if (a == b && a.valid() && a.dimension() == 1) return a;
  return binary_scalar(a, b, Op::Max, "max");
}
Law less(const Law& a, const Law& b) { return binary_scalar(a, b, Op::Less, "<"); }
Law less_equal(const Law& a, const Law& b) { return binary_scalar(a, b, Op::LessEqual, "<="); }

Law piecewise(const Law& condition, const Law& then_value, const Law& else_value) {
  const auto& g = same_graph(condition, then_value, "piecewise");
  same_graph(condition, else_value, "piecewise");
  if (condition.dimension() != 1)
    fail("'piecewise': the condition must be a scalar, got " + dim_name(condition.dimension()));
  if (then_value.dimension() != else_value.dimension())
    fail("'piecewise': branches have different dimensions (" + dim_name(then_value.dimension()) + " and " +
         dim_name(else_value.dimension()) + ")");
  if (condition.is_constant()) return condition.node().value != 0.0 ? then_value : else_value;
  if (then_value == else_value && condition.node().total) return then_value;
  return make(g, Op::Piecewise, then_value.dimension(), {condition.id(), then_value.id(), else_value.id()});
}

Law vec(const Law& x, const Law& y) {
  const auto& g = same_graph(x, y, "vec");
  require_scalar(x, "vec");
  require_scalar(y, "vec");
  return make(g, Op::Vec, 2, {x.id(), y.id()});
}

Law vec(const Law& x, const Law& y, const Law& z) {
  const auto& g = same_graph(x, y, "vec");
  same_graph(x, z, "vec");
  require_scalar(x, "vec");
  require_scalar(y, "vec");
  require_scalar(z, "vec");
  return make(g, Op::Vec, 3, {x.id(), y.id(), z.id()});
}

Law term(const Law& v, int index) {
  const auto& g = graph_of(v, "term");
  if (index < 1 || index > v.dimension())
    fail("'term': index " + std::to_string(index) + " is outside [1, " + std::to_string(v.dimension()) + "] for " +
         dim_name(v.dimension()));
  if (v.dimension() == 1) return v;
  if (v.op() == Op::Vec) return v.arg(static_cast<std::size_t>(index - 1));
  return make(g, Op::Term, 1, {v.id()}, 0.0, static_cast<std::uint32_t>(index));
}

Law dot(const Law& a, const Law& b) {
  const auto& g = same_graph(a, b, "dot");
  if (a.dimension() == 1 || a.dimension() != b.dimension())
    fail("'dot': expects two vectors of the same dimension, got " + dim_name(a.dimension()) + " and " +
         dim_name(b.dimension()));
  if ((a.is_zero() && b.node().total) || (b.is_zero() && a.node().total)) return constant_in(g, 0.0);
  return make(g, Op::Dot, 1, {a.id(), b.id()});
}

Law cross(const Law& a, const Law& b) {
  const auto& g = same_graph(a, b, "cross");
  if (a.dimension() != 3 || b.dimension() != 3)
    fail("'cross': expects two 3-vectors, got " + dim_name(a.dimension()) + " and " + dim_name(b.dimension()));
  if ((a.is_zero() && b.node().total) || (b.is_zero() && a.node().total)) return zero_of(g, 3);
  return make(g, Op::Cross, 3, {a.id(), b.id()});
}

Law norm(const Law& a) {
  const auto& g = graph_of(a, "norm");
  if (a.dimension() == 1) {
    Law out;
    if (fold(g, Op::Norm, a, nullptr, out)) return out;
  }
  return make(g, Op::Norm, 1, {a.id()});
}

Law normalize(const Law& a) {
  const auto& g = graph_of(a, "normalize");
  return make(g, Op::Normalize, a.dimension(), {a.id()});
}

// ---------------------------------------------------------------- rebuild / substitute

Law detail::build(Op op, std::span<const Law> args, int component) {
  switch (op) {
    case Op::Neg:
      return -args[0];
    case Op::Add:
      return args[0] + args[1];
    case Op::Sub:
      return args[0] - args[1];
    case Op::Mul:
      return args[0] * args[1];
    case Op::Div:
      return args[0] / args[1];
    case Op::Pow:
      return pow(args[0], args[1]);
    case Op::Sqrt:
      return sqrt(args[0]);
    case Op::Exp:
      return exp(args[0]);
    case Op::Log:
      return log(args[0]);
    case Op::Sin:
      return sin(args[0]);
    case Op::Cos:
      return cos(args[0]);
    case Op::Tan:
      return tan(args[0]);
    case Op::Asin:
      return asin(args[0]);
    case Op::Acos:
      return acos(args[0]);
    case Op::Atan:
      return atan(args[0]);
    case Op::Atan2:
      return atan2(args[0], args[1]);
    case Op::Sinh:
      return sinh(args[0]);
    case Op::Cosh:
      return cosh(args[0]);
    case Op::Tanh:
      return tanh(args[0]);
    case Op::Abs:
      return abs(args[0]);
    case Op::Sign:
      return sign(args[0]);
    case Op::Min:
      return min(args[0], args[1]);
    case Op::Max:
      return max(args[0], args[1]);
    case Op::Less:
      return less(args[0], args[1]);
    case Op::LessEqual:
      return less_equal(args[0], args[1]);
    case Op::Piecewise:
      return piecewise(args[0], args[1], args[2]);
    case Op::Vec:
      return args.size() == 2 ? vec(args[0], args[1]) : vec(args[0], args[1], args[2]);
    case Op::Term:
      return term(args[0], component);
    case Op::Dot:
      return dot(args[0], args[1]);
    case Op::Cross:
      return cross(args[0], args[1]);
    case Op::Norm:
      return norm(args[0]);
    case Op::Normalize:
      return normalize(args[0]);
    case Op::Constant:
    case Op::Parameter:
    case Op::Curve:
      break;
  }
  throw InternalError("law build: operation needs more than its arguments");
}

Law detail::rebuild(const Law& original, std::span<const Law> args) {
  const Node n = original.node();
  switch (n.op) {
    case Op::Constant:
    case Op::Parameter:
      return original;
    case Op::Curve: {
      Context ctx = original.context();
      return ctx.curve(ctx.curve_at(n.index), args[0], ctx.curve_name(n.index), static_cast<int>(n.order));
    }
    default:
      return build(n.op, args, static_cast<int>(n.index));
  }
}

namespace {
Law substitute_rec(const Law& e, NodeId param, const Law& value, std::unordered_map<NodeId, Law>& memo) {
  if (auto it = memo.find(e.id()); it != memo.end()) return it->second;
  const Node n = e.node();  // a copy: building nodes may reallocate the node array
  Law out;
  if (n.op == Op::Parameter) {
    out = e.id() == param ? value : e;
  } else {
    std::array<Law, 3> args;
    bool changed = false;
    for (std::size_t i = 0; i < n.arity; ++i) {
      args[i] = substitute_rec(e.arg(i), param, value, memo);
      changed = changed || !(args[i] == e.arg(i));
    }
    out = changed ? detail::rebuild(e, std::span<const Law>(args.data(), n.arity)) : e;
  }
  memo.emplace(e.id(), out);
  return out;
}
}  // namespace

Law substitute(const Law& expression, std::string_view name, const Law& value) {
  const auto& g = same_graph(expression, value, "substitute");
  require_scalar(value, "substitute");
  const auto& names = g->parameter_names;
  if (std::find(names.begin(), names.end(), name) == names.end()) return expression;
  const Law p = expression.context().parameter(name);
  std::unordered_map<NodeId, Law> memo;
  return substitute_rec(expression, p.id(), value, memo);
}

}  // namespace hula::law
