// SPDX-License-Identifier: MIT
// Issue 10, item 2 "pipes": `-` reads standard input for input files and
// writes standard output for -o (was: `--points -` failed and `-o -` created a
// file named "-"). The three-command shell pipeline is tests/apps/pipe_test.sh.
#include "cli.hpp"

namespace hula::regress {
namespace {

// checks: `interpolate --points - -o -` gives on stdout exactly the curve file written with real files.
TEST(Issue10Pipes, DashReadsStdinAndWritesStdout) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  const ProcessResult files =
      hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "curve.json").string()});
  ASSERT_EQ(files.exit_code, 0) << files.err;
  ProcessOptions in;
  in.stdin_data = kPointsCsv;
  const ProcessResult piped = hula({"interpolate", "--points", "-", "-o", "-"}, in);
  ASSERT_EQ(piped.exit_code, 0) << piped.err;
  EXPECT_EQ(piped.out, io::read_text_file(dir / "curve.json"));
  EXPECT_FALSE(fs::exists("-"));
}

// checks: a curve file piped into info and eval (`-`) gives the same results as the file itself.
TEST(Issue10Pipes, CurveFromStdinMatchesCurveFromFile) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  ASSERT_EQ(hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "c.json").string()}).exit_code,
            0);
  ProcessOptions in;
  in.stdin_data = io::read_text_file(dir / "c.json");
  const ProcessResult from_file = hula({"eval", (dir / "c.json").string(), "--at", "0,0.3,1", "--derivatives", "2"});
  const ProcessResult from_pipe = hula({"eval", "-", "--at", "0,0.3,1", "--derivatives", "2"}, in);
  ASSERT_EQ(from_pipe.exit_code, 0) << from_pipe.err;
  EXPECT_EQ(from_pipe.out, from_file.out);
}

}  // namespace
}  // namespace hula::regress
