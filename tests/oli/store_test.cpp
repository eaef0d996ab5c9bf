// SPDX-License-Identifier: MIT
// The SQLite store on its own: batches round-trip, the file refuses what it
// must (a newer schema naming both versions, a second writer, corrupt and
// truncated files, other applications' databases) and is never written then.
#include "hula/oli/store/store.hpp"

#include <gtest/gtest.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/testing/temp_dir.hpp"

namespace hula::oli::store {
namespace {

std::string read_all(const std::filesystem::path& p) { return io::read_text_file(p); }

void write_all(const std::filesystem::path& p, const std::string& bytes) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  out << bytes;
}

// Runs raw SQL on a file with SQLite directly (to fake other writers' files).
void raw_sql(const std::filesystem::path& p, const char* sql) {
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open(p.c_str(), &db), SQLITE_OK);
  ASSERT_EQ(sqlite3_exec(db, sql, nullptr, nullptr, nullptr), SQLITE_OK) << sqlite3_errmsg(db);
  sqlite3_close(db);
}

std::string error_of(const std::function<void()>& f, Errc code = Errc::IoError) {
  try {
    f();
  } catch (const Error& e) {
    EXPECT_EQ(errc_name(e.code()), errc_name(code)) << e.message();
    return e.message();
  }
  ADD_FAILURE() << "no error";
  return {};
}

Batch one_entity_batch(std::uint64_t revision, std::uint64_t label, std::string bytes) {
  Batch b;
  b.entities.emplace_back(label, std::move(bytes));
  StepRow step{revision, "add", "2026-12-01T00:00:00.000Z", true, {{label, std::nullopt}}};
  b.steps.push_back(step);
  b.revision = revision;
  b.next_label = label + 1;
  return b;
}

// Checks that a batch written is read back field for field, blobs byte for byte (zeros included).
TEST(Store, BatchesRoundTripThroughTheFile) {
  testing::TempDir dir;
  const std::string bytes(
      "\0\x01\xff"
      "blob",
      7);
  {
    Store s = Store::create(dir / "a.hula", {0, 1, "native", "now", "0.1.0"}, false);
    s.apply(one_entity_batch(1, 1, bytes));
  }
  Store s = Store::open(dir / "a.hula", Access::ReadOnly);
  const Snapshot snap = s.load();
  EXPECT_EQ(snap.schema_version, kSchemaVersion);
  EXPECT_EQ(snap.document.revision, 1u);
  EXPECT_EQ(snap.document.next_label, 2u);
  EXPECT_EQ(snap.document.backend, "native");
  ASSERT_EQ(snap.entities.size(), 1u);
  EXPECT_EQ(snap.entities[0].second, bytes);
  ASSERT_EQ(snap.steps.size(), 1u);
  EXPECT_EQ(snap.steps[0].name, "add");
  ASSERT_EQ(snap.steps[0].entities.size(), 1u);
  EXPECT_FALSE(snap.steps[0].entities[0].second.has_value());
  EXPECT_TRUE(s.integrity_check().empty());
}

// The size of `p` once it exceeds `size`, waiting at most 60 s for it.
std::uintmax_t wait_for_size_over(const std::filesystem::path& p, std::uintmax_t size) {
  for (int i = 0; i < 6000 && std::filesystem::file_size(p) <= size; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  return std::filesystem::file_size(p);
}

// Checks the WAL is still checkpointed into the database file while the writer stays open (SQLite's
// automatic checkpoint is replaced by the store's own thread), and every batch reads back after reopening.
TEST(Store, WalIsCheckpointedWhileTheWriterIsOpen) {
  testing::TempDir dir;
  const std::filesystem::path path = dir / "a.hula";
  const std::string blob(64 * 1024, 'x');  // 16 pages and more per commit: past 1,000 within 100 commits
  {
    Store s = Store::create(path, {0, 1, "native", "now", "0.1.0"}, false);
    const std::uintmax_t before = std::filesystem::file_size(path);
    for (std::uint64_t r = 1; r <= 100; ++r) s.apply(one_entity_batch(r, r, blob));
    EXPECT_GT(wait_for_size_over(path, before + 1024 * 1024), before + 1024 * 1024);
  }
  Store s = Store::open(path, Access::ReadOnly);
  const Snapshot snap = s.load();
  ASSERT_EQ(snap.entities.size(), 100u);
  for (const auto& [label, state] : snap.entities) EXPECT_EQ(state, blob) << "entity " << label;
  EXPECT_TRUE(s.integrity_check().empty());
}

// Checks the file is in WAL mode with the HULA application id (SQLite's own pragmas as the reference).
TEST(Store, FileIsWalWithApplicationId) {
  testing::TempDir dir;
  { (void)Store::create(dir / "a.hula", {}, false); }
  sqlite3* db = nullptr;
  ASSERT_EQ(sqlite3_open((dir / "a.hula").c_str(), &db), SQLITE_OK);
  auto one = [&](const char* sql) {
    sqlite3_stmt* st = nullptr;
    sqlite3_prepare_v2(db, sql, -1, &st, nullptr);
    sqlite3_step(st);
    std::string v = reinterpret_cast<const char*>(sqlite3_column_text(st, 0));
    sqlite3_finalize(st);
    return v;
  };
  EXPECT_EQ(one("PRAGMA journal_mode"), "wal");
  EXPECT_EQ(one("PRAGMA application_id"), std::to_string(kApplicationId));
  EXPECT_EQ(one("PRAGMA user_version"), std::to_string(kSchemaVersion));
  sqlite3_close(db);
}

// Checks that create refuses an existing file without overwrite and leaves it byte-identical.
TEST(Store, CreateRefusesExistingFile) {
  testing::TempDir dir;
  write_all(dir / "a.hula", "keep me");
  const std::string message = error_of([&] { (void)Store::create(dir / "a.hula", {}, false); });
  EXPECT_NE(message.find("already exists"), std::string::npos) << message;
  EXPECT_EQ(read_all(dir / "a.hula"), "keep me");
  (void)Store::create(dir / "a.hula", {}, true);
  EXPECT_NE(read_all(dir / "a.hula"), "keep me");
  EXPECT_EQ(dir.names(), std::vector<std::string>{"a.hula"});
}

// Checks a file of a newer schema is refused with both versions named, and not modified.
TEST(Store, NewerSchemaIsRefusedNamingBothVersions) {
  testing::TempDir dir;
  { (void)Store::create(dir / "a.hula", {}, false); }
  raw_sql(dir / "a.hula", "PRAGMA user_version = 7");
  const std::string before = read_all(dir / "a.hula");
  for (Access access : {Access::ReadWrite, Access::ReadOnly}) {
    const std::string message = error_of([&] { (void)Store::open(dir / "a.hula", access); });
    EXPECT_NE(message.find("version 7"), std::string::npos) << message;
    EXPECT_NE(message.find("up to " + std::to_string(kSchemaVersion)), std::string::npos) << message;
  }
  EXPECT_EQ(read_all(dir / "a.hula"), before);
}

// Checks garbage, truncated, empty and foreign SQLite files are refused by name and never written.
TEST(Store, CorruptTruncatedAndForeignFilesAreRefusedUntouched) {
  testing::TempDir dir;
  {
    Store s = Store::create(dir / "good.hula", {}, false);
    for (std::uint64_t r = 1; r <= 40; ++r) s.apply(one_entity_batch(r, r, std::string(3000, 'x')));
  }
  const std::string good = read_all(dir / "good.hula");
  ASSERT_GT(good.size(), 8192u);
  struct Case {
    std::string name, bytes, expect;
    Errc code = Errc::DocumentCorrupt;
  };
  std::string garbled = good;
  for (std::size_t i = 4096; i < garbled.size(); i += 7) garbled[i] = static_cast<char>(garbled[i] ^ 0x5a);
  const std::vector<Case> cases = {
      {"garbage.hula", std::string(5000, 'g'), "not a HulaHoops document", Errc::IoError},
      {"empty.hula", "", "truncated"},
      {"half.hula", good.substr(0, good.size() / 2), "corrupt"},
      {"header.hula", good.substr(0, 60), "truncated"},
      {"garbled.hula", garbled, "corrupt"},
  };
  for (const Case& c : cases) {
    write_all(dir / c.name, c.bytes);
    const std::string message = error_of(
        [&] {
          Store s = Store::open(dir / c.name, Access::ReadWrite);
          (void)s.load();
        },
        c.code);
    EXPECT_NE(message.find(c.name), std::string::npos) << message;
    EXPECT_NE(message.find(c.expect), std::string::npos) << c.name << ": " << message;
    EXPECT_EQ(read_all(dir / c.name), c.bytes) << c.name;
  }
  raw_sql(dir / "other.db", "CREATE TABLE t (x)");
  const std::string message = error_of([&] { (void)Store::open(dir / "other.db", Access::ReadWrite); });
  EXPECT_NE(message.find("another application"), std::string::npos) << message;
}

// Checks a second writer — another process, or another Store here — is refused while readers still work.
TEST(Store, SecondWriterIsRefused) {
  testing::TempDir dir;
  Store writer = Store::create(dir / "a.hula", {}, false);
  writer.apply(one_entity_batch(1, 1, "one"));
  const std::string message =
      error_of([&] { (void)Store::open(dir / "a.hula", Access::ReadWrite); }, Errc::DocumentLocked);
  EXPECT_NE(message.find("open for writing by another process"), std::string::npos) << message;
  const pid_t pid = fork();
  ASSERT_GE(pid, 0);
  if (pid == 0) {
    try {
      (void)Store::open(dir / "a.hula", Access::ReadWrite);
      _exit(1);
    } catch (const Error& e) {
      _exit(std::string(e.message()).find("open for writing") != std::string::npos ? 0 : 2);
    }
  }
  int status = 0;
  waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  Store reader = Store::open(dir / "a.hula", Access::ReadOnly);
  EXPECT_EQ(reader.load().entities.size(), 1u);
  writer.apply(one_entity_batch(2, 2, "two"));
  EXPECT_EQ(reader.load().entities.size(), 2u);
}

// Checks a failed batch (a constraint violation mid-batch) leaves nothing of itself in the file.
TEST(Store, FailedBatchLeavesNothing) {
  testing::TempDir dir;
  Store s = Store::create(dir / "a.hula", {}, false);
  s.apply(one_entity_batch(1, 1, "one"));
  Batch bad = one_entity_batch(2, 2, "two");
  bad.entities.emplace_back(0, std::string("label 0 violates CHECK (label >= 1)"));
  EXPECT_THROW(s.apply(bad), Error);
  const Snapshot snap = s.load();
  EXPECT_EQ(snap.document.revision, 1u);
  EXPECT_EQ(snap.entities.size(), 1u);
  EXPECT_EQ(snap.steps.size(), 1u);
}

}  // namespace
}  // namespace hula::oli::store
