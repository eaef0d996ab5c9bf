// SPDX-License-Identifier: MIT
// Seeded random NURBS curves for property tests (STYLE.md: test-support code
// is a library), and the dense-sample deviation used by the "operation leaves
// the curve unchanged" invariants of refine, elevate and reparam.
#pragma once

#include <cstdint>

#include "hula/core/rng.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::testing {

/// Shape of a random curve.
struct RandomCurveSpec {
  /// Degree p in [1, kMaxDegree]. Default 3.
  int degree = 3;
  /// Rational (weights in [0.2, 5]) or not. Default false.
  bool rational = false;
  /// Clamped ends (multiplicity p + 1) or a general non-decreasing knot vector. Default true.
  bool clamped = true;
  /// Number of control points beyond the minimum p + 1. Default 4.
  int extra_points = 4;
};

/// A valid random curve drawn from `rng`: control points in [-10, 10]^3,
/// interior knots with random multiplicities ≤ p, domain of random position
/// and length in [0.1, 10].
[[nodiscard]] nurbs::NurbsCurve random_curve(Rng& rng, const RandomCurveSpec& spec);

/// Full circle of radius R about the origin in the XY plane, rotated by
/// `angle` radians, as four rational quadratic arcs (The NURBS Book ex. 7.2:
/// weights 1, √½, 1, …; knots 0, ¼, ½, ¾, 1 doubled). 2-D, domain [0, 1]:
/// the closed-form fixture (|C(t)| = R, κ = 1/R, length 2πR).
[[nodiscard]] nurbs::NurbsCurve rational_circle(double R, double angle = 0.0);

/// max |a(t) - b(t)| over `samples` + 1 equally spaced parameters of a's
/// domain (b is evaluated at the same parameters; its domain must contain them).
[[nodiscard]] double max_deviation(const nurbs::NurbsCurve& a, const nurbs::NurbsCurve& b, int samples = 1000);

/// Inside a RapidCheck property: a random curve of degree 1 … max_degree,
/// rational or not, clamped or not, drawn from a generated seed (so a failing
/// case is reproducible from the printed counterexample).
[[nodiscard]] nurbs::NurbsCurve arbitrary_curve(int max_degree = 5);

}  // namespace hula::testing
