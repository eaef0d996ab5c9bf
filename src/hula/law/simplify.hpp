// SPDX-License-Identifier: MIT
// Algebraic simplification of laws: a normal form as a sum of terms
// c · x1^e1 · … · xk^ek over "atoms" x (parameters and every node that is not
// + − × ÷ or a power: sin(u), exp(u), log(u), a denominator that is a sum, …,
// each with its own arguments simplified first). Like terms are collected,
// products are expanded, integer powers of sums expanded up to a bound, and
// powers of one atom merged (x^a · x^b = x^(a+b), also for the fractional
// exponents of sqrt and pow). Two laws with the same normal form simplify to
// the same node, so simplify(f − g).is_zero() proves f = g for the identities
// of commutative rings with division by monomials — the check behind the
// antiderivative tests (d/dt F − f simplifies to 0) and the re-expansion of an
// integrand about a singular end (t = t0 + u makes t − t0 exactly u).
//
// A sum raised to a power is an atom scaled so that its first term has
// coefficient ±1 (4 + 8t and 1 + 2t share one atom); the sums with negative
// integer exponents of a term are multiplied out into one denominator (so
// 1/(1 + t²)² and 1/(1 + 2t² + t⁴) agree); sign(x)·|x|^(−1) is 1/x where it
// is defined (the derivative of log|x|); with SimplifyOptions::trig_identities
// sin² is written 1 − cos² (sin² + cos² = 1).
//
// What it does not know: polynomial division and factorisation (t²/(1 + t)
// is not 1 − t + 1/(1 + t)), exponential identities (e^a e^b = e^(a+b)) and
// trigonometric ones beyond sin² + cos² = 1. Powers with non-integer
// exponents are distributed only where that cannot change a value
// ((x²)^0.5 = |x| stays as it is).
#pragma once

#include <cstddef>

#include "hula/law/expr.hpp"

namespace hula::law {

/// Options of simplify().
struct SimplifyOptions {
  /// Largest number of terms of an intermediate sum; a product or power whose expansion would
  /// exceed it stays unexpanded (an atom). Default 256; valid 1 … 100 000.
  std::size_t max_terms = 256;
  /// Largest integer exponent to which a sum is expanded ((a + b)^n, 0 ≤ n ≤ this). Default 8;
  /// valid 0 … 64.
  int max_expand_power = 8;
  /// Also rewrite sin(x)^k (k ≥ 2) with cos(x)² = 1 − sin(x)², so that polynomials in sin x and cos x
  /// have one normal form. Exact as an identity but not as a computation: 1 − cos² loses all relative
  /// accuracy where sin x is small, so it is off by default (for checking identities, not for
  /// evaluating). Default false.
  bool trig_identities = false;
  /// @throws hula::Error(Errc::InvalidOption) naming the field
  void validate() const;
};

/// The normal form of f (see the file comment), built in f's context.
///
/// Values: equal to f wherever f is defined, up to rounding of the collected coefficients (a
/// coefficient that cancels to within 4 ε of the terms it came from is dropped as 0). The result
/// may be defined where f is not: cancellations such as x/x = 1 and x − x = 0 remove the
/// points where x is undefined or zero (removable singularities).
///
/// Example:
/// ```
/// law::Context ctx;
/// const law::Law f = law::parse("exp(t) + (t - 1)*exp(t) - t*exp(t)", ctx);
/// law::simplify(f).is_zero();   // true
/// ```
/// Vector laws are simplified component-wise through their builders (vec, dot, …).
/// Complexity: O(size of f × terms²) in the worst case, bounded by max_terms.
/// @throws hula::Error(Errc::InvalidArgument) if f is empty
/// @throws hula::Error(Errc::InvalidOption) from options.validate()
[[nodiscard]] Law simplify(const Law& f, const SimplifyOptions& options = {});

}  // namespace hula::law
