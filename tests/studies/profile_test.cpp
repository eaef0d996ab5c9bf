// SPDX-License-Identifier: MIT
#include "hula/studies/profile.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <vector>

#include "hula/io/profile_file.hpp"
#include "hula/law/parser.hpp"
#include "hula/testing/expect_error.hpp"
#include "hula/testing/temp_dir.hpp"

namespace {

using hula::Errc;
using hula::io::profile_from_json;
using hula::studies::Profile;

const hula::io::json::JsonPath kTarget = hula::io::json::root_path("target");

TEST(Profile, LawIsEvaluatedInItsVariable) {
  hula::law::Context ctx;
  const auto parse = [&](const char* text) {
    hula::law::ParseOptions o;
    o.parameters = {"u", "s", "w"};
    return hula::law::parse(text, ctx, o);
  };
  const Profile p = Profile::from_law(parse("0.05 + 0.02*sin(pi*s)"), "s");
  EXPECT_NEAR(p(0.5), 0.07, 1e-15);
  std::vector<double> u = {0.0, 0.25, 1.0}, out(3);
  p.sample(u, out);
  EXPECT_NEAR(out[1], 0.05 + 0.02 * std::sin(M_PI / 4), 1e-15);
  HULA_EXPECT_ERROR(Profile::from_law(parse("vec(u, u)")), Errc::InvalidArgument, "scalar");
  HULA_EXPECT_ERROR(Profile::from_law(parse("u + w")), Errc::InvalidArgument, "w");
  const Profile pole = Profile::from_law(parse("1/(u - 0.5)"));
  HULA_EXPECT_ERROR(pole(0.5), Errc::OutOfDomain, "u = 0.5");
}

TEST(Profile, SamplesAreJoinedLinearly) {
  const std::vector<double> u = {0.0, 0.5, 1.0}, v = {1.0, 3.0, 2.0};
  const Profile p = Profile::from_samples(u, v);
  EXPECT_DOUBLE_EQ(p(0.0), 1.0);
  EXPECT_NEAR(p(0.25), 2.0, 1e-14);
  EXPECT_NEAR(p(0.5), 3.0, 1e-14);
  EXPECT_NEAR(p(0.9), 2.2, 1e-14);
  EXPECT_NEAR(p(1.0), 2.0, 1e-14);
}

TEST(Profile, BsplineFunctionMatchesItsBernsteinForm) {
  const std::vector<double> knots = {0, 0, 0, 1, 1, 1}, c = {1, 3, 2};
  const Profile p = Profile::from_bspline(2, knots, c);
  for (double u : {0.0, 0.1, 0.37, 0.5, 0.8, 1.0}) {
    const double expected = (1 - u) * (1 - u) + 6 * u * (1 - u) + 2 * u * u;
    EXPECT_NEAR(p(u), expected, 1e-14) << u;
  }
  const std::vector<double> short_knots = {0, 0, 1, 1};
  HULA_EXPECT_ERROR(Profile::from_bspline(2, short_knots, c), Errc::InvalidArgument, "needs 6 knots");
  const std::vector<double> narrow = {0, 0, 0, 0.5, 0.5, 0.5};
  HULA_EXPECT_ERROR(Profile::from_bspline(2, narrow, c), Errc::InvalidArgument, "cover [0, 1]");
}

TEST(Profile, BadSamplesNameTheSample) {
  const std::vector<double> u = {0.0, 0.6, 0.6, 1.0}, v = {1, 2, 3, 4};
  HULA_EXPECT_ERROR(Profile::from_samples(u, v), Errc::InvalidArgument, "samples[2]");
  const std::vector<double> u2 = {0.1, 1.0}, v2 = {1, 2};
  HULA_EXPECT_ERROR(Profile::from_samples(u2, v2), Errc::InvalidArgument, "must cover [0, 1]");
  const std::vector<double> u3 = {0.0, 1.0}, v3 = {1, NAN};
  HULA_EXPECT_ERROR(Profile::from_samples(u3, v3), Errc::NonFiniteInput, "samples[1]");
  const std::vector<double> one = {0.0};
  HULA_EXPECT_ERROR(Profile::from_samples(one, one), Errc::InvalidArgument, "at least 2");
}

TEST(Profile, JsonFormsAndTheirErrors) {
  hula::law::Context ctx;
  hula::testing::TempDir dir;
  const auto parse = [&](const char* text) {
    return profile_from_json(hula::io::json::Json::parse(text), kTarget, hula::io::relative_to(dir.path()), ctx);
  };
  EXPECT_NEAR(parse(R"({"law": "2*u"})")(0.25), 0.5, 1e-15);
  EXPECT_NEAR(parse(R"({"law": "2*t", "variable": "t"})")(0.25), 0.5, 1e-15);
  EXPECT_NEAR(parse(R"({"samples": [[0, 0], [1, 4]]})")(0.25), 1.0, 1e-15);
  EXPECT_NEAR(parse(R"({"bspline": {"degree": 1, "knots": [0, 0, 1, 1], "coefficients": [2, 4]}})")(0.5), 3.0, 1e-15);
  { std::ofstream(dir.path() / "k.csv") << "0,1\n0.5,2\n1,1\n"; }
  EXPECT_NEAR(parse(R"({"csv": "k.csv"})")(0.75), 1.5, 1e-14);
  { std::ofstream(dir.path() / "bad.csv") << "0,1\n0.5,nan\n1,1\n"; }
  HULA_EXPECT_ERROR(parse(R"({"csv": "bad.csv"})"), Errc::NonFiniteInput, "nan");
  HULA_EXPECT_ERROR(parse(R"({"csv": "missing.csv"})"), Errc::IoError, "missing.csv");
  HULA_EXPECT_ERROR(parse(R"({"law": "2*u +"})"), Errc::ParseError, "target.law");
  HULA_EXPECT_ERROR(parse(R"({"law": "2*u", "scale": 2})"), Errc::ParseError, "target.scale: unknown member");
  HULA_EXPECT_ERROR(parse(R"({"spline": []})"), Errc::ParseError, "one of");
  HULA_EXPECT_ERROR(parse(R"({"samples": [[0, 0, 1], [1, 4, 1]]})"), Errc::ParseError, "[u, value]");
}

}  // namespace
