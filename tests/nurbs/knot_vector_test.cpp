// SPDX-License-Identifier: MIT
// KnotVector validation, span search and the ACIS form.
#include "hula/nurbs/knot_vector.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "hula/testing/expect_error.hpp"

namespace hula::nurbs {
namespace {

// checks: span search against the definition U[i] <= t < U[i+1] (Right) / U[i] < t <= U[i+1] (Left).
TEST(KnotVector, FindSpanMatchesDefinitionIncludingMultipleKnots) {
  const KnotVector kv({0, 0, 0, 0, 0.2, 0.5, 0.5, 0.8, 1, 1, 1, 1}, 3);
  EXPECT_EQ(kv.find_span(0.0), 3u);
  EXPECT_EQ(kv.find_span(0.1), 3u);
  EXPECT_EQ(kv.find_span(0.2), 4u);
  EXPECT_EQ(kv.find_span(0.2, Side::Left), 3u);
  EXPECT_EQ(kv.find_span(0.5), 6u);
  EXPECT_EQ(kv.find_span(0.5, Side::Left), 4u);
  EXPECT_EQ(kv.find_span(1.0), 7u);
  EXPECT_EQ(kv.find_span(1.0, Side::Left), 7u);
  EXPECT_EQ(kv.find_span(0.0, Side::Left), 3u);
  for (std::size_t hint = 0; hint < 12; ++hint) {
    for (double t : {0.0, 0.1, 0.2, 0.3, 0.5, 0.6, 0.8, 0.9, 1.0}) {
      EXPECT_EQ(kv.find_span(t, hint, Side::Right), kv.find_span(t, Side::Right)) << t << " " << hint;
      EXPECT_EQ(kv.find_span(t, hint, Side::Left), kv.find_span(t, Side::Left)) << t << " " << hint;
    }
  }
}

// checks: the ACIS n+p-1 form round-trips and the domain/multiplicities are as in eq. 28.
TEST(KnotVector, AcisFormRoundTrip) {
  const std::vector<double> acis = {0, 0, 0, 0.33, 0.66, 1, 1, 1};
  const KnotVector kv = KnotVector::from_acis(acis, 3);
  EXPECT_EQ(kv.size(), 10u);
  EXPECT_EQ(kv.control_point_count(), 6u);
  EXPECT_EQ(kv.to_acis(), acis);
  EXPECT_TRUE(kv.is_clamped());
  EXPECT_EQ(kv.multiplicity(0.0), 4);
  EXPECT_EQ(kv.multiplicity(0.33), 1);
  EXPECT_EQ(kv.breakpoints(), (std::vector<double>{0, 0.33, 0.66, 1}));
}

// checks: invalid knot vectors are refused with the index and value at fault.
TEST(KnotVector, RejectsBadKnotsAndNamesIndex) {
  HULA_EXPECT_ERROR(KnotVector({0, 0, 0, 0, 0.7, 0.4, 1, 1, 1, 1}, 3), Errc::InvalidKnots, "knots[5] = 0.4");
  HULA_EXPECT_ERROR(KnotVector({0, 0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1, 1, 1}, 3), Errc::InvalidKnots, "multiplicity 4");
  HULA_EXPECT_ERROR(KnotVector({0, 0, 0, 0, 0, 1, 1, 1, 1}, 3), Errc::InvalidKnots, "multiplicity 5");
  HULA_EXPECT_ERROR(KnotVector({0, 0, 1, 1}, 3), Errc::InvalidKnots, "needs at least 8");
  HULA_EXPECT_ERROR(KnotVector({0, 0, 0, 0, 1, 1, 1, 1}, 0), Errc::InvalidDegree, "degree = 0");
  HULA_EXPECT_ERROR(KnotVector({0, 0, 0, 0, INFINITY, 1, 1, 1, 1}, 3), Errc::NonFiniteInput, "knots[4] = inf");
  HULA_EXPECT_ERROR(KnotVector::from_acis(std::vector<double>{0, 0, 0, 0.5, 0.2, 1, 1, 1}, 3), Errc::InvalidKnots,
                    "knots[4] = 0.2");
  HULA_EXPECT_ERROR(KnotVector({1, 1, 1, 1, 1, 1, 1, 1}, 3), Errc::InvalidKnots, "empty");
}

// checks: reparameterisation maps the domain exactly and keeps knot ratios.
TEST(KnotVector, ReparameterisedMapsDomainExactly) {
  const KnotVector kv({-2, -2, 0, 1, 3, 3}, 1);
  const KnotVector r = kv.reparameterised({0.0, 1.0});
  EXPECT_EQ(r.domain().start, 0.0);
  EXPECT_EQ(r.domain().end, 1.0);
  EXPECT_DOUBLE_EQ(r[2], 0.4);
  EXPECT_DOUBLE_EQ(r[3], 0.6);
  HULA_EXPECT_ERROR(kv.reparameterised({1.0, 1.0}), Errc::InvalidArgument, "target domain");
}

// checks: uniform clamped knots are evenly spaced and refuse impossible requests by name.
TEST(KnotVector, UniformClamped) {
  const KnotVector kv = KnotVector::uniform_clamped(6, 3, {0.0, 3.0});
  EXPECT_EQ(kv.values().size(), 10u);
  EXPECT_DOUBLE_EQ(kv[4], 1.0);
  EXPECT_DOUBLE_EQ(kv[5], 2.0);
  EXPECT_TRUE(kv.is_clamped());
  HULA_EXPECT_ERROR(KnotVector::uniform_clamped(3, 3), Errc::InvalidDegree, "needs at least 4 control points");
  HULA_EXPECT_ERROR(KnotVector::uniform_clamped(5, 0), Errc::InvalidDegree, "degree = 0");
  HULA_EXPECT_ERROR(KnotVector::uniform_clamped(5, 2, {1.0, 1.0}), Errc::InvalidArgument, "domain [1, 1]");
}

}  // namespace
}  // namespace hula::nurbs
