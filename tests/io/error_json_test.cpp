// SPDX-License-Identifier: MIT
// error_to_json: the stable shape {"error": {"code", "message", "where"}} with
// only the present ErrorWhere members.
#include "hula/io/error_json.hpp"

#include <gtest/gtest.h>

namespace hula::io {
namespace {

// checks: code name, message without prefix, and only the set where-members.
TEST(ErrorJson, ShapeAndPresentMembersOnly) {
  const Error e(Errc::InvalidKnots, "knots[3] = 0.3 is less than knots[2] = 0.7", {.field = "knots", .index = 3});
  const auto j = error_to_json(e);
  EXPECT_EQ(j["error"]["code"], "InvalidKnots");
  EXPECT_EQ(j["error"]["message"], "knots[3] = 0.3 is less than knots[2] = 0.7");
  EXPECT_EQ(j["error"]["where"], (nlohmann::ordered_json{{"field", "knots"}, {"index", 3}}));
  EXPECT_EQ(j.size(), 1u);
}

// checks: line/column/component appear when set; an empty where is {}.
TEST(ErrorJson, LineColumnAndEmptyWhere) {
  const auto j = error_to_json(Error(Errc::ParseError, "bad", {.line = 3, .column = 4}));
  EXPECT_EQ(j["error"]["where"], (nlohmann::ordered_json{{"line", 3}, {"column", 4}}));
  const auto k = error_to_json(Error(Errc::IoError, "x"));
  EXPECT_TRUE(k["error"]["where"].is_object());
  EXPECT_TRUE(k["error"]["where"].empty());
}

}  // namespace
}  // namespace hula::io
