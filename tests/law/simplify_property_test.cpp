// SPDX-License-Identifier: MIT
// law::simplify keeps every value of a random expression where it is defined,
// against the unsimplified C-library reference of law_generators.hpp.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "hula/law/simplify.hpp"
#include "hula/testing/fpe.hpp"
#include "law_generators.hpp"
#include "law_test_util.hpp"

namespace hula::law {
namespace {

// checks: simplification never changes a value where the original is defined: random expressions
// against the unsimplified C-library reference (the simplified law may be defined where the
// reference is not, e.g. x/x).
RC_GTEST_PROP(LawSimplifyProperty, PreservesValues, ()) {
  testing::FpeGuard guard;
  const auto recipe = *test::gen_recipe(24, false);
  Context ctx;
  const Law l = simplify(test::build(recipe, ctx));
  for (int k = 0; k < 5; ++k) {
    const double t = *rc::gen::inRange(-3000, 3000) / 1000.0;
    const double want = test::reference(recipe, t);
    if (std::isnan(want) || std::isinf(want) || std::fabs(want) > 1e100) continue;
    const double got = test::eval1(l, t);
    RC_ASSERT(!std::isnan(got));
    RC_ASSERT(std::fabs(got - want) <= 1e-9 * (1.0 + std::fabs(want)));
  }
}

}  // namespace
}  // namespace hula::law
