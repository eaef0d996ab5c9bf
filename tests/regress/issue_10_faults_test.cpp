// SPDX-License-Identifier: MIT
// Issue 10, item 11 "faults" (SQLite's I/O fault simulation as the model):
// a standard output that fails (/dev/full, closed) is exit 3 with a message
// (was: exit 0, output lost); running out of memory under RLIMIT_AS is exit 6
// "OutOfMemory" (was: exit 5 "a bug in hula"); a file-size limit (RLIMIT_FSIZE)
// is a clean IoError that leaves the old file and no temporary; SIGKILL at
// random moments during -o, --log and --svg writes leaves each file with its
// old or its new content, never a mix, and the next run leaves no temporary.
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <random>
#include <thread>

#include "cli.hpp"

namespace hula::regress {
namespace {

// checks: output to /dev/full is exit 3 naming standard output and the system's reason.
TEST(Issue10Faults, FullStdoutIsExit3) {
  ProcessOptions o;
  o.stdout_path = "/dev/full";
  const ProcessResult r = hula({"demo"}, o);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(message_of(r).find("cannot write to standard output"), std::string::npos) << r.err;
  EXPECT_NE(message_of(r).find("No space left on device"), std::string::npos) << r.err;
}

// checks: a closed stdout (`>&-`) is exit 3 with the message on stderr.
TEST(Issue10Faults, ClosedStdoutIsExit3) {
  ProcessOptions o;
  o.close_stdout = true;
  const ProcessResult r = hula({"law", "sin(t)", "--at", "0.5"}, o);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(message_of(r).find("cannot write to standard output"), std::string::npos) << r.err;
}

// checks: with stdout closed, -o still gets exactly the curve (the summary cannot land in it) and the
// failed summary is exit 3.
TEST(Issue10Faults, ClosedStdoutNeverWritesIntoOutputFile) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  ProcessOptions o;
  o.close_stdout = true;
  const ProcessResult r =
      hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "c.json").string()}, o);
  EXPECT_EQ(r.exit_code, 3) << r.err;
  const json c = json::parse(io::read_text_file(dir / "c.json"));
  EXPECT_EQ(c["kind"], "nurbs");
  EXPECT_FALSE(c.contains("output"));
}

// checks: under a 1 GiB address-space limit a run needing ~800 GB ends with exit 6 and code OutOfMemory.
TEST(Issue10Faults, OutOfMemoryIsItsOwnExitCode) {
  const ProcessResult r = testing::run_process(
      "/usr/bin/prlimit", {"--as=1073741824", "--", HULA_CLI_PATH, "optimise", "--problem", "sphere", "--algorithm",
                           "ga-real", "--population", "1000000", "--dimension", "100000", "--generations", "1"});
  EXPECT_EQ(r.exit_code, 6) << r.err;
  EXPECT_EQ(error_of(r)["error"]["code"], "OutOfMemory");
}

// checks: with RLIMIT_FSIZE below the output's size, -o fails with exit 3, the old file stays, no temporary remains.
TEST(Issue10Faults, FileSizeLimitLeavesOldFile) {
  TempDir dir;
  std::string points;
  for (int i = 0; i < 2000; ++i) points += std::to_string(i) + "," + std::to_string((i * 7) % 13) + ",0\n";
  write(dir / "points.csv", points);
  write(dir / "curve.json", "OLD");
  const ProcessResult r =
      testing::run_process("/usr/bin/prlimit", {"--fsize=20000", "--", HULA_CLI_PATH, "interpolate", "--points",
                                                (dir / "points.csv").string(), "-o", (dir / "curve.json").string()});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(message_of(r).find("File too large"), std::string::npos) << r.err;
  EXPECT_EQ(io::read_text_file(dir / "curve.json"), "OLD");
  EXPECT_TRUE(temporaries(dir.path()).empty());
}

// Runs `args` `runs` times, each killed with SIGKILL after a random delay in [0, span], and checks after
// each kill that every file in `outputs` holds "OLD" or its complete new content; then runs once more
// to completion and checks the new content and that no temporary is left.
void kill_at_random_moments(const std::vector<std::string>& args, const fs::path& dir,
                            const std::vector<fs::path>& outputs, int runs) {
  for (const fs::path& p : outputs) write(p, "OLD");
  // The complete new contents, and how long a run takes.
  const auto t0 = std::chrono::steady_clock::now();
  const ProcessResult full = hula(args);
  const auto span = std::chrono::steady_clock::now() - t0;
  ASSERT_EQ(full.exit_code, 0) << full.err;
  std::vector<std::string> fresh;
  for (const fs::path& p : outputs) fresh.push_back(io::read_text_file(p));
  for (const fs::path& p : outputs) write(p, "OLD");
  std::mt19937_64 rng(20261201);
  std::uniform_int_distribution<long long> delay(
      0, std::chrono::duration_cast<std::chrono::microseconds>(span).count() * 11 / 10);
  for (int run = 0; run < runs; ++run) {
    testing::RunningProcess p = testing::start_process(HULA_CLI_PATH, args);
    std::this_thread::sleep_for(std::chrono::microseconds(delay(rng)));
    p.send(SIGKILL);
    (void)p.wait();
    for (std::size_t i = 0; i < outputs.size(); ++i) {
      const std::string now = io::read_text_file(outputs[i]);
      EXPECT_TRUE(now == "OLD" || now == fresh[i]) << outputs[i] << " holds " << now.size() << " bytes of a mix";
    }
  }
  const ProcessResult last = hula(args);
  ASSERT_EQ(last.exit_code, 0) << last.err;
  for (std::size_t i = 0; i < outputs.size(); ++i) EXPECT_EQ(io::read_text_file(outputs[i]), fresh[i]);
  EXPECT_TRUE(temporaries(dir).empty()) << temporaries(dir).front();
}

// checks: SIGKILL during an -o write of a 20,000-point curve leaves the old or the new file, never a mix.
TEST(Issue10Faults, KilledOutputWriteIsOldOrNew) {
  TempDir dir;
  std::string points;
  for (int i = 0; i < 20000; ++i) points += std::to_string(i) + "," + std::to_string((i * 7) % 13) + ",0\n";
  write(dir / "points.csv", points);
  kill_at_random_moments({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "c.json").string()},
                         dir.path(), {dir / "c.json"}, fault_kills(12));
}

// checks: SIGKILL during an optimise run streaming its --log leaves the old or the complete new log.
TEST(Issue10Faults, KilledLogWriteIsOldOrNew) {
  TempDir dir;
  kill_at_random_moments({"optimise", "--problem", "sphere", "--algorithm", "ga-real", "--dimension", "10",
                          "--population", "100", "--generations", "100", "--log", (dir / "log.csv").string()},
                         dir.path(), {dir / "log.csv"}, fault_kills(12));
}

// checks: SIGKILL during analyse --svg leaves each figure old or new, never a mix.
TEST(Issue10Faults, KilledSvgWriteIsOldOrNew) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  ASSERT_EQ(hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "c.json").string()}).exit_code,
            0);
  fs::create_directory(dir / "fig");
  std::vector<fs::path> figures;
  for (const char* name : {"curve", "kappa", "tau", "radius", "speed", "logcurvature"})
    figures.push_back(dir / "fig" / (std::string(name) + ".svg"));
  kill_at_random_moments({"analyse", (dir / "c.json").string(), "--samples", "20000", "--svg", (dir / "fig").string()},
                         dir / "fig", figures, fault_kills(12));
}

}  // namespace
}  // namespace hula::regress
