// SPDX-License-Identifier: MIT
// Contract tests of `hula analyse` (run as a process): exit codes, the exact
// JSON shape of io::curve_analysis_json (docs/formats.md "Curve analysis":
// columns t, s, points, frames {T, N, B}, curvature, torsion,
// curvature_derivative, speed, bishop {U, V}, then fins and planarity), null
// where undefined, values against the helix closed form, and arc-length
// sampling.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "hula/testing/process_json.hpp"
#include "hula/testing/run_process.hpp"
#include "hula/testing/temp_dir.hpp"

#ifndef HULA_CLI_PATH
#error "HULA_CLI_PATH must name the hula binary"
#endif

namespace hula::diffgeom {
namespace {

using nlohmann::json;
using testing::ProcessResult;

ProcessResult hula(const std::vector<std::string>& args) { return testing::run_process(HULA_CLI_PATH, args); }

std::string write(const testing::TempDir& dir, const std::string& name, const std::string& text) {
  const std::filesystem::path p = dir.path() / name;
  std::ofstream(p) << text;
  return p.string();
}

constexpr const char* kHelix =
    R"J({"kind": "law", "expression": "vec(2*cos(t), 2*sin(t), 0.5*t)", "parameter": "t", "domain": [0, 12.566370614359172]})J";
constexpr const char* kLine = R"J({"kind": "bezier", "control_points": [[0, 0, 0], [1, 1, 0], [2, 2, 0], [3, 3, 0]]})J";

// checks the exact key set and the helix values κ = 2/4.25, τ = 0.5/4.25, s = √4.25 t.
TEST(AnalyseCli, HelixShapeAndValues) {
  const testing::TempDir dir;
  const ProcessResult r = hula({"analyse", write(dir, "helix.json", kHelix), "--at", "0,1,2.5"});
  const json j = testing::stdout_json(r);
  std::vector<std::string> keys;
  for (const auto& [k, v] : j.items()) keys.push_back(k);
  std::sort(keys.begin(), keys.end());
  EXPECT_EQ(keys, (std::vector<std::string>{"bishop", "curvature", "curvature_derivative", "fins", "frames",
                                            "planarity", "points", "s", "speed", "t", "torsion"}));
  ASSERT_EQ(j["t"].size(), 3U);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_NEAR(j["curvature"][i].get<double>(), 2 / 4.25, 1e-10);
    EXPECT_NEAR(j["torsion"][i].get<double>(), 0.5 / 4.25, 1e-10);
    EXPECT_NEAR(j["s"][i].get<double>(), std::sqrt(4.25) * j["t"][i].get<double>(), 1e-10);
    EXPECT_EQ(j["bishop"]["U"][i].size(), 3U);
    EXPECT_EQ(j["frames"]["T"][i].size(), 3U);
  }
  EXPECT_FALSE(j["planarity"]["planar"].get<bool>());
}

// checks null for N, B, torsion, curvature_derivative on a straight line while T, κ = 0 and the Bishop frame
// are present.
TEST(AnalyseCli, NullWhereUndefined) {
  const testing::TempDir dir;
  const ProcessResult r = hula({"analyse", write(dir, "line.json", kLine), "--samples", "3"});
  const json j = testing::stdout_json(r);
  ASSERT_EQ(j["t"].size(), 3U);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_TRUE(j["frames"]["N"][i].is_null());
    EXPECT_TRUE(j["frames"]["B"][i].is_null());
    EXPECT_TRUE(j["torsion"][i].is_null());
    EXPECT_TRUE(j["curvature_derivative"][i].is_null());
    EXPECT_EQ(j["curvature"][i].get<double>(), 0.0);
    EXPECT_TRUE(j["frames"]["T"][i].is_array());
    EXPECT_TRUE(j["bishop"]["U"][i].is_array());
  }
  EXPECT_NEAR(j["s"][2].get<double>(), 3 * std::sqrt(2.0), 1e-12);
}

// checks --by arclength: equal arc-length steps along the helix (s = √4.25 t).
TEST(AnalyseCli, ByArcLength) {
  const testing::TempDir dir;
  const ProcessResult r = hula({"analyse", write(dir, "helix.json", kHelix), "--samples", "5", "--by", "arclength"});
  const json j = testing::stdout_json(r);
  const double L = std::sqrt(4.25) * 4 * M_PI;
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_NEAR(j["s"][i].get<double>(), L * static_cast<double>(i) / 4, 1e-9);
    EXPECT_NEAR(j["t"][i].get<double>(), 4 * M_PI * static_cast<double>(i) / 4, 1e-9);
  }
}

// checks --features on the planar S-curve (x, x³ − x) as a cubic Bézier split at a double knot: one inflection
// at t = 0.5, the knot table at the double knot (4 left and 4 right derivatives; one cubic, so C3), and the
// curvature extrema and monotonicity against the closed form.
TEST(AnalyseCli, Features) {
  const testing::TempDir dir;
  const std::string f = write(dir, "s.json",
                              R"J({"kind": "nurbs", "degree": 3, "knots": [0, 0, 0, 0, 0.5, 0.5, 1, 1, 1, 1],
      "control_points": [[-1, 0], [-0.6666666666666666, 0.6666666666666666], [-0.3333333333333333, 0.3333333333333333],
                         [0.3333333333333333, -0.3333333333333333], [0.6666666666666666, -0.6666666666666666], [1, 0]]})J");
  const ProcessResult r = hula({"analyse", f, "--samples", "2", "--features"});
  const json j = testing::stdout_json(r);
  ASSERT_TRUE(j.contains("features"));
  const json& ft = j["features"];
  ASSERT_EQ(ft["inflections"].size(), 1U);
  EXPECT_NEAR(ft["inflections"][0]["t"].get<double>(), 0.5, 1e-10);
  ASSERT_EQ(ft["knots"].size(), 1U);
  EXPECT_EQ(ft["knots"][0]["multiplicity"], 2);
  EXPECT_EQ(ft["knots"][0]["parametric"], 3);
  EXPECT_EQ(ft["knots"][0]["geometric"], 3);
  EXPECT_EQ(ft["knots"][0]["left"].size(), 4U);
  EXPECT_EQ(ft["knots"][0]["right"].size(), 4U);
  EXPECT_TRUE(ft["torsion_extrema"].empty());  // planar: τ = 0 is never a strict extremum
  // Curvature monotonicity against the closed form: the signed κ = 6x / (1 + (3x² − 1)²)^{3/2} (x = 2t − 1) has its
  // extrema where 5u² + 6u − 1 = 0, u = 3x² − 1, i.e. x = ±0.618688 (t = 0.190656, 0.809344); the inflection at
  // t = 0.5 is not a violation in the signed analysis. Pieces: decreasing, increasing, decreasing.
  const json& m = ft["curvature_monotonicity"];
  EXPECT_FALSE(m["monotone"].get<bool>());
  const double x_ext = std::sqrt((1.0 + (-6.0 + std::sqrt(56.0)) / 10.0) / 3.0);
  ASSERT_EQ(m["violations"].size(), 2U);
  EXPECT_NEAR(m["violations"][0]["t"].get<double>(), (1.0 - x_ext) / 2.0, 1e-6);
  EXPECT_NEAR(m["violations"][1]["t"].get<double>(), (1.0 + x_ext) / 2.0, 1e-6);
  // The same two points are the maxima of |κ|, with |κ| = 6|x| / (1 + (3x² − 1)²)^{3/2} at (x, x³ − x).
  const json& extrema = ft["curvature_extrema"];
  ASSERT_EQ(extrema.size(), 2U) << extrema.dump();
  for (std::size_t i = 0; i < 2; ++i) {
    const double x = i == 0 ? -x_ext : x_ext;
    const double u = 3.0 * x * x - 1.0;
    EXPECT_EQ(extrema[i]["kind"], "maximum");
    EXPECT_NEAR(extrema[i]["t"].get<double>(), (1.0 + x) / 2.0, 1e-6);
    EXPECT_NEAR(extrema[i]["curvature"].get<double>(), 6.0 * std::abs(x) / std::pow(1.0 + u * u, 1.5), 1e-9);
    EXPECT_NEAR(extrema[i]["point"][0].get<double>(), x, 1e-6);
    EXPECT_NEAR(extrema[i]["point"][1].get<double>(), x * x * x - x, 1e-6);
  }
  ASSERT_EQ(m["pieces"].size(), 3U);
  EXPECT_EQ(m["pieces"][0]["trend"], "decreasing");
  EXPECT_EQ(m["pieces"][1]["trend"], "increasing");
  EXPECT_EQ(m["pieces"][2]["trend"], "decreasing");
}

// checks --svg writes curve.svg, kappa.svg and tau.svg (complete SVG documents with a drawn line) and still
// prints the points; curve.svg names its view and legends each fin kind with its scale (io::curve_figures).
TEST(AnalyseCli, SvgFiles) {
  const testing::TempDir dir;
  const ProcessResult r =
      hula({"analyse", write(dir, "helix.json", kHelix), "--samples", "2", "--svg", (dir.path() / "fig").string()});
  ASSERT_EQ(testing::stdout_json(r)["t"].size(), 2U);
  for (const char* name : {"curve.svg", "kappa.svg", "tau.svg"}) {
    std::ifstream in(dir.path() / "fig" / name);
    std::ostringstream buffer;
    buffer << in.rdbuf();
    const std::string text = buffer.str();
    EXPECT_EQ(text.rfind("<svg", 0), 0U) << name;
    EXPECT_NE(text.find("</svg>"), std::string::npos) << name;
    EXPECT_NE(text.find("<polyline"), std::string::npos) << name;
    if (std::string(name) == "curve.svg") {
      EXPECT_NE(text.find("curve (seen from -Y, 20 degrees above) with curvature, torsion fins"), std::string::npos);
      EXPECT_NE(text.find("curvature fins P - s\u03BAN, s = "), std::string::npos);
      EXPECT_NE(text.find("torsion fins P + s\u03C4B, s = "), std::string::npos);
    }
  }
}

// checks --svg DIR/ with a trailing separator (as docs/cli.md and the README write it) creates the
// directory and its figures; it was refused as "cannot create the directory"
TEST(AnalyseCli, SvgDirectoryWithTrailingSeparator) {
  const testing::TempDir dir;
  const std::string figures = (dir.path() / "figures").string() + "/";
  const ProcessResult r = hula({"analyse", write(dir, "helix.json", kHelix), "--samples", "2", "--svg", figures});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(dir.path() / "figures" / "curve.svg"));
}

// checks --fins adds each kind's comb with its scale to the output: the normal fins of the helix
// (radius 2 about the z axis, N pointing to the axis) with --fin-scale 0.5 end 2.5 from the axis, at
// the --fin-density parameters
TEST(AnalyseCli, FinsOfEveryKindWithScaleAndDensity) {
  const testing::TempDir dir;
  const ProcessResult r = hula({"analyse", write(dir, "helix.json", kHelix), "--samples", "2", "--fins",
                                "normal,bishop", "--fin-scale", "0.5", "--fin-density", "5"});
  const json fins = testing::stdout_json(r)["fins"];
  ASSERT_EQ(fins.size(), 3U);
  EXPECT_EQ(fins[0]["kind"], "normal");
  EXPECT_EQ(fins[1]["kind"], "bishop-u");
  EXPECT_EQ(fins[2]["kind"], "bishop-v");
  EXPECT_EQ(fins[0]["scale"].get<double>(), 0.5);
  ASSERT_EQ(fins[0]["tip"].size(), 5U);
  for (const auto& tip : fins[0]["tip"]) {
    const double x = tip[0].get<double>(), y = tip[1].get<double>();
    EXPECT_NEAR(std::hypot(x, y), 2.5, 1e-9);
  }
  const ProcessResult bad =
      hula({"analyse", write(dir, "h.json", kHelix), "--samples", "2", "--fins", "curvature,tosion"});
  EXPECT_EQ(bad.exit_code, 3);
  EXPECT_NE(testing::stderr_error(bad)["message"].get<std::string>().find("--fins[1] = 'tosion'"), std::string::npos)
      << bad.err;
}

// checks --fins combescure against the helix closed form Q − P = s (τ/κ T + B) = (0, 0, s √(a² + b²)/a)
// (thesis 8.3 eq. 44; a = 2, b = 0.5, s = 0.5) at every one of the --fin-density parameters
TEST(AnalyseCli, CombescureFinsOfTheHelix) {
  const testing::TempDir dir;
  const ProcessResult r = hula({"analyse", write(dir, "helix.json", kHelix), "--samples", "2", "--fins", "combescure",
                                "--fin-scale", "0.5", "--fin-density", "7"});
  const json fins = testing::stdout_json(r)["fins"];
  ASSERT_EQ(fins.size(), 1U);
  EXPECT_EQ(fins[0]["kind"], "combescure");
  ASSERT_EQ(fins[0]["tip"].size(), 7U);
  for (std::size_t i = 0; i < 7; ++i) {
    const json& p = fins[0]["base"][i];
    const json& q = fins[0]["tip"][i];
    EXPECT_NEAR(q[0].get<double>(), p[0].get<double>(), 1e-9);
    EXPECT_NEAR(q[1].get<double>(), p[1].get<double>(), 1e-9);
    EXPECT_NEAR(q[2].get<double>() - p[2].get<double>(), 0.5 * std::sqrt(4.25) / 2.0, 1e-9);
  }
}

// checks --svg also writes radius.svg, speed.svg and logcurvature.svg as complete SVG documents (start
// with <svg, end with </svg>), each with a drawn path for a cubic whose curvature varies.
TEST(AnalyseCli, SvgRadiusSpeedLogCurvature) {
  const testing::TempDir dir;
  constexpr const char* kCubic =
      R"J({"kind": "bezier", "control_points": [[0, 0, 0], [1, 2, 0.5], [3, -1, 1], [4, 1, 0]]})J";
  const ProcessResult r =
      hula({"analyse", write(dir, "cubic.json", kCubic), "--samples", "3", "--svg", (dir.path() / "fig").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* name : {"radius.svg", "speed.svg", "logcurvature.svg"}) {
    ASSERT_TRUE(std::filesystem::exists(dir.path() / "fig" / name)) << name;
    std::ifstream in(dir.path() / "fig" / name);
    std::ostringstream buffer;
    buffer << in.rdbuf();
    std::string text = buffer.str();
    while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
    EXPECT_EQ(text.rfind("<svg", 0), 0U) << name;
    EXPECT_TRUE(text.ends_with("</svg>")) << name;
    EXPECT_NE(text.find("<polyline"), std::string::npos) << name;
  }
}

// checks the fin scale chosen when none is given (diffgeom::auto_fin_scale, the one rule): printed with the
// comb and the same as the legend of curve.svg, whose fins are the analysis's
TEST(AnalyseCli, AutomaticFinScaleIsTheFiguresOne) {
  const testing::TempDir dir;
  const ProcessResult r = hula({"analyse", write(dir, "helix.json", kHelix), "--samples", "2", "--fins", "curvature",
                                "--svg", (dir.path() / "fig").string()});
  const json fins = testing::stdout_json(r)["fins"];
  ASSERT_EQ(fins.size(), 1U);
  const double scale = fins[0]["scale"].get<double>();
  EXPECT_GT(scale, 0.0);
  std::ifstream in(dir.path() / "fig" / "curve.svg");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  char shown[64];
  std::snprintf(shown, sizeof shown, "s = %.3g", scale);
  EXPECT_NE(buffer.str().find(shown), std::string::npos) << shown;
}

// checks exit codes: 2 for a usage error (both --at and --samples), 3 for an out-of-domain t naming t[1]
// and for a missing file.
TEST(AnalyseCli, ExitCodes) {
  const testing::TempDir dir;
  const std::string f = write(dir, "helix.json", kHelix);
  EXPECT_EQ(hula({"analyse", f, "--at", "0", "--samples", "3"}).exit_code, 2);
  EXPECT_EQ(hula({"analyse", f, "--by", "speed", "--samples", "3"}).exit_code, 2);
  const ProcessResult out = hula({"analyse", f, "--at", "0,20"});
  EXPECT_EQ(out.exit_code, 3);
  const json e = testing::stderr_error(out);
  EXPECT_EQ(e["code"], "OutOfDomain");
  EXPECT_EQ(e["where"]["index"], 1);
  EXPECT_EQ(hula({"analyse", (dir.path() / "missing.json").string(), "--samples", "2"}).exit_code, 3);
  EXPECT_EQ(hula({"analyse", f}).exit_code, 3);
}

}  // namespace
}  // namespace hula::diffgeom
