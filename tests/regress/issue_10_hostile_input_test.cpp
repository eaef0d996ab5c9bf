// SPDX-License-Identifier: MIT
// Issue 10, item 11 "hardened against hostile input": a JSON file nested
// 65,000 deep (was: SIGSEGV in every reader) is refused naming the depth cap;
// non-regular inputs (/dev/zero, a FIFO) are refused unless they are `-` (was:
// read until memory ran out); messages never quote a file's content (was: a
// study's {"csv": "../../etc/passwd"} quoted its first line); "weights": []
// is refused by name (was: silently read as a polynomial curve).
#include <sys/stat.h>

#include <cmath>

#include "cli.hpp"

namespace hula::regress {
namespace {

std::string nested(std::size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); }

// checks: every reader refuses a 65,000-deep document with a ParseError naming the 64-level cap, without crashing.
TEST(Issue10HostileInput, DeeplyNestedJsonIsRefusedByEveryReader) {
  TempDir dir;
  write(dir / "deep.json", nested(65000));
  const std::string deep = (dir / "deep.json").string();
  const std::vector<std::vector<std::string>> commands = {
      {"info", deep},
      {"interpolate", "--points", deep, "-o", (dir / "c.json").string()},
      {"optimise", "--problem-file", deep, "--algorithm", "ga-real"},
      {"fair-knots", deep},
      {"match-curvature", deep},
  };
  for (const auto& args : commands) {
    const ProcessResult r = hula(args);
    EXPECT_EQ(r.exit_code, 3) << args[0] << ": " << r.err;
    EXPECT_NE(message_of(r).find("limit of 64 levels"), std::string::npos) << args[0] << ": " << r.err;
  }
}

// checks: /dev/zero as an input file is refused at once as a non-regular file naming - as the way to pipe.
// (A FIFO is read as a pipe by the command line since issue 25, tests/apps/test_terminal_cli.py; the
// server still refuses it, tests/regress/issue_24_server_requests_test.cpp.)
TEST(Issue10HostileInput, NonRegularInputsAreRefused) {
  TempDir dir;
  for (const std::string& path : {std::string("/dev/zero")}) {
    const ProcessResult r = hula({"info", path});
    EXPECT_EQ(r.exit_code, 3) << r.err;
    EXPECT_NE(message_of(r).find("give - to read standard input"), std::string::npos) << r.err;
  }
  // A study profile naming /dev/zero is refused the same way.
  write(dir / "study.json", R"({"format": "hula-study", "version": 1, "study": "match-curvature",
    "points": [[0, 0], [5, 20], [40, 0]], "lower": [[0, 0], [30, 30], [0, 0]], "upper": [[0, 0], [35, 30], [0, 0]],
    "target": {"csv": "/dev/zero"}})");
  const ProcessResult s = hula({"match-curvature", (dir / "study.json").string()});
  EXPECT_EQ(s.exit_code, 3) << s.err;
  EXPECT_NE(message_of(s).find("character device"), std::string::npos) << s.err;
}

// checks: a study whose profile csv names a private file never quotes that file's content in the error.
TEST(Issue10HostileInput, MessagesNeverQuoteAFilesContent) {
  TempDir dir;
  write(dir / "secret.txt", "root:x:0:0:SECRET-TOKEN-123:/root:/bin/bash\nsecond line\n");
  write(dir / "study.json", R"({"format": "hula-study", "version": 1, "study": "match-curvature",
    "points": [[0, 0], [5, 20], [40, 0]], "lower": [[0, 0], [30, 30], [0, 0]], "upper": [[0, 0], [35, 30], [0, 0]],
    "target": {"csv": "secret.txt"}})");
  const ProcessResult s = hula({"match-curvature", (dir / "study.json").string()});
  EXPECT_EQ(s.exit_code, 3) << s.err;
  EXPECT_EQ(s.err.find("SECRET"), std::string::npos) << s.err;
  EXPECT_EQ(s.err.find("root:x"), std::string::npos) << s.err;
  // The same file given as a curve file (not JSON): the parser's "last read" token is not echoed.
  const ProcessResult c = hula({"info", (dir / "secret.txt").string()});
  EXPECT_EQ(c.exit_code, 3) << c.err;
  EXPECT_EQ(c.err.find("root"), std::string::npos) << c.err;
  // A long string value is quoted by its first 16 characters only.
  write(dir / "kind.json", R"({"kind": "SECRET-TOKEN-123-and-much-more"})");
  const ProcessResult k = hula({"info", (dir / "kind.json").string()});
  EXPECT_EQ(k.exit_code, 3) << k.err;
  EXPECT_EQ(k.err.find("and-much-more"), std::string::npos) << k.err;
}

// checks: "weights": [] is refused naming weights (was: read as a polynomial curve).
TEST(Issue10HostileInput, EmptyWeightsAreRefusedByName) {
  TempDir dir;
  write(dir / "c.json", R"({"kind": "nurbs", "degree": 1, "knots": [0, 0, 1, 1],
                            "control_points": [[0, 0], [1, 1]], "weights": []})");
  const ProcessResult r = hula({"info", (dir / "c.json").string()});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(message_of(r).find("weights is empty"), std::string::npos) << r.err;
  EXPECT_EQ(error_of(r)["error"]["where"]["field"], "weights");
}

// checks: a valid cubic with 300,000 control points is read and measured (was: refused by a fixed
// arc-length budget); its length matches the polyline through the data to 1e-3 relative.
TEST(Issue10HostileInput, LargeValidCurveIsHandled) {
  TempDir dir;
  std::string points;
  double polyline = 0.0;
  double px = 0.0, py = 0.0;
  for (int i = 0; i < 299998; ++i) {
    const double x = i * 0.01, y = std::sin(i * 0.001);
    if (i > 0) polyline += std::hypot(x - px, y - py);
    px = x;
    py = y;
    points += std::to_string(x) + "," + std::to_string(y) + "\n";
  }
  write(dir / "points.csv", points);
  const ProcessResult i =
      hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "big.json").string()});
  ASSERT_EQ(i.exit_code, 0) << i.err;
  EXPECT_EQ(json::parse(i.out)["control_points"], 300000);
  const ProcessResult r = hula({"info", (dir / "big.json").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NEAR(json::parse(r.out)["length"].get<double>(), polyline, 1e-3 * polyline);
}

}  // namespace
}  // namespace hula::regress
