// SPDX-License-Identifier: MIT
// Issue 24, item 15: a non-finite literal (1e999) in a study's points was
// refused as NonFiniteInput with no member and no line/column (`where` empty),
// unlike every other bad study value. The JSON reader now locates it.
#include "cli.hpp"

namespace hula::regress {
namespace {

// checks: the error names spline.points[2][1], the literal, and its line and column (counted by hand in the
// text below: line 3, column 71), with where.field/index/component set.
TEST(Issue24StudyNonFinite, OverflowingLiteralNamesMemberLineAndColumn) {
  TempDir dir;
  write(dir / "study.json",
        "{\"format\": \"hula-study\", \"version\": 1, \"study\": \"hermite\",\n"
        " \"rebuild\": \"quintic\",\n"
        " \"spline\": {\"kind\": \"interpolated\", \"points\": [[0, 0], [40, 25], [80, 1e999], [120, 0]]}}\n");
  const ProcessResult r = hula({"hermite", (dir / "study.json").string()});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  const json e = error_of(r)["error"];
  EXPECT_EQ(e["code"], "NonFiniteInput");
  const std::string m = e.value("message", std::string());
  EXPECT_NE(m.find("spline.points[2][1] = 1e999"), std::string::npos) << m;
  EXPECT_NE(m.find("line 3, column 71"), std::string::npos) << m;
  EXPECT_EQ(e["where"]["field"], "spline");
  EXPECT_EQ(e["where"]["index"], 2);
  EXPECT_EQ(e["where"]["component"], 1);
  EXPECT_EQ(e["where"]["line"], 3);
  EXPECT_EQ(e["where"]["column"], 71);
}

}  // namespace
}  // namespace hula::regress
