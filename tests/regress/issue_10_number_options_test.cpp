// SPDX-License-Identifier: MIT
// Issue 10, item 3 "numbers on the command line": integers are signed 64-bit
// and range-checked per option with what the user typed in the message (was:
// --population=-5 became 18446744073709551611, 99999999999999999999 was
// saturated, --seed -1 and --threads -1 wrapped, --dimension 0 silently ran
// the default); bounds whose width overflows are refused naming the bounds
// (was: every individual non-finite and the objective blamed).
#include "cli.hpp"

namespace hula::regress {
namespace {

struct Case {
  std::vector<std::string> args;
  std::string expected;  // a piece of the message
};

ProcessResult optimise(const std::vector<std::string>& extra) {
  std::vector<std::string> args = {"optimise", "--problem", "sphere", "--algorithm", "ga-real", "--generations", "2"};
  args.insert(args.end(), extra.begin(), extra.end());
  return hula(args);
}

// checks: each out-of-range integer is a usage error (exit 2) quoting the flag and the typed value.
TEST(Issue10NumberOptions, IntegersAreSigned64BitAndRangeChecked) {
  const std::vector<Case> cases = {
      {{"--population=-5"}, "--population -5: must be an integer in [1, 1000000]"},
      {{"--population", "99999999999999999999"}, "--population 99999999999999999999: outside the signed 64-bit range"},
      {{"--population", "7"}, "--population 7: must be an even number in [2, 1000000]"},
      {{"--seed", "-1"}, "--seed -1: must be an integer >= 0"},
      {{"--threads", "-1"}, "--threads -1: must be an integer in [0, 1024]"},
      {{"--dimension", "0"}, "--dimension 0: must be an integer in [1, 100000]"},
      {{"--evaluations", "1e3"}, "--evaluations 1e3: not an integer"},
      {{"--time", "0"}, "--time 0: must be a number > 0"},
      {{"--crossover", "nan"}, "--crossover nan: must be a number in [0, 1]"},
  };
  for (const Case& c : cases) {
    const ProcessResult r = optimise(c.args);
    EXPECT_EQ(r.exit_code, 2) << c.args[0] << ": " << r.err;
    EXPECT_NE(message_of(r).find(c.expected), std::string::npos) << r.err;
  }
}

// checks: study commands parse --seed and --threads the same way (was: --threads -1 wrapped and was echoed).
TEST(Issue10NumberOptions, StudyThreadsAndSeedAreRangeChecked) {
  for (const std::string& flag : {std::string("--threads"), std::string("--seed")}) {
    const ProcessResult r = hula({"fair-knots", "study.json", flag, "-1"});
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(message_of(r).find(flag + " -1: must be an integer"), std::string::npos) << r.err;
  }
}

// checks: bounds of ±1e308 are refused naming --lower/--upper (the width upper - lower overflows a double).
TEST(Issue10NumberOptions, OverflowingBoundWidthNamesTheBounds) {
  const ProcessResult r = optimise({"--dimension", "2", "--lower", "-1e308,-1", "--upper", "1e308,1"});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  const std::string m = message_of(r);
  EXPECT_NE(m.find("--lower/--upper"), std::string::npos) << m;
  EXPECT_NE(m.find("overflows"), std::string::npos) << m;
  EXPECT_EQ(error_of(r)["error"]["code"], "InvalidOption");
}

// checks: a problem file with such bounds is refused by the problem's own validation, naming the variable.
TEST(Issue10NumberOptions, OverflowingBoundWidthInProblemFileNamesTheVariable) {
  TempDir dir;
  write(dir / "p.json", R"({"name": "wide", "variables": [{"name": "x", "lower": -1e308, "upper": 1e308}],
                            "objectives": ["x*x"]})");
  const ProcessResult r =
      hula({"optimise", "--problem-file", (dir / "p.json").string(), "--algorithm", "ga-real", "--generations", "1"});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(message_of(r).find("variables[0]"), std::string::npos) << r.err;
  EXPECT_NE(message_of(r).find("overflows"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace hula::regress
