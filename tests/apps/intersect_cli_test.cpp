// SPDX-License-Identifier: MIT
// `hula intersect A B`, `hula intersect A --self` and `hula distance A B` run
// as a process: their JSON is the library's answer through the io codec, bit
// for bit (nurbs::intersect / self_intersect / curve_distance, then
// io::intersection_to_json / curve_distance_to_json), and the closed forms
// of a circle and a secant hold; bad command lines are refused naming the
// option.
#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hula/io/intersection_json.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/nurbs/bezier.hpp"
#include "hula/testing/curve_generators.hpp"
#include "hula/testing/process_json.hpp"
#include "hula/testing/run_process.hpp"
#include "hula/testing/temp_dir.hpp"

#ifndef HULA_CLI_PATH
#error "HULA_CLI_PATH must name the hula binary"
#endif

namespace hula {
namespace {

using nlohmann::json;

struct Files {
  testing::TempDir dir;
  std::string circle = (dir / "circle.json").string();
  std::string line = (dir / "line.json").string();
  std::string loop = (dir / "loop.json").string();
  nurbs::NurbsCurve c = testing::rational_circle(2.0, 0.4);
  nurbs::NurbsCurve l = [] {
    const std::vector<Vec3> P = {{-3, 1, 0}, {3, 1, 0}};
    return nurbs::make_bezier(P, {}, 2);
  }();
  nurbs::NurbsCurve o = [] {
    const std::vector<Vec3> P = {{0, 0, 0}, {2, 1, 0}, {-1, 1, 0}, {1, 0, 0}};
    return nurbs::make_bezier(P, {}, 2);
  }();
  Files() {
    io::write_curve_file(circle, c);
    io::write_curve_file(line, l);
    io::write_curve_file(loop, o);
  }
};

json members_of(json doc, std::initializer_list<const char*> drop) {
  for (const char* key : drop) doc.erase(key);
  return doc;
}

// checks: `hula intersect` prints the library's result through the codec; the circle x² + y² = 4 meets y = 1 at
// x = ±√3 (closed form).
TEST(IntersectCli, TwoCurvesAreTheLibraryAnswer) {
  const Files f;
  const json out = testing::stdout_json(testing::run_process(HULA_CLI_PATH, {"intersect", f.circle, f.line}));
  EXPECT_EQ(out["a"], f.circle);
  EXPECT_EQ(out["b"], f.line);
  EXPECT_EQ(members_of(out, {"a", "b"}), io::intersection_to_json(nurbs::intersect(f.c, f.l), 2));
  ASSERT_EQ(out["points"].size(), 2U);
  for (const json& p : out["points"]) {
    EXPECT_NEAR(std::fabs(p["point"][0].get<double>()), std::sqrt(3.0), 1e-14);
    EXPECT_EQ(p["kind"], "crossing");
  }
}

// checks: `hula intersect --self` on a cubic loop prints one crossing, the library's; a circle has none.
TEST(IntersectCli, SelfIsTheLibraryAnswer) {
  const Files f;
  const json out = testing::stdout_json(testing::run_process(HULA_CLI_PATH, {"intersect", f.loop, "--self"}));
  EXPECT_EQ(out["self"], true);
  EXPECT_EQ(members_of(out, {"a", "self"}), io::intersection_to_json(nurbs::self_intersect(f.o), 2));
  EXPECT_EQ(out["points"].size(), 1U);
  const json circle = testing::stdout_json(testing::run_process(HULA_CLI_PATH, {"intersect", f.circle, "--self"}));
  EXPECT_TRUE(circle["points"].empty());
}

// checks: `hula distance` prints the library's answer; a line 5 above the circle's centre is 3 away (closed form);
// --tolerance reaches the library.
TEST(IntersectCli, DistanceIsTheLibraryAnswer) {
  const Files f;
  testing::TempDir dir;
  const std::vector<Vec3> P = {{-4, 5, 0}, {4, 5, 0}};
  const nurbs::NurbsCurve high = nurbs::make_bezier(P, {}, 2);
  io::write_curve_file(dir / "high.json", high);
  const json out = testing::stdout_json(
      testing::run_process(HULA_CLI_PATH, {"distance", f.circle, (dir / "high.json").string(), "--tolerance", "1e-9"}));
  nurbs::IntersectOptions o;
  o.tolerance.resabs = 1e-9;
  EXPECT_EQ(members_of(out, {"a", "b"}), io::curve_distance_to_json(nurbs::curve_distance(f.c, high, o), 2));
  EXPECT_NEAR(out["distance"].get<double>(), 3.0, 1e-14);
}

// checks: a second curve with --self, neither, and a non-positive tolerance are refused naming the option.
TEST(IntersectCli, RefusesBadCommandLines) {
  const Files f;
  const testing::ProcessResult both = testing::run_process(HULA_CLI_PATH, {"intersect", f.circle, f.line, "--self"});
  EXPECT_EQ(both.exit_code, 3);
  EXPECT_EQ(testing::stderr_error(both)["where"]["field"], "self");
  EXPECT_EQ(testing::run_process(HULA_CLI_PATH, {"intersect", f.circle}).exit_code, 3);
  const testing::ProcessResult tol =
      testing::run_process(HULA_CLI_PATH, {"distance", f.circle, f.line, "--tolerance", "0"});
  EXPECT_EQ(tol.exit_code, 2);
  EXPECT_NE(tol.err.find("--tolerance"), std::string::npos) << tol.err;
  EXPECT_EQ(testing::run_process(HULA_CLI_PATH, {"distance", f.circle, (f.dir / "missing.json").string()}).exit_code,
            3);
}

}  // namespace
}  // namespace hula
