// SPDX-License-Identifier: MIT
// The storage behind a law Context: the node array, the hash-consing table,
// parameter names, NURBS leaves and the derivative memo (one entry per node
// and parameter, which is what keeps high-order derivatives compact).
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

#include "hula/law/expr.hpp"

namespace hula::law {

/// Hash of a node's structure (op, dimension, arguments, payload).
struct NodeHash {
  std::size_t operator()(const Node& n) const noexcept;
};
/// Structural equality of nodes (constants compared bit for bit).
struct NodeEqual {
  bool operator()(const Node& a, const Node& b) const noexcept;
};

struct Graph {
  std::vector<Node> nodes;
  std::unordered_map<Node, NodeId, NodeHash, NodeEqual> table;
  std::vector<std::string> parameter_names;
  std::vector<nurbs::NurbsCurve> curves;
  std::vector<std::string> curve_names;
  /// (node << 32 | parameter) → derivative node.
  std::unordered_map<std::uint64_t, NodeId> derivatives;

  /// Interns a node whose arguments are already in the graph; fills height and total.
  /// @throws hula::Error(Errc::InvalidArgument) beyond kMaxNodes or kMaxHeight
  NodeId intern(Node n);
  [[nodiscard]] static Law handle(const std::shared_ptr<Graph>& g, NodeId id) { return Law(g, id); }
  [[nodiscard]] static const std::shared_ptr<Graph>& of(const Law& l) { return l.graph_; }
  [[nodiscard]] static Context context(const std::shared_ptr<Graph>& g) { return Context(g); }
};

namespace detail {
/// The same operation as `original` on new arguments, through the simplifying builders.
[[nodiscard]] Law rebuild(const Law& original, std::span<const Law> args);
/// Operation `op` on `args` through its simplifying builder: the one map from
/// an Op to its builder, shared by rebuild and the parser. `component` is the
/// 1-based index of Op::Term. Not for Constant, Parameter and Curve, which
/// carry data besides their arguments.
/// @throws InternalError for those three ops
[[nodiscard]] Law build(Op op, std::span<const Law> args, int component = 0);
}  // namespace detail

}  // namespace hula::law
