// SPDX-License-Identifier: MIT
// Crash and fault tests of file documents (issue 11): a child process applying
// transactions in a loop is killed with SIGKILL at random moments, 200 times;
// every time the file opens, passes the document check and holds exactly the
// state after some revision R at or beyond the last one the child reported
// committed — a prefix of its transactions, nothing reported lost. The same
// with a full disk (RLIMIT_FSIZE) and an unwritable directory: a clear error
// and the old content intact. The reference is an in-memory replay of the same
// deterministic schedule of transactions.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <poll.h>
#include <pwd.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <functional>
#include <map>
#include <thread>

#include "hula/core/rng.hpp"
#include "hula/oli/document.hpp"
#include "hula/testing/temp_dir.hpp"
#include "oli_fixtures.hpp"

namespace hula::oli {
namespace {

using testing::observable;

// Transaction number r (1-based) of the schedule: every 7th adds a point set of r % 50 + 20
// points, the others move a point of an existing entity. Deterministic in r and the document.
void scheduled(Document& doc, std::uint64_t r) {
  const auto outcome = doc.transact("step " + std::to_string(r), [&](Edit& e) {
    const std::vector<Label> labels = doc.labels();
    if (r % 7 == 1 || labels.empty()) {
      PointSet set;
      for (std::uint64_t i = 0; i < r % 50 + 20; ++i)
        set.points.emplace_back(static_cast<double>(r), static_cast<double>(i), 0.25 * static_cast<double>(i));
      (void)e.add_point_set(std::move(set));
    } else {
      const Label l = labels[r % labels.size()];
      const std::size_t n = doc.get(l).point_set().points.size();
      e.move_point(l, r % n, {static_cast<double>(r), -static_cast<double>(r), 0.5});
    }
  });
  outcome.throw_if_failed();
}

// The document after transactions 1..r of the schedule, in memory.
class Expected {
 public:
  const Json& at(std::uint64_t r) {
    while (states_.size() <= r) {
      if (!states_.empty()) scheduled(doc_, states_.size());
      states_.push_back(observable(doc_));
    }
    return states_[r];
  }

 private:
  Document doc_;
  std::vector<Json> states_;
};

// What the child writes once the document is open (then the kill timer starts).
constexpr std::uint64_t kReady = ~std::uint64_t{0};

// The child: opens the document and applies the schedule from its revision on, writing each
// committed revision (8 bytes) to `out` after the commit returned.
[[noreturn]] void child_loop(const std::filesystem::path& path, int out, std::uint64_t until) {
  try {
    Document doc = Document::open(path, OpenMode::ReadWrite, 50);
    if (::write(out, &kReady, sizeof kReady) != sizeof kReady) _exit(3);
    for (std::uint64_t r = doc.revision() + 1; r <= until; ++r) {
      scheduled(doc, r);
      if (::write(out, &r, sizeof r) != sizeof r) _exit(3);
    }
    _exit(0);
  } catch (const Error& e) {
    const std::string m = e.message();
    std::uint64_t marker = 0;
    if (::write(out, &marker, sizeof marker) < 0) _exit(4);
    if (::write(out, m.data(), m.size()) < 0) _exit(4);
    _exit(2);
  } catch (...) {
    _exit(5);
  }
}

struct ChildReport {
  std::vector<std::uint64_t> committed;
  std::string error;
  int status = 0;
};

// Forks a child running child_loop; `killer` (may be null) decides when to SIGKILL it.
ChildReport run_child(const std::filesystem::path& path, std::uint64_t until, const std::function<void()>& setup,
                      std::optional<std::chrono::microseconds> kill_after) {
  int fds[2];
  EXPECT_EQ(::pipe(fds), 0);
  const pid_t pid = ::fork();
  if (pid == 0) {
    ::close(fds[0]);
    if (setup) setup();
    child_loop(path, fds[1], until);
  }
  ::close(fds[1]);
  std::string bytes;
  if (kill_after) {
    // Start the timer once the child has opened the document (or failed to).
    char first[8];
    std::size_t have = 0;
    ssize_t n = 0;
    while (have < sizeof first && (n = ::read(fds[0], first + have, sizeof first - have)) > 0)
      have += static_cast<std::size_t>(n);
    bytes.append(first, have);
    std::this_thread::sleep_for(*kill_after);
    ::kill(pid, SIGKILL);
  }
  ChildReport report;
  char buffer[4096];
  ssize_t got = 0;
  while ((got = ::read(fds[0], buffer, sizeof buffer)) > 0) bytes.append(buffer, static_cast<std::size_t>(got));
  ::close(fds[0]);
  ::waitpid(pid, &report.status, 0);
  std::size_t at = 0;
  while (at + 8 <= bytes.size()) {
    std::uint64_t r = 0;
    std::memcpy(&r, bytes.data() + at, 8);
    at += 8;
    if (r == 0) {
      report.error = bytes.substr(at);
      break;
    }
    if (r != kReady) report.committed.push_back(r);
  }
  return report;
}

// Checks the file opens, passes the check and equals the schedule after its revision ≥ the last reported one.
void expect_prefix(const std::filesystem::path& path, const ChildReport& child, Expected& expected,
                   std::uint64_t& last) {
  const CheckReport check = Document::check_file(path);
  ASSERT_TRUE(check.ok) << (check.problems.empty() ? "" : check.problems[0]);
  const Document doc = Document::open(path, OpenMode::ReadOnly);
  const std::uint64_t reported = child.committed.empty() ? last : child.committed.back();
  ASSERT_GE(doc.revision(), reported) << "a transaction reported committed was lost";
  ASSERT_GE(doc.revision(), last);
  ASSERT_EQ(observable(doc), expected.at(doc.revision())) << "revision " << doc.revision();
  last = doc.revision();
}

// Checks 200 SIGKILLs at random moments each leave a file at a committed prefix of the schedule.
TEST(Crash, KillNineAtRandomMomentsLeavesACommittedPrefix) {
  hula::testing::TempDir dir;
  const auto path = dir / "crash.hula";
  { (void)Document::create(path); }
  Expected expected;
  Rng rng(11);
  std::uint64_t last = 0;
  for (int run = 0; run < 200; ++run) {
    const auto delay = std::chrono::microseconds(rng.below(3000));
    const ChildReport child = run_child(path, 1'000'000, nullptr, delay);
    ASSERT_TRUE(WIFSIGNALED(child.status) || WIFEXITED(child.status));
    ASSERT_NO_FATAL_FAILURE(expect_prefix(path, child, expected, last)) << "run " << run;
  }
  EXPECT_GT(last, 20u) << "the children committed too little for the test to mean anything";
}

// Checks a full disk (RLIMIT_FSIZE) fails the commit with a clear error and keeps the committed prefix.
TEST(Crash, FullDiskGivesAClearErrorAndKeepsCommittedState) {
  hula::testing::TempDir dir;
  const auto path = dir / "full.hula";
  {
    Document doc = Document::create(path);
    for (std::uint64_t r = 1; r <= 10; ++r) scheduled(doc, r);
  }
  Expected expected;
  std::uint64_t last = 10;
  const auto size = std::filesystem::file_size(path);
  const ChildReport child = run_child(
      path, 100'000,
      [size] {
        ::signal(SIGXFSZ, SIG_IGN);  // a write past the limit then fails with EFBIG instead of killing
        const rlimit limit{size + 64 * 1024, size + 64 * 1024};
        ::setrlimit(RLIMIT_FSIZE, &limit);
      },
      std::nullopt);
  ASSERT_TRUE(WIFEXITED(child.status)) << child.status;
  EXPECT_EQ(WEXITSTATUS(child.status), 2) << child.error;
  EXPECT_NE(child.error.find(path.string()), std::string::npos) << child.error;
  EXPECT_NE(child.error.find("full"), std::string::npos) << child.error;
  EXPECT_FALSE(child.committed.empty());
  expect_prefix(path, child, expected, last);
  EXPECT_EQ(last, child.committed.back());
}

// Checks a document in an unwritable directory is refused for writing by name, and still reads.
TEST(Crash, UnwritableDirectoryIsRefusedAndContentKept) {
  hula::testing::TempDir dir;
  const auto sub = dir / "ro";
  std::filesystem::create_directory(sub);
  const auto path = sub / "a.hula";
  {
    Document doc = Document::create(path);
    for (std::uint64_t r = 1; r <= 5; ++r) scheduled(doc, r);
  }
  ::chmod(path.c_str(), 0666);
  ::chmod(sub.c_str(), 0555);
  // Root ignores permissions: the child drops to an unprivileged user first.
  const bool root = ::geteuid() == 0;
  const passwd* nobody = ::getpwnam("nobody");
  if (root) {
    ASSERT_NE(nobody, nullptr);
  }
  if (root) ::chmod(dir.path().c_str(), 0755);
  const uid_t uid = root ? nobody->pw_uid : 0;
  const gid_t gid = root ? nobody->pw_gid : 0;
  const ChildReport child = run_child(
      path, 100,
      [root, uid, gid] {
        if (root && (::setgid(gid) != 0 || ::setuid(uid) != 0)) _exit(6);
      },
      std::nullopt);
  ::chmod(sub.c_str(), 0755);
  ASSERT_TRUE(WIFEXITED(child.status)) << child.status;
  EXPECT_EQ(WEXITSTATUS(child.status), 2) << child.error;
  EXPECT_NE(child.error.find(path.string()), std::string::npos) << child.error;
  EXPECT_TRUE(child.committed.empty());
  Expected expected;
  std::uint64_t last = 5;
  expect_prefix(path, child, expected, last);
  EXPECT_EQ(last, 5u);
}

}  // namespace
}  // namespace hula::oli
