// SPDX-License-Identifier: MIT
// Issue 24, item 6: a 278-byte hostile entity blob (an array count of
// 150,000,000) made `doc check` allocate 3.5 GB for 9 s, and with 0xFFFFFFFF
// every `doc` command exited 6 (out of memory). Every count read from a blob is
// now bounded by the bytes that remain before anything is allocated.
#include <sqlite3.h>

#include <cstdint>
#include <cstring>

#include "cli.hpp"

namespace hula::regress {
namespace {

// An entity blob: magic "HLE1", a skeleton of `text`, then an array count with nothing after it.
std::string hostile_blob(std::uint32_t count) {
  const std::string text = R"({"kind": "curve", "attributes": {}, "data": {"$f64": 0}})";
  std::string blob = "HLE1";
  const auto u32 = [&](std::uint32_t v) {
    char b[4];
    std::memcpy(b, &v, 4);
    blob.append(b, 4);
  };
  u32(static_cast<std::uint32_t>(text.size()));
  blob += text;
  u32(count);
  blob.append(8, '\0');  // one empty array's length, so the blob is not simply truncated at the count
  return blob;
}

// Replaces entity 1's stored state with `blob`, with SQLite directly (a hostile or damaged file).
void plant(const fs::path& doc, const std::string& blob) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(doc.c_str(), &db), SQLITE_OK);
  sqlite3_stmt* st = nullptr;
  ASSERT_EQ(sqlite3_prepare_v2(db, "UPDATE entities SET state = ? WHERE label = 1", -1, &st, nullptr), SQLITE_OK);
  sqlite3_bind_blob(st, 1, blob.data(), static_cast<int>(blob.size()), SQLITE_TRANSIENT);
  EXPECT_EQ(sqlite3_step(st), SQLITE_DONE) << sqlite3_errmsg(db);
  EXPECT_EQ(sqlite3_changes(db), 1);
  sqlite3_finalize(st);
  sqlite3_close(db);
}

// checks: under a 1 GB address-space limit, `doc check` of a document whose entity blob claims 150,000,000
// and 0xFFFFFFFF arrays reports the file broken (exit 3, "ok": false) with a problem naming the array
// count, and `doc list` refuses it as corrupt (exit 3) — neither runs out of memory (exit 6).
TEST(Issue24BlobCounts, HostileArrayCountIsRefusedBeforeAllocating) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  ASSERT_EQ(hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "c.json").string()}).exit_code,
            0);
  const fs::path doc = dir / "d.hula";
  ASSERT_EQ(hula({"doc", "new", doc.string()}).exit_code, 0);
  ASSERT_EQ(hula({"doc", "add", doc.string(), "--curve", (dir / "c.json").string()}).exit_code, 0);
  for (const std::uint32_t count : {150'000'000U, 0xFFFFFFFFU}) {
    plant(doc, hostile_blob(count));
    const auto limited = [&](const std::string& command) {
      return testing::run_process("/bin/sh", {"-c", "ulimit -v 1000000 && exec \"$0\" doc \"$1\" \"$2\"", HULA_CLI_PATH,
                                              command, doc.string()});
    };
    const ProcessResult check = limited("check");
    ASSERT_EQ(check.exit_code, 3) << count << ": " << check.err.substr(0, 300);
    const json report = json::parse(check.out);
    EXPECT_EQ(report["ok"], false);
    EXPECT_NE(report["problems"].dump().find("array count " + std::to_string(count)), std::string::npos)
        << report["problems"].dump();
    const ProcessResult list = limited("list");
    EXPECT_EQ(list.exit_code, 3) << count << ": " << list.err.substr(0, 300);
    EXPECT_NE(message_of(list).find("array count"), std::string::npos) << list.err.substr(0, 300);
  }
}

}  // namespace
}  // namespace hula::regress
