// SPDX-License-Identifier: MIT
// Rule-based symbolic integration (see antiderivative.hpp). Notation: p is the
// integration parameter, u = a·p + b a linear argument (a ≠ 0, constants), and
// ∫ denotes an antiderivative with respect to p.
#include "hula/law/antiderivative.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/law/singularities.hpp"
#include "hula/law/tape.hpp"

namespace hula::law {

namespace {

using Poly = std::vector<double>;  // coefficients c_0 … c_n of Σ c_k p^k
constexpr std::size_t kMaxPolyDegree = 64;

class Integrator {
 public:
  Integrator(const Context& ctx, std::uint32_t p) : ctx_(ctx), p_(p) {}

  bool depends(const Law& e) {
    if (auto it = depends_.find(e.id()); it != depends_.end()) return it->second;
    const Node n = e.node();
    bool d = n.op == Op::Parameter && n.index == p_;
    for (std::size_t i = 0; i < n.arity && !d; ++i) d = depends(e.arg(i));
    depends_.emplace(e.id(), d);
    return d;
  }

  /// Coefficients when e is a polynomial in p with constant coefficients.
  std::optional<Poly> poly(const Law& e) {
    if (auto it = poly_.find(e.id()); it != poly_.end()) return it->second;
    std::optional<Poly> r = poly_uncached(e);
    if (r && r->size() > kMaxPolyDegree + 1) r.reset();
    poly_.emplace(e.id(), r);
    return r;
  }

  std::optional<Law> integrate(const Law& f);

 private:
  std::optional<Poly> poly_uncached(const Law& e) {
    const Node n = e.node();
    if (n.dimension != 1) return std::nullopt;
    switch (n.op) {
      case Op::Constant:
        return Poly{n.value};
      case Op::Parameter:
        if (n.index == p_) return Poly{0.0, 1.0};
        return std::nullopt;
      case Op::Neg: {
        auto a = poly(e.arg(0));
        if (!a) return std::nullopt;
        for (double& c : *a) c = -c;
        return a;
      }
      case Op::Add:
      case Op::Sub: {
        auto a = poly(e.arg(0));
        auto b = poly(e.arg(1));
        if (!a || !b) return std::nullopt;
        Poly r(std::max(a->size(), b->size()), 0.0);
        for (std::size_t k = 0; k < a->size(); ++k) r[k] += (*a)[k];
        for (std::size_t k = 0; k < b->size(); ++k) r[k] += n.op == Op::Add ? (*b)[k] : -(*b)[k];
        return r;
      }
      case Op::Mul: {
        auto a = poly(e.arg(0));
        auto b = poly(e.arg(1));
        if (!a || !b || a->size() + b->size() > kMaxPolyDegree + 2) return std::nullopt;
        return multiply(*a, *b);
      }
      case Op::Div: {
        auto a = poly(e.arg(0));
        const Law d = e.arg(1);
        if (!a || !d.is_constant() || d.node().value == 0.0) return std::nullopt;
        for (double& c : *a) c /= d.node().value;
        return a;
      }
      case Op::Pow: {
        const Law k = e.arg(1);
        if (!k.is_constant()) return std::nullopt;
        const double kv = k.node().value;
        if (kv < 0 || kv != std::floor(kv) || kv > static_cast<double>(kMaxPolyDegree)) return std::nullopt;
        auto a = poly(e.arg(0));
        if (!a) return std::nullopt;
        Poly r{1.0};
        for (int i = 0; i < static_cast<int>(kv); ++i) {
          if (r.size() + a->size() > kMaxPolyDegree + 2) return std::nullopt;
          r = multiply(r, *a);
        }
        return r;
      }
      default:
        return std::nullopt;
    }
  }

  static Poly multiply(const Poly& a, const Poly& b) {
    Poly r(a.size() + b.size() - 1, 0.0);
    for (std::size_t i = 0; i < a.size(); ++i)
      for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
    return r;
  }

  /// u = a p + b with a ≠ 0: returns a.
  std::optional<double> linear_slope(const Law& u) {
    auto c = poly(u);
    if (!c) return std::nullopt;
    while (c->size() > 1 && c->back() == 0.0) c->pop_back();
    if (c->size() != 2) return std::nullopt;
    return (*c)[1];
  }

  /// Horner form of Σ c_k p^k.
  Law horner(const Poly& c) {
    const Law p = param();
    Law r = ctx_.constant(0.0);
    for (std::size_t k = c.size(); k-- > 0;) r = r * p + ctx_.constant(c[k]);
    return r;
  }

  Law param() const { return ctx_.parameter(ctx_.parameter_name(p_)); }

  Context ctx_;
  std::uint32_t p_;
  std::unordered_map<NodeId, bool> depends_;
  std::unordered_map<NodeId, std::optional<Poly>> poly_;
  std::unordered_map<NodeId, std::optional<Law>> memo_;

 public:
  std::optional<Law> integrate_uncached(const Law& f);
};

std::optional<Law> Integrator::integrate(const Law& f) {
  if (auto it = memo_.find(f.id()); it != memo_.end()) return it->second;
  std::optional<Law> r = integrate_uncached(f);
  memo_.emplace(f.id(), r);
  return r;
}

std::optional<Law> Integrator::integrate_uncached(const Law& f) {
  const Node n = f.node();  // a copy: building nodes may reallocate the node array
  const Law p = param();
  if (n.dimension > 1) {
    if (n.op != Op::Vec && depends(f)) {
      // component-wise through term()
      std::vector<Law> comps;
      for (int k = 1; k <= n.dimension; ++k) {
        auto c = integrate(term(f, k));
        if (!c) return std::nullopt;
        comps.push_back(*c);
      }
      return n.dimension == 2 ? vec(comps[0], comps[1]) : vec(comps[0], comps[1], comps[2]);
    }
    if (!depends(f)) return f * p;
    std::vector<Law> comps;
    for (std::size_t k = 0; k < n.arity; ++k) {
      auto c = integrate(f.arg(k));
      if (!c) return std::nullopt;
      comps.push_back(*c);
    }
    return n.arity == 2 ? vec(comps[0], comps[1]) : vec(comps[0], comps[1], comps[2]);
  }
  if (!depends(f)) return f * p;  // ∫c = c p
  if (auto c = poly(f)) {         // ∫Σ c_k p^k = Σ c_k p^(k+1)/(k+1)
    Poly r(c->size() + 1, 0.0);
    for (std::size_t k = 0; k < c->size(); ++k) r[k + 1] = (*c)[k] / static_cast<double>(k + 1);
    return horner(r);
  }
  auto A = [&f](std::size_t i) { return f.arg(i); };
  switch (n.op) {
    case Op::Neg: {
      auto a = integrate(A(0));
      if (a) return -*a;
      return std::nullopt;
    }
    case Op::Add:
    case Op::Sub: {  // linearity
      auto a = integrate(A(0));
      auto b = integrate(A(1));
      if (!a || !b) return std::nullopt;
      return n.op == Op::Add ? *a + *b : *a - *b;
    }
    case Op::Mul: {  // constant factors
      if (!depends(A(0))) {
        auto b = integrate(A(1));
        if (b) return A(0) * *b;
        return std::nullopt;
      }
      if (!depends(A(1))) {
        auto a = integrate(A(0));
        if (a) return *a * A(1);
      }
      return std::nullopt;
    }
    case Op::Div: {
      if (!depends(A(1))) {  // ∫g/c = (∫g)/c
        auto a = integrate(A(0));
        if (a) return *a / A(1);
        return std::nullopt;
      }
      if (!depends(A(0))) {  // ∫k/(a p + b) = k log|a p + b| / a
        if (auto s = linear_slope(A(1))) return A(0) * log(abs(A(1))) / *s;
      }
      return std::nullopt;
    }
    case Op::Pow: {  // ∫u^k = u^(k+1)/(a (k+1)), k ≠ −1; ∫u^−1 = log|u|/a
      if (!A(1).is_constant()) return std::nullopt;
      const double k = A(1).node().value;
      const auto s = linear_slope(A(0));
      if (!s) return std::nullopt;
      if (k == -1.0) return log(abs(A(0))) / *s;
      return pow(A(0), k + 1.0) / (*s * (k + 1.0));
    }
    case Op::Sqrt: {  // ∫√u = (2/3) u^(3/2) / a
      if (auto s = linear_slope(A(0))) return pow(A(0), 1.5) * (2.0 / (3.0 * *s));
      return std::nullopt;
    }
    case Op::Sin:
    case Op::Cos:
    case Op::Exp:
    case Op::Sinh:
    case Op::Cosh:
    case Op::Tan: {
      const auto s = linear_slope(A(0));
      if (!s) return std::nullopt;
      const Law u = A(0);
      switch (n.op) {
        case Op::Sin:
          return -cos(u) / *s;  // ∫sin u = −cos u / a
        case Op::Cos:
          return sin(u) / *s;  // ∫cos u = sin u / a
        case Op::Exp:
          return f / *s;  // ∫e^u = e^u / a
        case Op::Sinh:
          return cosh(u) / *s;  // ∫sinh u = cosh u / a
        case Op::Cosh:
          return sinh(u) / *s;  // ∫cosh u = sinh u / a
        default:
          return -log(abs(cos(u))) / *s;  // ∫tan u = −log|cos u| / a
      }
    }
    case Op::Abs: {  // ∫|u| = u|u| / (2a)
      if (auto s = linear_slope(A(0))) return A(0) * f / (2.0 * *s);
      return std::nullopt;
    }
    case Op::Piecewise: {
      // piecewise(x ◁ y, g, h) with x − y = a p + b: switch at s = −b/a. F = piecewise(c, G, H + G(s) − H(s)),
      // continuous at s.
      const Law c = A(0);
      if (c.op() != Op::Less && c.op() != Op::LessEqual) return std::nullopt;
      auto d = poly(c.arg(0) - c.arg(1));
      if (!d) return std::nullopt;
      while (d->size() > 1 && d->back() == 0.0) d->pop_back();
      auto g = integrate(A(1));
      auto h = integrate(A(2));
      if (!g || !h) return std::nullopt;
      if (d->size() == 1) return piecewise(c, *g, *h);  // condition constant in p
      if (d->size() != 2) return std::nullopt;
      const double sw = -(*d)[0] / (*d)[1];
      const std::string name = ctx_.parameter_name(p_);
      const Law at = ctx_.constant(sw);
      const Law jump = substitute(*g, name, at) - substitute(*h, name, at);
      return piecewise(c, *g, *h + jump);
    }
    default:
      return std::nullopt;
  }
}

}  // namespace

std::optional<Law> antiderivative(const Law& f, std::string_view parameter) {
  if (!f.valid()) throw Error(Errc::InvalidArgument, "antiderivative: empty law");
  Context ctx = f.context();
  const Law p = ctx.parameter(parameter);
  Integrator in(ctx, p.node().index);
  return in.integrate(f);
}

std::optional<DefiniteIntegralResult> symbolic_definite_integral(const Law& f, std::string_view parameter, double a,
                                                                 double b) {
  if (!f.valid() || f.dimension() != 1) throw Error(Errc::InvalidArgument, "definite_integral: expects a scalar law");
  if (!std::isfinite(a) || !std::isfinite(b))
    throw Error(Errc::InvalidArgument,
                "definite_integral: bounds must be finite, got [" + format_number(a) + ", " + format_number(b) + "]");
  std::optional<Law> F = antiderivative(f, parameter);
  if (!F.has_value() || a == b) return std::nullopt;
  // F(b) − F(a) is only the integral when f has no pole or undefined region on [a, b].
  const SingularityReport rep = singularities(f, parameter, std::min(a, b), std::max(a, b));
  if (!rep.undefined.empty()) return std::nullopt;
  for (const Singularity& s : rep.points) {
    switch (s.kind) {
      case SingularityKind::DivisionByZero:
      case SingularityKind::TanPole:
      case SingularityKind::LogBoundary:
      case SingularityKind::PowerBase:
      case SingularityKind::SqrtBoundary:
      case SingularityKind::InverseTrigBound:
      case SingularityKind::NormalizeZero:
      case SingularityKind::Atan2Origin:
        return std::nullopt;
      default:
        break;
    }
  }
  const std::string in[1] = {std::string(parameter)};
  const Law outs[1] = {*F};
  const Tape tape = Tape::compile(outs, in);
  double fa = 0, fb = 0;
  const bool ok = tape.evaluate(std::span<const double>(&a, 1), std::span<double>(&fa, 1)) &&
                  tape.evaluate(std::span<const double>(&b, 1), std::span<double>(&fb, 1));
  if (!ok || !std::isfinite(fa) || !std::isfinite(fb)) return std::nullopt;
  DefiniteIntegralResult r;
  r.value = fb - fa;
  r.error_estimate = 16 * std::numeric_limits<double>::epsilon() * (std::fabs(fa) + std::fabs(fb));
  r.method = IntegralMethod::Symbolic;
  r.converged = true;
  r.antiderivative = *F;
  return r;
}

DefiniteIntegralResult definite_integral(const Law& f, std::string_view parameter, double a, double b,
                                         const IntegrationOptions& options) {
  options.validate();
  if (std::optional<DefiniteIntegralResult> exact = symbolic_definite_integral(f, parameter, a, b)) return *exact;
  DefiniteIntegralResult r;
  const IntegrationResult n = integrate(f, parameter, a, b, options);
  r.value = n.value;
  r.error_estimate = n.error_estimate;
  r.converged = n.converged;
  r.method = IntegralMethod::Numeric;
  return r;
}

}  // namespace hula::law
