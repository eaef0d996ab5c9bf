// SPDX-License-Identifier: MIT
// Contract tests of `hula reconstruct` run as a process: the exact JSON shape
// ({"points": [{"s", "position", "T", "N", "B"}], "integration": {"method",
// "steps", "rejected_steps", "breakpoints"}, "fit": {"control_points",
// "segments", "tolerance", "max_deviation"}}), values against the closed-form
// helix, the default sample arc lengths, the atomically written NURBS file, a
// kinked κ against composite Gauss–Legendre in bounded work, the work limit,
// and exit codes 2/3/4 with the error JSON naming the option (and the column
// of a bad expression).
#include <gtest/gtest.h>

#include <algorithm>
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

// checks: the helix κ = a/(a²+b²) = 0.16, τ = b/(a²+b²) = 0.08 (a = 5, b = 2.5) prints exactly the documented keys,
// matches the closed form at s = 7 to 1e-9 and is fitted within the default 1e-6 of its size (box diagonal ≤ 23).
TEST(ReconstructCli, HelixShapeAndValues) {
  const ProcessResult r = hula({"reconstruct", "--kappa", "0.16", "--tau", "0.08", "--length", "20", "--at", "0,7",
                                "--start-point", "5,0,0", "--start-frame", "0,2,1,-1,0,0"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  ASSERT_EQ(j.size(), 3u);
  ASSERT_EQ(j["points"].size(), 2u);
  ASSERT_EQ(j["integration"].size(), 4u);
  EXPECT_EQ(j["integration"]["method"], "frenet-serret");
  EXPECT_EQ(j["integration"]["breakpoints"], 0);
  ASSERT_EQ(j["fit"].size(), 4u);
  EXPECT_TRUE(j["fit"]["control_points"].is_number_integer());
  // The box of the helix from s = 0 to 20 (r = 5, rise 2.5·20/√31.25 ≈ 8.9) has a diagonal below 10√2 + 9 < 24.
  EXPECT_GT(j["fit"]["tolerance"].get<double>(), 1e-6 * 8.9);
  EXPECT_LT(j["fit"]["tolerance"].get<double>(), 1e-6 * 24);
  EXPECT_LE(j["fit"]["max_deviation"].get<double>(), j["fit"]["tolerance"].get<double>());
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

// checks (issue 26): --exact makes -o write the curve by its laws (kind natural, with the integration tolerance),
// read back as an exact curve: the helix κ = 0.16, τ = 0.08 has κ and τ to rounding and the printed points.
TEST(ReconstructCli, ExactWritesTheLaws) {
  testing::TempDir dir;
  const std::string out = (dir.path() / "helix.json").string();
  const ProcessResult r = hula({"reconstruct", "--kappa", "0.16", "--tau", "0.08", "--length", "20", "--tolerance",
                                "1e-11", "--at", "13", "-o", out, "--exact"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  const curve::Curve c = io::read_curve_file(out);
  ASSERT_EQ(c.kind(), curve::Kind::Natural);
  const auto& d = std::get<curve::NaturalData>(c.data());
  EXPECT_EQ(d.curvature, "0.16");
  EXPECT_EQ(d.torsion, "0.08");
  EXPECT_EQ(d.tolerance, 1e-11);
  for (std::size_t k = 0; k < 3; ++k) EXPECT_NEAR(c.point(13.0)[k], j["points"][0]["position"][k].get<double>(), 1e-10);
  // --exact needs -o, and is refused with a held end (the boundary-value problem changes the laws).
  EXPECT_EQ(hula({"reconstruct", "--kappa", "1", "--tau", "0", "--length", "2", "--exact"}).exit_code, 3);
  EXPECT_EQ(
      hula({"reconstruct", "--kappa", "1", "--tau", "0", "--length", "2", "--end-point", "1,1,0", "--exact", "-o", out})
          .exit_code,
      3);
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
      {{"reconstruct", "--kappa", "1", "--tau", "0", "--length", "1", "--fit-tolerance", "2"}, 3, "fit-tolerance"},
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

// Angle θ(s) of the 64-hat κ below in closed form: each hat max(0, 1 − |s − c|/h) integrates to a
// piecewise quadratic, the sum of the finished hats plus the partial one.
double hats_angle(double s, double h) {
  double theta = 0.0;
  for (int i = 0; i < 64; ++i) {
    const double c = (2 * i + 1) * h, u = std::clamp(s - (c - h), 0.0, 2 * h);
    theta += u <= h ? u * u / (2 * h) : h - (2 * h - u) * (2 * h - u) / (2 * h);
  }
  return theta;
}

// checks: a kinked κ law (64 hat functions, 127 kinks, no closed-form antiderivative) reconstructs in bounded work (it
// used to run for minutes: step control and knot search shrinking to rounding size at each kink): the end point
// matches ∫(cos θ, sin θ) ds with the closed-form θ by composite 8-point Gauss–Legendre on each kink-free piece to
// 1e-8, the end tangent the closed-form angle; the integration steps onto every kink (127 breakpoints) in at most 4
// steps per piece, and the fit within 1e-6 of the size has a knot at each kink and at most 6 segments per piece.
TEST(ReconstructCli, KinkedHatCurvatureFinishes) {
  const double h = 8.0 / 128;  // hats of half-width h centred at (2i + 1) h: they touch, kinks every h
  std::string kappa;
  for (int i = 0; i < 64; ++i) {
    if (i) kappa += " + ";
    kappa += "max(0, 1 - abs(s - " + std::to_string((2 * i + 1) * h) + ")/" + std::to_string(h) + ")";
  }
  const ProcessResult r = hula({"reconstruct", "--kappa", kappa, "--tau", "0", "--length", "8", "--at", "8"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  // Reference: 8-point Gauss–Legendre on 16 sub-pieces of each of the 128 pieces [k h, (k + 1) h].
  const double x8[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  const double w8[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  double x = 0.0, y = 0.0;
  const double piece = h / 16;
  for (int k = 0; k < 128 * 16; ++k) {
    const double mid = (k + 0.5) * piece;
    for (int q = 0; q < 4; ++q)
      for (const double sign : {-1.0, 1.0}) {
        const double theta = hats_angle(mid + sign * x8[q] * piece / 2, h);
        x += w8[q] * piece / 2 * std::cos(theta);
        y += w8[q] * piece / 2 * std::sin(theta);
      }
  }
  EXPECT_NEAR(j["points"][0]["position"][0].get<double>(), x, 1e-8);
  EXPECT_NEAR(j["points"][0]["position"][1].get<double>(), y, 1e-8);
  EXPECT_NEAR(std::atan2(j["points"][0]["T"][1].get<double>(), j["points"][0]["T"][0].get<double>()),
              std::remainder(hats_angle(8.0, h), 2 * M_PI), 1e-8);
  EXPECT_EQ(j["integration"]["method"], "planar-numeric-angle");
  EXPECT_EQ(j["integration"]["breakpoints"], 127);
  EXPECT_LE(j["integration"]["steps"].get<int>(), 4 * 128);
  EXPECT_LE(j["fit"]["segments"].get<int>(), 6 * 128);
  EXPECT_GE(j["fit"]["segments"].get<int>(), 128);
  EXPECT_LE(j["fit"]["max_deviation"].get<double>(), j["fit"]["tolerance"].get<double>());
}

// checks: a law too rough for the work limit (|sin(20000 s)|: ~51,000 kinks on [0, 8]) fails with NumericalFailure
// naming kappa and the fit's limit max_segments = 2000 (exit 4) instead of running for minutes.
TEST(ReconstructCli, WorkLimitNamesKappa) {
  const ProcessResult r = hula({"reconstruct", "--kappa", "abs(sin(20000*s))", "--tau", "0", "--length", "8"});
  EXPECT_EQ(r.exit_code, 4) << r.out;
  const json e = testing::stderr_error(r);
  EXPECT_EQ(e["code"], "NumericalFailure");
  EXPECT_EQ(e["where"]["field"], "kappa");
  EXPECT_NE(e["message"].get<std::string>().find("max_segments = 2000"), std::string::npos) << e["message"];
}

}  // namespace
}  // namespace hula::intrinsic
