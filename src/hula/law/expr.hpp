// SPDX-License-Identifier: MIT
// The law expression DAG: scalar and vector functions of named parameters,
// after the thesis's function representation (4.3) and ACIS's LAW classes
// (10.2.3, 10.2.4). Expressions live in a Context that hash-conses every node
// (structurally equal subexpressions are stored once, so equality of two
// Laws is an index comparison) and simplifies on construction without ever
// changing a value: constant folding (only to finite results), x + 0, x − 0,
// x · 1, x / 1, x ^ 1, −(−x), and x · 0 → 0, x − x → 0, x ^ 0 → 1 only when x
// is defined for every finite input ("total").
//
// Values: a law has dimension 1 (scalar), 2 or 3 (vector), known when it is
// built. Undefined results (1/0, sqrt(−1), log(0), asin(2), normalize(0),
// atan2(0, 0), 0^−1, a NURBS leaf outside its domain) evaluate to NaN and are
// reported by the evaluators as "undefined" (docs/modules/law.md); ±inf only
// ever means overflow.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::law {

/// Node kinds of the DAG.
enum class Op : std::uint8_t {
  Constant,   ///< a finite double (value)
  Parameter,  ///< a named parameter (index into Context::parameter_names)
  Neg,        ///< −a
  Add,        ///< a + b (same dimension)
  Sub,        ///< a − b (same dimension)
  Mul,        ///< a · b (scalar · scalar, scalar · vector or vector · scalar)
  Div,        ///< a / b (b scalar); undefined where b = 0
  Pow,        ///< a ^ b (scalars); undefined for a < 0 with non-integer b and for 0 ^ (b < 0)
  Sqrt,       ///< √a; undefined for a < 0
  Exp,        ///< e^a
  Log,        ///< natural log; undefined for a ≤ 0
  Sin,
  Cos,
  Tan,
  Asin,  ///< undefined for |a| > 1
  Acos,  ///< undefined for |a| > 1
  Atan,
  Atan2,  ///< atan2(a, b) = angle of (b, a); undefined at (0, 0)
  Sinh,
  Cosh,
  Tanh,
  Abs,
  Sign,  ///< −1, 0 or 1
  Min,
  Max,
  Less,       ///< 1 if a < b else 0
  LessEqual,  ///< 1 if a ≤ b else 0
  Piecewise,  ///< a ≠ 0 ? b : c (c, b same dimension; only the selected branch matters)
  Vec,        ///< vec(a, b[, c]): 2- or 3-vector from scalars
  Term,       ///< component `index` (1-based) of a vector
  Dot,        ///< a · b of vectors of equal dimension
  Cross,      ///< a × b of 3-vectors
  Norm,       ///< Euclidean length |a|
  Normalize,  ///< a / |a|; undefined where a = 0
  Curve,      ///< derivative `order` of NURBS curve `index` at the scalar a (a 3-vector)
};

/// Index of a node in its Context.
using NodeId = std::uint32_t;
/// Marks an unused argument slot.
inline constexpr NodeId kNoNode = 0xffffffffU;

/// One node of the DAG. Immutable once created.
struct Node {
  Op op = Op::Constant;
  /// 1 for a scalar, 2 or 3 for a vector.
  std::uint8_t dimension = 1;
  /// Number of used entries in args.
  std::uint8_t arity = 0;
  /// True when the node is finite-valued for every finite parameter value
  /// (overflow aside): the condition for value-preserving x·0 → 0.
  bool total = true;
  /// Longest path to a leaf (leaves have height 0); bounded by kMaxHeight.
  std::uint32_t height = 0;
  std::array<NodeId, 3> args{kNoNode, kNoNode, kNoNode};
  /// Op::Constant: the value.
  double value = 0.0;
  /// Op::Parameter: parameter index; Op::Term: 1-based component; Op::Curve: curve index.
  std::uint32_t index = 0;
  /// Op::Curve: derivative order.
  std::uint32_t order = 0;
};

/// Largest number of nodes a Context holds. Building beyond it (a huge
/// expression or runaway derivative growth) throws Errc::InvalidArgument.
inline constexpr std::size_t kMaxNodes = 1'000'000;
/// Largest node height (nesting depth). Recursive algorithms stay within a
/// few megabytes of stack below it.
inline constexpr std::uint32_t kMaxHeight = 4000;

class Context;
struct Graph;

/// A handle on one node of a Context: cheap to copy, compared by identity
/// (which, thanks to hash-consing, is structural equality).
class Law {
 public:
  /// An empty handle (no context); most operations on it throw.
  Law() = default;

  /// True when the handle refers to a node.
  [[nodiscard]] bool valid() const noexcept { return graph_ != nullptr; }
  /// The node (throws hula::Error(Errc::InvalidArgument) on an empty handle).
  /// @note The reference is valid until the context creates another node (any builder,
  ///   derivative or parse on it may reallocate the node array): copy the Node to keep it.
  [[nodiscard]] const Node& node() const;
  [[nodiscard]] Op op() const { return node().op; }
  /// 1 for scalars, 2 or 3 for vectors.
  [[nodiscard]] int dimension() const { return node().dimension; }
  [[nodiscard]] NodeId id() const noexcept { return id_; }
  /// Argument i of the node (i < node().arity).
  [[nodiscard]] Law arg(std::size_t i) const;
  /// True for Op::Constant.
  [[nodiscard]] bool is_constant() const { return op() == Op::Constant; }
  /// True for a constant (or vec of constants) equal to zero.
  [[nodiscard]] bool is_zero() const;
  /// The context that owns the node.
  [[nodiscard]] Context context() const;

  friend bool operator==(const Law& a, const Law& b) noexcept { return a.graph_ == b.graph_ && a.id_ == b.id_; }

 private:
  friend class Context;
  friend struct Graph;
  Law(std::shared_ptr<Graph> graph, NodeId id) : graph_(std::move(graph)), id_(id) {}
  std::shared_ptr<Graph> graph_;
  NodeId id_ = kNoNode;
};

/// Owner of a hash-consed expression DAG, its parameter names and NURBS
/// leaves, and the memo of derivatives. Copies share the same DAG.
///
/// Not thread-safe: build and differentiate from one thread, then compile a
/// Tape (immutable) for concurrent evaluation.
class Context {
 public:
  /// A new, empty context.
  Context();

  /// A constant.
  /// @throws hula::Error(Errc::NonFiniteInput) if value is NaN or infinite
  [[nodiscard]] Law constant(double value) const;
  /// A 2- or 3-vector of constants.
  [[nodiscard]] Law constant(const Vec3& value, int dimension = 3) const;
  /// The parameter with this name (created on first use).
  /// @param name an identifier: a letter or '_' then letters, digits, '_';
  ///   not a function name nor `pi` / `e`
  /// @throws hula::Error(Errc::InvalidArgument) naming the bad name
  [[nodiscard]] Law parameter(std::string_view name) const;
  /// A NURBS curve as a leaf: C^(order)(argument), a 3-vector (z = 0 for planar curves).
  /// Its derivatives come from NurbsCurve::derivatives. Undefined (NaN) outside the curve's domain.
  /// @param name identifier used by print() and parse() (ParseOptions::curves); empty = "curve<k>"
  /// @throws hula::Error(Errc::InvalidArgument) if argument is not a scalar of this context or the
  ///   name is not an identifier or already names another curve
  [[nodiscard]] Law curve(const nurbs::NurbsCurve& curve, const Law& argument, std::string_view name = {},
                          int order = 0) const;

  /// Number of nodes stored (a measure of DAG size).
  [[nodiscard]] std::size_t node_count() const;
  /// Number of nodes reachable from `root` (its DAG size, shared nodes once).
  [[nodiscard]] static std::size_t size(const Law& root);
  /// Names of the parameters created so far, in creation order.
  [[nodiscard]] std::vector<std::string> parameter_names() const;
  /// Name of parameter `index`.
  [[nodiscard]] const std::string& parameter_name(std::uint32_t index) const;
  /// NURBS leaf curve `index` and its name.
  [[nodiscard]] const nurbs::NurbsCurve& curve_at(std::uint32_t index) const;
  [[nodiscard]] const std::string& curve_name(std::uint32_t index) const;
  /// Index of the curve with this name, or -1.
  [[nodiscard]] int find_curve(std::string_view name) const;

  friend bool operator==(const Context& a, const Context& b) noexcept { return a.graph_ == b.graph_; }

 private:
  friend class Law;
  friend struct Graph;
  explicit Context(std::shared_ptr<Graph> g) : graph_(std::move(g)) {}
  std::shared_ptr<Graph> graph_;
};

/// @name Builders
/// Each checks dimensions and throws hula::Error(Errc::InvalidArgument) with a
/// message naming the operation (e.g. "'+': cannot combine a scalar and a
/// 3-vector"); operands from different contexts throw the same.
/// Mixed Law/double forms turn the double into a constant of the law's context.
///@{
[[nodiscard]] Law operator-(const Law& a);
[[nodiscard]] Law operator+(const Law& a, const Law& b);
[[nodiscard]] Law operator-(const Law& a, const Law& b);
[[nodiscard]] Law operator*(const Law& a, const Law& b);
[[nodiscard]] Law operator/(const Law& a, const Law& b);
[[nodiscard]] Law operator+(const Law& a, double b);
[[nodiscard]] Law operator+(double a, const Law& b);
[[nodiscard]] Law operator-(const Law& a, double b);
[[nodiscard]] Law operator-(double a, const Law& b);
[[nodiscard]] Law operator*(const Law& a, double b);
[[nodiscard]] Law operator*(double a, const Law& b);
[[nodiscard]] Law operator/(const Law& a, double b);
[[nodiscard]] Law operator/(double a, const Law& b);
[[nodiscard]] Law pow(const Law& a, const Law& b);
[[nodiscard]] Law pow(const Law& a, double b);
[[nodiscard]] Law sqrt(const Law& a);
[[nodiscard]] Law exp(const Law& a);
[[nodiscard]] Law log(const Law& a);
[[nodiscard]] Law sin(const Law& a);
[[nodiscard]] Law cos(const Law& a);
[[nodiscard]] Law tan(const Law& a);
[[nodiscard]] Law asin(const Law& a);
[[nodiscard]] Law acos(const Law& a);
[[nodiscard]] Law atan(const Law& a);
/// atan2(y, x): the angle of the point (x, y).
[[nodiscard]] Law atan2(const Law& y, const Law& x);
[[nodiscard]] Law sinh(const Law& a);
[[nodiscard]] Law cosh(const Law& a);
[[nodiscard]] Law tanh(const Law& a);
[[nodiscard]] Law abs(const Law& a);
[[nodiscard]] Law sign(const Law& a);
[[nodiscard]] Law min(const Law& a, const Law& b);
[[nodiscard]] Law max(const Law& a, const Law& b);
/// 1 where a < b, else 0.
[[nodiscard]] Law less(const Law& a, const Law& b);
/// 1 where a ≤ b, else 0.
[[nodiscard]] Law less_equal(const Law& a, const Law& b);
/// `then_value` where condition ≠ 0, else `else_value`. Only the selected branch is evaluated in
/// effect: an undefined unselected branch does not make the result undefined.
[[nodiscard]] Law piecewise(const Law& condition, const Law& then_value, const Law& else_value);
/// 2-vector from two scalars.
[[nodiscard]] Law vec(const Law& x, const Law& y);
/// 3-vector from three scalars.
[[nodiscard]] Law vec(const Law& x, const Law& y, const Law& z);
/// Component `index` of a vector, 1-based as the thesis's term_law.
/// @throws hula::Error(Errc::InvalidArgument) if index is not in [1, dimension]
[[nodiscard]] Law term(const Law& v, int index);
[[nodiscard]] Law dot(const Law& a, const Law& b);
[[nodiscard]] Law cross(const Law& a, const Law& b);
[[nodiscard]] Law norm(const Law& a);
[[nodiscard]] Law normalize(const Law& a);
///@}

/// Composition: `expression` with every occurrence of parameter `name` replaced by `value`
/// (a scalar of the same context). Simplifies as it rebuilds.
/// @throws hula::Error(Errc::InvalidArgument) if value is not a scalar of the same context
[[nodiscard]] Law substitute(const Law& expression, std::string_view name, const Law& value);

namespace detail {
/// Applies a scalar operation exactly as the evaluators do (NaN for undefined).
[[nodiscard]] double apply(Op op, double a, double b);
}  // namespace detail

}  // namespace hula::law
