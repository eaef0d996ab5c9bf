// SPDX-License-Identifier: MIT
// Issue 24, item 3: what SIGKILL left behind. `doc new [--force]` left
// `.NAME.hula.new-XXXXXX` databases with their -wal/-shm/-journal (27 of 69
// kills), never cleaned; a killed `doc export --format step` left the
// `hula-exchange` helper running (19 of 30), writing the output after its
// parent died, and `hula-exchange-XXXXXX` folders holding a copy of the curve
// data in the temporary directory (34 of 42). Temporaries now carry their
// owner's pid and the next run removes those whose owner is gone; the helper
// dies with its parent.
#include <signal.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <random>
#include <thread>

#include "cli.hpp"
#include "hula/core/error.hpp"

namespace hula::regress {
namespace {

// The sorted names in `dir`.
std::vector<std::string> names_in(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

// The pids of live processes (not zombies: their command line is empty) whose command line holds `text`.
std::vector<int> live_processes_mentioning(const std::string& text) {
  std::vector<int> out;
  for (const auto& e : fs::directory_iterator("/proc")) {
    const std::string name = e.path().filename().string();
    if (name.empty() || !std::all_of(name.begin(), name.end(), [](char c) { return c >= '0' && c <= '9'; })) continue;
    try {
      if (io::read_text_file(e.path() / "cmdline").find(text) != std::string::npos) out.push_back(std::stoi(name));
    } catch (const Error&) {  // the process ended meanwhile
    }
  }
  return out;
}

// Runs `args` `runs` times, each SIGKILLed after a seeded random delay in [0, 1.1 × a full run], calling
// `after_kill` after each.
template <class F>
void kill_at_random_moments(const std::vector<std::string>& args, int runs, std::uint64_t seed, F&& after_kill) {
  const auto t0 = std::chrono::steady_clock::now();
  const ProcessResult full = hula(args);
  const auto span = std::chrono::steady_clock::now() - t0;
  ASSERT_EQ(full.exit_code, 0) << full.err;
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<long long> delay(
      0, std::chrono::duration_cast<std::chrono::microseconds>(span).count() * 11 / 10);
  for (int run = 0; run < runs; ++run) {
    testing::RunningProcess p = testing::start_process(HULA_CLI_PATH, args);
    std::this_thread::sleep_for(std::chrono::microseconds(delay(rng)));
    p.send(SIGKILL);
    (void)p.wait();
    after_kill(run);
  }
}

// checks: after each of 12 kills (HULA_FAULT_KILLS nightly) of `doc new --force` at random moments, the document,
// when there is one, is sound; the next `doc new --force` leaves the folder holding the document alone (no
// `.d.hula.new-*` database, -wal, -shm or -journal), and the document is sound.
TEST(Issue24KillLeftovers, KilledDocNewLeavesNothingAfterTheNextRun) {
  TempDir dir;
  const std::string doc = (dir / "d.hula").string();
  kill_at_random_moments({"doc", "new", "--force", doc}, fault_kills(12), 2024120701, [&](int run) {
    if (!fs::exists(doc)) return;
    const ProcessResult check = hula({"doc", "check", doc});
    EXPECT_EQ(check.exit_code, 0) << "kill " << run << ": " << check.out << check.err;
  });
  const ProcessResult again = hula({"doc", "new", "--force", doc});
  ASSERT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"d.hula"});
  const ProcessResult check = hula({"doc", "check", doc});
  ASSERT_EQ(check.exit_code, 0) << check.err;
  EXPECT_EQ(json::parse(check.out)["ok"], true);
}

// A pid no process has: a child that has exited and been reaped.
pid_t dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

// checks: what a `doc new --force` killed between creating its database and renaming it leaves — the
// database with its -wal, -shm and -journal, named with its (dead) pid — is removed by the next `doc new`, and
// by the next writer of the document (`doc add`); the kill windows are milliseconds, so this places them.
TEST(Issue24KillLeftovers, KilledDocNewDatabaseIsRemovedByTheNextRun) {
  TempDir dir;
  const std::string doc = (dir / "d.hula").string();
  const std::string left = ".d.hula.new-" + std::to_string(dead_pid()) + "-Ab12Cd";
  for (const char* suffix : {"", "-wal", "-shm", "-journal"}) write(dir / (left + suffix), std::string(4096, 'x'));
  ASSERT_EQ(hula({"doc", "new", "--force", doc}).exit_code, 0);
  EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"d.hula"});
  for (const char* suffix : {"", "-wal"}) write(dir / (left + suffix), "x");
  write(dir / "points.csv", kPointsCsv);
  ASSERT_EQ(hula({"doc", "add", doc, "--points", (dir / "points.csv").string()}).exit_code, 0);
  EXPECT_EQ(names_in(dir.path()), (std::vector<std::string>{"d.hula", "points.csv"}));
}

// checks: what a campaign killed while writing a study copy leaves beside the study — the copy's atomic-write
// temporary `..hula-batch-<dead pid>-0.json.tmp-<dead pid>-XXXXXX` (found by the probe after a kill; no run
// removed it) — and a copy itself are removed by the next `hula batch` of a campaign using that folder; a
// name of another form is left.
TEST(Issue24KillLeftovers, KilledCampaignsStudyCopyTemporaryIsRemovedByTheNextRun) {
  TempDir dir;
  fs::create_directory(dir / "studies");
  write(dir / "studies" / "s.json",
        R"({"format": "hula-study", "version": 1, "study": "fair-knots", "method": "none", "energy": "bending",)"
        R"( "points": [[0, 0], [1, 1], [2, 0], [3, 1]]})");
  write(dir / "c.json",
        R"({"format": "hula-campaign", "version": 1, "items": [{"id": "a", "study": "studies/s.json"}]})");
  const std::string dead = std::to_string(dead_pid());
  const std::string temporary = "..hula-batch-" + dead + "-0.json.tmp-" + dead + "-Ab12Cd";
  const std::string copy = ".hula-batch-" + dead + "-1.json";
  write(dir / "studies" / temporary, "{");
  write(dir / "studies" / copy, "{}");
  write(dir / "studies" / "..hula-batch-x", "not a pid");
  const ProcessResult r = hula({"batch", (dir / "c.json").string(), "--results", (dir / "r.json").string()});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(names_in(dir / "studies"), (std::vector<std::string>{"..hula-batch-x", "s.json"}));
}

#ifdef HULA_WITH_OCCT
// checks: the scratch folder of a killed exchange (`hula-exchange-<dead pid>-XXXXXX` with the request holding the
// curve data) is removed by the next export; another user's name pattern (`hula-exchange-x`) is left.
TEST(Issue24KillLeftovers, KilledExchangeScratchIsRemovedByTheNextExport) {
  TempDir dir;
  const fs::path tmp = dir / "tmp";
  fs::create_directory(tmp);
  const fs::path left = tmp / ("hula-exchange-" + std::to_string(dead_pid()) + "-Ab12Cd");
  fs::create_directory(left);
  write(left / "request.json", "{}");
  fs::create_directory(tmp / "hula-exchange-x");
  write(dir / "points.csv", kPointsCsv);
  ASSERT_EQ(hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "c.json").string()}).exit_code,
            0);
  const std::string doc = (dir / "d.hula").string();
  ASSERT_EQ(hula({"doc", "new", doc}).exit_code, 0);
  ASSERT_EQ(hula({"doc", "add", doc, "--curve", (dir / "c.json").string()}).exit_code, 0);
  const char* old_tmpdir = ::getenv("TMPDIR");
  const std::string saved = old_tmpdir != nullptr ? old_tmpdir : "";
  ::setenv("TMPDIR", tmp.c_str(), 1);
  const ProcessResult r = hula({"doc", "export", doc, "1", "--format", "step", "-o", (dir / "c.step").string()});
  if (old_tmpdir != nullptr)
    ::setenv("TMPDIR", saved.c_str(), 1);
  else
    ::unsetenv("TMPDIR");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(names_in(tmp), std::vector<std::string>{"hula-exchange-x"});
}
#endif

// checks: temporaries of a live process — this test's, named with its pid — are never taken for a killed
// run's: a `doc new` beside them leaves them.
TEST(Issue24KillLeftovers, LiveOwnersTemporariesAreKept) {
  TempDir dir;
  const std::string mine = ".d.hula.new-" + std::to_string(::getpid()) + "-abcdef";
  write(dir / mine, "live");
  write(dir / ".d.hula.new-notapid", "not ours");
  ASSERT_EQ(hula({"doc", "new", (dir / "d.hula").string()}).exit_code, 0);
  EXPECT_EQ(names_in(dir.path()), (std::vector<std::string>{mine, ".d.hula.new-notapid", "d.hula"}));
}

// checks: a temporary named with the pid of a live process that started after the temporary was last changed
// (here this test's pid on a file dated a day back) is a killed run's whose pid was reused: it is removed.
TEST(Issue24KillLeftovers, ReusedPidIsNoOwner) {
  TempDir dir;
  const std::string old = ".d.hula.new-" + std::to_string(::getpid()) + "-old123";
  write(dir / old, "left by a killed run");
  fs::last_write_time(dir / old, fs::file_time_type::clock::now() - std::chrono::hours(24));
  ASSERT_EQ(hula({"doc", "new", (dir / "d.hula").string()}).exit_code, 0);
  EXPECT_EQ(names_in(dir.path()), std::vector<std::string>{"d.hula"});
}

// The control points of `curve` (a curve file or `doc show` output).
json control_points_of(const std::string& text) { return json::parse(text)["control_points"]; }

// checks: SIGKILL at 12 random moments (HULA_FAULT_KILLS nightly) of `doc set 1 --curve` alternating between two
// 4,000-point curves leaves, after each kill, a sound document (`doc check`) whose entity holds the curve of the
// last acknowledged run or of the killed one — never an older one (no acknowledged change lost), never a mix —
// and beside it only the document and SQLite's own -wal/-shm/-journal: no temporary, and no process still
// running on it.
TEST(Issue24KillLeftovers, KilledDocSetKeepsTheLastAcknowledgedChange) {
  TempDir dir;
  std::vector<json> curves;
  for (int c = 0; c < 2; ++c) {
    std::string points;
    for (int i = 0; i < 4000; ++i)
      points +=
          std::to_string(i) + "," + std::to_string((i * (7 + c)) % 13) + "," + std::to_string((i * 5) % 11) + "\n";
    const fs::path csv = dir / ("p" + std::to_string(c) + ".csv"), curve = dir / ("c" + std::to_string(c) + ".json");
    write(csv, points);
    ASSERT_EQ(hula({"interpolate", "--points", csv.string(), "-o", curve.string()}).exit_code, 0);
    curves.push_back(control_points_of(io::read_text_file(curve)));
  }
  const std::string doc = (dir / "d.hula").string();
  ASSERT_EQ(hula({"doc", "new", doc}).exit_code, 0);
  ASSERT_EQ(hula({"doc", "add", doc, "--curve", (dir / "c0.json").string()}).exit_code, 0);
  const auto set_to = [&](int c) {
    return std::vector<std::string>{"doc", "set",     doc,
                                    "1",   "--curve", (dir / ("c" + std::to_string(c) + ".json")).string()};
  };
  const auto held = [&] {
    const ProcessResult show = hula({"doc", "show", doc, "1"});
    EXPECT_EQ(show.exit_code, 0) << show.err;
    const json points = control_points_of(show.out);
    return points == curves[0] ? 0 : points == curves[1] ? 1 : -1;
  };
  int acknowledged = 1;  // kill_at_random_moments runs the command once to its end first
  const std::vector<std::string> inputs{"c0.json", "c1.json", "p0.csv", "p1.csv"};
  kill_at_random_moments(set_to(1), fault_kills(12), 2024120703, [&](int run) {
    const ProcessResult check = hula({"doc", "check", doc});
    EXPECT_EQ(check.exit_code, 0) << "kill " << run << ": " << check.out << check.err;
    const int now = held();
    EXPECT_TRUE(now == acknowledged || now == 1)
        << "kill " << run << ": the entity holds curve " << now << ", the last acknowledged is " << acknowledged;
    for (const std::string& name : names_in(dir.path()))
      EXPECT_TRUE(name.rfind("d.hula", 0) == 0 || std::find(inputs.begin(), inputs.end(), name) != inputs.end())
          << "kill " << run << " left " << name;
    EXPECT_TRUE(live_processes_mentioning(doc).empty()) << "kill " << run;
    // An acknowledged change back to the first curve: the next kill must leave it or the killed run's.
    ASSERT_EQ(hula(set_to(0)).exit_code, 0);
    acknowledged = 0;
    EXPECT_EQ(held(), 0) << "run " << run << ": an acknowledged change is not in the document";
  });
}

#ifdef HULA_WITH_OCCT
// A whole STEP or IGES file of about `size` bytes (its header holds the time it was written): STEP from its
// "ISO-10303-21;" to its "END-ISO-10303-21;", IGES ending with its terminate section (a line with 'T' in
// column 73).
bool whole_exchange_file(const std::string& text, std::size_t size, const std::string& format) {
  if (text.size() + 200 <= size || text.size() >= size + 200) return false;
  if (format == "step") {
    const std::string end = "END-ISO-10303-21;\n";
    return text.rfind("ISO-10303-21;", 0) == 0 && text.compare(text.size() - end.size(), end.size(), end) == 0;
  }
  const std::size_t last = text.find_last_not_of("\r\n");
  const std::size_t from = text.rfind('\n', last);
  const std::string line = text.substr(from == std::string::npos ? 0 : from + 1, last + 1 - (from + 1));
  return line.size() >= 73 && line[72] == 'T';
}

// SIGKILL at random moments of `doc export --format FORMAT` of a 20,000-point curve (the helper runs for most of
// the command): see the tests below.
void check_killed_export(const std::string& format, const std::string& file, std::uint64_t seed) {
  TempDir dir;
  const fs::path tmp = dir / "tmp";
  fs::create_directory(tmp);
  const char* old_tmpdir = ::getenv("TMPDIR");
  const std::string saved = old_tmpdir != nullptr ? old_tmpdir : "";
  ::setenv("TMPDIR", tmp.c_str(), 1);  // the children's temporary directory
  std::string points;
  for (int i = 0; i < 20000; ++i)
    points += std::to_string(i) + "," + std::to_string((i * 7) % 13) + "," + std::to_string((i * 5) % 11) + "\n";
  write(dir / "points.csv", points);
  const std::string doc = (dir / "d.hula").string();
  ASSERT_EQ(hula({"doc", "new", doc}).exit_code, 0);
  ASSERT_EQ(hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "c.json").string()}).exit_code,
            0);
  ASSERT_EQ(hula({"doc", "add", doc, "--curve", (dir / "c.json").string()}).exit_code, 0);
  const fs::path out = dir / "out" / file;
  fs::create_directory(dir / "out");
  const std::vector<std::string> args{"doc", "export", doc, "1", "--format", format, "-o", out.string()};
  ASSERT_EQ(hula(args).exit_code, 0);
  const std::size_t size = io::read_text_file(out).size();
  write(out, "OLD");
  kill_at_random_moments(args, fault_kills(12), seed, [&](int run) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(500);
    while (!live_processes_mentioning(tmp.string()).empty() && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    EXPECT_TRUE(live_processes_mentioning(tmp.string()).empty()) << "kill " << run << ": the helper outlived hula";
    const std::string now = io::read_text_file(out);
    EXPECT_TRUE(now == "OLD" || whole_exchange_file(now, size, format))
        << "kill " << run << ": " << now.size() << " bytes of a mix";
  });
  ASSERT_EQ(hula(args).exit_code, 0);
  EXPECT_TRUE(whole_exchange_file(io::read_text_file(out), size, format));
  EXPECT_EQ(names_in(tmp), std::vector<std::string>{});
  EXPECT_EQ(names_in(dir / "out"), std::vector<std::string>{file});
  if (old_tmpdir != nullptr)
    ::setenv("TMPDIR", saved.c_str(), 1);
  else
    ::unsetenv("TMPDIR");
}

// checks: SIGKILL at 12 random moments (HULA_FAULT_KILLS nightly) of `doc export --format step` leaves no helper
// running 0.5 s after its parent died (it kept running and wrote the output), the output old or whole; the next
// export leaves the temporary directory ($TMPDIR) empty — no `hula-exchange-*` folder — and no temporary beside
// the output.
TEST(Issue24KillLeftovers, KilledStepExportLeavesNoHelperAndNoScratch) {
  check_killed_export("step", "c.step", 2024120702);
}

// checks: the same for `doc export --format iges`.
TEST(Issue24KillLeftovers, KilledIgesExportLeavesNoHelperAndNoScratch) {
  check_killed_export("iges", "c.igs", 2024120704);
}
#endif

}  // namespace
}  // namespace hula::regress
