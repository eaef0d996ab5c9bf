// SPDX-License-Identifier: MIT
// `hula fair-knots` run as a process on the thesis's study files
// (examples/studies): the numbers in its JSON, the files under --svg and
// --log, and the error JSON for a bad study file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "hula/testing/run_process.hpp"
#include "hula/testing/temp_dir.hpp"

#ifndef HULA_CLI_PATH
#error "HULA_CLI_PATH must name the hula binary"
#endif
#ifndef HULA_EXAMPLES_DIR
#error "HULA_EXAMPLES_DIR must name examples/studies"
#endif

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

hula::testing::ProcessResult hula_run(const std::vector<std::string>& args) {
  return hula::testing::run_process(HULA_CLI_PATH, args);
}

std::string example(const std::string& name) { return (fs::path(HULA_EXAMPLES_DIR) / name).string(); }

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// checks: 7.4.2 Example 2: chord-length energy, the thesis's best GA vector evaluated, both optimisers at the
// optimum 0.0976372 (symmetric p2 = 0.5) and in agreement, the map CSV (40 x 40 rows) and the SVGs
TEST(CliFairKnots, ThesisExample2) {
  hula::testing::TempDir dir;
  const fs::path svg = dir.path() / "svg";
  const fs::path log = dir.path() / "run.csv";
  const auto r = hula_run({"fair-knots", example("fair-knots-7.4-example2.json"), "--svg", svg.string(), "--log",
                           log.string(), "--seed", "3"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json out = json::parse(r.out);
  EXPECT_EQ(out["study"]["seed"], 3);
  EXPECT_EQ(out["energy"], "bending");
  const json& chord = out["chord_length"];
  EXPECT_EQ(chord["parameters"], json::array({0.0, 0.25, 0.5, 0.75, 1.0}));
  EXPECT_NEAR(chord["energy"].get<double>(), 0.10223729, 1e-7);
  EXPECT_EQ(chord["curve"]["kind"], "nurbs");
  EXPECT_NEAR(out["given"]["energy"].get<double>(), 0.0978364, 1e-6);
  for (const char* method : {"ga", "deterministic"}) {
    SCOPED_TRACE(method);
    const json& m = out[method];
    EXPECT_NEAR(m["energy"].get<double>(), 0.0976372, 1e-4 * 0.0976372);
    EXPECT_LE(m["energy"].get<double>(), chord["energy"].get<double>());
    EXPECT_NEAR(m["parameters"][2].get<double>(), 0.5, 0.01);
    EXPECT_GT(m["evaluations"].get<int>(), 10);
    EXPECT_GE(m["seconds"].get<double>(), 0.0);
  }
  EXPECT_LT(std::abs(out["agreement"]["relative_energy"].get<double>()), 1e-3);
  EXPECT_EQ(out["map"]["knots"], json::array({1, 3}));
  for (const char* f : {"curve_before.svg", "curve_after.svg", "convergence.svg", "energy_map.svg"}) {
    EXPECT_NE(slurp(svg / f).find("<svg"), std::string::npos) << f;
  }
  const std::string csv = slurp(svg / "energy_map.csv");
  EXPECT_EQ(csv.rfind("k1,k2,energy\n", 0), 0u);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 40 * 40);
  EXPECT_EQ(slurp(log).rfind("generation,", 0), 0u);
}

// checks: a study file with an unknown member or unordered parameters fails with exit 3 and the member named,
// before any output
TEST(CliFairKnots, BadStudyFileIsRefused) {
  hula::testing::TempDir dir;
  const fs::path bad = dir.path() / "bad.json";
  std::ofstream(bad) << R"({"format": "hula-study", "version": 1, "study": "fair-knots",
    "points": [[0, 0], [100, 0], [100, 100]], "parameters": [0, 1.5, 1]})";
  auto r = hula_run({"fair-knots", bad.string()});
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_TRUE(r.out.empty());
  EXPECT_NE(r.err.find("parameters[2] = 1"), std::string::npos) << r.err;
  std::ofstream(bad) << R"({"format": "hula-study", "version": 1, "study": "fair-knots",
    "points": [[0, 0], [100, 0], [100, 100]], "knot_vector": [0, 0.5, 1]})";
  r = hula_run({"fair-knots", bad.string()});
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("knot_vector"), std::string::npos) << r.err;
}

}  // namespace

namespace {

// checks: --occt on 7.4.2 Example 1 adds Open CASCADE's three baselines with the best curve's end tangent angles
// (the natural-end GA curve's, reported under "ends"), each with OCCT's status and, where OCCT returned a curve,
// finite energies and the data points' deviations (the corner point (100, 0) is off every baseline, which only
// holds the ends: deviation > 0, while the studies' curves interpolate it); baselines.svg has every curve.
TEST(CliFairKnots, OcctBaselinesBesideTheOptimisers) {
  hula::testing::TempDir dir;
  const fs::path svg = dir.path() / "svg";
  const auto r = hula_run({"fair-knots", example("fair-knots-7.4-example1.json"), "--occt", "--svg", svg.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json out = json::parse(r.out);
  ASSERT_TRUE(out.contains("occt"));
  const json& occt = out["occt"];
  ASSERT_EQ(occt["curves"].size(), 3u);
  EXPECT_EQ(occt["ends"]["tangent_angles"].size(), 2u);
  int with_curve = 0;
  for (const json& c : occt["curves"]) {
    EXPECT_FALSE(c["status"].get<std::string>().empty()) << c["name"];
    if (c["curve"].is_null()) continue;
    ++with_curve;
    EXPECT_GT(c["bending"].get<double>(), 0.0) << c["name"];
    EXPECT_GT(c["max_deviation"].get<double>(), 1.0) << c["name"];
  }
  EXPECT_GE(with_curve, 1);
  const std::string figure = slurp(svg / "baselines.svg");
  EXPECT_NE(figure.find("OCCT batten"), std::string::npos);
  EXPECT_NE(figure.find("GA"), std::string::npos);
}

}  // namespace
