// SPDX-License-Identifier: MIT
// The sum-of-monomials normal form of simplify.hpp. A Sum maps a monomial (a
// sorted list of (atom node, exponent)) to its coefficient; an atom is a
// simplified node that is not + − × ÷ or a power. Products distribute, integer
// powers of sums expand (bounded), and a quotient by a single monomial inverts
// its exponents; anything larger than the bounds stays an atom.
#include "hula/law/simplify.hpp"

#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/law/detail/graph.hpp"

namespace hula::law {

void SimplifyOptions::validate() const {
  if (max_terms < 1 || max_terms > 100'000)
    throw Error(Errc::InvalidOption, "max_terms = " + std::to_string(max_terms) + " is outside [1, 100000]",
                ErrorWhere{.field = "max_terms"});
  if (max_expand_power < 0 || max_expand_power > 64)
    throw Error(Errc::InvalidOption, "max_expand_power = " + std::to_string(max_expand_power) + " is outside [0, 64]",
                ErrorWhere{.field = "max_expand_power"});
}

namespace {

using AtomPower = std::pair<NodeId, double>;  // (atom, non-zero exponent)
using Monomial = std::vector<AtomPower>;      // sorted by atom
using Sum = std::map<Monomial, double>;       // monomial → non-zero coefficient

constexpr double kEps = std::numeric_limits<double>::epsilon();

bool is_integer(double x) { return x == std::floor(x); }

// a + b with a coefficient that cancels to rounding size (|a + b| ≤ 4 ε max(|a|, |b|)) read as 0.
void add_term(Sum& s, const Monomial& m, double c) {
  if (c == 0.0) return;
  auto [it, inserted] = s.emplace(m, c);
  if (inserted) return;
  const double r = it->second + c;
  if (std::fabs(r) <= 4.0 * kEps * std::max(std::fabs(it->second), std::fabs(c)))
    s.erase(it);
  else
    it->second = r;
}

Monomial multiply_monomials(const Monomial& a, const Monomial& b) {
  Monomial r;
  r.reserve(a.size() + b.size());
  std::size_t i = 0, j = 0;
  while (i < a.size() || j < b.size()) {
    if (j == b.size() || (i < a.size() && a[i].first < b[j].first)) {
      r.push_back(a[i++]);
    } else if (i == a.size() || b[j].first < a[i].first) {
      r.push_back(b[j++]);
    } else {
      const double e = a[i].second + b[j].second;
      if (e != 0.0) r.emplace_back(a[i].first, e);
      ++i;
      ++j;
    }
  }
  return r;
}

std::optional<double> constant_of(const Sum& s) {
  if (s.empty()) return 0.0;
  if (s.size() == 1 && s.begin()->first.empty()) return s.begin()->second;
  return std::nullopt;
}

class Simplifier {
 public:
  Simplifier(Context ctx, const SimplifyOptions& options) : ctx_(std::move(ctx)), o_(options) {}

  // The simplified law of any dimension.
  Law simplify(const Law& e) {
    if (auto it = laws_.find(e.id()); it != laws_.end()) return it->second;
    Law out;
    if (e.dimension() == 1) {
      out = to_law(nf(e));
    } else {
      out = rebuild_simplified(e);
    }
    laws_.emplace(e.id(), out);
    return out;
  }

 private:
  // The node rebuilt on simplified arguments (through the value-preserving builders).
  Law rebuild_simplified(const Law& e) {
    const Node n = e.node();  // a copy: building may reallocate the node array
    if (n.arity == 0) return e;
    std::array<Law, 3> args;
    for (std::size_t i = 0; i < n.arity; ++i) args[i] = simplify(e.arg(i));
    return detail::rebuild(e, std::span<const Law>(args.data(), n.arity));
  }

  Sum atom(const Law& a, double exponent = 1.0) {
    if (a.is_constant()) {
      const double v = std::pow(a.node().value, exponent);
      Sum s;
      if (std::isfinite(v)) {
        add_term(s, {}, v);
        return s;
      }
    }
    atoms_.emplace(a.id(), a);
    Sum s;
    s.emplace(Monomial{{a.id(), exponent}}, 1.0);
    return s;
  }

  bool too_big(std::size_t terms) const { return terms > o_.max_terms; }

  Sum add(const Sum& a, const Sum& b, double sign) {
    Sum r = a;
    for (const auto& [m, c] : b) add_term(r, m, sign * c);
    return r;
  }

  std::optional<Sum> multiply(const Sum& a, const Sum& b) {
    if (too_big(a.size() * b.size())) return std::nullopt;
    Sum r;
    for (const auto& [ma, ca] : a)
      for (const auto& [mb, cb] : b) {
        const double c = ca * cb;
        if (!std::isfinite(c)) return std::nullopt;
        add_term(r, multiply_monomials(ma, mb), c);
      }
    return r;
  }

  // s^k for an integer k ≥ 0 by repeated multiplication, or nullopt past the bounds.
  std::optional<Sum> power(const Sum& s, int k) {
    Sum r;
    r.emplace(Monomial{}, 1.0);
    for (int i = 0; i < k; ++i) {
      std::optional<Sum> next = multiply(r, s);
      if (!next) return std::nullopt;
      r = std::move(*next);
    }
    return r;
  }

  // One term c·m raised to a constant exponent k, when that cannot change a value: any integer k
  // (exponents multiply, c^k finite), or a non-integer k on c > 0 times one atom whose exponent is
  // odd or already fractional ((x³)^(1/3) = x where defined; (x²)^(1/2) = |x| is left alone).
  std::optional<Sum> monomial_power(double c, const Monomial& m, double k) {
    const bool integer = is_integer(k);
    if (!integer) {
      if (!(c > 0.0) || m.size() != 1) return std::nullopt;
      const double e = m.front().second;
      if (is_integer(e) && std::fmod(std::fabs(e), 2.0) == 0.0) return std::nullopt;
    }
    const double ck = std::pow(c, k);
    if (!std::isfinite(ck) || ck == 0.0) return std::nullopt;
    Monomial r;
    for (const auto& [x, e] : m) r.emplace_back(x, e * k);
    Sum s;
    s.emplace(std::move(r), ck);
    return s;
  }

  Sum nf(const Law& e) {
    if (auto it = sums_.find(e.id()); it != sums_.end()) return it->second;
    Sum s = normalise(nf_uncached(e));
    sums_.emplace(e.id(), s);
    return s;
  }

  // A sum S to the power k as an atom, scaled so that its first term has coefficient ±1:
  // S^k = |c|^k (S/|c|)^k, so equal sums up to a factor (4 + 8t and 1 + 2t) share one atom.
  Sum sum_power(const Sum& sum, double k) {
    if (sum.size() == 1) {
      const auto& [m, c] = *sum.begin();
      if (std::optional<Sum> s = monomial_power(c, m, k)) return *s;
    }
    const double q = std::fabs(sum.begin()->second);
    const double qk = std::pow(q, k);
    if (!(std::isfinite(qk) && qk > 0.0)) return atom(to_law(sum), k);
    Sum scaled;
    for (const auto& [m, c] : sum) scaled.emplace(m, c / q);
    const Law a = to_law(scaled);
    sum_atoms_.emplace(a.id(), scaled);
    Sum s = atom(a, k);
    for (auto& [m, c] : s) c *= qk;
    return s;
  }

  // The rules that need several factors of one term (file comment of simplify.hpp):
  //  sign(X)^a |X|^b (b a negative integer) = X^b sign(X)^((a + b) mod 2), defined where the term is;
  //  sin(X)^k = sin(X)^(k mod 2) (1 − cos(X)²)^(k div 2) when trig_identities is on;
  //  the sums with negative integer exponents multiplied out into one denominator.
  Sum normalise(const Sum& s) {
    Sum out;
    for (const auto& [m, c] : s) {
      const Sum t = normalise_term(m, c);
      for (const auto& [m2, c2] : t) add_term(out, m2, c2);
    }
    return out;
  }

  Sum normalise_term(const Monomial& m, double c) {
    Monomial rest;
    Sum factor;  // what the removed factors become
    factor.emplace(Monomial{}, c);
    auto times = [&](const Sum& x) {
      if (std::optional<Sum> r = multiply(factor, x)) {
        factor = std::move(*r);
        return true;
      }
      return false;
    };
    std::vector<bool> used(m.size(), false);
    Sum denominator;  // product of the sums with negative integer exponents, expanded
    denominator.emplace(Monomial{}, 1.0);
    bool has_denominator = false;
    for (std::size_t i = 0; i < m.size(); ++i) {
      if (used[i]) continue;
      const auto& [x, e] = m[i];
      const Law& a = atoms_.at(x);
      if (a.op() == Op::Abs && e < 0.0 && is_integer(e)) {
        for (std::size_t j = 0; j < m.size(); ++j) {
          const Law& b = atoms_.at(m[j].first);
          if (j == i || used[j] || b.op() != Op::Sign || !(b.arg(0) == a.arg(0)) || !is_integer(m[j].second)) continue;
          const long parity = ((static_cast<long>(m[j].second) + static_cast<long>(e)) % 2 + 2) % 2;
          Sum x_power = sum_power(nf(a.arg(0)), e);
          std::optional<Sum> with_sign = parity == 1 ? multiply(x_power, atom(b)) : std::optional<Sum>(x_power);
          if (with_sign && times(*with_sign)) used[i] = used[j] = true;
          break;
        }
        if (used[i]) continue;
      }
      if (o_.trig_identities && a.op() == Op::Sin && is_integer(e) && e >= 2.0) {
        const Law co = cos(a.arg(0));
        Sum one_minus;  // 1 − cos²
        one_minus.emplace(Monomial{}, 1.0);
        atoms_.emplace(co.id(), co);
        add_term(one_minus, Monomial{{co.id(), 2.0}}, -1.0);
        std::optional<Sum> p = power(one_minus, static_cast<int>(e) / 2);
        if (p && static_cast<long>(e) % 2 == 1) p = multiply(*p, atom(a));
        if (p && times(*p)) {
          used[i] = true;
          continue;
        }
      }
      if (e < 0.0 && is_integer(e) && e >= -o_.max_expand_power) {
        if (auto it = sum_atoms_.find(x); it != sum_atoms_.end()) {
          if (std::optional<Sum> p = power(it->second, static_cast<int>(-e)))
            if (std::optional<Sum> d = multiply(denominator, *p)) {
              denominator = std::move(*d);
              has_denominator = true;
              used[i] = true;
              continue;
            }
        }
      }
    }
    for (std::size_t i = 0; i < m.size(); ++i)
      if (!used[i]) rest.push_back(m[i]);
    Sum term;
    term.emplace(std::move(rest), 1.0);
    std::optional<Sum> product = multiply(term, factor);
    if (!product) {
      Sum unchanged;
      unchanged.emplace(m, c);
      return unchanged;
    }
    Sum out = std::move(*product);
    if (has_denominator) {
      if (std::optional<Sum> d = multiply(out, sum_power(denominator, -1.0))) out = std::move(*d);
    }
    return out;
  }

  Sum nf_uncached(const Law& e) {
    const Node n = e.node();
    switch (n.op) {
      case Op::Constant: {
        Sum s;
        add_term(s, {}, n.value);
        return s;
      }
      case Op::Parameter:
        return atom(e);
      case Op::Neg: {
        Sum s = nf(e.arg(0));
        for (auto& [m, c] : s) c = -c;
        return s;
      }
      case Op::Add:
      case Op::Sub: {
        if (n.dimension != 1) break;
        Sum s = add(nf(e.arg(0)), nf(e.arg(1)), n.op == Op::Add ? 1.0 : -1.0);
        if (too_big(s.size())) return atom(rebuild_simplified(e));
        return s;
      }
      case Op::Mul: {
        if (n.dimension != 1) break;
        if (std::optional<Sum> s = multiply(nf(e.arg(0)), nf(e.arg(1)))) return *s;
        return atom(rebuild_simplified(e));
      }
      case Op::Div: {
        if (n.dimension != 1) break;
        const Sum num = nf(e.arg(0));
        const Sum den = nf(e.arg(1));
        if (den.empty()) return atom(rebuild_simplified(e));  // division by zero stays visible
        if (den.size() == 1) {
          // Division by one term c·m: multiply by (1/c)·m^(−1).
          const auto& [m, c] = *den.begin();
          Monomial inv;
          for (const auto& [x, k] : m) inv.emplace_back(x, -k);
          Sum d;
          d.emplace(std::move(inv), 1.0 / c);
          if (std::optional<Sum> s = multiply(num, d)) return *s;
          return atom(rebuild_simplified(e));
        }
        // A numerator proportional to the denominator: the constant ratio.
        if (num.size() == den.size()) {
          double ratio = 0.0;
          bool proportional = true;
          for (auto a = num.begin(), b = den.begin(); a != num.end() && proportional; ++a, ++b) {
            if (a->first != b->first) {
              proportional = false;
              break;
            }
            const double r = a->second / b->second;
            if (a == num.begin())
              ratio = r;
            else
              proportional = std::fabs(r - ratio) <= 8.0 * kEps * std::fabs(ratio);
          }
          if (proportional) {
            Sum s;
            add_term(s, {}, ratio);
            return s;
          }
        }
        // Otherwise the denominator, in normal form, is an atom with exponent −1.
        if (std::optional<Sum> s = multiply(num, sum_power(den, -1.0))) return *s;
        return atom(rebuild_simplified(e));
      }
      case Op::Pow:
      case Op::Sqrt: {
        const Sum base = nf(e.arg(0));
        const Sum expo = n.op == Op::Sqrt ? Sum{{Monomial{}, 0.5}} : nf(e.arg(1));
        const std::optional<double> k = constant_of(expo);
        if (!k || base.empty()) return atom(rebuild_simplified(e));
        if (*k == 0.0) return atom(rebuild_simplified(e));  // 0^0 and friends: left to the builder
        if (base.size() == 1) {
          const auto& [m, c] = *base.begin();
          if (std::optional<Sum> s = monomial_power(c, m, *k)) return *s;
        } else if (is_integer(*k) && *k > 0.0 && *k <= o_.max_expand_power) {
          if (std::optional<Sum> s = power(base, static_cast<int>(*k))) return *s;
        }
        // A sum to a power (negative, fractional or too high): the sum is the atom, so that
        // (1 + t²)^(−2) keeps its base as one factor.
        if (is_integer(*k) || base.size() > 1) return sum_power(base, *k);
        return atom(rebuild_simplified(e));
      }
      default:
        break;
    }
    return atom(rebuild_simplified(e));
  }

  Law factor_law(NodeId x, double e) {
    const Law& a = atoms_.at(x);
    if (e == 1.0) return a;
    if (e == 0.5) return sqrt(a);
    return pow(a, e);
  }

  Law monomial_law(const Monomial& m) {
    Law num = ctx_.constant(1.0);
    Law den = ctx_.constant(1.0);
    for (const auto& [x, e] : m) {
      if (e > 0.0)
        num = num * factor_law(x, e);
      else
        den = den * factor_law(x, -e);
    }
    return den.is_constant() ? num : num / den;
  }

  Law to_law(const Sum& s) {
    if (s.empty()) return ctx_.constant(0.0);
    Law out;
    bool first = true;
    for (const auto& [m, c] : s) {
      const Law mono = monomial_law(m);
      const double a = std::fabs(c);
      const Law term = m.empty() ? ctx_.constant(a) : (a == 1.0 ? mono : ctx_.constant(a) * mono);
      if (first) {
        out = c < 0.0 ? -term : term;
        first = false;
      } else {
        out = c < 0.0 ? out - term : out + term;
      }
    }
    return out;
  }

  Context ctx_;
  SimplifyOptions o_;
  std::unordered_map<NodeId, Law> atoms_;
  std::unordered_map<NodeId, Sum> sum_atoms_;  // atoms made from a sum (sum_power): the sum
  std::unordered_map<NodeId, Sum> sums_;
  std::unordered_map<NodeId, Law> laws_;
};

}  // namespace

Law simplify(const Law& f, const SimplifyOptions& options) {
  options.validate();
  if (!f.valid()) throw Error(Errc::InvalidArgument, "simplify: empty law");
  Simplifier s(f.context(), options);
  return s.simplify(f);
}

}  // namespace hula::law
