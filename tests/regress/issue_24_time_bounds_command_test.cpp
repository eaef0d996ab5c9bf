// SPDX-License-Identifier: MIT
// Issue 24, item 7: `fair-knots --time S` bounded each optimiser and each
// re-centring round, not the command: `--time 0.3` ran 2.49 s over 11 rounds
// with "stopped": false. One deadline now covers every optimiser and round.
#include <chrono>

#include "cli.hpp"

namespace hula::regress {
namespace {

// checks: `fair-knots` with "method": "both" runs a GA and then the simplex, each of which would run for
// hours. Under --time 1 the whole command ends with both optimisers stopped, and the seconds the two
// report add up to at most the limit plus one generation's slack (0.5 s); before the fix each ran its own
// second (sum ≈ 2 s).
TEST(Issue24TimeBoundsCommand, FairKnotsTimeBoundsEveryOptimiserTogether) {
  TempDir dir;
  write(dir / "s.json", R"({"format": "hula-study", "version": 1, "study": "fair-knots", "seed": 1, "threads": 1,
    "points": [[0, 0], [10, 0], [29, 0], [31, 2], [31, 31], [31, 41]], "method": "both",
    "ga": {"algorithm": "real", "population": 40, "generations": 1000000, "max_recentres": 1000},
    "deterministic": {"max_evaluations": 100000000}})");
  const auto t0 = std::chrono::steady_clock::now();
  const ProcessResult r = hula({"fair-knots", (dir / "s.json").string(), "--time", "1"});
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  ASSERT_TRUE(j.contains("ga") && j.contains("deterministic")) << r.out.substr(0, 400);
  EXPECT_EQ(j["ga"]["stopped"], true);
  EXPECT_EQ(j["deterministic"]["stopped"], true);
  const double seconds = j["ga"]["seconds"].get<double>() + j["deterministic"]["seconds"].get<double>();
  EXPECT_LT(seconds, 1.5) << "ga " << j["ga"]["seconds"] << " s, deterministic " << j["deterministic"]["seconds"];
  EXPECT_GE(wall, 1.0);
}

}  // namespace
}  // namespace hula::regress
