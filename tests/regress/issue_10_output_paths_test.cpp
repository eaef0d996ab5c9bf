// SPDX-License-Identifier: MIT
// Issue 10, item 1 "writes that cannot hurt" and item 11 "outputs checked
// before the computation": `-o` refuses symlinks, devices, FIFOs and
// directories by name and leaves them as they were; a killed write's
// temporary file is removed by the next write; --log to a missing directory
// fails before the run, leaving -o untouched.
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "cli.hpp"

namespace hula::regress {
namespace {

// checks: -o naming a symlink is refused and the link and its target stay as they were (was: the link replaced).
TEST(Issue10OutputPaths, SymlinkOutputIsRefusedAndKept) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  write(dir / "target.json", "precious");
  fs::create_symlink(dir / "target.json", dir / "link.json");
  const ProcessResult r =
      hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "link.json").string()});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(message_of(r).find("symbolic link"), std::string::npos) << r.err;
  EXPECT_NE(message_of(r).find("--output"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_symlink(dir / "link.json"));
  EXPECT_EQ(io::read_text_file(dir / "target.json"), "precious");
}

// checks: -o naming a character device, a FIFO or a directory is refused by name (was: renamed over).
TEST(Issue10OutputPaths, DeviceFifoAndDirectoryOutputsAreRefused) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
  fs::create_directory(dir / "sub");
  for (const auto& [target, kind] :
       std::vector<std::pair<std::string, std::string>>{{"/dev/null", "character device"},
                                                        {(dir / "fifo").string(), "FIFO"},
                                                        {(dir / "sub").string(), "directory"}}) {
    const ProcessResult r = hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", target});
    EXPECT_EQ(r.exit_code, 3) << target << ": " << r.err;
    EXPECT_NE(message_of(r).find(kind), std::string::npos) << r.err;
  }
  struct stat st {};
  ASSERT_EQ(::lstat("/dev/null", &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  EXPECT_TRUE(fs::is_fifo(dir / "fifo"));
  EXPECT_TRUE(fs::is_directory(dir / "sub"));
  EXPECT_TRUE(temporaries(dir.path()).empty());
}

// checks: a temporary left by a killed writer (dead pid) is removed by the next write to the same target,
// while one of a live process is kept (was: every killed write left a full-size .NAME.tmp-XXXXXX behind).
TEST(Issue10OutputPaths, StaleTemporaryOfKilledWriteIsCleaned) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  // A pid that no longer exists: a child that has exited and been reaped.
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  const std::string stale = ".curve.json.tmp-" + std::to_string(child) + "-AbC123";
  const std::string live = ".curve.json.tmp-" + std::to_string(::getpid()) + "-XyZ789";
  write(dir / stale, std::string(4096, 'x'));
  write(dir / live, "in progress");
  const ProcessResult r =
      hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "curve.json").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_FALSE(fs::exists(dir / stale));
  EXPECT_TRUE(fs::exists(dir / live));
}

// checks: --log in a missing directory fails before the run (exit 3 naming --log) and -o stays untouched
// (was: the failure came after the whole computation, with -o already replaced).
TEST(Issue10OutputPaths, LogPathIsCheckedBeforeTheRun) {
  TempDir dir;
  const ProcessResult r = hula({"optimise", "--problem", "sphere", "--algorithm", "ga-real", "--generations",
                                "100000000", "--log", (dir / "missing" / "log.csv").string()});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(message_of(r).find("--log"), std::string::npos) << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

// checks: an -o in a missing directory fails before reading or computing anything (exit 3 naming --output).
TEST(Issue10OutputPaths, OutputPathIsCheckedBeforeTheRun) {
  TempDir dir;
  const ProcessResult r = hula(
      {"interpolate", "--points", (dir / "no-points.csv").string(), "-o", (dir / "missing" / "curve.json").string()});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(message_of(r).find("--output"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace hula::regress
