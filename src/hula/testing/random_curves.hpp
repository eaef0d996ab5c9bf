// SPDX-License-Identifier: MIT
// Seeded random NURBS curves for property and oracle tests: degree 1–max,
// rational or not, with repeated interior knots, on a random domain.
#pragma once

#include <cstdint>

#include "hula/core/rng.hpp"
#include "hula/nurbs/nurbs_curve.hpp"

namespace hula::testing {

/// Options of random_curve.
struct RandomCurveOptions {
  int min_degree = 1;
  int max_degree = 5;
  std::size_t min_points = 0;  ///< 0: degree + 1
  std::size_t max_points = 12;
  bool rational = false;
  bool repeated_knots = true;  ///< allow interior multiplicities up to the degree
  bool planar = false;
  double scale = 10.0;  ///< control point coordinates in [-scale, scale]
};

/// A valid random curve drawn from rng.
[[nodiscard]] nurbs::NurbsCurve random_curve(Rng& rng, const RandomCurveOptions& options = {});

}  // namespace hula::testing
