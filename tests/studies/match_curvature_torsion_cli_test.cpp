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
// within 1e-3 (the polished best compromise), and every member carries both errors.
TEST(MatchCurvatureTorsionCli, HelixExampleMatchesBothProfiles) {
  const hula::testing::TempDir dir;
  const ProcessResult r = hula_run({"match-curvature-torsion", kExample, "--svg", (dir.path() / "svg").string(),
                                    "--log", (dir.path() / "log.csv").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json j = Json::parse(r.out);
  ASSERT_FALSE(j["front"].empty());
  bool both = false;
  for (const Json& m : j["front"]) {
    ASSERT_TRUE(m.contains("curvature") && m.contains("torsion") && m.contains("points"));
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
  };
  for (const Case& c : cases) {
    const ProcessResult r = run_with(c.edit);
    EXPECT_EQ(r.exit_code, 3) << c.needle << "\n" << r.err;
    EXPECT_NE(r.err.find(c.needle), std::string::npos) << c.needle << "\n" << r.err;
  }
}

}  // namespace
