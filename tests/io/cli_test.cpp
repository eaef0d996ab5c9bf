// SPDX-License-Identifier: MIT
// Contract tests of the `hula` binary (run as a process): exit codes 0/2/3/4,
// the error JSON on stderr, machine-readable JSON on stdout, 2-D output for
// 2-D files, and atomic output files (a failing command leaves an existing
// file byte-identical and no temporary file behind).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "hula/io/atomic_file.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/testing/process_json.hpp"
#include "hula/testing/run_process.hpp"
#include "hula/testing/temp_dir.hpp"

#ifndef HULA_CLI_PATH
#error "HULA_CLI_PATH must name the hula binary"
#endif

namespace hula::io {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::ProcessResult;

ProcessResult hula(const std::vector<std::string>& args) { return testing::run_process(HULA_CLI_PATH, args); }

std::string data(const std::string& name) {
  const char* root = std::getenv("HULA_TEST_DATA");
  return (fs::path(root ? root : "tests/data") / "io" / name).string();
}

using testing::TempDir;

// Parses stderr as the error JSON and checks its code.
json expect_error_json(const ProcessResult& r, const std::string& code) {
  const json e = testing::stderr_error(r);
  EXPECT_EQ(e.value("code", ""), code) << r.err;
  EXPECT_TRUE(e.contains("message") && e["message"].is_string()) << r.err;
  EXPECT_TRUE(e.contains("where") && e["where"].is_object()) << r.err;
  return json{{"error", e}};
}

// checks: --version prints the version and exits 0.
TEST(Cli, Version) {
  const ProcessResult r = hula({"--version"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.out.find("hula "), std::string::npos) << r.out;
}

// checks: command-line errors exit 2 with the usage error JSON on stderr.
TEST(Cli, UsageErrorsExit2) {
  for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
           {"--no-such-option"},
           {"eval"},
           {"eval", data("circle_rational.json")},
           {"bogus-command"},
           {"eval", data("circle_rational.json"), "--at", "0", "--side", "up"},
           {"eval", data("circle_rational.json"), "--at", "0", "--clamp", "--extrapolate"},
           {"interpolate", "-o", "x.json"}}) {
    const ProcessResult r = hula(args);
    EXPECT_EQ(r.exit_code, 2) << args[0] << " " << r.err;
    expect_error_json(r, "UsageError");
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
}

// checks: a file with decreasing knots exits 3 with InvalidKnots naming field knots and index 3.
TEST(Cli, BadKnotFileExit3WithErrorJson) {
  const ProcessResult r = hula({"eval", data("bad_knots.json"), "--at", "0.5"});
  EXPECT_EQ(r.exit_code, 3);
  const json j = expect_error_json(r, "InvalidKnots");
  EXPECT_EQ(j["error"]["where"]["field"], "knots");
  EXPECT_EQ(j["error"]["where"]["index"], 3);
  EXPECT_TRUE(r.out.empty());
  const ProcessResult info = hula({"info", data("bad_knots.json")});
  EXPECT_EQ(info.exit_code, 3);
  expect_error_json(info, "InvalidKnots");
}

// checks: an out-of-domain or unparsable t exits 3 with the error naming t and its index.
TEST(Cli, BadParameterExit3) {
  const ProcessResult r = hula({"eval", data("circle_rational.json"), "--at", "0.5,1.5"});
  EXPECT_EQ(r.exit_code, 3);
  const json j = expect_error_json(r, "OutOfDomain");
  EXPECT_EQ(j["error"]["where"]["field"], "t");
  EXPECT_EQ(j["error"]["where"]["index"], 1);
  EXPECT_NE(j["error"]["message"].get<std::string>().find("1.5"), std::string::npos);

  const ProcessResult p = hula({"eval", data("circle_rational.json"), "--at", "0,abc"});
  EXPECT_EQ(p.exit_code, 3);
  const json k = expect_error_json(p, "ParseError");
  EXPECT_NE(k["error"]["message"].get<std::string>().find("t[1] = \"abc\""), std::string::npos);
}

// checks: missing files exit 3 with IoError naming the path.
TEST(Cli, MissingFileExit3) {
  const ProcessResult r = hula({"info", "/nonexistent/curve.json"});
  EXPECT_EQ(r.exit_code, 3);
  const json j = expect_error_json(r, "IoError");
  EXPECT_NE(j["error"]["message"].get<std::string>().find("/nonexistent/curve.json"), std::string::npos);
}

// checks: a derivative that overflows double precision exits 4 (NumericalFailure).
TEST(Cli, NumericalFailureExit4) {
  TempDir dir;
  write_file_atomically(dir / "steep.json", R"({"kind": "nurbs", "degree": 1, "knots": [0, 0, 1e-200, 1e-200],
                                              "control_points": [[0, 0], [1e200, 0]]})");
  const ProcessResult r = hula({"eval", (dir / "steep.json").string(), "--at", "0", "--derivatives", "1"});
  EXPECT_EQ(r.exit_code, 4) << r.err;
  expect_error_json(r, "NumericalFailure");
}

// checks: eval prints {"results": [{"t", "derivatives"}]} with [x, y] vectors for a 2-D curve;
// --clamp and --extrapolate are accepted outside the domain.
TEST(Cli, EvalOutputShape) {
  const ProcessResult r = hula({"eval", data("circle_rational.json"), "--at", "0,0.25", "--derivatives", "2"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  ASSERT_EQ(j["results"].size(), 2u);
  EXPECT_EQ(j["results"][1]["t"], 0.25);
  ASSERT_EQ(j["results"][1]["derivatives"].size(), 3u);
  for (const auto& v : j["results"][1]["derivatives"]) EXPECT_EQ(v.size(), 2u);

  const ProcessResult c = hula({"eval", data("circle_rational.json"), "--at", "1.5", "--clamp"});
  ASSERT_EQ(c.exit_code, 0) << c.err;
  EXPECT_NEAR(json::parse(c.out)["results"][0]["derivatives"][0][0].get<double>(), 1.0, 1e-15);
  EXPECT_EQ(hula({"eval", data("circle_rational.json"), "--at", "1.5", "--extrapolate"}).exit_code, 0);
  EXPECT_EQ(hula({"eval", data("circle_rational.json"), "--at", "0.25", "--side", "left"}).exit_code, 0);
}

// checks: interpolate writes a nurbs file equal to interpolate_cubic's curve and prints a summary;
// --keep-inputs writes the interpolated kind; 2-D points give 2-D output.
TEST(Cli, InterpolateWritesCurve) {
  TempDir dir;
  const fs::path out = dir / "curve.json";
  const ProcessResult r = hula({"interpolate", "--points", data("thesis_points.csv"), "--start", "bessel", "--end",
                                "clamped:100,0,0", "-o", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json summary = json::parse(r.out);
  EXPECT_EQ(summary["output"], out.string());
  EXPECT_EQ(summary["degree"], 3);
  EXPECT_EQ(summary["control_points"], 6);
  const curve::Curve f = read_curve_file(out);
  EXPECT_EQ(f.kind(), curve::Kind::Nurbs);
  nurbs::InterpolationOptions o;
  o.start = nurbs::EndCondition::bessel();
  o.end = nurbs::EndCondition::clamped({100, 0, 0});
  const std::vector<Vec3> pts = {{0, 0, 0}, {40, 25, 0}, {80, -25, 0}, {120, 0, 0}};
  EXPECT_EQ(f.nurbs(), nurbs::interpolate_cubic(pts, o));
  EXPECT_EQ(dir.names(), std::vector<std::string>{"curve.json"});

  const ProcessResult k = hula({"interpolate", "--points", data("thesis_points.csv"), "--keep-inputs",
                                "--parameterisation", "centripetal", "-o", out.string()});
  ASSERT_EQ(k.exit_code, 0) << k.err;
  const curve::Curve g = read_curve_file(out);
  EXPECT_EQ(g.kind(), curve::Kind::Interpolated);
  EXPECT_EQ(std::get<curve::InterpolatedData>(g.data()).parameterisation, nurbs::Parameterisation::Centripetal);
  // --parameterisation foley: the file keeps "foley" and resolves to interpolate_cubic at Foley parameters.
  const ProcessResult fo = hula({"interpolate", "--points", data("thesis_points.csv"), "--keep-inputs",
                                 "--parameterisation", "foley", "-o", out.string()});
  ASSERT_EQ(fo.exit_code, 0) << fo.err;
  EXPECT_NE(read_text_file(out).find("\"foley\""), std::string::npos);
  nurbs::InterpolationOptions fopt;
  fopt.parameterisation = nurbs::Parameterisation::Foley;
  EXPECT_EQ(read_curve_file(out).nurbs(), nurbs::interpolate_cubic(pts, fopt));

  write_file_atomically(dir / "p2.csv", "0,0\n1,1\n2,0\n");
  const ProcessResult t = hula(
      {"interpolate", "--points", (dir / "p2.csv").string(), "--knots", "0,1,3", "-o", (dir / "c2.json").string()});
  ASSERT_EQ(t.exit_code, 0) << t.err;
  EXPECT_EQ(read_curve_file(dir / "c2.json").nurbs().dimension(), 2);
  const json c2 = json::parse(read_text_file(dir / "c2.json"));
  for (const auto& p : c2["control_points"]) EXPECT_EQ(p.size(), 2u);
}

// checks interpolate --lagrange writes nurbs::interpolate_lagrange's Bézier curve (degree N − 1) at the
// --parameterisation parameters, bit for bit, and refuses --start with it (usage, exit 2)
TEST(Cli, InterpolateLagrangeWritesThePolynomial) {
  TempDir dir;
  const fs::path out = dir / "lagrange.json";
  const ProcessResult r = hula({"interpolate", "--points", data("thesis_points.csv"), "--lagrange",
                                "--parameterisation", "centripetal", "-o", out.string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<Vec3> pts = {{0, 0, 0}, {40, 25, 0}, {80, -25, 0}, {120, 0, 0}};
  const nurbs::NurbsCurve expected =
      nurbs::interpolate_lagrange(pts, nurbs::parameterise(pts, nurbs::Parameterisation::Centripetal), 2);
  const nurbs::NurbsCurve got = read_curve_file(out).nurbs();
  EXPECT_EQ(got.degree(), 3);
  EXPECT_EQ(got.knots().values().size(), expected.knots().values().size());
  for (std::size_t i = 0; i < expected.control_points().size(); ++i)
    EXPECT_EQ(got.control_points()[i], expected.control_points()[i]) << i;
  EXPECT_EQ(json::parse(r.out)["method"], "lagrange");
  EXPECT_EQ(hula({"interpolate", "--points", data("thesis_points.csv"), "--lagrange", "--start", "bessel", "-o",
                  out.string()})
                .exit_code,
            2);
}

// checks: a failing interpolate leaves an existing output file byte-identical and no temporary file.
TEST(Cli, FailingInterpolateLeavesExistingFileUntouched) {
  TempDir dir;
  const fs::path existing = dir / "existing.json";
  const std::string original = "{\"kind\": \"bezier\", \"control_points\": [[0, 0], [1, 1]]}\n";
  write_file_atomically(existing, original);
  write_file_atomically(dir / "bad.csv", "0,0,0\n1,oops,0\n2,0,0\n");
  write_file_atomically(dir / "same.csv", "0,0,0\n0,0,0\n");

  const ProcessResult bad = hula({"interpolate", "--points", (dir / "bad.csv").string(), "-o", existing.string()});
  EXPECT_EQ(bad.exit_code, 3);
  const json j = expect_error_json(bad, "ParseError");
  EXPECT_EQ(j["error"]["where"]["line"], 2);
  EXPECT_EQ(j["error"]["where"]["column"], 3);

  const ProcessResult end =
      hula({"interpolate", "--points", data("thesis_points.csv"), "--end", "clamped:1,x", "-o", existing.string()});
  EXPECT_EQ(end.exit_code, 3);
  expect_error_json(end, "ParseError");

  const ProcessResult knots =
      hula({"interpolate", "--points", data("thesis_points.csv"), "--knots", "0,2,1,3", "-o", existing.string()});
  EXPECT_EQ(knots.exit_code, 3);
  EXPECT_EQ(expect_error_json(knots, "InvalidArgument")["error"]["where"]["field"], "knots");

  EXPECT_EQ(read_text_file(existing), original);
  EXPECT_EQ(dir.names(), (std::vector<std::string>{"bad.csv", "existing.json", "same.csv"}));

  // A failure while writing (the target is a directory) leaves no temporary file either.
  fs::create_directory(dir / "sub");
  write_file_atomically(dir / "sub" / "keep", "x");
  const ProcessResult w = hula({"interpolate", "--points", data("thesis_points.csv"), "-o", (dir / "sub").string()});
  EXPECT_EQ(w.exit_code, 3);
  expect_error_json(w, "IoError");
  EXPECT_EQ(dir.names(), (std::vector<std::string>{"bad.csv", "existing.json", "same.csv", "sub"}));
}

// checks: info prints the documented members; a planar 3-D curve reports planar with normal +Z.
TEST(Cli, InfoMembers) {
  const ProcessResult r = hula({"info", data("interpolated_thesis.json")});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  for (const char* key : {"kind", "degree", "knots", "control_points", "weights", "domain", "rational", "dimension",
                          "length", "planarity", "inputs"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["kind"], "interpolated");
  EXPECT_TRUE(j["weights"].is_null());
  EXPECT_EQ(j["rational"], false);
  EXPECT_EQ(j["dimension"], 3);
  EXPECT_EQ(j["planarity"]["planar"], true);
  EXPECT_EQ(j["planarity"]["normal"], json::array({0.0, 0.0, 1.0}));

  TempDir dir;
  write_file_atomically(dir / "twisted.json", R"({"kind": "bezier", "control_points": [[0, 0, 0], [1, 0, 0],
                                                 [1, 1, 0], [1, 1, 1]]})");
  const json t = json::parse(hula({"info", (dir / "twisted.json").string()}).out);
  EXPECT_EQ(t["planarity"]["planar"], false);
  EXPECT_TRUE(t["planarity"]["normal"].is_null());
}

// checks: the demo reports C1 but not C2 at the thesis's double knot (plain `hula` prints help).
TEST(Cli, DemoReportsDoubleKnotContinuity) {
  const ProcessResult r = hula({"demo"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  ASSERT_EQ(j["examples"].size(), 4u);
  const json& dk = j["examples"][3];
  EXPECT_EQ(dk["continuity"]["t"], 0.33);
  EXPECT_EQ(dk["continuity"]["multiplicity"], 2);
  EXPECT_EQ(dk["continuity"]["parametric"], 1);  // C1, not C2 (the analysis's knot entry)
  EXPECT_EQ(dk["derivative_table"]["rows"].size(), 4u);
}

}  // namespace
}  // namespace hula::io

namespace hula::io {
namespace {

// checks: `hula law` output shape (results like eval, scalars as one-element arrays), printed derivative,
// roots/extrema/integral against closed forms, and positioned errors with exit 3.
TEST(CliLaw, OutputAndAnalyses) {
  const ProcessResult r =
      hula({"law", "sin(t)", "--at", "0,1", "--derivatives", "2", "--print-derivative", "1", "--roots", "0.5,7",
            "--extrema", "0,6.283185307179586", "--integrate", "0,3.141592653589793"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_EQ(j["expression"], "sin(t)");
  ASSERT_EQ(j["results"].size(), 2u);
  EXPECT_EQ(j["results"][1]["t"], 1.0);
  ASSERT_EQ(j["results"][1]["derivatives"].size(), 3u);
  EXPECT_EQ(j["results"][1]["derivatives"][0].size(), 1u);
  EXPECT_DOUBLE_EQ(j["results"][1]["derivatives"][1][0].get<double>(), std::cos(1.0));
  EXPECT_EQ(j["derivative"]["expression"], "cos(t)");
  ASSERT_EQ(j["roots"]["roots"].size(), 2u);
  EXPECT_NEAR(j["roots"]["roots"][0].get<double>(), 3.141592653589793, 1e-13);
  EXPECT_NEAR(j["extrema"]["maximum"]["t"].get<double>(), 1.5707963267948966, 1e-12);
  EXPECT_EQ(j["integral"]["method"], "symbolic");
  EXPECT_NEAR(j["integral"]["value"].get<double>(), 2.0, 1e-14);

  const ProcessResult bad = hula({"law", "t + vec(t, t, t)"});
  EXPECT_EQ(bad.exit_code, 3);
  const json e = expect_error_json(bad, "ParseError");
  EXPECT_EQ(e["error"]["where"]["column"], 3);
  EXPECT_NE(e["error"]["message"].get<std::string>().find("'+'"), std::string::npos);

  const ProcessResult undef = hula({"law", "1/t", "--at", "1,0"});
  EXPECT_EQ(undef.exit_code, 3);
  const json u = expect_error_json(undef, "OutOfDomain");
  EXPECT_NE(
      u["error"]["message"].get<std::string>().find("t[1] = 0: the law is undefined there (1/t: division by zero)"),
      std::string::npos);
  EXPECT_EQ(hula({"law", "sin(t", "--at", "0"}).exit_code, 3);
  EXPECT_EQ(hula({"law", "vec(t, t)", "--roots", "0,1"}).exit_code, 3);
}

// checks: `hula eval` and `info` take a law curve file; eval values are the law's (exact), info reports
// the stand-in NURBS and its deviation; a law undefined in its domain is an invalid file (exit 3).
TEST(CliLaw, LawCurveFiles) {
  TempDir dir;
  const std::string helix = (dir / "helix.json").string();
  write_file_atomically(helix, R"j({"kind": "law", "expression": "vec(2*cos(t), 2*sin(t), 0.5*t)",
                                   "parameter": "t", "domain": [0, 12.566370614359172]})j");
  const ProcessResult r = hula({"eval", helix, "--at", "0,1", "--derivatives", "1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const json j = json::parse(r.out);
  EXPECT_DOUBLE_EQ(j["results"][1]["derivatives"][0][0].get<double>(), 2 * std::cos(1.0));
  EXPECT_DOUBLE_EQ(j["results"][1]["derivatives"][1][2].get<double>(), 0.5);
  EXPECT_EQ(hula({"eval", helix, "--at", "13"}).exit_code, 3);
  EXPECT_EQ(hula({"eval", helix, "--at", "13", "--clamp"}).exit_code, 0);
  const ProcessResult info = hula({"info", helix});
  ASSERT_EQ(info.exit_code, 0) << info.err;
  const json ji = json::parse(info.out);
  EXPECT_EQ(ji["kind"], "law");
  EXPECT_LE(ji["law"]["approximation_deviation"].get<double>(), 1e-6);
  EXPECT_NEAR(ji["length"].get<double>(), std::sqrt(4.25) * 12.566370614359172, 1e-5);

  const std::string bad = (dir / "bad.json").string();
  write_file_atomically(bad, R"j({"kind": "law", "expression": "vec(t, 1/t)", "domain": [-1, 1]})j");
  const ProcessResult b = hula({"info", bad});
  EXPECT_EQ(b.exit_code, 3);
  const json e = expect_error_json(b, "InvalidArgument");
  EXPECT_EQ(e["error"]["where"]["field"], "domain");
}

}  // namespace
}  // namespace hula::io
