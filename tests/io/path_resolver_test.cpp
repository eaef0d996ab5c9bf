// SPDX-License-Identifier: MIT
// The path resolvers against the file system: relative_to joins relative names to its base,
// confined_to keeps every name inside its workspace (".." and symbolic links included).
#include "hula/io/path_resolver.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "hula/core/error.hpp"
#include "hula/testing/expect_error.hpp"
#include "hula/testing/temp_dir.hpp"

namespace hula::io {
namespace {

// checks: relative names resolve against the base, absolute names stay as written, empty names are refused.
TEST(PathResolver, RelativeToJoinsRelativeNames) {
  const PathResolver r = relative_to("/data/studies");
  EXPECT_EQ(r("kappa.csv", "target.csv"), std::filesystem::path("/data/studies/kappa.csv"));
  EXPECT_EQ(r("/tmp/k.csv", "target.csv"), std::filesystem::path("/tmp/k.csv"));
  HULA_EXPECT_ERROR(r("", "target.csv"), Errc::InvalidArgument, "target.csv");
}

// checks: a workspace resolver accepts names inside it and refuses absolute names, ".." escapes
// (the issue's {"csv": "../../etc/passwd"}) and a symbolic link that points outside, naming the field.
TEST(PathResolver, ConfinedToRefusesEscapes) {
  const testing::TempDir dir;
  const std::filesystem::path ws = dir.path() / "ws";
  std::filesystem::create_directories(ws / "sub");
  std::ofstream(ws / "sub" / "k.csv") << "0,1\n1,1\n";
  std::filesystem::create_directory_symlink(dir.path(), ws / "out");
  const PathResolver r = confined_to(ws);
  EXPECT_EQ(r("sub/k.csv", "target.csv"), std::filesystem::weakly_canonical(ws / "sub" / "k.csv"));
  EXPECT_EQ(r("sub/../sub/k.csv", "target.csv"), std::filesystem::weakly_canonical(ws / "sub" / "k.csv"));
  HULA_EXPECT_ERROR(r("../../etc/passwd", "target.csv"), Errc::InvalidArgument,
                    "target.csv: \"../../etc/passwd\" leaves");
  HULA_EXPECT_ERROR(r("/etc/passwd", "target.csv"), Errc::InvalidArgument, "not a relative file name");
  HULA_EXPECT_ERROR(r("out/secret.csv", "f"), Errc::InvalidArgument, "leaves the workspace");
  EXPECT_EQ(r("out/ws/sub/k.csv", "f"), std::filesystem::weakly_canonical(ws / "sub" / "k.csv"));  // back inside
  HULA_EXPECT_ERROR(r("sub/..", "f"), Errc::InvalidArgument, "the workspace itself");
  HULA_EXPECT_ERROR(r("", "f"), Errc::InvalidArgument, "empty");
}

}  // namespace
}  // namespace hula::io
