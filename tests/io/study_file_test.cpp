// SPDX-License-Identifier: MIT
#include "hula/io/study_file.hpp"

#include <gtest/gtest.h>

#include "hula/testing/expect_error.hpp"

namespace {

using hula::Errc;
using hula::io::parse_study_json;

TEST(StudyFile, EnvelopeIsReadWithDefaults) {
  const auto doc = parse_study_json(R"({"format": "hula-study", "version": 1, "study": "fair-knots"})", "fair-knots");
  EXPECT_EQ(doc.header.kind, "fair-knots");
  EXPECT_EQ(doc.header.seed, 1u);
  EXPECT_EQ(doc.header.threads, 1u);
  const auto seeded = parse_study_json(
      R"({"format": "hula-study", "version": 1, "study": "hermite", "seed": 42, "threads": 0})", "hermite");
  EXPECT_EQ(seeded.header.seed, 42u);
  EXPECT_EQ(seeded.header.threads, 0u);
  const auto back = hula::io::header_to_json(seeded.header);
  EXPECT_EQ(back["seed"], 42);
  EXPECT_EQ(back["study"], "hermite");
}

TEST(StudyFile, BadEnvelopesNameTheMember) {
  HULA_EXPECT_ERROR(parse_study_json(R"({"version": 1, "study": "x"})", "x"), Errc::ParseError, "format");
  HULA_EXPECT_ERROR(parse_study_json(R"({"format": "hula-curve", "version": 1, "study": "x"})", "x"), Errc::ParseError,
                    "hula-study");
  HULA_EXPECT_ERROR(parse_study_json(R"({"format": "hula-study", "version": 2, "study": "x"})", "x"), Errc::ParseError,
                    "version");
  HULA_EXPECT_ERROR(parse_study_json(R"({"format": "hula-study", "version": 1, "study": "hermite"})", "fair-knots"),
                    Errc::ParseError, "this command runs \"fair-knots\"");
  HULA_EXPECT_ERROR(parse_study_json(R"({"format": "hula-study", "version": 1, "study": "x", "seed": -1})", "x"),
                    Errc::ParseError, "seed");
  HULA_EXPECT_ERROR(parse_study_json("[1, 2]", "x"), Errc::ParseError, "object");
  HULA_EXPECT_ERROR(parse_study_json("{\"format\": ", "x"), Errc::ParseError, "line 1");
}

TEST(StudyFile, UnknownMembersAreRefused) {
  const auto doc = parse_study_json(R"({"format": "hula-study", "version": 1, "study": "x", "pointz": []})", "x");
  HULA_EXPECT_ERROR(hula::io::check_members(doc.body, {"points", "target"}), Errc::ParseError,
                    "pointz: unknown member");
  EXPECT_NO_THROW(hula::io::check_members(
      parse_study_json(R"({"format": "hula-study", "version": 1, "study": "x", "points": []})", "x").body,
      {"points", "target"}));
}

}  // namespace
