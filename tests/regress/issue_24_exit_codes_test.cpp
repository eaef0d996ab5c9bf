// SPDX-License-Identifier: MIT
// Issue 24, item 8: exit codes. `hula --version > /dev/full` and `hula --help >
// /dev/full` exited 0 (CLI11 printed them unchecked); memory running out where
// the CLI did not catch it aborted with "terminate called after throwing ...
// std::bad_alloc", exit 134, instead of the documented 6 (OutOfMemory).
#include "cli.hpp"

namespace hula::regress {
namespace {

// checks: --version, --help and a subcommand's --help on a full disk exit 3 naming standard output; on a
// working stdout they exit 0 with the text.
TEST(Issue24ExitCodes, VersionAndHelpToAFullDiskFail) {
  ProcessOptions full;
  full.stdout_path = "/dev/full";
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"--version"}, {"--help"}, {"edit", "--help"}, {"interpolate", "--help"}}) {
    const ProcessResult r = hula(args, full);
    EXPECT_EQ(r.exit_code, 3) << args[0] << ": " << r.err;
    EXPECT_NE(message_of(r).find("standard output"), std::string::npos) << r.err;
    const ProcessResult ok = hula(args);
    EXPECT_EQ(ok.exit_code, 0) << ok.err;
    EXPECT_FALSE(ok.out.empty());
  }
  EXPECT_EQ(hula({"--version"}).out.rfind("hula ", 0), 0U);
}

// checks: under an address-space limit too small for the run, hula exits 6 with the OutOfMemory error JSON
// (was: abort, exit 134). The limit is set by the shell (ulimit -v, KiB) that execs hula.
TEST(Issue24ExitCodes, OutOfMemoryIsExitSix) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  ASSERT_EQ(hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "c.json").string()}).exit_code,
            0);
  const std::string command =
      "ulimit -v 1500000 && exec \"$0\" analyse \"$1\" --samples 1000000 --fins curvature "
      "--fin-density 1000000 --svg \"$2\"";
  const ProcessResult r = testing::run_process(
      "/bin/sh", {"-c", command, HULA_CLI_PATH, (dir / "c.json").string(), (dir / "figures").string()});
  EXPECT_EQ(r.exit_code, 6) << r.err.substr(0, 400);
  EXPECT_EQ(error_of(r)["error"]["code"], "OutOfMemory") << r.err.substr(0, 400);
  EXPECT_TRUE(r.out.empty());
}

}  // namespace
}  // namespace hula::regress
