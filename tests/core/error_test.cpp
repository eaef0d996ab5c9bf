// SPDX-License-Identifier: MIT
// hula::Error carries a stable code name, the message and the location.
#include "hula/core/error.hpp"

#include <gtest/gtest.h>

namespace hula {
namespace {

// checks: code names are the documented stable strings (docs/errors.md).
TEST(Error, StableCodeNames) {
  EXPECT_EQ(errc_name(Errc::InvalidArgument), "InvalidArgument");
  EXPECT_EQ(errc_name(Errc::NonFiniteInput), "NonFiniteInput");
  EXPECT_EQ(errc_name(Errc::TooFewPoints), "TooFewPoints");
  EXPECT_EQ(errc_name(Errc::CoincidentPoints), "CoincidentPoints");
  EXPECT_EQ(errc_name(Errc::InvalidKnots), "InvalidKnots");
  EXPECT_EQ(errc_name(Errc::InvalidDegree), "InvalidDegree");
  EXPECT_EQ(errc_name(Errc::InvalidWeight), "InvalidWeight");
  EXPECT_EQ(errc_name(Errc::OutOfDomain), "OutOfDomain");
  EXPECT_EQ(errc_name(Errc::InvalidOption), "InvalidOption");
  EXPECT_EQ(errc_name(Errc::ParseError), "ParseError");
  EXPECT_EQ(errc_name(Errc::IoError), "IoError");
  EXPECT_EQ(errc_name(Errc::NumericalFailure), "NumericalFailure");
  EXPECT_EQ(errc_name(Errc::ScaleOutOfRange), "ScaleOutOfRange");
}

// checks: what() is "Code: message" and where() keeps the machine-readable location.
TEST(Error, MessageAndWhere) {
  const Error e(Errc::InvalidKnots, "knots[7] = 0.4 is less than knots[6] = 0.5", {.field = "knots", .index = 7});
  EXPECT_STREQ(e.what(), "InvalidKnots: knots[7] = 0.4 is less than knots[6] = 0.5");
  EXPECT_EQ(e.message(), "knots[7] = 0.4 is less than knots[6] = 0.5");
  EXPECT_EQ(e.where().field, "knots");
  EXPECT_EQ(e.where().index, 7u);
  EXPECT_FALSE(e.where().line.has_value());
  EXPECT_EQ(format_number(0.1), "0.10000000000000001");
}

// checks: HULA_ASSERT throws InternalError (never aborts) when asserts are enabled.
TEST(Error, AssertThrowsInternalError) {
#if !defined(NDEBUG) || defined(HULA_ENABLE_ASSERTS)
  EXPECT_THROW(HULA_ASSERT(1 + 1 == 3, "arithmetic"), InternalError);
#else
  GTEST_SKIP() << "asserts compiled out in this configuration";
#endif
}

}  // namespace
}  // namespace hula
