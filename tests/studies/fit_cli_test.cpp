// SPDX-License-Identifier: MIT
// `hula fit` as a user runs it: the docs/cli.md "hula fit" examples and the docs/formats.md
// "fit" study example executed on a seeded wave cloud (hula/testing/point_clouds.hpp), checked
// against the cloud's known strays and inflections, and the refusals of bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "hula/io/atomic_file.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/points_file.hpp"
#include "hula/io/study_file.hpp"
#include "hula/nurbs/closest_point.hpp"
#include "hula/testing/point_clouds.hpp"
#include "hula/testing/run_process.hpp"
#include "hula/testing/temp_dir.hpp"

namespace hula {
namespace {

using io::Json;

// The wave cloud of the docs: 1000 points, noise 0.1, 1 % strays, shuffled, seed 1, as CSV.
testing::Cloud write_wave(const std::filesystem::path& file) {
  const testing::Cloud cloud =
      testing::scanned_cloud({.curve = testing::KnownCurve::Wave, .points = 1000, .noise = 0.1, .seed = 1});
  std::ostringstream csv;
  csv.precision(17);
  for (const Vec3& p : cloud.points) csv << p.x << ',' << p.y << '\n';
  io::write_file_atomically(file, csv.str());
  return cloud;
}

// The commands of the "```console" blocks of a section of a page (lines starting "$ hula ").
std::vector<std::vector<std::string>> console_commands(const std::string& page, const std::string& heading) {
  std::vector<std::vector<std::string>> out;
  const std::size_t section = page.find(heading);
  if (section == std::string::npos) return out;
  const std::size_t section_end = page.find("\n## ", section + 3);
  for (std::size_t begin = page.find("```console\n", section); begin < section_end;
       begin = page.find("```console\n", begin + 10)) {
    const std::size_t end = page.find("```", begin + 10);
    std::istringstream block(page.substr(begin + 11, end - begin - 11));
    for (std::string line; std::getline(block, line);)
      if (line.rfind("$ hula ", 0) == 0) {
        std::istringstream words(line.substr(7));
        std::vector<std::string> args;
        for (std::string w; words >> w;) args.push_back(w);
        out.push_back(args);
      }
  }
  return out;
}

// Relative file names of a command made absolute in `dir` (the binary runs elsewhere).
std::vector<std::string> in_dir(const std::filesystem::path& dir, std::vector<std::string> args) {
  for (std::size_t i = 0; i < args.size(); ++i)
    if (args[i].ends_with(".csv") || args[i].ends_with(".json") || (i > 0 && args[i - 1] == "--svg"))
      args[i] = (dir / args[i]).string();
  return args;
}

// Checks the docs/cli.md `hula fit` examples run on the wave cloud: exit 0, the strays printed are the
// generator's, every kept point within the class tolerance, the known curve's 2 inflections after
// fairing, and the figures written.
TEST(FitCli, DocsExamplesRunAndFindTheStrays) {
  const auto commands = console_commands(io::read_text_file("docs/cli.md"), "## `hula fit`");
  ASSERT_GE(commands.size(), 2u);
  for (const auto& command : commands) {
    testing::TempDir dir;
    const testing::Cloud cloud = write_wave(dir / "wave.csv");
    const testing::ProcessResult r = testing::run_process(HULA_CLI_PATH, in_dir(dir.path(), command));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const Json out = Json::parse(r.out);
    EXPECT_EQ(out["strays"].get<std::vector<std::size_t>>(), cloud.strays);
    EXPECT_LE(out["after"]["max_deviation"].get<double>(), out["tolerance"].get<double>());
    EXPECT_EQ(out["after"]["inflections"].get<std::size_t>(), 2u);
    EXPECT_TRUE(std::filesystem::exists(out["output"].get<std::string>()));
    if (std::find(command.begin(), command.end(), "--svg") != command.end()) {
      EXPECT_TRUE(std::filesystem::exists(dir / "figures" / "curvature.svg"));
      EXPECT_TRUE(std::filesystem::exists(dir / "figures" / "fit.svg"));
    }
  }
}

// Checks `hula fit --points FILE.dat --ordered --tolerance 1e-4` and `hula approximate --points FILE.dat
// --tolerance 1e-4` on every airfoil file of tests/data/real as shipped (name lines, Lednicer form):
// exit 0, every point kept, at most 40 control points (fit), and every point of the file within 1e-4
// of the written curve, re-measured here by closest point.
TEST(FitCli, RealAirfoilFilesAsShipped) {
  const char* root = std::getenv("HULA_TEST_DATA");
  ASSERT_NE(root, nullptr);
  testing::TempDir dir;
  std::size_t files = 0;
  for (const auto& e : std::filesystem::directory_iterator(std::filesystem::path(root) / "real")) {
    if (e.path().extension() != ".dat") continue;
    ++files;
    SCOPED_TRACE(e.path().filename().string());
    const std::vector<Vec3> pts = io::read_points_file(e.path()).points;
    const std::string out = (dir / "curve.json").string();
    for (const std::string command : {"fit", "approximate"}) {
      std::vector<std::string> args{command, "--points", e.path().string(), "--tolerance", "1e-4", "-o", out};
      if (command == "fit") args.push_back("--ordered");
      const testing::ProcessResult r = testing::run_process(HULA_CLI_PATH, args);
      ASSERT_EQ(r.exit_code, 0) << command << ": " << r.err;
      const Json j = Json::parse(r.out);
      if (command == "fit") {
        EXPECT_EQ(j["kept"].get<std::size_t>(), pts.size());
        EXPECT_LE(j["after"]["control_points"].get<std::size_t>(), 40u);
        EXPECT_EQ(j["ordering"], "given");
      }
      EXPECT_LE(j.contains("after") ? j["after"]["max_deviation"].get<double>() : j["max_deviation"].get<double>(),
                1e-4);
      const nurbs::NurbsCurve c = io::read_curve_file(out).nurbs();
      double worst = 0.0;
      for (const Vec3& q : pts) worst = std::max(worst, nurbs::closest_point(c, q).distance);
      EXPECT_LE(worst, 1e-4 * (1 + 1e-9)) << command;
    }
  }
  EXPECT_GE(files, 10u);
}

// Checks the docs/formats.md "fit" study example (its points file beside it) runs with `hula fit STUDY`
// and gives the same strays as the generator.
TEST(FitCli, FormatsStudyExampleRuns) {
  const std::string page = io::read_text_file("docs/formats.md");
  const std::size_t section = page.find("### Study kind \"fit\"");
  ASSERT_NE(section, std::string::npos);
  const std::size_t begin = page.find("```json\n", section);
  const std::size_t end = page.find("```", begin + 8);
  testing::TempDir dir;
  const testing::Cloud cloud = write_wave(dir / "wave.csv");
  io::write_file_atomically(dir / "fit-study.json", page.substr(begin + 8, end - begin - 8));
  const testing::ProcessResult r = testing::run_process(
      HULA_CLI_PATH, {"fit", (dir / "fit-study.json").string(), "-o", (dir / "out.json").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Json out = Json::parse(r.out);
  EXPECT_EQ(out["strays"].get<std::vector<std::size_t>>(), cloud.strays);
  EXPECT_EQ(out["tolerance"].get<double>(), 0.3);
}

// Checks --save-study writes a "fit" study that, run again, gives the same strays and curve figures.
TEST(FitCli, SavedStudyRepeatsTheRun) {
  testing::TempDir dir;
  write_wave(dir / "wave.csv");
  const testing::ProcessResult first =
      testing::run_process(HULA_CLI_PATH, {"fit", "--points", (dir / "wave.csv").string(), "--tolerance", "0.4", "-o",
                                           (dir / "a.json").string(), "--save-study", (dir / "saved.json").string()});
  ASSERT_EQ(first.exit_code, 0) << first.err;
  const testing::ProcessResult again =
      testing::run_process(HULA_CLI_PATH, {"fit", (dir / "saved.json").string(), "-o", (dir / "b.json").string()});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  const Json a = Json::parse(first.out), b = Json::parse(again.out);
  EXPECT_EQ(a["strays"], b["strays"]);
  EXPECT_EQ(a["after"], b["after"]);
  EXPECT_EQ(b["tolerance"].get<double>(), 0.4);
}

// Checks the refusals: unknown study member (named), class and tolerance together, no input (exit 3,
// error JSON naming the field), and that no output file is left behind.
TEST(FitCli, RefusesBadInputNamingIt) {
  testing::TempDir dir;
  write_wave(dir / "wave.csv");
  io::write_file_atomically(
      dir / "bad.json",
      R"({"format": "hula-study", "version": 1, "study": "fit", "points": "wave.csv", "tolerence": 1})");
  io::write_file_atomically(dir / "both.json", R"({"format": "hula-study", "version": 1, "study": "fit",
    "points": "wave.csv", "class": "A", "tolerance": 0.2})");
  const auto out = (dir / "out.json").string();
  testing::ProcessResult r = testing::run_process(HULA_CLI_PATH, {"fit", (dir / "bad.json").string(), "-o", out});
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("tolerence"), std::string::npos) << r.err;
  r = testing::run_process(HULA_CLI_PATH, {"fit", (dir / "both.json").string(), "-o", out});
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("tolerance"), std::string::npos) << r.err;
  r = testing::run_process(HULA_CLI_PATH, {"fit", "-o", out});
  EXPECT_EQ(r.exit_code, 3);
  EXPECT_NE(r.err.find("--points"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace hula
