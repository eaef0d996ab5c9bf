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

// checks: read_input_text maps a regular file of kMapBytes or more and gives its bytes exactly (NUL
// bytes, no final newline, a length that is not a multiple of the page size), reads a smaller one, a
// moved-from value is empty, and its errors are read_text_file's (missing file, directory, size limit).
TEST(AtomicFile, InputTextIsTheFilesBytes) {
  TempDir dir;
  std::string big;
  for (std::size_t i = 0; big.size() < InputText::kMapBytes + 4097; ++i) big += std::to_string(i * 7919 % 1009) + ",";
  big[12345] = '\0';
  write_file_atomically(dir.path() / "big.csv", big);
  InputText mapped = read_input_text(dir.path() / "big.csv", kMaxGeometryInputBytes);
  EXPECT_EQ(mapped.text(), big);
  const InputText moved = std::move(mapped);
  EXPECT_EQ(moved.text(), big);
  EXPECT_TRUE(mapped.text().empty());  // NOLINT(bugprone-use-after-move): the moved-from state is specified
  write_file_atomically(dir.path() / "small.csv", "1,2,3\n");
  EXPECT_EQ(read_input_text(dir.path() / "small.csv").text(), "1,2,3\n");
  HULA_EXPECT_ERROR(read_input_text(dir.path() / "missing.json"), Errc::IoError, "missing.json");
  HULA_EXPECT_ERROR(read_input_text(dir.path()), Errc::IoError, "directory");
  HULA_EXPECT_ERROR(read_input_text(dir.path() / "big.csv", InputText::kMapBytes), Errc::IoError, "limit");
}

}  // namespace
}  // namespace hula::io
