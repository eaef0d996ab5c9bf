// SPDX-License-Identifier: MIT
// `hula match-curvature-torsion` on the example study file and on bad study files.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hula/testing/run_process.hpp"
#include "hula/testing/temp_dir.hpp"

namespace {

using hula::testing::ProcessResult;
using Json = nlohmann::json;

ProcessResult hula_run(const std::vector<std::string>& args) { return hula::testing::run_process(HULA_CLI_PATH, args); }

const std::string kExample = std::string(HULA_SOURCE_DIR) + "/examples/studies/match-curvature-torsion-helix.json";

// Issue 6: κ and τ both prescribed from a known space curve; the Pareto set contains a curve matching both
// within 1e-3 (the polished best compromise), and every member carries both errors and its curve.
TEST(MatchCurvatureTorsionCli, HelixExampleMatchesBothProfiles) {
  const hula::testing::TempDir dir;
  const ProcessResult r = hula_run({"match-curvature-torsion", kExample, "--svg", (dir.path() / "svg").string(),
                                    "--log", (dir.path() / "log.csv").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json j = Json::parse(r.out);
  ASSERT_FALSE(j["front"].empty());
  bool both = false;
  for (const Json& m : j["front"]) {
    ASSERT_TRUE(m.contains("curvature") && m.contains("torsion") && m.contains("points") && m.contains("curve"));
    EXPECT_EQ(m["curve"]["kind"], "nurbs");
    both = both || (m["curvature"].get<double>() < 1e-3 && m["torsion"].get<double>() < 1e-3);
  }
  EXPECT_TRUE(both);
  EXPECT_GT(j["nsga2_front"].size(), 5U);
  EXPECT_LT(j["compromise"]["curvature"].get<double>(), 1e-3);
  EXPECT_LT(j["compromise"]["torsion"].get<double>(), 1e-3);
  EXPECT_GT(j["start"]["curvature"].get<double>(), 5e-3);
  EXPECT_EQ(j["study"]["study"], "match-curvature-torsion");
  EXPECT_EQ(j["compromise"]["curve"]["kind"], "nurbs");
  for (const char* f :
       {"curve_before.svg", "curve_after.svg", "profile.svg", "torsion_profile.svg", "pareto.svg", "convergence.svg"})
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "svg" / f)) << f;
  EXPECT_GT(std::filesystem::file_size(dir.path() / "log.csv"), 1000U);
  // The resolved study repeats the run exactly.
  std::ofstream(dir.path() / "again.json") << j["study"].dump();
  const ProcessResult again = hula_run({"match-curvature-torsion", (dir.path() / "again.json").string()});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(Json::parse(again.out)["front"], j["front"]);
}

// checks: with boxes of ±0.5 the helix example's start (moved by about 1) cannot reach the known helix in one run;
// "max_recentres" re-runs with each box centred on the previous best compromise (the study's widths) until both errors
// are below 1e-3; the "map" holds both objectives on its grid, its "result" values are the compromise's own errors, the
// resolved study echoes both members and --svg writes both map figures and the CSV.
TEST(MatchCurvatureTorsionCli, RecentredRoundsAndMap) {
  const hula::testing::TempDir dir;
  Json study = Json::parse(std::ifstream(kExample));
  for (std::size_t k = 1; k < study["lower"].size(); ++k)
    study["lower"][k] = study["upper"][k] = Json::array({0.5, 0.5, 0.5});
  study["nsga2"] = Json{{"population", 40}, {"generations", 40}};
  study["samples"] = 100;
  study["max_recentres"] = 6;
  study["map"] = Json{{"variables", Json::array({"points[1].x", "points[2].z"})}, {"grid", 5}};
  const auto path = dir.path() / "recentre.json";
  std::ofstream(path) << study.dump();
  const ProcessResult r = hula_run({"match-curvature-torsion", path.string(), "--svg", (dir.path() / "svg").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json j = Json::parse(r.out);
  const Json& rounds = j["rounds"];
  ASSERT_GE(rounds.size(), 2U);
  EXPECT_FALSE(rounds[0]["on_bound"].empty());
  for (std::size_t k = 1; k < rounds.size(); ++k) {
    const Json& p = rounds[k - 1]["best_points"];
    const double centre[] = {p[1][0].get<double>(), p[1][1].get<double>(), p[1][2].get<double>()};
    for (std::size_t v = 0; v < 3; ++v) {
      EXPECT_NEAR(rounds[k]["lower"][v].get<double>(), centre[v] - 0.5, 1e-12);
      EXPECT_NEAR(rounds[k]["upper"][v].get<double>(), centre[v] + 0.5, 1e-12);
    }
  }
  EXPECT_LT(j["compromise"]["curvature"].get<double>(), 1e-3);
  EXPECT_LT(j["compromise"]["torsion"].get<double>(), 1e-3);
  const Json& map = j["map"];
  ASSERT_EQ(map["curvature"].size(), 5U);
  ASSERT_EQ(map["torsion"][4].size(), 5U);
  EXPECT_NEAR(map["result"]["curvature"].get<double>(), j["compromise"]["curvature"].get<double>(), 1e-15);
  EXPECT_NEAR(map["result"]["torsion"].get<double>(), j["compromise"]["torsion"].get<double>(), 1e-15);
  EXPECT_EQ(j["study"]["max_recentres"].get<int>(), 6);
  EXPECT_EQ(j["study"]["map"]["variables"][1], "points[2].z");
  for (const char* f : {"fitness_map.svg", "torsion_map.svg", "fitness_map.csv"})
    EXPECT_TRUE(std::filesystem::exists(dir.path() / "svg" / f)) << f;
}

TEST(MatchCurvatureTorsionCli, BadStudiesAreRefusedBeforeAnyRun) {
  const hula::testing::TempDir dir;
  Json base = Json::parse(std::ifstream(kExample));
  const auto run_with = [&](const std::function<void(Json&)>& edit) {
    Json j = base;
    edit(j);
    const auto path = dir.path() / "bad.json";
    std::ofstream(path) << j.dump();
    return hula_run({"match-curvature-torsion", path.string()});
  };
  struct Case {
    std::function<void(Json&)> edit;
    const char* needle;
  };
  const std::vector<Case> cases = {
      {[](Json& j) { j["torsion_targett"] = 1; }, "torsion_targett: unknown member"},
      {[](Json& j) { j.erase("torsion_target"); }, "torsion_target"},
      {[](Json& j) { j["nsga2"]["population"] = 7; }, "nsga2.population"},
      {[](Json& j) { j["nsga2"]["eta"] = 7; }, "nsga2.eta: unknown member"},
      {[](Json& j) { j["lower"][1][0] = -1; }, "lower"},
      {[](Json& j) { j["samples"] = 0; }, "samples"},
      {[](Json& j) {
         j["torsion_target"] = Json{{"samples", Json::array({Json::array({0, 1}), Json::array({0.5})})}};
       },
       "torsion_target.samples"},
      {[](Json& j) {
         for (auto& p : j["points"]) p.erase(2);
         for (auto& p : j["lower"]) p.erase(2);
         for (auto& p : j["upper"]) p.erase(2);
       },
       "3-D points"},
      {[](Json& j) { j.erase("end_tangent"); }, "torsion of the curve is undefined"},
      {[](Json& j) {
         j["map"] = Json{{"variables", Json::array({"points[1].x", "points[0].y"})}};
       },
       "is not a free design variable"},
      {[](Json& j) { j["max_recentres"] = "3"; }, "max_recentres"},
  };
  for (const Case& c : cases) {
    const ProcessResult r = run_with(c.edit);
    EXPECT_EQ(r.exit_code, 3) << c.needle << "\n" << r.err;
    EXPECT_NE(r.err.find(c.needle), std::string::npos) << c.needle << "\n" << r.err;
  }
}

}  // namespace
