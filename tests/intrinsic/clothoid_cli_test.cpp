// SPDX-License-Identifier: MIT
// Contract tests of `hula clothoid` run as a process: the JSON shape ({"kind", "segments": [{"start",
// "theta0", "kappa0", "dkappa", "length", "end", "theta1", "kappa1"}], "length", "iterations"(, "points")}),
// the G1 quarter circle against its closed form, the G2 result's joins and end values against the request,
// `--at` sampling, and exit codes 2/3 with the error JSON naming the input.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>
#include <vector>

#include "hula/core/vec.hpp"
#include "hula/curve/curve.hpp"
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

// checks: G1 from (0, 0) heading +x to (1, 1) heading +y is the unit quarter circle (κ0 = 1, κ′ = 0, L = π/2,
// closed form) with exactly the documented keys; --at π/4 is the circle's point (1 − cos, sin)(π/4), to 1e-12.
TEST(ClothoidCli, G1QuarterCircle) {
  const ProcessResult r = hula({"clothoid", "--start-point", "0,0", "--start-angle", "0", "--end-point", "1,1",
                                "--end-angle", "1.5707963267948966", "--at", "0.7853981633974483"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j.size(), 5u);
  EXPECT_EQ(j["kind"], "g1");
  ASSERT_EQ(j["segments"].size(), 1u);
  const json& s = j["segments"][0];
  EXPECT_EQ(s.size(), 8u);
  EXPECT_NEAR(s["kappa0"].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(s["dkappa"].get<double>(), 0.0, 1e-12);
  EXPECT_NEAR(j["length"].get<double>(), std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(s["end"][0].get<double>(), 1.0, 1e-12);
  EXPECT_NEAR(s["end"][1].get<double>(), 1.0, 1e-12);
  const json& p = j["points"][0];
  EXPECT_NEAR(p["point"][0].get<double>(), std::sin(std::numbers::pi / 4), 1e-12);
  EXPECT_NEAR(p["point"][1].get<double>(), 1.0 - std::cos(std::numbers::pi / 4), 1e-12);
  EXPECT_NEAR(p["theta"].get<double>(), std::numbers::pi / 4, 1e-12);
  EXPECT_NEAR(p["kappa"].get<double>(), 1.0, 1e-12);
}

// checks (issue 26): -o writes the G2 spline as a curve file by its curvature law (kind natural, read back as
// an exact curve whose end is the requested point and whose κ at the ends is the request, to 1e-10);
// --to-nurbs TOL writes its NURBS instead, within TOL of that exact curve at 200 arc lengths.
TEST(ClothoidCli, WritesTheExactCurveOrItsNurbs) {
  testing::TempDir dir;
  const std::string exact = (dir.path() / "g2.json").string(), fitted = (dir.path() / "g2-nurbs.json").string();
  const std::vector<std::string> base = {
      "clothoid", "--start-point", "-2,3", "--start-angle", "1.0471975511965976",  "--start-curvature",
      "-0.2",     "--end-point",   "3,2",  "--end-angle",   "-0.7853981633974483", "--end-curvature",
      "0.5"};
  std::vector<std::string> args = base;
  args.insert(args.end(), {"-o", exact, "--tolerance", "1e-12"});
  const ProcessResult r = hula(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["output"]["kind"], "natural");
  EXPECT_EQ(j["output"]["path"], exact);
  const curve::Curve c = io::read_curve_file(exact);
  ASSERT_EQ(c.kind(), curve::Kind::Natural);
  EXPECT_EQ(std::get<curve::NaturalData>(c.data()).tolerance, 1e-12);
  EXPECT_NEAR(c.length(), j["length"].get<double>(), 1e-14 * j["length"].get<double>());
  EXPECT_LT(distance(c.point(c.length()), Vec3{3, 2, 0}), 1e-10);
  EXPECT_LT(distance(c.point(0.0), Vec3{-2, 3, 0}), 1e-15);
  args = base;
  args.insert(args.end(), {"-o", fitted, "--to-nurbs", "1e-8"});
  const ProcessResult n = hula(args);
  ASSERT_EQ(n.exit_code, 0) << n.err;
  const json k = json::parse(n.out);
  EXPECT_EQ(k["output"]["kind"], "nurbs");
  EXPECT_LE(k["output"]["max_deviation"].get<double>(), 1e-8);
  const curve::Curve f = io::read_curve_file(fitted);
  ASSERT_EQ(f.kind(), curve::Kind::Nurbs);
  for (int i = 0; i <= 200; ++i) {
    const double s = c.length() * i / 200.0;
    EXPECT_LT(distance(f.point(std::min(s, f.domain().end)), c.point(s)), 1e-8 + 1e-10) << "s = " << s;
  }
  // --to-nurbs without -o writes nothing and says so (exit 2: the option needs -o).
  args = base;
  args.insert(args.end(), {"--to-nurbs", "1e-8"});
  EXPECT_EQ(hula(args).exit_code, 2);
}

// checks: G2 on Bertolazzi–Frego's test_G2_1 data prints three segments whose printed end values equal the next
// segment's start values and the last one's the request (angle modulo 2π), to 1e-10, and lengths that sum.
TEST(ClothoidCli, G2JoinsAndEnd) {
  const ProcessResult r =
      hula({"clothoid", "--start-point", "-2,3", "--start-angle", "1.0471975511965976", "--start-curvature", "-0.2",
            "--end-point", "3,2", "--end-angle", "-0.7853981633974483", "--end-curvature", "0.5"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["kind"], "g2");
  const json& s = j["segments"];
  ASSERT_EQ(s.size(), 3u);
  double total = 0.0;
  for (std::size_t i = 0; i < 3; ++i) {
    total += s[i]["length"].get<double>();
    if (i == 2) break;
    for (std::size_t k = 0; k < 2; ++k)
      EXPECT_NEAR(s[i]["end"][k].get<double>(), s[i + 1]["start"][k].get<double>(), 1e-10) << i;
    EXPECT_NEAR(s[i]["theta1"].get<double>(), s[i + 1]["theta0"].get<double>(), 1e-10) << i;
    EXPECT_NEAR(s[i]["kappa1"].get<double>(), s[i + 1]["kappa0"].get<double>(), 1e-10) << i;
  }
  EXPECT_NEAR(j["length"].get<double>(), total, 1e-12);
  EXPECT_NEAR(s[0]["kappa0"].get<double>(), -0.2, 1e-15);
  EXPECT_NEAR(s[2]["end"][0].get<double>(), 3.0, 1e-10);
  EXPECT_NEAR(s[2]["end"][1].get<double>(), 2.0, 1e-10);
  EXPECT_NEAR(std::remainder(s[2]["theta1"].get<double>() + std::numbers::pi / 4, 2 * std::numbers::pi), 0.0, 1e-10);
  EXPECT_NEAR(s[2]["kappa1"].get<double>(), 0.5, 1e-10);
}

// checks: bad input exits 3 naming the field (coincident points, a 3-number point, --at past the end, one
// curvature without the other between two points); a missing angle is a usage error (exit 2).
TEST(ClothoidCli, ErrorsNameTheInput) {
  struct Case {
    std::vector<std::string> args;
    int code;
    std::string field;
  };
  const std::vector<std::string> base = {"clothoid", "--start-point", "0,0", "--start-angle", "0", "--end-angle", "1"};
  const auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> a = base;
    a.insert(a.end(), extra.begin(), extra.end());
    return a;
  };
  for (const Case& c :
       {Case{with({"--end-point", "0,0"}), 3, "p1"}, Case{with({"--end-point", "1,0,0"}), 3, "end-point"},
        Case{with({"--end-point", "1,0", "--at", "0,99"}), 3, "at"}}) {
    const ProcessResult r = hula(c.args);
    EXPECT_EQ(r.exit_code, c.code) << r.err;
    EXPECT_EQ(testing::stderr_error(r)["where"]["field"], c.field) << r.err;
  }
  const ProcessResult at = hula(with({"--end-point", "1,0", "--at", "0,99"}));
  EXPECT_EQ(testing::stderr_error(at)["where"]["index"], 1) << at.err;
  // Between two points one curvature alone names the missing one.
  const ProcessResult one = hula(with({"--end-point", "1,0", "--start-curvature", "1"}));
  EXPECT_EQ(one.exit_code, 3) << one.err;
  EXPECT_EQ(testing::stderr_error(one)["code"], "InvalidArgument") << one.err;
  EXPECT_EQ(testing::stderr_error(one)["where"]["field"], "end_curvature") << one.err;
  const ProcessResult r = hula({"clothoid", "--start-point", "0,0", "--end-point", "1,0"});
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_EQ(testing::stderr_error(r)["code"], "UsageError");
}

// Writes points "x y" lines to `path`.
void write_points(const std::filesystem::path& path, const std::vector<std::array<double, 2>>& pts) {
  std::ofstream out(path);
  out.precision(17);
  for (const auto& p : pts) out << p[0] << ' ' << p[1] << '\n';
}

// checks: --points --closed (G2 by default) through six points of a loop: "through" 6, six segments, each segment's
// printed end equal to the next one's start, angle (mod 2π) and curvature to 1e-9, the closing joint included,
// every segment ending on its data point; the -o curve file is a natural curve of the same length through the
// points (evaluated exactly, to 1e-9); --g1 gives the same positions and angles but not the curvatures; --biarc gives
// 12 arcs (dkappa 0) with G1 joints.
TEST(ClothoidCli, ClosedSplineThroughPoints) {
  testing::TempDir dir;
  const std::vector<std::array<double, 2>> pts{{2, 0}, {1, 1.6}, {-1, 1.9}, {-2.2, 0.2}, {-1, -1.7}, {1.2, -1.5}};
  write_points(dir.path() / "loop.txt", pts);
  const std::string file = (dir.path() / "loop.txt").string(), out = (dir.path() / "loop.json").string();
  const auto check = [&](const json& j, std::size_t per, bool g2) {
    const json& s = j["segments"];
    EXPECT_EQ(j["through"], 6);
    EXPECT_EQ(j["closed"], true);
    ASSERT_EQ(s.size(), 6 * per);
    for (std::size_t i = 0; i < s.size(); ++i) {
      const json& a = s[i];
      const json& b = s[(i + 1) % s.size()];
      for (std::size_t k = 0; k < 2; ++k) EXPECT_NEAR(a["end"][k].get<double>(), b["start"][k].get<double>(), 1e-9);
      EXPECT_NEAR(std::remainder(a["theta1"].get<double>() - b["theta0"].get<double>(), 2 * std::numbers::pi), 0.0,
                  1e-9);
      if (g2) {
        EXPECT_NEAR(a["kappa1"].get<double>(), b["kappa0"].get<double>(), 1e-9) << i;
      }
      if ((i + 1) % per == 0) {
        const auto& p = pts[((i + 1) / per) % pts.size()];
        EXPECT_NEAR(a["end"][0].get<double>(), p[0], 1e-9);
        EXPECT_NEAR(a["end"][1].get<double>(), p[1], 1e-9);
      }
    }
  };
  const ProcessResult r = hula({"clothoid", "--points", file, "--closed", "-o", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["kind"], "g2");
  check(j, 1, true);
  const curve::Curve c = io::read_curve_file(out);
  ASSERT_EQ(c.kind(), curve::Kind::Natural);
  EXPECT_NEAR(c.length(), j["length"].get<double>(), 1e-12);
  double at = 0.0;
  for (std::size_t i = 0; i < 6; ++i) {
    at += j["segments"][i]["length"].get<double>();
    const auto& p = pts[(i + 1) % 6];
    EXPECT_LT(distance(c.point(std::min(at, c.length())), Vec3{p[0], p[1], 0}), 1e-9) << i;
  }
  const ProcessResult g1 = hula({"clothoid", "--points", file, "--closed", "--g1"});
  ASSERT_EQ(g1.exit_code, 0) << g1.err;
  const json k = json::parse(g1.out);
  EXPECT_EQ(k["kind"], "g1");
  check(k, 1, false);
  double jump = 0.0;
  for (std::size_t i = 0; i < 6; ++i)
    jump = std::max(
        jump, std::abs(k["segments"][i]["kappa1"].get<double>() - k["segments"][(i + 1) % 6]["kappa0"].get<double>()));
  EXPECT_GT(jump, 1e-3);
  const ProcessResult b = hula({"clothoid", "--points", file, "--closed", "--biarc"});
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const json bj = json::parse(b.out);
  EXPECT_EQ(bj["kind"], "biarc");
  check(bj, 2, false);
  for (const json& seg : bj["segments"]) EXPECT_EQ(seg["dkappa"].get<double>(), 0.0);
}

// checks: an open spline with given end angles starts and ends with them (mod 2π, 1e-12); points on a circle of
// radius 2 give κ = 0.5 on every segment (1e-10); the usage errors of the new options exit 2 and bad points exit 3
// naming "points" and the index.
TEST(ClothoidCli, OpenSplineEndAnglesCircleAndErrors) {
  testing::TempDir dir;
  std::vector<std::array<double, 2>> circle;
  for (const double t : {0.0, 0.5, 1.3, 1.9, 2.8}) circle.push_back({2 * std::cos(t), 2 * std::sin(t)});
  write_points(dir.path() / "arc.txt", circle);
  const std::string file = (dir.path() / "arc.txt").string();
  const ProcessResult r = hula({"clothoid", "--points", file});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["closed"], false);
  for (const json& seg : j["segments"]) {
    EXPECT_NEAR(seg["kappa0"].get<double>(), 0.5, 1e-10);
    EXPECT_NEAR(seg["dkappa"].get<double>(), 0.0, 1e-10);
  }
  EXPECT_NEAR(j["length"].get<double>(), 2 * 2.8, 1e-10);
  const ProcessResult e = hula({"clothoid", "--points", file, "--start-angle", "0.1", "--end-angle", "3"});
  ASSERT_EQ(e.exit_code, 0) << e.err;
  const json ej = json::parse(e.out);
  EXPECT_NEAR(ej["segments"][0]["theta0"].get<double>(), 0.1, 1e-15);
  EXPECT_NEAR(std::remainder(ej["segments"][3]["theta1"].get<double>() - 3.0, 2 * std::numbers::pi), 0.0, 1e-12);
  // One end's angle, the other end's curvature: the circle's own values give the circle back.
  const ProcessResult k = hula({"clothoid", "--points", file, "--end-angle", "4.3707963267948966",  // 2.8 + π/2
                                "--start-curvature", "0.5"});
  ASSERT_EQ(k.exit_code, 0) << k.err;
  for (const json& seg : json::parse(k.out)["segments"]) {
    EXPECT_NEAR(seg["kappa0"].get<double>(), 0.5, 1e-10);
    EXPECT_NEAR(seg["dkappa"].get<double>(), 0.0, 1e-10);
  }
  const ProcessResult kg1 = hula({"clothoid", "--points", file, "--g1", "--end-curvature", "0.5"});
  EXPECT_EQ(kg1.exit_code, 3) << kg1.err;
  EXPECT_EQ(testing::stderr_error(kg1)["where"]["field"], "end_curvature") << kg1.err;
  for (const auto& args : {std::vector<std::string>{"clothoid", "--points", file, "--g1", "--g2"},
                           std::vector<std::string>{"clothoid", "--points", file, "--end-point", "1,1"},
                           std::vector<std::string>{"clothoid", "--start-point", "0,0", "--start-angle", "0",
                                                    "--end-point", "1,0", "--end-angle", "0", "--closed"}}) {
    const ProcessResult u = hula(args);
    EXPECT_EQ(u.exit_code, 2) << u.err;
    EXPECT_EQ(testing::stderr_error(u)["code"], "UsageError") << u.err;
  }
  write_points(dir.path() / "dup.txt", {{0, 0}, {1, 0}, {1, 0}, {2, 1}});
  const ProcessResult d = hula({"clothoid", "--points", (dir.path() / "dup.txt").string()});
  EXPECT_EQ(d.exit_code, 3) << d.err;
  EXPECT_EQ(testing::stderr_error(d)["where"]["field"], "points");
  EXPECT_EQ(testing::stderr_error(d)["where"]["index"], 2);
  write_points(dir.path() / "two.txt", {{0, 0}, {1, 0}});
  const ProcessResult t = hula({"clothoid", "--points", (dir.path() / "two.txt").string(), "--closed"});
  EXPECT_EQ(t.exit_code, 3) << t.err;
  EXPECT_EQ(testing::stderr_error(t)["code"], "TooFewPoints") << t.err;
}

}  // namespace
}  // namespace hula::intrinsic
