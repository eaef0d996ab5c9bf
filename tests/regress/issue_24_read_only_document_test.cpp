// SPDX-License-Identifier: MIT
// Issue 24, item 10: a sound document on a read-only mount could not be listed
// ("unable to open database file… is its directory writable?": SQLite's WAL
// reader needs a -shm file beside it) and `doc check` called it broken. Where
// the directory cannot be written, nothing can change the file, and it is now
// opened immutable.
#include <unistd.h>

#include "cli.hpp"

namespace hula::regress {
namespace {

// Runs `hula ARGS...` in a private mount namespace where `dir` is bind-mounted read-only (a real read-only
// mount: root's write access is refused with EROFS). Exit 97 when the namespace or the mount is not allowed.
ProcessResult on_read_only_mount(const fs::path& dir, const std::vector<std::string>& args) {
  std::vector<std::string> argv = {
      "-m",
      "/bin/sh",
      "-c",
      "mount --bind \"$1\" \"$1\" && mount -o remount,ro,bind \"$1\" || exit 97; shift; exec \"$0\" \"$@\"",
      HULA_CLI_PATH,
      dir.string()};
  argv.insert(argv.end(), args.begin(), args.end());
  return testing::run_process("/usr/bin/unshare", argv);
}

// checks: a document with one curve, closed cleanly (no -wal, no -shm), on a read-only mount: `doc list` lists
// its one entity and `doc check` says ok, with the revision written; nothing is created beside it.
TEST(Issue24ReadOnlyDocument, SoundDocumentOnAReadOnlyMountListsAndChecks) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  ASSERT_EQ(hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "c.json").string()}).exit_code,
            0);
  const fs::path doc = dir / "d.hula";
  ASSERT_EQ(hula({"doc", "new", doc.string()}).exit_code, 0);
  ASSERT_EQ(hula({"doc", "add", doc.string(), "--curve", (dir / "c.json").string()}).exit_code, 0);
  ASSERT_FALSE(fs::exists(doc.string() + "-wal"));
  const ProcessResult probe = on_read_only_mount(dir.path(), {"--version"});
  if (probe.exit_code == 97 || probe.exit_code == 127 || probe.exit_code == 1)
    GTEST_SKIP() << "no private read-only mount here (unshare -m needs CAP_SYS_ADMIN): " << probe.err;
  ASSERT_EQ(probe.exit_code, 0) << probe.err;
  const ProcessResult list = on_read_only_mount(dir.path(), {"doc", "list", doc.string()});
  ASSERT_EQ(list.exit_code, 0) << list.err;
  EXPECT_EQ(json::parse(list.out)["entities"].size(), 1U) << list.out;
  const ProcessResult check = on_read_only_mount(dir.path(), {"doc", "check", doc.string()});
  ASSERT_EQ(check.exit_code, 0) << check.err;
  const json c = json::parse(check.out);
  EXPECT_EQ(c["ok"], true) << check.out;
  EXPECT_EQ(c["entities"], 1) << check.out;
  EXPECT_FALSE(fs::exists(doc.string() + "-shm"));
}

}  // namespace
}  // namespace hula::regress
