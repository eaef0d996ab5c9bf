// SPDX-License-Identifier: MIT
// Replays the law-parser fuzz corpus (fuzz/corpus/law_parser/: seeds and every
// crasher found, kept as regression inputs) through the fuzzer's own check, so
// each fixed crash stays fixed in the ordinary gcc test build.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "law_parser_check.hpp"

namespace {

// checks: every corpus input either parses and round-trips through print/parse, or is a hula::Error
// (the fuzzer's property, against the stored corpus).
TEST(LawParserCorpus, EveryInputKeepsTheContract) {
  const std::filesystem::path dir = "fuzz/corpus/law_parser";
  ASSERT_TRUE(std::filesystem::is_directory(dir)) << "run from the source root";
  std::size_t files = 0, parsed = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    std::ifstream in(entry.path(), std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    ++files;
    if (hula::fuzz::check_law_parser_input(ss.str())) ++parsed;
  }
  EXPECT_GE(files, 6U);
  EXPECT_GE(parsed, 4U);
}

}  // namespace
