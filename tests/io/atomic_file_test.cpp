// SPDX-License-Identifier: MIT
// read_text_file / write_file_atomically: contents, replacement, permissions
// kept, and failures that name the path and leave no temporary file behind.
#include "hula/io/atomic_file.hpp"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include "hula/core/error.hpp"
#include "hula/testing/expect_error.hpp"
#include "hula/testing/temp_dir.hpp"

namespace hula::io {
namespace {

namespace fs = std::filesystem;

using testing::TempDir;

// checks: a new file gets the contents (binary-exact, with NUL and CRLF bytes).
TEST(AtomicFile, WritesNewFile) {
  TempDir dir;
  const std::string contents("a\r\nb\0c", 6);
  write_file_atomically(dir.path() / "x.json", contents);
  EXPECT_EQ(read_text_file(dir.path() / "x.json"), contents);
  EXPECT_EQ(dir.names().size(), 1u);
}

// checks: replacing keeps the permission bits of the old file and leaves no temporary behind.
TEST(AtomicFile, ReplacesExistingFileKeepingMode) {
  TempDir dir;
  const fs::path p = dir.path() / "curve.json";
  write_file_atomically(p, "old");
  ASSERT_EQ(::chmod(p.c_str(), 0640), 0);
  write_file_atomically(p, "new contents");
  EXPECT_EQ(read_text_file(p), "new contents");
  struct stat st {};
  ASSERT_EQ(::stat(p.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0640u);
  EXPECT_EQ(dir.names().size(), 1u);
}

// checks: a missing directory is an IoError naming the path.
TEST(AtomicFile, MissingDirectoryIsIoError) {
  TempDir dir;
  const fs::path p = dir.path() / "no-such-dir" / "x.json";
  HULA_EXPECT_ERROR(write_file_atomically(p, "x"), Errc::IoError, p.string());
}

// checks: when the rename fails (target is a non-empty directory) the temporary file is removed.
TEST(AtomicFile, FailedRenameRemovesTemporary) {
  TempDir dir;
  const fs::path target = dir.path() / "busy";
  fs::create_directory(target);
  write_file_atomically(target / "keep", "x");
  HULA_EXPECT_ERROR(write_file_atomically(target, "data"), Errc::IoError, target.string());
  EXPECT_EQ(dir.names().size(), 1u);  // only the directory itself
  EXPECT_EQ(read_text_file(target / "keep"), "x");
}

// checks: reading a missing file or a directory is an IoError naming the path.
TEST(AtomicFile, ReadErrorsNamePath) {
  TempDir dir;
  HULA_EXPECT_ERROR(read_text_file(dir.path() / "missing.json"), Errc::IoError, "missing.json");
  HULA_EXPECT_ERROR(read_text_file(dir.path()), Errc::IoError, "directory");
}

}  // namespace
}  // namespace hula::io
