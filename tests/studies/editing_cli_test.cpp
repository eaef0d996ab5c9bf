// SPDX-License-Identifier: MIT
// The `hula fin-compound`, `hula edit-projection` and `hula hermite` commands
// run as processes on the example study files (examples/studies/): the values
// they print are checked against closed forms (the Combescure compound of a
// helix is the helix shifted along its axis by C w / r), the definitions (the
// dropped coordinate does not change, the edited derivatives are the rotated
// and scaled ones) and the forward check of the compound inverse; bad study
// files give exit code 3 and an error naming the member, before any figure is
// written.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "hula/io/json_curve.hpp"
#include "hula/testing/process_json.hpp"
#include "hula/testing/run_process.hpp"
#include "hula/testing/temp_dir.hpp"

#ifndef HULA_CLI_PATH
#error "HULA_CLI_PATH must name the hula binary"
#endif
#ifndef HULA_EXAMPLES_DIR
#error "HULA_EXAMPLES_DIR must name examples/studies"
#endif

namespace hula {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using testing::ProcessResult;

ProcessResult hula(const std::vector<std::string>& args) { return testing::run_process(HULA_CLI_PATH, args); }
std::string example(const std::string& name) { return (fs::path(HULA_EXAMPLES_DIR) / name).string(); }

json run_ok(const std::vector<std::string>& args) { return testing::stdout_json(hula(args)); }

std::string write(const fs::path& dir, const std::string& name, const std::string& text) {
  const fs::path p = dir / name;
  std::ofstream(p) << text;
  return p.string();
}

// Runs a bad study file: exit 3, the error code, a message naming `member`, and no figure directory.
void expect_bad(const std::string& command, const std::string& text, const std::string& code,
                const std::string& member) {
  testing::TempDir dir;
  const std::string file = write(dir.path(), "bad.json", text);
  const fs::path svg = dir.path() / "figures";
  const ProcessResult r = hula({command, file, "--svg", svg.string()});
  EXPECT_EQ(r.exit_code, 3) << r.out << r.err;
  const json e = testing::stderr_error(r);
  EXPECT_EQ(e["code"], code) << r.err;
  EXPECT_NE(e["message"].get<std::string>().find(member), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(svg)) << "figures written before the error";
}

// checks the projection technique example: the prescribed compound is honoured (forward check), z is
// unchanged, y moved by about the 0.4 bump, and the figures are written.
TEST(EditingCli, FinCompoundProjectionEdit) {
  testing::TempDir dir;
  const json out = run_ok({"fin-compound", example("fin-compound-edit.json"), "--svg", dir.path().string()});
  const json& e = out["edit"];
  EXPECT_LT(e["forward_deviation"].get<double>(), 1e-8);
  EXPECT_LT(e["max_change"][2].get<double>(), 1e-12);
  EXPECT_NEAR(e["max_change"][1].get<double>(), 0.4, 0.05);
  EXPECT_GT(e["min_stretch"].get<double>(), 0.5);
  for (const char* f : {"before.svg", "after.svg", "rebuilt-yz.svg", "rebuilt-zx.svg"})
    EXPECT_TRUE(fs::exists(dir.path() / f)) << f;
}

// checks the Combescure example against the closed form: Q(t) = helix(t) + (0, 0, C √(r² + h²) / r).
TEST(EditingCli, CombescureHelixIsShiftedHelix) {
  testing::TempDir dir;
  const fs::path q = dir.path() / "q.json";
  const json out = run_ok({"fin-compound", example("combescure-helix.json"), "-o", q.string()});
  EXPECT_LT(out["compound"]["round_trip_deviation"].get<double>(), 1e-12);
  const curve::Curve file = io::read_curve_file(q);
  const double shift = 0.8 * std::sqrt(4.25) / 2.0;
  for (int i = 0; i <= 40; ++i) {
    const double t = 4.0 * std::numbers::pi * i / 40.0;
    const Vec3 expect{2.0 * std::cos(t), 2.0 * std::sin(t), 0.5 * t + shift};
    EXPECT_LT(distance(file.nurbs().evaluate(t), expect), 1e-9) << "t = " << t;
  }
  const json inv = run_ok({"fin-compound", example("combescure-inverse.json")});
  EXPECT_LT(inv["parent"]["round_trip_deviation"].get<double>(), 1e-12);
}

// checks the projection edit example: y unchanged, x and z changed, the construction exact; --seed,
// --threads and --log are recorded and the log holds the output.
TEST(EditingCli, EditProjectionChangesTwoComponents) {
  testing::TempDir dir;
  const fs::path log = dir.path() / "run.json";
  const ProcessResult r = hula(
      {"edit-projection", example("edit-projection.json"), "--seed", "7", "--threads", "2", "--log", log.string()});
  const json out = testing::stdout_json(r);
  EXPECT_LT(out["max_deviation"].get<double>(), 1e-12);
  EXPECT_LT(out["max_change"][1].get<double>(), 1e-12);
  EXPECT_GT(out["max_change"][0].get<double>(), 0.1);
  EXPECT_GT(out["max_change"][2].get<double>(), 0.1);
  EXPECT_EQ(out["seed"], 7);
  EXPECT_EQ(out["threads"], 2);
  std::ifstream in(log);
  EXPECT_EQ(json::parse(in), out);
}

// checks the Hermite example: P' at knot 1 is the spline's turned by 30°, P'' at knot 2 turned by −20° and
// scaled 1.5 (rotation written out), knots 0 and 3 keep their derivatives.
TEST(EditingCli, HermiteEditedDerivatives) {
  const json out = run_ok({"hermite", example("hermite-direction.json")});
  auto v = [](const json& j) { return Vec3{j[0].get<double>(), j[1].get<double>(), 0.0}; };
  auto rot = [](const Vec3& d, double deg, double s) {
    const double a = deg * std::numbers::pi / 180.0;
    return Vec3{s * (std::cos(a) * d.x - std::sin(a) * d.y), s * (std::sin(a) * d.x + std::cos(a) * d.y), 0.0};
  };
  const json& b = out["before"];
  const json& a = out["after"];
  EXPECT_LT(distance(v(a[1]["first"]), rot(v(b[1]["first"]), 30, 1.0)), 1e-9);
  EXPECT_LT(distance(v(a[2]["second"]), rot(v(b[2]["second"]), -20, 1.5)), 1e-8);
  for (int k : {0, 3}) EXPECT_LT(distance(v(a[k]["first"]), v(b[k]["first"])), 1e-9);
  const json mag = run_ok({"hermite", example("hermite-magnitude.json")});
  EXPECT_LT(distance(v(mag["after"][1]["first"]), 2.0 * v(mag["before"][1]["first"])), 1e-9);
}

// checks bad study files: unknown member, wrong plane, non-planar edit, mismatched counts, bad edits.
TEST(EditingCli, BadStudiesNameTheMember) {
  const std::string env = R"("format": "hula-study", "version": 1, )";
  const std::string curve = R"({"kind": "interpolated", "points": [[0, 0, 0], [1, 1, 1], [2, 0, 2], [3, 1, 0]]})";
  expect_bad("edit-projection",
             "{" + env + R"("study": "edit-projection", "plane": "zx", "curve": )" + curve + R"(, "edited": )" + curve +
                 ", \"colour\": 1}",
             "ParseError", "colour");
  expect_bad(
      "edit-projection",
      "{" + env + R"("study": "edit-projection", "plane": "xz", "curve": )" + curve + R"(, "edited": )" + curve + "}",
      "InvalidArgument", "plane");
  expect_bad(
      "edit-projection",
      "{" + env + R"("study": "edit-projection", "plane": "zx", "curve": )" + curve + R"(, "edited": )" + curve + "}",
      "InvalidArgument", "edited is not planar in zx");
  expect_bad("fin-compound",
             "{" + env + R"("study": "fin-compound", "method": "projection", "plane": "xy", "curve": )" + curve +
                 R"(, "compound": )" + curve + "}",
             "InvalidArgument", "compound is not planar in xy");
  expect_bad("fin-compound",
             "{" + env + R"("study": "fin-compound", "method": "combescure", "curve": )" + curve + R"(, "compound": )" +
                 curve + "}",
             "ParseError", "exactly one of");
  expect_bad("fin-compound",
             "{" + env + R"("study": "fin-compound", "method": "projection", "plane": "xy", "scale": 0, "curve": )" +
                 curve + "}",
             "InvalidOption", "scale");
  const std::string spline_bad_count =
      R"({"kind": "interpolated", "points": [[0, 0], [1, 1], [2, 0]], "parameters": [0, 1]})";
  expect_bad("hermite", "{" + env + R"("study": "hermite", "spline": )" + spline_bad_count + "}", "InvalidArgument",
             "spline");
  const std::string spline = R"({"kind": "interpolated", "points": [[0, 0], [1, 1], [2, 0]]})";
  expect_bad("hermite", "{" + env + R"("study": "hermite", "spline": )" + spline + R"(, "edits": [{"knot": 5}]})",
             "InvalidArgument", "edits[0].knot = 5");
  expect_bad("hermite",
             "{" + env + R"("study": "hermite", "spline": )" + spline + R"(, "edits": [{"knot": 1, "angle": 3}]})",
             "ParseError", "angle");
  expect_bad("hermite",
             "{" + env + R"("study": "hermite", "spline": )" + spline +
                 R"(, "rebuild": "cubic", "edits": [{"knot": 1, "normal_scale": 2}]})",
             "InvalidArgument", "edits[0].normal_angle");
}

}  // namespace
}  // namespace hula
