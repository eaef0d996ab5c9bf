// SPDX-License-Identifier: MIT
// Issue 27, item 4: every `hula` command paid for loading Open CASCADE and pagmo2 (and running pagmo's
// static initialisers) at start-up, `hula --version` included; then Ceres Solver (with its linear-algebra
// stack) and Open MPI, about 6 ms each. All four are plugins now (hula/core/plugin.hpp), loaded by the
// commands that use them. Checked with the dynamic loader's own report of the files it opens
// (LD_DEBUG=files, which lists the whole DT_NEEDED closure of the binary), not with timing.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "hula/testing/run_process.hpp"
#include "hula/testing/temp_dir.hpp"

#ifndef HULA_CLI_PATH
#error "HULA_CLI_PATH must name the hula binary"
#endif

namespace {

using hula::testing::ProcessResult;

// Runs hula with the loader reporting every shared object it opens on stderr.
ProcessResult hula_traced(const std::vector<std::string>& args) {
  std::vector<std::string> argv = {"LD_DEBUG=files", HULA_CLI_PATH};
  argv.insert(argv.end(), args.begin(), args.end());
  return hula::testing::run_process("/usr/bin/env", argv);
}

// True if the loader opened a file whose name contains `name` (its "file=PATH [0];" lines).
bool opened(const ProcessResult& r, const std::string& name) {
  std::size_t at = 0;
  while ((at = r.err.find("file=", at)) != std::string::npos) {
    const std::size_t end = r.err.find_first_of(" \n", at);
    if (r.err.substr(at, end - at).find(name) != std::string::npos) return true;
    at = end;
  }
  return false;
}

// checks: `hula --version` opens neither Open CASCADE's toolkits nor pagmo nor their plugins
TEST(Issue27Startup, VersionLoadsNeitherOpenCascadeNorPagmo) {
  const ProcessResult r = hula_traced({"--version"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "hula " HULA_VERSION "\n");
  EXPECT_NE(r.err.find("file=libtbb"), std::string::npos) << "LD_DEBUG=files reported nothing:\n" << r.err;
  EXPECT_FALSE(opened(r, "libTKernel")) << r.err;
  EXPECT_FALSE(opened(r, "libpagmo")) << r.err;
  EXPECT_FALSE(opened(r, "libhula_")) << r.err;
}

// checks: `hula --version` opens neither Ceres nor anything of its linear-algebra stack, nor Open MPI
TEST(Issue27Startup, VersionLoadsNeitherCeresNorMpi) {
  const ProcessResult r = hula_traced({"--version"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("file=libtbb"), std::string::npos) << "LD_DEBUG=files reported nothing:\n" << r.err;
  for (const char* library : {"libceres", "libglog", "libcholmod", "liblapack", "libgfortran", "libmpi", "libopen-pal",
                              "libopen-rte", "libhwloc", "libevent"})
    EXPECT_FALSE(opened(r, library)) << library << " loaded at start-up:\n" << r.err;
}

// checks: `hula --version` opens neither libsqlite3 (Debian links it -z now: ~1,600 symbols bound at start-up) nor
// the plugin that holds it
TEST(Issue27Startup, VersionLoadsNoSqlite) {
  const ProcessResult r = hula_traced({"--version"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("file=libtbb"), std::string::npos) << "LD_DEBUG=files reported nothing:\n" << r.err;
  EXPECT_FALSE(opened(r, "libsqlite3")) << r.err;
  EXPECT_FALSE(opened(r, "libhula_sqlite")) << r.err;
}

// checks: a document is still an SQLite database (the file starts with SQLite's 16-byte header, "SQLite format 3"
// and a NUL, sqlite.org/fileformat.html), written and read through the plugin, which brings libsqlite3
TEST(Issue27Startup, DocumentLoadsTheSqlitePlugin) {
  const hula::testing::TempDir dir;
  const std::string curve = (dir.path() / "c.json").string(), doc = (dir.path() / "d.hula").string();
  ASSERT_EQ(hula_traced({"interpolate", "--points", "examples/cli/pts.csv", "-o", curve}).exit_code, 0);
  const ProcessResult made = hula_traced({"doc", "new", doc});
  ASSERT_EQ(made.exit_code, 0) << made.err;
  EXPECT_TRUE(opened(made, "/libhula_sqlite.so")) << made.err;
  EXPECT_TRUE(opened(made, "libsqlite3")) << made.err;
  ASSERT_EQ(hula_traced({"doc", "add", doc, "--curve", curve}).exit_code, 0);
  const ProcessResult listed = hula_traced({"doc", "list", doc});
  ASSERT_EQ(listed.exit_code, 0) << listed.err;
  EXPECT_EQ(nlohmann::json::parse(listed.out).at("entities").size(), 1U) << listed.out;
  std::ifstream file(doc, std::ios::binary);
  std::string header(16, '\0');
  file.read(header.data(), 16);
  EXPECT_EQ(header, std::string("SQLite format 3\0", 16));
}

// checks: a hybrid curvature match (GA, then Ceres's bounded Levenberg–Marquardt) still runs, through the Ceres
// plugin, and finds the known answer: the target is the curvature profile of the spline through (0,0), (35,20),
// (40,0), and the free middle point starts at (32,23), so the match must move it back to (35,20).
TEST(Issue27Startup, HybridMatchLoadsTheCeresPluginAndFindsTheKnownPoint) {
  const hula::testing::TempDir dir;
  const std::string study = (dir.path() / "study.json").string();
  std::ofstream(study) << R"({"format": "hula-study", "version": 1, "study": "match-curvature", "seed": 1,
    "threads": 1, "points": [[0, 0], [32, 23], [40, 0]],
    "lower": [[0, 0], [5, 5], [0, 0]], "upper": [[0, 0], [5, 5], [0, 0]],
    "target": {"of_points": [[0, 0], [35, 20], [40, 0]]}, "abscissa": "parameter", "samples": 100,
    "method": "hybrid", "ga": {"algorithm": "real", "population": 8, "generations": 2}})";
  const ProcessResult r = hula_traced({"match-curvature", study});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(opened(r, "/libhula_ceres.so")) << r.err;
  // Debian's Ceres is a static library, linked into the plugin: its shared dependencies come with it.
  EXPECT_TRUE(opened(r, "libcholmod")) << r.err;
  EXPECT_TRUE(opened(r, "libglog")) << r.err;
  const nlohmann::json out = nlohmann::json::parse(r.out);
  const nlohmann::json& pt2 = out.at("best_points").at(1);
  EXPECT_NEAR(pt2.at(0).get<double>(), 35.0, 1e-5) << out.at("lm").dump();
  EXPECT_NEAR(pt2.at(1).get<double>(), 20.0, 1e-5) << out.at("lm").dump();
  EXPECT_LT(out.at("after").at("mean").get<double>(), 1e-6) << out.at("lm").dump();
}

// checks: a pagmo algorithm still runs from the command line, through the plugin, which brings libpagmo
TEST(Issue27Startup, PagmoAlgorithmLoadsThePlugin) {
  const ProcessResult r = hula_traced({"optimise", "--problem", "sphere", "--dimension", "3", "--algorithm", "pagmo-de",
                                       "--population", "10", "--generations", "5", "--seed", "1"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("\"evaluations\""), std::string::npos) << r.out;
  EXPECT_TRUE(opened(r, "/libhula_pagmo.so")) << r.err;
  EXPECT_TRUE(opened(r, "libpagmo")) << r.err;
}

// checks: a document with the occt backend still adds a curve, through the plugin, which brings Open CASCADE
TEST(Issue27Startup, OcctBackendLoadsThePlugin) {
  const hula::testing::TempDir dir;
  const std::string curve = (dir.path() / "c.json").string(), doc = (dir.path() / "d.hula").string();
  ASSERT_EQ(hula_traced({"interpolate", "--points", "examples/cli/pts.csv", "-o", curve}).exit_code, 0);
  ASSERT_EQ(hula_traced({"doc", "new", doc, "--backend", "occt"}).exit_code, 0);
  const ProcessResult r = hula_traced({"doc", "add", doc, "--curve", curve});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "{\n  \"label\": 1,\n  \"revision\": 1\n}\n");
  EXPECT_TRUE(opened(r, "/libhula_occt.so")) << r.err;
  EXPECT_TRUE(opened(r, "libTKernel")) << r.err;
}

}  // namespace
