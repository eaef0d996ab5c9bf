// SPDX-License-Identifier: MIT
// Derivative rules (Ceres jet.h style: each rule with its expansion). Notation:
// a, b are the arguments, a' = da/dp, q is the node itself (reused so that
// e.g. (e^a)' = q·a' shares the exponential).
#include "hula/law/derive.hpp"

#include <string>

#include "hula/core/error.hpp"
#include "hula/law/detail/graph.hpp"

namespace hula::law {

namespace {

Law zero_like(const Law& e) {
  Context ctx = e.context();
  Law z = ctx.constant(0.0);
  if (e.dimension() == 1) return z;
  return e.dimension() == 2 ? vec(z, z) : vec(z, z, z);
}

Law d(const Law& e, std::uint32_t p);

Law rule(const Law& q, std::uint32_t p) {
  const Node n = q.node();  // a copy: building nodes may reallocate the node array
  Context ctx = q.context();
  auto c = [&ctx](double v) { return ctx.constant(v); };
  auto A = [&q](std::size_t i) { return q.arg(i); };
  auto D = [&q, p](std::size_t i) { return d(q.arg(i), p); };
  switch (n.op) {
    case Op::Constant:
      return c(0.0);
    case Op::Parameter:
      return c(n.index == p ? 1.0 : 0.0);
    case Op::Neg:
      return -D(0);  // (−a)' = −a'
    case Op::Add:
      return D(0) + D(1);  // (a + b)' = a' + b'
    case Op::Sub:
      return D(0) - D(1);  // (a − b)' = a' − b'
    case Op::Mul:
      return D(0) * A(1) + A(0) * D(1);  // (ab)' = a'b + ab'
    case Op::Div:
      return (D(0) - q * D(1)) / A(1);  // (a/b)' = (a' − q b') / b
    case Op::Pow: {
      const Law b = A(1);
      if (b.is_constant()) {
        // (a^k)' = k a^(k−1) a'
        const double k = b.node().value;
        return (c(k) * pow(A(0), c(k - 1.0))) * D(0);
      }
      // (a^b)' = q (b' log a + b a'/a)
      return q * (D(1) * log(A(0)) + b * D(0) / A(0));
    }
    case Op::Sqrt:
      return D(0) / (c(2.0) * q);  // (√a)' = a' / (2q)
    case Op::Exp:
      return q * D(0);  // (e^a)' = q a'
    case Op::Log:
      return D(0) / A(0);  // (log a)' = a'/a
    case Op::Sin:
      return cos(A(0)) * D(0);  // (sin a)' = cos a · a'
    case Op::Cos:
      return -(sin(A(0)) * D(0));  // (cos a)' = −sin a · a'
    case Op::Tan:
      return (c(1.0) + q * q) * D(0);  // (tan a)' = (1 + q²) a'
    case Op::Asin:
      return D(0) / sqrt(c(1.0) - A(0) * A(0));  // a' / √(1 − a²)
    case Op::Acos:
      return -(D(0) / sqrt(c(1.0) - A(0) * A(0)));  // −a' / √(1 − a²)
    case Op::Atan:
      return D(0) / (c(1.0) + A(0) * A(0));  // a' / (1 + a²)
    case Op::Atan2:                          // atan2(y, x)' = (x y' − y x')/(x² + y²)
      return (A(1) * D(0) - A(0) * D(1)) / (A(0) * A(0) + A(1) * A(1));
    case Op::Sinh:
      return cosh(A(0)) * D(0);  // (sinh a)' = cosh a · a'
    case Op::Cosh:
      return sinh(A(0)) * D(0);  // (cosh a)' = sinh a · a'
    case Op::Tanh:
      return (c(1.0) - q * q) * D(0);  // (tanh a)' = (1 − q²) a'
    case Op::Abs:
      return sign(A(0)) * D(0);  // |a|' = sign(a) a' (0 at the kink)
    case Op::Sign:               // piecewise constant: 0 (jump at a = 0)
    case Op::Less:
    case Op::LessEqual:
      return c(0.0);
    case Op::Min:
      return piecewise(less_equal(A(0), A(1)), D(0), D(1));  // a' where a ≤ b (ties take a')
    case Op::Max:
      return piecewise(less_equal(A(1), A(0)), D(0), D(1));  // a' where a ≥ b
    case Op::Piecewise:
      return piecewise(A(0), D(1), D(2));  // branch-wise, switch points excluded
    case Op::Vec:
      return n.arity == 2 ? vec(D(0), D(1)) : vec(D(0), D(1), D(2));  // component-wise
    case Op::Term:
      return term(D(0), static_cast<int>(n.index));  // term(v, i)' = term(v', i)
    case Op::Dot:
      return dot(D(0), A(1)) + dot(A(0), D(1));  // (a·b)' = a'·b + a·b'
    case Op::Cross:
      return cross(D(0), A(1)) + cross(A(0), D(1));  // (a×b)' = a'×b + a×b'
    case Op::Norm:                                   // |a|' = a·a' / |a|
      if (A(0).dimension() == 1) return sign(A(0)) * D(0);
      return dot(A(0), D(0)) / q;
    case Op::Normalize: {  // (a/|a|)' = (a' − q (q·a')) / |a|
      const Law da = D(0);
      if (A(0).dimension() == 1) return zero_like(q);
      return (da - q * dot(q, da)) / norm(A(0));
    }
    case Op::Curve: {  // C^(k)(a)' = C^(k+1)(a) a'
      const Law a = A(0);
      return ctx.curve(ctx.curve_at(n.index), a, ctx.curve_name(n.index), static_cast<int>(n.order + 1)) * D(0);
    }
  }
  throw InternalError("law derivative: unknown op");
}

Law d(const Law& e, std::uint32_t p) {
  auto& g = *Graph::of(e);
  const std::uint64_t key = (static_cast<std::uint64_t>(e.id()) << 32) | p;
  if (auto it = g.derivatives.find(key); it != g.derivatives.end()) return Graph::handle(Graph::of(e), it->second);
  Law out = rule(e, p);
  if (out.dimension() != e.dimension()) throw InternalError("law derivative changed the dimension");
  g.derivatives.emplace(key, out.id());
  return out;
}

}  // namespace

Law derivative(const Law& expression, std::string_view parameter, int order) {
  if (order < 0) throw Error(Errc::InvalidArgument, "derivative order must be >= 0, got " + std::to_string(order));
  if (!expression.valid()) throw Error(Errc::InvalidArgument, "derivative of an empty law");
  Context ctx = expression.context();
  const Law p = ctx.parameter(parameter);
  Law out = expression;
  for (int k = 0; k < order; ++k) out = d(out, p.node().index);
  return out;
}

std::vector<Law> derivatives(const Law& expression, std::string_view parameter, int order) {
  if (order < 0) throw Error(Errc::InvalidArgument, "derivative order must be >= 0, got " + std::to_string(order));
  std::vector<Law> out{expression};
  for (int k = 1; k <= order; ++k) out.push_back(derivative(out.back(), parameter, 1));
  return out;
}

}  // namespace hula::law
