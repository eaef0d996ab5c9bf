// SPDX-License-Identifier: MIT
// Issue 24, item 13: the server answered 500 (IoError) for a locked, a corrupt
// or a full document, reads included while a CLI `doc run` held the file; 500
// was not in the documented error table. Each now has its own code and status:
// DocumentLocked 423, DocumentCorrupt 422, StorageFull 507 (docs/errors.md).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "hula/core/error.hpp"
#include "hula/io/atomic_file.hpp"
#include "hula/oli/document.hpp"
#include "hula/server/http.hpp"
#include "hula/testing/temp_dir.hpp"

namespace hula::regress {
namespace {

namespace fs = std::filesystem;

// The code of the hula::Error `f` throws (a failure when it throws nothing).
template <class F>
std::string code_of(F&& f) {
  try {
    f();
  } catch (const Error& e) {
    return std::string(errc_name(e.code()));
  }
  ADD_FAILURE() << "no hula::Error";
  return {};
}

// checks: a second writer of a document held by a first gets DocumentLocked (was IoError), which the server
// answers 423; a document truncated to 50 bytes, and one whose pages are overwritten, are DocumentCorrupt, 422.
TEST(Issue24DocumentErrorStatus, LockedAndCorruptDocumentsHaveTheirOwnCodes) {
  testing::TempDir dir;
  const fs::path path = dir / "a.hula";
  {
    oli::Document writer = oli::Document::create(path);
    EXPECT_EQ(code_of([&] { (void)oli::Document::open(path); }), "DocumentLocked");
  }
  const std::string bytes = io::read_text_file(path);
  ASSERT_GT(bytes.size(), 4096U);
  const fs::path truncated = dir / "t.hula";
  io::write_file_atomically(truncated, bytes.substr(0, 50));
  EXPECT_EQ(code_of([&] { (void)oli::Document::open(truncated, oli::OpenMode::ReadOnly); }), "DocumentCorrupt");
  // A valid 100-byte header over pages of garbage: SQLite reports SQLITE_CORRUPT or SQLITE_NOTADB.
  const fs::path garbage = dir / "g.hula";
  std::string g = bytes;
  for (std::size_t i = 100; i < g.size(); ++i) g[i] = static_cast<char>(0xA5);
  io::write_file_atomically(garbage, g);
  EXPECT_EQ(code_of([&] { (void)oli::Document::open(garbage, oli::OpenMode::ReadOnly); }), "DocumentCorrupt");
}

// checks: the one table of statuses: locked 423, corrupt 422, full 507, other I/O 500.
TEST(Issue24DocumentErrorStatus, StatusTable) {
  EXPECT_EQ(server::http_status(Errc::DocumentLocked), 423U);
  EXPECT_EQ(server::http_status(Errc::DocumentCorrupt), 422U);
  EXPECT_EQ(server::http_status(Errc::StorageFull), 507U);
  EXPECT_EQ(server::http_status(Errc::IoError), 500U);
  EXPECT_EQ(errc_name(Errc::StorageFull), "StorageFull");
}

}  // namespace
}  // namespace hula::regress
