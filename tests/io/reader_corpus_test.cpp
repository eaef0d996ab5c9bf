// SPDX-License-Identifier: MIT
// Replays the reader fuzz corpora (fuzz/corpus/<reader>_reader/: seeds and
// every crasher found, kept as regression inputs) through the fuzzers' own
// check (fuzz/reader_checks.hpp), so each fixed crash stays fixed in the
// ordinary gcc build — among them the 65,000-deep JSON that crashed every
// reader (issue 10).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "hula/io/atomic_file.hpp"
#include "reader_checks.hpp"

namespace {

namespace fs = std::filesystem;
using hula::fuzz::Reader;

// Replays one corpus; returns {files, values read}.
std::pair<std::size_t, std::size_t> replay(const std::string& name, Reader reader) {
  const fs::path dir = fs::path("fuzz/corpus") / (name + "_reader");
  EXPECT_TRUE(fs::is_directory(dir)) << "run from the source root";
  std::size_t files = 0, read = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    ++files;
    if (hula::fuzz::check_reader_input(reader, hula::io::read_text_file(entry.path()))) ++read;
  }
  return {files, read};
}

// checks: every curve corpus input is a curve that round-trips, or a hula::Error (the fuzzer's property).
TEST(ReaderCorpus, Curve) {
  const auto [files, read] = replay("curve", Reader::Curve);
  EXPECT_GE(files, 8u);
  EXPECT_GE(read, 4u);
}

// checks: every points corpus input (JSON and CSV) is a point set or a hula::Error.
TEST(ReaderCorpus, Points) {
  const auto [files, read] = replay("points", Reader::Points);
  EXPECT_GE(files, 5u);
  EXPECT_GE(read, 3u);
}

// checks: every problem corpus input is a valid problem or a hula::Error.
TEST(ReaderCorpus, Problem) {
  const auto [files, read] = replay("problem", Reader::Problem);
  EXPECT_GE(files, 3u);
  EXPECT_GE(read, 1u);
}

// checks: every study corpus input (the example studies among them) reads or is a hula::Error.
TEST(ReaderCorpus, Study) {
  const auto [files, read] = replay("study", Reader::Study);
  EXPECT_GE(files, 20u);
  EXPECT_GE(read, 15u);
}

// checks: every profile corpus input samples or is a hula::Error (a csv naming /dev/zero is refused).
TEST(ReaderCorpus, Profile) {
  const auto [files, read] = replay("profile", Reader::Profile);
  EXPECT_GE(files, 6u);
  EXPECT_GE(read, 4u);
}

}  // namespace
