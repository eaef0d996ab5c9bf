// SPDX-License-Identifier: MIT
// Issue 24, item 13 (full disk): on a full disk `doc new` failed with IoError
// ("switch to WAL: the disk is full ...") and opening an existing document
// with "PRAGMA application_id: disk I/O error" (SQLite could not grow the -shm
// file: ENOSPC reported as SQLITE_IOERR), so the server answered both 500
// where docs/errors.md promises StorageFull, 507. The probe reran this on a
// small tmpfs.
#include <utility>

#include "cli.hpp"

namespace hula::regress {
namespace {

// Runs, in a private mount namespace, a shell script with a 900 KiB tmpfs mounted on `dir` ($1) and the hula
// binary as $0 (exit 97 when the namespace or the mount is not allowed). `script` runs in `dir`.
ProcessResult on_small_tmpfs(const fs::path& dir, const std::string& script, const std::vector<std::string>& args) {
  std::vector<std::string> argv = {
      "-m",          "/bin/sh",
      "-c",          "mount -t tmpfs -o size=900k tmpfs \"$1\" || exit 97; cd \"$1\" || exit 97; " + script,
      HULA_CLI_PATH, dir.string()};
  argv.insert(argv.end(), args.begin(), args.end());
  return testing::run_process("/usr/bin/unshare", argv);
}

// Fills the current folder's file system (dd stops at ENOSPC).
constexpr const char* kFill = "dd if=/dev/zero of=filler bs=4k 2>/dev/null; ";

// checks: on a tmpfs filled to the last block, `doc new` of a new document and `doc list` / `doc set` of a
// document made before the disk filled each exit 3 with StorageFull naming the document (was IoError), and
// `doc new` leaves no temporary database beside it (the script exits 99 if it does).
TEST(Issue24FullDiskDocument, FullDiskIsStorageFull) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  fs::create_directory(dir / "ws");
  const std::string points = (dir / "points.csv").string();
  const ProcessResult probe = on_small_tmpfs(dir / "ws", "exec \"$0\" --version", {});
  if (probe.exit_code == 97 || probe.exit_code == 127 || probe.exit_code == 1)
    GTEST_SKIP() << "no private tmpfs mount here (unshare -m needs CAP_SYS_ADMIN): " << probe.err;
  ASSERT_EQ(probe.exit_code, 0) << probe.err;
  const std::string made =
      "\"$0\" doc new d.hula > /dev/null && \"$0\" doc add d.hula --points \"$2\" > /dev/null || exit 98; ";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"doc new",
       std::string(kFill) + "\"$0\" doc new n.hula; rc=$?; ls -A | grep -q 'hula.new-' && exit 99; exit $rc"},
      {"doc list", made + kFill + "exec \"$0\" doc list d.hula"},
      {"doc set", made + kFill + "exec \"$0\" doc set d.hula 1 --attribute 'name=\"x\"'"},
  };
  for (const auto& [name, script] : cases) {
    const ProcessResult r = on_small_tmpfs(dir / "ws", script, {points});
    ASSERT_NE(r.exit_code, 98) << name << ": setting up failed: " << r.err;
    EXPECT_EQ(r.exit_code, 3) << name << ": " << r.err;
    const json e = error_of(r)["error"];
    EXPECT_EQ(e["code"], "StorageFull") << name << ": " << r.err;
    EXPECT_NE(e.value("message", std::string()).find(".hula"), std::string::npos) << name << ": " << r.err;
  }
}

}  // namespace
}  // namespace hula::regress
