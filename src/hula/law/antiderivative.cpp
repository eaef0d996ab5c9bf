// SPDX-License-Identifier: MIT
// Rule-based symbolic integration (see antiderivative.hpp). Notation: p is the
// integration parameter, u a subexpression, u' = du/dp, ∫ an antiderivative
// with respect to p, P and Q polynomials in p with constant coefficients.
//
// An integrand that is not a sum is read as a product
//     k · P(p) · b1^e1 · … · bn^en
// (k independent of p, P the polynomial factors, b the other factors with
// constant exponents; √u is u^(1/2), a quotient a negative exponent) and the
// rules are tried in this order:
//   1. rational functions P / D with deg D ≤ 2 (or D a power of a linear
//      factor): polynomial division, log, atan or −1/(2ap + b) forms;
//   2. P · (αp + β)^e: P rewritten in powers of u = αp + β, then term by term;
//   3. substitution ∫ g(u) u' = G(u): for each factor, u = its base (g = u^e)
//      or, for a function of one argument, u = that argument (g = sin, cos, exp,
//      sinh, cosh, tan, tanh, log, atan, asin, acos); the rest of the product
//      divided by u' must simplify (law::simplify) to a constant c, and then
//      ∫ = c·G(u) — which includes every linear argument (u' constant);
//   4. by parts: P · e^u, P · sin u, cos u, sinh u, cosh u (u linear) in closed
//      (tabular) form; P · log u, atan u, asin u, acos u as Q·g(u) − ∫Q·g'(u)
//      with Q = ∫P (chosen to vanish at the root of a linear u, so that
//      Q·u'/u is a polynomial);
//   5. e^(αp+β) · sin(γp+δ) and cos in closed form;
//   6. sin^m(u) cos^n(u), u linear: an odd power gives a polynomial in the
//      other function times its derivative; even powers reduce with
//      ∫sin^2q = −sin^(2q−1) cos/(2q u') + (2q−1)/(2q) ∫sin^(2q−2);
//      sin/cos products of two different linear arguments by product-to-sum;
//   7. (mp + n)/√Q and √Q, Q quadratic: asin (leading coefficient < 0) or
//      log forms.
#include "hula/law/antiderivative.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/law/derive.hpp"
#include "hula/law/detail/improper.hpp"
#include "hula/law/detail/short_print.hpp"
#include "hula/law/parser.hpp"
#include "hula/law/simplify.hpp"
#include "hula/law/singularities.hpp"
#include "hula/law/tape.hpp"

namespace hula::law {

namespace {

using Poly = std::vector<double>;  // coefficients c_0 … c_n of Σ c_k p^k
constexpr std::size_t kMaxPolyDegree = 64;
// Nesting of by-parts steps (each integrates a simpler integrand again).
constexpr int kMaxDepth = 8;
// Largest sin/cos power reduced by rule 6.
constexpr int kMaxTrigPower = 32;

void trim(Poly& c) {
  while (c.size() > 1 && c.back() == 0.0) c.pop_back();
}

Poly multiply(const Poly& a, const Poly& b) {
  Poly r(a.size() + b.size() - 1, 0.0);
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = 0; j < b.size(); ++j) r[i + j] += a[i] * b[j];
  return r;
}

Poly derivative_of(const Poly& c) {
  if (c.size() <= 1) return {0.0};
  Poly r(c.size() - 1);
  for (std::size_t k = 1; k < c.size(); ++k) r[k - 1] = c[k] * static_cast<double>(k);
  return r;
}

Poly integral_of(const Poly& c) {  // the antiderivative vanishing at 0
  Poly r(c.size() + 1, 0.0);
  for (std::size_t k = 0; k < c.size(); ++k) r[k + 1] = c[k] / static_cast<double>(k + 1);
  return r;
}

double evaluate(const Poly& c, double x) {
  double r = 0.0;
  for (std::size_t k = c.size(); k-- > 0;) r = r * x + c[k];
  return r;
}

bool is_zero(const Poly& c) {
  return std::all_of(c.begin(), c.end(), [](double v) { return v == 0.0; });
}

std::size_t degree(Poly c) {
  trim(c);
  return c.size() - 1;
}

// P(p) rewritten in powers of u = α p + β: P(p) = Σ b_k u^k (Taylor shift of P((u − β)/α)).
Poly in_powers_of_linear(const Poly& P, double alpha, double beta) {
  // Horner in u: P = Σ c_k p^k with p = (u − β)/α, i.e. p as the polynomial {−β/α, 1/α} in u.
  const Poly p_in_u{-beta / alpha, 1.0 / alpha};
  Poly r{0.0};
  for (std::size_t k = P.size(); k-- > 0;) {
    r = multiply(r, p_in_u);
    r[0] += P[k];
  }
  return r;
}

// Binomial coefficient C(n, k).
double binomial(int n, int k) {
  double r = 1.0;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

/// One factor base^exponent of a product (exponent a non-zero constant).
struct Factor {
  Law base;
  double exponent = 1.0;
};

/// An integrand read as k · P · Π base^exponent.
struct Product {
  Law constant;                 // independent of p
  Poly poly{1.0};               // polynomial factors
  std::vector<Factor> factors;  // the others, bases merged
};

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

  std::optional<Law> integrate(const Law& f) {
    if (auto it = memo_.find(f.id()); it != memo_.end()) return it->second;
    std::optional<Law> r = integrate_uncached(f);
    memo_.emplace(f.id(), r);
    return r;
  }

  /// The first term of the integrand's sum no rule applied to (empty if none recorded).
  [[nodiscard]] const Law& blocking() const { return blocking_; }

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

  /// u = α p + β with α ≠ 0: {β, α}.
  std::optional<std::pair<double, double>> linear(const Law& u) {
    auto c = poly(u);
    if (!c) return std::nullopt;
    trim(*c);
    if (c->size() != 2) return std::nullopt;
    return std::pair{(*c)[0], (*c)[1]};
  }

  /// Horner form of Σ c_k p^k.
  Law horner(const Poly& c) {
    const Law p = param();
    Law r = ctx_.constant(0.0);
    for (std::size_t k = c.size(); k-- > 0;) r = r * p + ctx_.constant(c[k]);
    return r;
  }

  Law param() const { return ctx_.parameter(ctx_.parameter_name(p_)); }
  Law c(double v) const { return ctx_.constant(v); }

  // The first failing term of the top-level sum (not of the integrals tried inside a by-parts step).
  void note_blocking(const Law& term) {
    if (depth_ == 0 && !blocking_.valid() && term.op() != Op::Add && term.op() != Op::Sub && term.op() != Op::Neg)
      blocking_ = term;
  }

  // ------------------------------------------------------------------ products

  void factorise(const Law& e, double sign, Product& out) {
    const Node n = e.node();
    if (!depends(e)) {
      out.constant = sign > 0 ? out.constant * e : out.constant / e;
      return;
    }
    if (sign > 0) {
      if (auto q = poly(e)) {
        out.poly = multiply(out.poly, *q);
        return;
      }
    }
    switch (n.op) {
      case Op::Neg:
        out.constant = -out.constant;
        factorise(e.arg(0), sign, out);
        return;
      case Op::Mul:
        factorise(e.arg(0), sign, out);
        factorise(e.arg(1), sign, out);
        return;
      case Op::Div:
        factorise(e.arg(0), sign, out);
        factorise(e.arg(1), -sign, out);
        return;
      case Op::Pow: {
        const Law k = e.arg(1);
        if (k.is_constant()) {
          const Law b = e.arg(0);
          // (e^u)^k = e^(k u): one exponential factor.
          if (b.op() == Op::Exp) {
            out.factors.push_back({exp(k * b.arg(0)), sign});
            return;
          }
          const double kv = k.node().value;
          if (sign > 0 && kv > 0 && kv == std::floor(kv) && kv <= static_cast<double>(kMaxPolyDegree))
            if (auto q = poly(b)) {
              for (int i = 0; i < static_cast<int>(kv); ++i) out.poly = multiply(out.poly, *q);
              return;
            }
          out.factors.push_back({b, sign * kv});
          return;
        }
        break;
      }
      case Op::Sqrt:
        out.factors.push_back({e.arg(0), 0.5 * sign});
        return;
      default:
        break;
    }
    out.factors.push_back({e, sign});
  }

  std::optional<Product> product(const Law& f) {
    Product pr{c(1.0), {1.0}, {}};
    factorise(f, 1.0, pr);
    // Merge equal bases.
    std::vector<Factor> merged;
    for (const Factor& x : pr.factors) {
      auto it = std::find_if(merged.begin(), merged.end(), [&](const Factor& y) { return y.base == x.base; });
      if (it == merged.end())
        merged.push_back(x);
      else
        it->exponent += x.exponent;
    }
    merged.erase(std::remove_if(merged.begin(), merged.end(), [](const Factor& x) { return x.exponent == 0.0; }),
                 merged.end());
    pr.factors = std::move(merged);
    if (pr.poly.size() > kMaxPolyDegree + 1) return std::nullopt;
    trim(pr.poly);
    return pr;
  }

  Law factor_law(const Factor& x) {
    if (x.exponent == 1.0) return x.base;
    if (x.exponent == 0.5) return sqrt(x.base);
    return pow(x.base, x.exponent);
  }

  // k · P · Π factors except `skip` (SIZE_MAX: none).
  Law rest_of(const Product& pr, std::size_t skip) {
    Law r = pr.constant * horner(pr.poly);
    for (std::size_t i = 0; i < pr.factors.size(); ++i)
      if (i != skip) r = r * factor_law(pr.factors[i]);
    return r;
  }

  // ---------------------------------------------------------------- rule 1, 2

  // ∫ N/D for polynomials with deg D ≤ 2 (D with no root in common with N assumed; the forms are
  // valid on every interval without a root of D).
  std::optional<Law> rational(const Poly& num, Poly den) {
    trim(den);
    const std::size_t dd = den.size() - 1;
    if (dd == 0) {
      Poly q = num;
      for (double& v : q) v /= den[0];
      return horner(integral_of(q));
    }
    if (dd > 2) return std::nullopt;
    // Polynomial division num = S·den + R, deg R < deg den.
    Poly r = num;
    trim(r);
    Poly s(r.size() >= den.size() ? r.size() - den.size() + 1 : 1, 0.0);
    while (r.size() >= den.size() && !(r.size() == 1 && r[0] == 0.0)) {
      const std::size_t shift = r.size() - den.size();
      const double q = r.back() / den.back();
      s[shift] = q;
      for (std::size_t i = 0; i < den.size(); ++i) r[shift + i] -= q * den[i];
      r.pop_back();
      if (r.empty()) r = {0.0};
    }
    trim(r);
    Law out = horner(integral_of(s));
    const Law p = param();
    if (dd == 1) {  // R constant: R/(αp + β) → (R/α) log|αp + β|
      const double alpha = den[1];
      if (r[0] != 0.0) out = out + c(r[0] / alpha) * log(abs(horner(den)));
      return out;
    }
    // den = a p² + b p + cc, R = m p + n: (m/2a)·(2ap + b)/den + (n − m b/2a)/den.
    const double a = den[2], b = den[1], cc = den[0];
    const double m = r.size() > 1 ? r[1] : 0.0, n = r[0];
    const Law q = horner(den);
    if (m != 0.0) out = out + c(m / (2.0 * a)) * log(abs(q));
    const double k = n - m * b / (2.0 * a);
    if (k == 0.0) return out;
    const double disc = b * b - 4.0 * a * cc;
    const Law lin = c(2.0 * a) * p + c(b);  // 2ap + b
    if (disc < 0.0) {
      // ∫1/den = 2/√(−D) atan((2ap + b)/√(−D))
      const double w = std::sqrt(-disc);
      return out + c(2.0 * k / w) * atan(horner({b / w, 2.0 * a / w}));
    }
    if (disc > 0.0) {
      // ∫1/den = 1/√D log|(2ap + b − √D)/(2ap + b + √D)|
      const double w = std::sqrt(disc);
      return out + c(k / w) * log(abs((lin - c(w)) / (lin + c(w))));
    }
    // Double root: ∫1/(a (p − r)²) = −2/(2ap + b)
    return out - c(2.0 * k) / lin;
  }

  // ∫ k P(p) (αp + β)^e: P in powers of u = αp + β, each u^(j+e) integrated.
  std::optional<Law> poly_times_linear_power(const Product& pr) {
    if (pr.factors.size() != 1) return std::nullopt;
    const Factor& x = pr.factors.front();
    const auto lin = linear(x.base);
    if (!lin) return std::nullopt;
    const auto [beta, alpha] = *lin;
    const Poly b = in_powers_of_linear(pr.poly, alpha, beta);
    const Law u = x.base;
    Law out = c(0.0);
    for (std::size_t j = 0; j < b.size(); ++j) {
      if (b[j] == 0.0) continue;
      const double e = static_cast<double>(j) + x.exponent;
      if (e == -1.0)
        out = out + c(b[j] / alpha) * log(abs(u));
      else if (e + 1.0 == 0.5)
        out = out + c(b[j] / (alpha * 0.5)) * sqrt(u);
      else
        out = out + c(b[j] / (alpha * (e + 1.0))) * pow(u, e + 1.0);
    }
    return pr.constant * out;
  }

  // ---------------------------------------------------------------- rule 3

  // G with G' = g for the function g of one argument applied to x = u.
  std::optional<Law> primitive_of_function(Op op, const Law& u) {
    switch (op) {
      case Op::Sin:
        return -cos(u);  // ∫sin = −cos
      case Op::Cos:
        return sin(u);  // ∫cos = sin
      case Op::Exp:
        return exp(u);  // ∫e^x = e^x
      case Op::Sinh:
        return cosh(u);  // ∫sinh = cosh
      case Op::Cosh:
        return sinh(u);  // ∫cosh = sinh
      case Op::Tan:
        return -log(abs(cos(u)));  // ∫tan = −log|cos|
      case Op::Tanh:
        return log(cosh(u));  // ∫tanh = log cosh
      case Op::Log:
        return u * log(u) - u;  // ∫log x = x log x − x
      case Op::Atan:
        return u * atan(u) - c(0.5) * log(c(1.0) + u * u);  // ∫atan x = x atan x − ½ log(1 + x²)
      case Op::Asin:
        return u * asin(u) + sqrt(c(1.0) - u * u);  // ∫asin x = x asin x + √(1 − x²)
      case Op::Acos:
        return u * acos(u) - sqrt(c(1.0) - u * u);  // ∫acos x = x acos x − √(1 − x²)
      default:
        return std::nullopt;
    }
  }

  // ∫x^e for x = u: x^(e+1)/(e+1), or log|x| for e = −1.
  Law primitive_of_power(const Law& u, double e) {
    if (e == -1.0) return log(abs(u));
    if (e + 1.0 == 0.5) return c(2.0) * sqrt(u);
    return pow(u, e + 1.0) / c(e + 1.0);
  }

  // c with rest = c·u', or nullopt when the ratio depends on p.
  std::optional<Law> constant_ratio(const Law& rest, const Law& u) {
    const Law du = derivative(u, ctx_.parameter_name(p_));
    if (du.is_zero()) return std::nullopt;
    const Law ratio = simplify(rest / du);
    if (depends(ratio)) return std::nullopt;
    return ratio;
  }

  std::optional<Law> substitution(const Product& pr) {
    for (std::size_t i = 0; i < pr.factors.size(); ++i) {
      const Factor& x = pr.factors[i];
      const Law rest = rest_of(pr, i);
      // u = the base: ∫ u^e u' = G(u).
      if (depends(x.base))
        if (auto k = constant_ratio(rest, x.base)) return *k * primitive_of_power(x.base, x.exponent);
      // u = the argument of a function of one argument.
      if (x.exponent == 1.0 && x.base.node().arity == 1 && x.base.dimension() == 1) {
        const Law u = x.base.arg(0);
        if (!depends(u)) continue;
        const std::optional<Law> G = primitive_of_function(x.base.op(), u);
        if (!G) continue;
        if (auto k = constant_ratio(rest, u)) return *k * *G;
      }
    }
    // A polynomial factor with a negative or fractional power written as a factor: handled above
    // (it is a base). The polynomial part as u: ∫ P' g(P)… is covered by the factors' bases.
    return std::nullopt;
  }

  // ---------------------------------------------------------------- rule 4

  // Tabular integration by parts of P · g(αp + β) for g = exp, sin, cos, sinh, cosh.
  std::optional<Law> tabular(const Poly& P, Op op, const Law& u, double alpha) {
    // A = Σ s_k P^(2k)/α^(2k+1), B = Σ s_k P^(2k+1)/α^(2k+2) (s_k = (−1)^k for sin and cos, 1 for sinh and
    // cosh); for exp, S = Σ (−1)^k P^(k)/α^(k+1).
    std::vector<Poly> d{P};
    while (!is_zero(d.back())) d.push_back(derivative_of(d.back()));
    auto combine = [&](std::size_t first, std::size_t step, bool alternate) {
      Poly r{0.0};
      double sign = 1.0;
      for (std::size_t k = first; k < d.size(); k += step) {
        const double scale = sign / std::pow(alpha, static_cast<double>(k + 1));
        if (r.size() < d[k].size()) r.resize(d[k].size(), 0.0);
        for (std::size_t j = 0; j < d[k].size(); ++j) r[j] += scale * d[k][j];
        if (alternate) sign = -sign;
      }
      return r;
    };
    switch (op) {
      case Op::Exp: {
        Poly s{0.0};
        for (std::size_t k = 0; k < d.size(); ++k) {
          const double scale = ((k % 2 == 0) ? 1.0 : -1.0) / std::pow(alpha, static_cast<double>(k + 1));
          if (s.size() < d[k].size()) s.resize(d[k].size(), 0.0);
          for (std::size_t j = 0; j < d[k].size(); ++j) s[j] += scale * d[k][j];
        }
        return horner(s) * exp(u);  // ∫P e^u = e^u Σ (−1)^k P^(k)/α^(k+1)
      }
      case Op::Sin:  // ∫P sin u = −cos u·A + sin u·B
        return horner(combine(1, 2, true)) * sin(u) - horner(combine(0, 2, true)) * cos(u);
      case Op::Cos:  // ∫P cos u = sin u·A + cos u·B
        return horner(combine(0, 2, true)) * sin(u) + horner(combine(1, 2, true)) * cos(u);
      case Op::Sinh:  // ∫P sinh u = cosh u·A − sinh u·B
        return horner(combine(0, 2, false)) * cosh(u) - horner(combine(1, 2, false)) * sinh(u);
      case Op::Cosh:  // ∫P cosh u = sinh u·A − cosh u·B
        return horner(combine(0, 2, false)) * sinh(u) - horner(combine(1, 2, false)) * cosh(u);
      default:
        return std::nullopt;
    }
  }

  std::optional<Law> by_parts(const Product& pr) {
    if (pr.factors.size() != 1 || pr.factors.front().exponent != 1.0) return std::nullopt;
    const Law g = pr.factors.front().base;
    if (g.dimension() != 1 || g.node().arity != 1) return std::nullopt;
    const Law u = g.arg(0);
    switch (g.op()) {
      case Op::Exp:
      case Op::Sin:
      case Op::Cos:
      case Op::Sinh:
      case Op::Cosh: {
        const auto lin = linear(u);
        if (!lin) return std::nullopt;
        if (auto F = tabular(pr.poly, g.op(), u, lin->second)) return pr.constant * *F;
        return std::nullopt;
      }
      case Op::Log:
      case Op::Atan:
      case Op::Asin:
      case Op::Acos: {
        // ∫P g(u) = Q g(u) − ∫Q g(u)'. Q = ∫P, shifted to vanish at the root of a linear u.
        if (depth_ >= kMaxDepth) return std::nullopt;
        Poly Q = integral_of(pr.poly);
        if (const auto lin = linear(u)) Q[0] -= evaluate(Q, -lin->first / lin->second);
        const Law q = horner(Q);
        const Law rest = q * derivative(g, ctx_.parameter_name(p_));
        ++depth_;
        const std::optional<Law> inner = integrate(rest);
        --depth_;
        if (!inner) return std::nullopt;
        return pr.constant * (q * g - *inner);
      }
      default:
        return std::nullopt;
    }
  }

  // ---------------------------------------------------------------- rule 5, 6

  std::optional<Law> exp_trig(const Product& pr) {
    if (pr.factors.size() != 2 || degree(pr.poly) != 0) return std::nullopt;
    const Factor* e = nullptr;
    const Factor* t = nullptr;
    for (const Factor& x : pr.factors) {
      if (x.exponent != 1.0) return std::nullopt;
      if (x.base.op() == Op::Exp)
        e = &x;
      else if (x.base.op() == Op::Sin || x.base.op() == Op::Cos)
        t = &x;
    }
    if (!e || !t) return std::nullopt;
    const Law u = e->base.arg(0), v = t->base.arg(0);
    const auto lu = linear(u), lv = linear(v);
    if (!lu || !lv) return std::nullopt;
    const double a = lu->second, b = lv->second, n = a * a + b * b;
    const Law k = pr.constant * c(pr.poly[0] / n) * exp(u);
    // ∫e^u sin v = e^u (a sin v − b cos v)/(a² + b²); ∫e^u cos v = e^u (a cos v + b sin v)/(a² + b²).
    if (t->base.op() == Op::Sin) return k * (c(a) * sin(v) - c(b) * cos(v));
    return k * (c(a) * cos(v) + c(b) * sin(v));
  }

  // ∫ sin^m(u) cos^n(u) dp, u = αp + β.
  Law trig_powers(int m, int n, const Law& u, double alpha) {
    const Law s = sin(u), co = cos(u);
    auto pw = [&](const Law& x, int k) { return k == 1 ? x : pow(x, static_cast<double>(k)); };
    Law out = c(0.0);
    if (m % 2 == 1) {
      // sin^m cos^n = Σ_j C(h, j)(−1)^j cos^(n+2j) sin, h = (m−1)/2; ∫cos^k sin = −cos^(k+1)/((k+1)α).
      const int h = (m - 1) / 2;
      for (int j = 0; j <= h; ++j) {
        const int k = n + 2 * j;
        out = out + c(-binomial(h, j) * (j % 2 == 0 ? 1.0 : -1.0) / ((k + 1) * alpha)) * pw(co, k + 1);
      }
      return out;
    }
    if (n % 2 == 1) {
      const int h = (n - 1) / 2;
      for (int j = 0; j <= h; ++j) {
        const int k = m + 2 * j;
        out = out + c(binomial(h, j) * (j % 2 == 0 ? 1.0 : -1.0) / ((k + 1) * alpha)) * pw(s, k + 1);
      }
      return out;
    }
    // Both even: cos^n = (1 − sin²)^(n/2), then I_q = ∫sin^(2q) by
    // I_q = −sin^(2q−1) cos/(2q α) + (2q−1)/(2q) I_(q−1), I_0 = p.
    const int h = n / 2;
    const int top = m / 2 + h;
    std::vector<Law> I{param()};
    for (int q = 1; q <= top; ++q)
      I.push_back(c(-1.0 / (2.0 * q * alpha)) * pw(s, 2 * q - 1) * co + c((2.0 * q - 1.0) / (2.0 * q)) * I.back());
    for (int j = 0; j <= h; ++j)
      out = out + c(binomial(h, j) * (j % 2 == 0 ? 1.0 : -1.0)) * I[static_cast<std::size_t>(m / 2 + j)];
    return out;
  }

  std::optional<Law> trig(const Product& pr) {
    if (degree(pr.poly) != 0 || pr.factors.empty() || pr.factors.size() > 2) return std::nullopt;
    for (const Factor& x : pr.factors) {
      if (x.base.op() != Op::Sin && x.base.op() != Op::Cos) return std::nullopt;
      if (x.exponent < 1.0 || x.exponent > kMaxTrigPower || x.exponent != std::floor(x.exponent)) return std::nullopt;
    }
    const Law k = pr.constant * c(pr.poly[0]);
    const Law u = pr.factors.front().base.arg(0);
    const bool same = pr.factors.size() == 1 || pr.factors.back().base.arg(0) == u;
    if (same) {
      const auto lin = linear(u);
      if (!lin) return std::nullopt;
      int m = 0, n = 0;
      for (const Factor& x : pr.factors) (x.base.op() == Op::Sin ? m : n) += static_cast<int>(x.exponent);
      return k * trig_powers(m, n, u, lin->second);
    }
    // Two different arguments, each to the first power: product to sum.
    const Factor& x = pr.factors[0];
    const Factor& y = pr.factors[1];
    if (x.exponent != 1.0 || y.exponent != 1.0 || depth_ >= kMaxDepth) return std::nullopt;
    const Law A = x.base.arg(0), B = y.base.arg(0);
    if (!linear(A) || !linear(B)) return std::nullopt;
    const bool sa = x.base.op() == Op::Sin, sb = y.base.op() == Op::Sin;
    Law sum;
    if (sa && sb)
      sum = c(0.5) * (cos(A - B) - cos(A + B));  // sin A sin B
    else if (!sa && !sb)
      sum = c(0.5) * (cos(A - B) + cos(A + B));  // cos A cos B
    else if (sa)
      sum = c(0.5) * (sin(A + B) + sin(A - B));  // sin A cos B
    else
      sum = c(0.5) * (sin(A + B) + sin(B - A));  // cos A sin B
    ++depth_;
    const std::optional<Law> F = integrate(simplify(sum));
    --depth_;
    if (!F) return std::nullopt;
    return k * *F;
  }

  // ---------------------------------------------------------------- rule 7

  // ∫1/√Q for Q = a p² + b p + c.
  std::optional<Law> inverse_sqrt_quadratic(const Poly& q) {
    const double a = q[2], b = q[1], cc = q[0];
    const Law p = param();
    const Law lin = c(2.0 * a) * p + c(b);
    if (a < 0.0) {
      // −asin((2ap + b)/√D)/√(−a), D = b² − 4ac > 0 (else Q < 0 everywhere).
      const double disc = b * b - 4.0 * a * cc;
      if (!(disc > 0.0)) return std::nullopt;
      return c(-1.0 / std::sqrt(-a)) * asin(lin / c(std::sqrt(disc)));
    }
    // log|2ap + b + 2√a √Q| / √a
    return c(1.0 / std::sqrt(a)) * log(abs(lin + c(2.0 * std::sqrt(a)) * sqrt(horner(q))));
  }

  std::optional<Law> sqrt_quadratic(const Product& pr) {
    if (pr.factors.size() != 1) return std::nullopt;
    const Factor& x = pr.factors.front();
    auto q = poly(x.base);
    if (!q) return std::nullopt;
    trim(*q);
    if (q->size() != 3) return std::nullopt;
    const double a = (*q)[2], b = (*q)[1], cc = (*q)[0];
    const Law root = sqrt(x.base);
    if (x.exponent == -0.5 && degree(pr.poly) <= 1) {
      // (mp + n)/√Q = (m/2a)·Q'/√Q + (n − m b/2a)/√Q; ∫Q'/√Q = 2√Q.
      const double m = pr.poly.size() > 1 ? pr.poly[1] : 0.0, n = pr.poly[0];
      const double k = n - m * b / (2.0 * a);
      Law out = c(m / a) * root;
      if (k != 0.0) {
        const auto inv = inverse_sqrt_quadratic(*q);
        if (!inv) return std::nullopt;
        out = out + c(k) * *inv;
      }
      return pr.constant * out;
    }
    if (x.exponent == 0.5 && degree(pr.poly) == 0) {
      // ∫√Q = (2ap + b)√Q/(4a) + (4ac − b²)/(8a) ∫1/√Q
      const auto inv = inverse_sqrt_quadratic(*q);
      if (!inv) return std::nullopt;
      const Law lin = c(2.0 * a) * param() + c(b);
      return pr.constant * c(pr.poly[0]) * (lin * root / c(4.0 * a) + c((4.0 * a * cc - b * b) / (8.0 * a)) * *inv);
    }
    return std::nullopt;
  }

  // ---------------------------------------------------------------- dispatch

  std::optional<Law> integrate_product(const Law& f) {
    const std::optional<Product> pr = product(f);
    if (!pr) return std::nullopt;
    // Rule 1: every factor a polynomial to a negative integer power.
    bool rational_only = !pr->factors.empty();
    Poly den{1.0};
    for (const Factor& x : pr->factors) {
      const auto q = poly(x.base);
      if (!q || x.exponent > 0.0 || x.exponent != std::floor(x.exponent) ||
          x.exponent < -static_cast<double>(kMaxPolyDegree)) {
        rational_only = false;
        break;
      }
      for (int i = 0; i < static_cast<int>(-x.exponent) && den.size() <= kMaxPolyDegree; ++i) den = multiply(den, *q);
    }
    if (rational_only && degree(den) <= 2)
      if (auto F = rational(pr->poly, den)) return pr->constant * *F;
    if (auto F = poly_times_linear_power(*pr)) return F;
    if (auto F = substitution(*pr)) return F;
    if (auto F = by_parts(*pr)) return F;
    if (auto F = exp_trig(*pr)) return F;
    if (auto F = trig(*pr)) return F;
    if (auto F = sqrt_quadratic(*pr)) return F;
    return std::nullopt;
  }

  std::optional<Law> integrate_uncached(const Law& f) {
    const Node n = f.node();  // a copy: building nodes may reallocate the node array
    const Law p = param();
    if (n.dimension > 1) {
      if (n.op != Op::Vec && depends(f)) {
        // component-wise through term()
        std::vector<Law> comps;
        for (int k = 1; k <= n.dimension; ++k) {
          auto comp = integrate(term(f, k));
          if (!comp) return std::nullopt;
          comps.push_back(*comp);
        }
        return n.dimension == 2 ? vec(comps[0], comps[1]) : vec(comps[0], comps[1], comps[2]);
      }
      if (!depends(f)) return f * p;
      std::vector<Law> comps;
      for (std::size_t k = 0; k < n.arity; ++k) {
        auto comp = integrate(f.arg(k));
        if (!comp) return std::nullopt;
        comps.push_back(*comp);
      }
      return n.arity == 2 ? vec(comps[0], comps[1]) : vec(comps[0], comps[1], comps[2]);
    }
    if (!depends(f)) return f * p;                         // ∫c = c p
    if (auto q = poly(f)) return horner(integral_of(*q));  // ∫Σ c_k p^k = Σ c_k p^(k+1)/(k+1)
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
        if (!a) note_blocking(A(0));
        auto b = integrate(A(1));
        if (!b) note_blocking(A(1));
        if (!a || !b) return std::nullopt;
        return n.op == Op::Add ? *a + *b : *a - *b;
      }
      case Op::Abs: {  // ∫|u| = u|u| / (2a)
        if (auto lin = linear(A(0))) return A(0) * f / (2.0 * lin->second);
        return std::nullopt;
      }
      case Op::Piecewise: {
        // piecewise(x ◁ y, g, h) with x − y = a p + b: switch at s = −b/a. F = piecewise(c, G, H + G(s) − H(s)),
        // continuous at s.
        const Law cond = A(0);
        if (cond.op() != Op::Less && cond.op() != Op::LessEqual) return std::nullopt;
        auto d = poly(cond.arg(0) - cond.arg(1));
        if (!d) return std::nullopt;
        trim(*d);
        auto g = integrate(A(1));
        auto h = integrate(A(2));
        if (!g || !h) return std::nullopt;
        if (d->size() == 1) return piecewise(cond, *g, *h);  // condition constant in p
        if (d->size() != 2) return std::nullopt;
        const double sw = -(*d)[0] / (*d)[1];
        const std::string name = ctx_.parameter_name(p_);
        const Law at = ctx_.constant(sw);
        const Law jump = substitute(*g, name, at) - substitute(*h, name, at);
        return piecewise(cond, *g, *h + jump);
      }
      default:
        return integrate_product(f);
    }
  }

  Context ctx_;
  std::uint32_t p_;
  int depth_ = 0;
  Law blocking_;
  std::unordered_map<NodeId, bool> depends_;
  std::unordered_map<NodeId, std::optional<Poly>> poly_;
  std::unordered_map<NodeId, std::optional<Law>> memo_;
};

}  // namespace

AntiderivativeReport antiderivative_report(const Law& f, std::string_view parameter) {
  if (!f.valid()) throw Error(Errc::InvalidArgument, "antiderivative: empty law");
  Context ctx = f.context();
  const Law p = ctx.parameter(parameter);
  Integrator in(ctx, p.node().index);
  AntiderivativeReport r;
  r.antiderivative = in.integrate(f);
  if (!r.antiderivative) r.blocking_term = in.blocking().valid() ? in.blocking() : f;
  return r;
}

std::optional<Law> antiderivative(const Law& f, std::string_view parameter) {
  return antiderivative_report(f, parameter).antiderivative;
}

namespace {

using detail::short_print;

// A compiled scalar law; NaN where undefined.
class Scalar {
 public:
  Scalar(const Law& f, std::string_view parameter) : tape_(compile(f, parameter)) {}
  double operator()(double t) const {
    double v = 0.0;
    if (!tape_.evaluate(std::span<const double>(&t, 1), std::span<double>(&v, 1))) return std::nan("");
    return v;
  }

 private:
  static Tape compile(const Law& f, std::string_view parameter) {
    const std::string in[1] = {std::string(parameter)};
    const Law outs[1] = {f};
    return Tape::compile(outs, in);
  }
  Tape tape_;
};

struct ClosedForm {
  std::optional<DefiniteIntegralResult> result;
  std::string reason;  // why not, when result is empty
};

// F(b) − F(a) with the limits of F at the improper points of f (see symbolic_definite_integral()).
ClosedForm closed_form(const Law& f, const Law& F, std::string_view parameter, double a, double b) {
  const double lo = std::min(a, b), hi = std::max(a, b), w = hi - lo;
  const std::string name(parameter);
  const SingularityReport rep = singularities(f, parameter, lo, hi);
  std::vector<double> improper;  // points of [lo, hi] where F needs a limit
  for (const UndefinedInterval& u : rep.undefined) {
    // A region of positive length; one that shrinks onto a point is that point (1/0 sampled at a pole).
    if (u.end - u.start > 1e-9 * w)
      return {std::nullopt,
              "the integrand is undefined on [" + format_number(u.start) + ", " + format_number(u.end) + "]"};
    double mid = std::clamp(0.5 * (u.start + u.end), lo, hi);
    for (const double x : {lo, hi})
      if (std::fabs(x - mid) <= 1e-9 * w) mid = x;
    for (const Singularity& s : rep.points)
      if (std::fabs(s.t - mid) <= 1e-9 * w) mid = s.t;
    improper.push_back(mid);
  }
  for (const Singularity& s : rep.points)
    if (detail::is_improper_kind(s.kind)) improper.push_back(s.t);
  const Scalar Fs(F, parameter);
  // The limit of F at t0 from the side dir: F(t0) when finite (the rules build antiderivatives that are
  // continuous wherever they are finite), else F(t0 + dir·u) at shrinking u when those agree.
  auto limit = [&](double t0, double dir) -> std::optional<double> {
    const double v = Fs(t0);
    if (std::isfinite(v)) return v;
    const Scalar g(detail::shifted_law(F, parameter, t0, dir), parameter);
    const double v1 = g(w * 1e-30), v2 = g(w * 1e-60), v3 = g(w * 1e-120);
    if (!std::isfinite(v1) || !std::isfinite(v2) || !std::isfinite(v3)) return std::nullopt;
    if (std::fabs(v2 - v3) > 1e-14 * (1.0 + std::fabs(v3)) || std::fabs(v1 - v2) > 1e-12 * (1.0 + std::fabs(v3)))
      return std::nullopt;
    return v3;
  };
  // An improper point where f grows like a non-integrable pole (at the rounded position of a pole F may still
  // be finite, e.g. −log|cos t| at the double nearest π/2) is left to the numeric path, which reports it.
  for (const double t0 : improper)
    for (const double dir : {-1.0, 1.0}) {
      if ((dir < 0.0 && t0 <= lo) || (dir > 0.0 && t0 >= hi)) continue;
      const double side = dir > 0.0 ? hi - t0 : t0 - lo;
      const double p = detail::growth_exponent(detail::shifted_law(f, parameter, t0, dir), parameter, side);
      if (!detail::integrable_growth(p))
        return {std::nullopt, "the integrand is not integrable at " + name + " = " + format_number(t0)};
    }
  auto no_limit = [&](double t) {
    return ClosedForm{std::nullopt, "the antiderivative " + short_print(F) + " has no finite limit at " + name + " = " +
                                        format_number(t)};
  };
  for (const double t0 : improper) {
    if (t0 <= lo || t0 >= hi) continue;  // the ends are taken below
    const std::optional<double> left = limit(t0, -1.0), right = limit(t0, 1.0);
    if (!left || !right || std::fabs(*left - *right) > 1e-12 * (1.0 + std::fabs(*left))) return no_limit(t0);
  }
  const std::optional<double> Fa = limit(lo, 1.0), Fb = limit(hi, -1.0);
  if (!Fa) return no_limit(lo);
  if (!Fb) return no_limit(hi);
  // F itself defined inside (a formula with a narrower domain than f would give a wrong difference).
  for (int i = 1; i < 64; ++i) {
    const double t = lo + w * (i + 0.5) / 64.5;
    if (std::isnan(Fs(t)))
      return {std::nullopt,
              "the antiderivative " + short_print(F) + " is undefined at " + name + " = " + format_number(t)};
  }
  DefiniteIntegralResult r;
  r.value = (*Fb - *Fa) * (a < b ? 1.0 : -1.0);
  r.error_estimate = 16 * std::numeric_limits<double>::epsilon() * (std::fabs(*Fa) + std::fabs(*Fb));
  r.method = IntegralMethod::Symbolic;
  r.converged = true;
  r.antiderivative = F;
  return {r, {}};
}

void check_definite(const Law& f, double a, double b) {
  if (!f.valid() || f.dimension() != 1) throw Error(Errc::InvalidArgument, "definite_integral: expects a scalar law");
  if (std::isnan(a) || std::isnan(b))
    throw Error(Errc::InvalidArgument,
                "definite_integral: bounds must be numbers, got [" + format_number(a) + ", " + format_number(b) + "]");
}

}  // namespace

std::optional<DefiniteIntegralResult> symbolic_definite_integral(const Law& f, std::string_view parameter, double a,
                                                                 double b) {
  check_definite(f, a, b);
  if (!std::isfinite(a) || !std::isfinite(b))
    throw Error(Errc::InvalidArgument,
                "definite_integral: bounds must be finite, got [" + format_number(a) + ", " + format_number(b) + "]");
  std::optional<Law> F = antiderivative(f, parameter);
  if (!F.has_value() || a == b) return std::nullopt;
  return closed_form(f, *F, parameter, a, b).result;
}

DefiniteIntegralResult definite_integral(const Law& f, std::string_view parameter, double a, double b,
                                         const IntegrationOptions& options) {
  options.validate();
  check_definite(f, a, b);
  DefiniteIntegralResult r;
  r.method = IntegralMethod::Numeric;
  if (a == b) {
    r.converged = true;
    r.numeric_reason = "an empty interval";
    return r;
  }
  if (std::isfinite(a) && std::isfinite(b)) {
    const AntiderivativeReport ad = antiderivative_report(f, parameter);
    if (ad.antiderivative) {
      ClosedForm cf = closed_form(f, *ad.antiderivative, parameter, a, b);
      if (cf.result) return *cf.result;
      r.numeric_reason = std::move(cf.reason);
    } else {
      r.numeric_reason = "no closed-form antiderivative of " + short_print(ad.blocking_term);
    }
  } else {
    r.numeric_reason = "an infinite bound";
  }
  IntegrationResult n = integrate(f, parameter, a, b, options);
  r.value = n.value;
  r.error_estimate = n.error_estimate;
  r.converged = n.converged;
  r.divergent = n.divergent;
  r.singular_points = std::move(n.singular_points);
  return r;
}

}  // namespace hula::law
