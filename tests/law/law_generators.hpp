// SPDX-License-Identifier: MIT
// RapidCheck generators of random laws for the law property tests: a random
// expression tree is drawn as a recipe (so RapidCheck can print and shrink it)
// and built either through the simplifying builders or evaluated directly with
// the C library as an independent reference.
#pragma once

#include <rapidcheck.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "hula/law/expr.hpp"

namespace hula::law::test {

/// One node of a random tree in prefix order: kind and a constant.
struct Step {
  int kind = 0;
  double value = 0.0;
};

/// Kinds: 0 param t, 1 constant, 2..(2+kBinary) binary, then unary.
inline constexpr int kLeafKinds = 2;
inline constexpr int kBinaryKinds = 8;  // + - * / min max pow-int piecewise(<)
inline constexpr int kUnaryKinds = 11;  // neg sin cos exp(·/4) sqrt log abs atan tanh sign tan

/// Random recipe of at most `max_nodes` steps (smooth_only: only everywhere-differentiable ops).
inline rc::Gen<std::vector<Step>> gen_recipe(int max_nodes, bool smooth_only) {
  return rc::gen::exec([max_nodes, smooth_only] {
    std::vector<Step> steps;
    int open = 1;
    while (open > 0) {
      const bool leaf_only = static_cast<int>(steps.size()) + open >= max_nodes;
      int kind =
          leaf_only ? *rc::gen::inRange(0, kLeafKinds) : *rc::gen::inRange(0, kLeafKinds + kBinaryKinds + kUnaryKinds);
      if (smooth_only) {
        // only + − × and smooth unary functions
        static const int smooth[] = {0, 1, 2, 3, 4, 10, 11, 12, 13, 17, 18};
        kind = leaf_only ? *rc::gen::inRange(0, 2) : smooth[*rc::gen::inRange(0, 11)];
      }
      Step s{kind, 0.0};
      if (kind == 1) {
        static const double picks[] = {0.0, 1.0, -1.0, 2.0, 0.5, 3.0};
        const int which = *rc::gen::inRange(0, 8);
        s.value = which < 6 ? picks[which] : *rc::gen::inRange(-300, 300) / 100.0;
      }
      if (kind == 8) s.value = *rc::gen::inRange(-2, 4);  // integer power
      steps.push_back(s);
      --open;
      if (kind >= kLeafKinds && kind < kLeafKinds + kBinaryKinds) open += 2;
      if (kind >= kLeafKinds + kBinaryKinds) open += 1;
    }
    return steps;
  });
}

/// Builds the recipe through the law builders.
inline Law build(const std::vector<Step>& steps, std::size_t& i, const Context& ctx) {
  const Step s = steps[i++];
  const Law t = ctx.parameter("t");
  switch (s.kind) {
    case 0:
      return t;
    case 1:
      return ctx.constant(s.value);
    default:
      break;
  }
  if (s.kind < kLeafKinds + kBinaryKinds) {
    const Law a = build(steps, i, ctx);
    const Law b = build(steps, i, ctx);
    switch (s.kind) {
      case 2:
        return a + b;
      case 3:
        return a - b;
      case 4:
        return a * b;
      case 5:
        return a / b;
      case 6:
        return min(a, b);
      case 7:
        return max(a, b);
      case 8:
        return pow(a, ctx.constant(s.value)) + b;
      default:
        return piecewise(less(a, b), a, b * 2.0);
    }
  }
  const Law a = build(steps, i, ctx);
  switch (s.kind - kLeafKinds - kBinaryKinds) {
    case 0:
      return -a;
    case 1:
      return sin(a);
    case 2:
      return cos(a);
    case 3:
      return exp(a / 4.0);
    case 4:
      return sqrt(a);
    case 5:
      return log(a);
    case 6:
      return abs(a);
    case 7:
      return atan(a);
    case 8:
      return tanh(a);
    case 9:
      return sign(a);
    default:
      return tan(a);
  }
}

inline Law build(const std::vector<Step>& steps, const Context& ctx) {
  std::size_t i = 0;
  return build(steps, i, ctx);
}

/// Independent reference: evaluates the recipe with the C library (NaN where undefined),
/// without any simplification.
inline double reference(const std::vector<Step>& steps, std::size_t& i, double t) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const Step s = steps[i++];
  if (s.kind == 0) return t;
  if (s.kind == 1) return s.value;
  if (s.kind < kLeafKinds + kBinaryKinds) {
    const double a = reference(steps, i, t);
    const double b = reference(steps, i, t);
    if (std::isnan(a) || std::isnan(b)) return nan;
    switch (s.kind) {
      case 2:
        return a + b;
      case 3:
        return a - b;
      case 4:
        return a * b;
      case 5:
        return b == 0 ? nan : a / b;
      case 6:
        return std::fmin(a, b);
      case 7:
        return std::fmax(a, b);
      case 8: {
        const int k = static_cast<int>(s.value);
        if (a == 0 && k < 0) return nan;
        return std::pow(a, k) + b;
      }
      default:
        return a < b ? a : b * 2.0;
    }
  }
  const double a = reference(steps, i, t);
  if (std::isnan(a)) return nan;
  switch (s.kind - kLeafKinds - kBinaryKinds) {
    case 0:
      return -a;
    case 1:
      return std::sin(a);
    case 2:
      return std::cos(a);
    case 3:
      return std::exp(a / 4.0);
    case 4:
      return a < 0 ? nan : std::sqrt(a);
    case 5:
      return a <= 0 ? nan : std::log(a);
    case 6:
      return std::fabs(a);
    case 7:
      return std::atan(a);
    case 8:
      return std::tanh(a);
    case 9:
      return a > 0 ? 1.0 : (a < 0 ? -1.0 : 0.0);
    default:
      return std::tan(a);
  }
}

inline double reference(const std::vector<Step>& steps, double t) {
  std::size_t i = 0;
  return reference(steps, i, t);
}

}  // namespace hula::law::test
