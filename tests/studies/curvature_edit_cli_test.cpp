// SPDX-License-Identifier: MIT
// `hula reconstruct --curve` as a user runs it (design by curvature, issue 21): the thesis's Example 1 corner
// (examples/workspace/example1-corner.json) edited with a change of |κ| keeps its data end points (closed form),
// end tangents and (--hold curvature) its natural ends' κ = 0, read back from the written curve file; the
// refusals of options that do not apply.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "hula/diffgeom/frenet.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/testing/run_process.hpp"
#include "hula/testing/temp_dir.hpp"

namespace hula {
namespace {

using io::Json;

const std::string kExample1 = std::string(HULA_SOURCE_DIR) + "/examples/workspace/example1-corner.json";
// A cos² bump of |κ| at s = 62 (30 % of the corner's length), half-width 34, height 0.004.
const std::string kBump = "piecewise(abs((s - 62)/34) < 1, 0.004*cos(1.5707963267948966*(s - 62)/34)^2, 0)";

diffgeom::FrenetPoint at_end(const nurbs::NurbsCurve& c, bool end) {
  diffgeom::FrenetOptions o;
  if (end) o.eval.side = nurbs::Side::Left;
  return diffgeom::frenet(c, end ? c.domain().end : c.domain().start, o);
}

// checks: the edited curve file is an interpolated spline of at most 6 points through (0, 0) and (100, 100), with the
// original's end tangents, κ = 0 at both natural ends (G2), no inflection, and the report says so.
TEST(CurvatureEditCli, KeepsExample1Ends) {
  testing::TempDir dir;
  const std::string out = (dir / "edited.json").string();
  const testing::ProcessResult r = testing::run_process(
      HULA_CLI_PATH,
      {"reconstruct", "--curve", kExample1, "--kappa", kBump, "--target", "change", "--hold", "curvature", "-o", out});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json report = Json::parse(r.out)["edit"];
  EXPECT_EQ(report["kind"], "interpolated");
  EXPECT_EQ(report["handles_before"], 3);
  EXPECT_LE(report["handles_after"].get<int>(), 6);
  EXPECT_EQ(report["inflections_after"], 0);
  const curve::Curve before = io::read_curve_file(kExample1);
  const curve::Curve after = io::read_curve_file(out);
  ASSERT_EQ(after.kind(), curve::Kind::Interpolated);
  const auto& data = std::get<curve::InterpolatedData>(after.data());
  EXPECT_EQ(data.points.front(), (Vec3{0, 0, 0}));
  EXPECT_EQ(data.points.back(), (Vec3{100, 100, 0}));
  for (const bool end : {false, true}) {
    const diffgeom::FrenetPoint a = at_end(before.nurbs(), end), b = at_end(after.nurbs(), end);
    EXPECT_LE(distance(a.position, b.position), 1e-9);
    EXPECT_LE(distance(a.tangent, b.tangent), 1e-9);
    EXPECT_LE(std::abs(b.signed_curvature), 1e-9);
  }
}

// checks: options that do not apply with --curve, and --curve's own bad values, are refused with the usage or input
// exit code and a message naming them.
TEST(CurvatureEditCli, RefusesWhatDoesNotApply) {
  const auto run = [](std::vector<std::string> extra) {
    std::vector<std::string> args{"reconstruct", "--curve", kExample1, "--kappa", "0.01"};
    args.insert(args.end(), extra.begin(), extra.end());
    return testing::run_process(HULA_CLI_PATH, args);
  };
  testing::ProcessResult r = run({"--length", "10"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--length"), std::string::npos) << r.err;
  r = run({"--fit-tolerance", "1e-3"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--fit-tolerance"), std::string::npos) << r.err;
  r = run({"--hold", "g3"});
  EXPECT_EQ(r.exit_code, 2);
  r = run({"--tau", "0.1"});
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("torsion"), std::string::npos) << r.err;
  // Without --curve, --length and --tau are still required.
  r = testing::run_process(HULA_CLI_PATH, {"reconstruct", "--kappa", "1", "--tau", "0"});
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--length"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace hula
