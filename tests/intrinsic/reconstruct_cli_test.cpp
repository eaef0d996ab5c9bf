// SPDX-License-Identifier: MIT
// Contract tests of `hula reconstruct` run as a process: the exact JSON shape
// ({"points": [{"s", "position", "T", "N", "B"}], "fit": {"control_points",
// "max_deviation"}}), values against the closed-form helix, the default
// sample arc lengths, the atomically written NURBS file, and exit codes 2/3
// with the error JSON naming the option (and the column of a bad expression).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hula/io/json_curve.hpp"
#include "hula/testing/process_json.hpp"
#include "hula/testing/run_process.hpp"
#include "hula/testing/temp_dir.hpp"

#ifndef HULA_CLI_PATH
#error "HULA_CLI_PATH must name the hula binary"
#endif

namespace hula::intrinsic {
namespace {

using nlohmann::json;
using testing::ProcessResult;

ProcessResult hula(const std::vector<std::string>& args) { return testing::run_process(HULA_CLI_PATH, args); }

// checks: the helix κ = a/(a²+b²) = 0.16, τ = b/(a²+b²) = 0.08 (a = 5, b = 2.5) prints exactly the documented keys and
// matches the closed form at s = 7 to 1e-9.
TEST(ReconstructCli, HelixShapeAndValues) {
  const ProcessResult r = hula({"reconstruct", "--kappa", "0.16", "--tau", "0.08", "--length", "20", "--at", "0,7",
                                "--start-point", "5,0,0", "--start-frame", "0,2,1,-1,0,0"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  ASSERT_EQ(j.size(), 2u);
  ASSERT_EQ(j["points"].size(), 2u);
  ASSERT_EQ(j["fit"].size(), 2u);
  EXPECT_TRUE(j["fit"]["control_points"].is_number_integer());
  EXPECT_LE(j["fit"]["max_deviation"].get<double>(), 1e-10);
  for (const auto& p : j["points"]) {
    EXPECT_EQ(p.size(), 5u);
    for (const char* k : {"position", "T", "N", "B"}) EXPECT_EQ(p[k].size(), 3u) << k;
  }
  // a = 5, b = 2.5, c = sqrt(31.25): r(s) = (a cos(s/c), a sin(s/c), b s/c).
  const double c = std::sqrt(31.25), s = 7.0;
  const double exact[3] = {5 * std::cos(s / c), 5 * std::sin(s / c), 2.5 * s / c};
  EXPECT_EQ(j["points"][1]["s"].get<double>(), 7.0);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(j["points"][1]["position"][k].get<double>(), exact[k], 1e-9);
}

// checks: without --at the points are s = 0, L/4, L/2, 3L/4, L; -o writes a quintic NURBS file on [0, L].
TEST(ReconstructCli, DefaultSamplesAndOutputFile) {
  testing::TempDir dir;
  const std::string out = (dir.path() / "spiral.json").string();
  const ProcessResult r = hula({"reconstruct", "--kappa", "s", "--tau", "0", "--length", "2", "-o", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  ASSERT_EQ(j["points"].size(), 5u);
  EXPECT_EQ(j["points"][0]["s"].get<double>(), 0.0);
  EXPECT_EQ(j["points"][2]["s"].get<double>(), 1.0);
  EXPECT_EQ(j["points"][4]["s"].get<double>(), 2.0);
  const curve::Curve f = io::read_curve_file(out);
  EXPECT_EQ(f.kind(), curve::Kind::Nurbs);
  EXPECT_EQ(f.nurbs().degree(), 5);
  EXPECT_EQ(f.nurbs().domain().end, 2.0);
  EXPECT_EQ(f.nurbs().control_points().size(), j["fit"]["control_points"].get<std::size_t>());
}

// checks: a bad expression exits 3 with ParseError naming the option, the expression and the column.
TEST(ReconstructCli, BadExpressionExit3NamesColumn) {
  const ProcessResult r = hula({"reconstruct", "--kappa", "1", "--tau", "0.3*cos(2*s", "--length", "2"});
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_TRUE(r.out.empty());
  const json e = testing::stderr_error(r);
  EXPECT_EQ(e["code"], "ParseError");
  EXPECT_EQ(e["where"]["field"], "tau");
  EXPECT_EQ(e["where"]["column"], 12);  // end of input, just after the 11 characters
  EXPECT_NE(e["message"].get<std::string>().find("'0.3*cos(2*s'"), std::string::npos) << e["message"];
  // An unknown parameter: only s is allowed.
  const ProcessResult u = hula({"reconstruct", "--kappa", "t", "--tau", "0", "--length", "2"});
  EXPECT_EQ(u.exit_code, 3);
  EXPECT_EQ(testing::stderr_error(u)["where"]["field"], "kappa");
}

// checks: bad values exit 3 naming the field; missing required options exit 2.
TEST(ReconstructCli, BadValuesAndUsage) {
  struct Case {
    std::vector<std::string> args;
    int code;
    std::string field;
  };
  const std::vector<Case> cases = {
      {{"reconstruct", "--kappa", "1", "--tau", "0", "--length", "0"}, 3, "length"},
      {{"reconstruct", "--kappa", "1", "--tau", "0", "--length", "1", "--start-frame", "1,0,0,3,0,0"},
       3,
       "start_frame.normal"},
      {{"reconstruct", "--kappa", "1", "--tau", "0", "--length", "1", "--start-frame", "0,0,0,0,1,0"},
       3,
       "start_frame.tangent"},
      {{"reconstruct", "--kappa", "1", "--tau", "0", "--length", "1", "--start-frame", "1,0,0"}, 3, "start-frame"},
      {{"reconstruct", "--kappa", "1", "--tau", "0", "--length", "1", "--start-point", "1,x,0"}, 3, "start-point"},
      {{"reconstruct", "--kappa", "1", "--tau", "0", "--length", "1", "--tolerance", "0"}, 3, "tolerance"},
      {{"reconstruct", "--kappa", "1", "--tau", "0", "--length", "1", "--at", "2"}, 3, "s"},
      {{"reconstruct", "--kappa", "sqrt(1-s)", "--tau", "0.1", "--length", "2"}, 4, "kappa"},
  };
  for (const Case& c : cases) {
    const ProcessResult r = hula(c.args);
    EXPECT_EQ(r.exit_code, c.code) << r.err;
    EXPECT_EQ(testing::stderr_error(r)["where"]["field"], c.field) << r.err;
  }
  const ProcessResult usage = hula({"reconstruct", "--kappa", "1", "--length", "1"});
  EXPECT_EQ(usage.exit_code, 2);
  EXPECT_EQ(testing::stderr_error(usage)["code"], "UsageError");
}

// checks: with --end-point on the unit circle's own quarter-turn end (1, 1, 0) the boundary-value route needs no
// correction (mean |δκ| ≈ 0, the closed-form circle), and with a different end and --free-length it lands on it.
TEST(ReconstructCli, EndPointHeldPlanar) {
  const ProcessResult r =
      hula({"reconstruct", "--kappa", "1", "--tau", "0", "--length", "1.5707963267948966", "--end-point", "1,1,0"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_LT(j["direct"]["mean_curvature_deviation"].get<double>(), 1e-8);
  const json& end = j["points"][4]["position"];
  EXPECT_NEAR(end[0].get<double>(), 1.0, 1e-9);
  EXPECT_NEAR(end[1].get<double>(), 1.0, 1e-9);
  const ProcessResult f = hula({"reconstruct", "--kappa", "1", "--tau", "0", "--length", "1.5707963267948966",
                                "--end-point", "1.3,0.9,0", "--free-length"});
  ASSERT_EQ(f.exit_code, 0) << f.err;
  const json jf = json::parse(f.out);
  EXPECT_NE(jf["direct"]["length"].get<double>(), 1.5707963267948966);
  EXPECT_NEAR(jf["points"][4]["position"][0].get<double>(), 1.3, 1e-8);
  EXPECT_NEAR(jf["points"][4]["position"][1].get<double>(), 0.9, 1e-8);
}

// checks: the space boundary-value route on the CLI: a helix held to an end point and an end tangent away from its
// own meets both (end errors ≤ 1e-9·L) and reports torsion corrections; --free-length alone is refused.
TEST(ReconstructCli, EndPointAndTangentHeldInSpace) {
  const ProcessResult r = hula({"reconstruct", "--kappa", "0.16", "--tau", "0.08", "--length", "20", "--end-point",
                                "-3,8,5", "--end-tangent", "-1,-0.2,0.4", "--at", "20"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_FALSE(j["direct"]["planar"].get<bool>());
  EXPECT_LE(j["direct"]["end_point_error"].get<double>(), 2e-8);
  EXPECT_LE(j["direct"]["end_tangent_error"].get<double>(), 1e-9);
  EXPECT_TRUE(j["direct"].contains("torsion_correction"));
  const double expected[3] = {-3, 8, 5};
  for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(j["points"][0]["position"][k].get<double>(), expected[k], 2e-8);
  const ProcessResult bad = hula({"reconstruct", "--kappa", "1", "--tau", "0", "--length", "1", "--free-length"});
  EXPECT_EQ(bad.exit_code, 3);
  EXPECT_EQ(testing::stderr_error(bad)["where"]["field"], "free-length") << bad.err;
}

}  // namespace
}  // namespace hula::intrinsic
