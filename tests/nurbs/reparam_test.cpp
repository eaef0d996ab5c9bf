// SPDX-License-Identifier: MIT
// Reparameterisation, reversal and split: documented errors. Same point set,
// chain rule and C' sign flip on random curves: reparam_property_test.cpp.
#include "hula/nurbs/reparam.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "hula/testing/curve_generators.hpp"
#include "hula/testing/expect_error.hpp"

namespace hula::nurbs {
namespace {

// checks: documented errors name the offending value.
TEST(Reparam, ErrorsNameTheInput) {
  const NurbsCurve c(2, {0, 0, 0, 1, 1, 1}, {{0, 0, 0}, {1, 1, 0}, {2, 0, 0}});
  HULA_EXPECT_ERROR(split(c, 0.0), Errc::OutOfDomain, "t = 0");
  HULA_EXPECT_ERROR(split(c, 1.0), Errc::OutOfDomain, "t = 1");
  HULA_EXPECT_ERROR(split(c, 7.5), Errc::OutOfDomain, "t = 7.5");
  HULA_EXPECT_ERROR(split(c, NAN), Errc::NonFiniteInput, "t = nan");
  HULA_EXPECT_ERROR(reparameterise(c, {2.0, 1.0}), Errc::InvalidArgument, "domain = [2, 1]");
  HULA_EXPECT_ERROR(reparameterise(c, {0.0, INFINITY}), Errc::InvalidArgument, "inf");
}

}  // namespace
}  // namespace hula::nurbs
