// SPDX-License-Identifier: MIT
// `hula doc` as a user runs it: the example of docs/cli.md executed line by
// line (its printed JSON is the contract, compared member by member, times
// excepted), and every failing subcommand leaving the file byte-identical.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "hula/io/atomic_file.hpp"
#include "hula/io/json_read.hpp"
#include "hula/testing/run_process.hpp"
#include "hula/testing/temp_dir.hpp"

#ifndef HULA_CLI_PATH
#error "HULA_CLI_PATH must name the hula binary"
#endif

namespace hula {
namespace {

using Json = io::json::Json;
using testing::ProcessResult;

// Splits a command line as a POSIX shell would for words, single and double quotes.
std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> out;
  std::string word;
  bool in_word = false;
  char quote = 0;
  for (char c : line) {
    if (quote != 0) {
      if (c == quote)
        quote = 0;
      else
        word += c;
    } else if (c == '\'' || c == '"') {
      quote = c;
      in_word = true;
    } else if (c == ' ') {
      if (in_word) out.push_back(word);
      word.clear();
      in_word = false;
    } else {
      word += c;
      in_word = true;
    }
  }
  if (in_word) out.push_back(word);
  return out;
}

// Expected JSON matches actual JSON, where an expected "…" string matches any value.
bool matches(const Json& expected, const Json& actual) {
  if (expected.is_string() && expected.get<std::string>() == "…") return true;
  if (expected.is_object()) {
    if (!actual.is_object() || expected.size() != actual.size()) return false;
    for (const auto& [key, value] : expected.items())
      if (!actual.contains(key) || !matches(value, actual.at(key))) return false;
    return true;
  }
  if (expected.is_array()) {
    if (!actual.is_array() || expected.size() != actual.size()) return false;
    for (std::size_t i = 0; i < expected.size(); ++i)
      if (!matches(expected[i], actual[i])) return false;
    return true;
  }
  return expected == actual;
}

ProcessResult run_in(const std::filesystem::path& dir, std::vector<std::string> args) {
  // The binary runs with its paths relative to `dir`: give it absolute ones.
  for (std::string& a : args)
    if (a.ends_with(".hula") || a.ends_with(".json") || a.ends_with(".step") || a.ends_with(".igs"))
      a = (dir / a).string();
  return testing::run_process(HULA_CLI_PATH, args);
}

// Checks the docs/cli.md `hula doc` examples (every console block of the section, each in a fresh
// directory) print what the page shows, line by line.
TEST(DocCli, DocsExampleRunsAsShown) {
  const std::string page = io::read_text_file("docs/cli.md");
  const std::size_t section = page.find("## `hula doc`");
  ASSERT_NE(section, std::string::npos);
  const std::size_t section_end = page.find("\n## ", section + 3);
  std::size_t blocks = 0;
  for (std::size_t begin = page.find("```console\n", section); begin < section_end;
       begin = page.find("```console\n", begin + 10)) {
    ++blocks;
    const std::size_t end = page.find("```", begin + 10);
    std::istringstream block(page.substr(begin + 11, end - begin - 11));
    testing::TempDir dir;
    std::filesystem::copy_file("examples/curves/spine.json", dir / "spine.json");
    std::vector<std::pair<std::string, std::string>> steps;  // command, expected output
    for (std::string line; std::getline(block, line);) {
      if (line.rfind("$ ", 0) == 0)
        steps.emplace_back(line.substr(2), "");
      else if (!steps.empty())
        steps.back().second += line + "\n";
    }
    ASSERT_GE(steps.size(), 4u);
    for (const auto& [command, expected_text] : steps) {
      std::vector<std::string> args = split(command);
      ASSERT_EQ(args.front(), "hula");
      args.erase(args.begin());
      const ProcessResult r = run_in(dir.path(), args);
      ASSERT_EQ(r.exit_code, 0) << command << "\n" << r.err;
      Json actual = Json::parse(r.out);
      // Paths printed are the absolute ones the test passed: compare their file names.
      if (actual.contains("file")) actual["file"] = std::filesystem::path(actual["file"].get<std::string>()).filename();
      const Json expected = Json::parse(expected_text);
      EXPECT_TRUE(matches(expected, actual))
          << command << "\nexpected " << expected.dump() << "\nactual   " << actual.dump();
    }
  }
  EXPECT_GE(blocks, 2u);  // the document example and the STEP/IGES one
}

// Checks each failing subcommand exits non-zero with an error JSON and leaves the file byte-identical.
TEST(DocCli, FailingSubcommandsLeaveTheFileUnchanged) {
  testing::TempDir dir;
  std::filesystem::copy_file("examples/curves/spine.json", dir / "spine.json");
  io::write_file_atomically(dir / "bad.json", R"({"kind": "bezier", "control_points": [[0, 0, 0]]})");
  io::write_file_atomically(dir / "garbage.json", "{not json");
  io::write_file_atomically(dir / "garbage.step", "solid cube\nendsolid\n");
  ASSERT_EQ(run_in(dir.path(), {"doc", "new", "a.hula"}).exit_code, 0);
  ASSERT_EQ(run_in(dir.path(), {"doc", "add", "a.hula", "--curve", "spine.json"}).exit_code, 0);
  ASSERT_EQ(run_in(dir.path(), {"doc", "add", "a.hula", "--curve", "spine.json", "--name", "locked"}).exit_code, 0);
  ASSERT_EQ(run_in(dir.path(), {"doc", "set", "a.hula", "2", "--attribute", "locked=true"}).exit_code, 0);
  const std::string before = io::read_text_file(dir / "a.hula");
  struct Case {
    std::vector<std::string> args;
    int exit_code;
    std::string code;
  };
  const std::vector<Case> cases = {
      {{"doc", "new", "a.hula"}, 3, "IoError"},
      {{"doc", "add", "a.hula", "--curve", "bad.json"}, 3, "TooFewPoints"},
      {{"doc", "add", "a.hula", "--curve", "missing.json"}, 3, "IoError"},
      {{"doc", "set", "a.hula", "9", "--attribute", "name=\"x\""}, 3, "InvalidArgument"},
      {{"doc", "set", "a.hula", "1", "--attribute", "colour=\"red\""}, 3, "InvalidArgument"},
      {{"doc", "set", "a.hula", "1", "--attribute", "name={"}, 3, "ParseError"},
      {{"doc", "set", "a.hula", "1", "--move-point", "7", "--to", "1,2,3"}, 3, "InvalidArgument"},
      {{"doc", "set", "a.hula", "1", "--move-point", "0", "--to", "1,nan,3"}, 3, "NonFiniteInput"},
      {{"doc", "set", "a.hula", "2", "--move-point", "0", "--to", "1,2,3"}, 3, "InvalidArgument"},
      {{"doc", "remove", "a.hula", "2"}, 3, "InvalidArgument"},
      {{"doc", "remove", "a.hula", "0"}, 3, "ParseError"},
      {{"doc", "redo", "a.hula"}, 3, "InvalidArgument"},
      {{"doc", "import", "a.hula", "garbage.json"}, 3, "ParseError"},
      {{"doc", "import", "a.hula", "bad.json"}, 3, "TooFewPoints"},
      {{"doc", "show", "a.hula", "5"}, 3, "InvalidArgument"},
      {{"doc", "export", "a.hula", "5", "-o", "out.json"}, 3, "InvalidArgument"},
      // STEP and IGES (through the isolated exchange helper) and the kernel backend.
      {{"doc", "import", "a.hula", "garbage.step"}, 3, "ParseError"},
      {{"doc", "import", "a.hula", "missing.igs"}, 3, "IoError"},
      {{"doc", "export", "a.hula", "5", "--format", "iges", "-o", "out.igs"}, 3, "InvalidArgument"},
      {{"doc", "export", "a.hula", "1", "--format", "dwg", "-o", "out.json"}, 2, "UsageError"},
      {{"doc", "new", "b.hula", "--backend", "acis"}, 2, "UsageError"},
  };
  for (const Case& c : cases) {
    const ProcessResult r = run_in(dir.path(), c.args);
    std::string line;
    for (const auto& a : c.args) line += a + " ";
    EXPECT_EQ(r.exit_code, c.exit_code) << line << r.err;
    EXPECT_TRUE(r.out.empty()) << line << r.out;
    const Json error = Json::parse(r.err, nullptr, false);
    ASSERT_FALSE(error.is_discarded()) << line << r.err;
    EXPECT_EQ(error["error"]["code"], c.code) << line << r.err;
    EXPECT_EQ(io::read_text_file(dir / "a.hula"), before) << line;
  }
  EXPECT_FALSE(std::filesystem::exists(dir / "out.json"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out.igs"));
  EXPECT_FALSE(std::filesystem::exists(dir / "b.hula"));
  const ProcessResult check = run_in(dir.path(), {"doc", "check", "a.hula"});
  EXPECT_EQ(check.exit_code, 0) << check.out;
}

// Checks check reports a corrupt file with exit 3 and a problem naming it, without changing it.
TEST(DocCli, CheckReportsACorruptFile) {
  testing::TempDir dir;
  io::write_file_atomically(dir / "x.hula", std::string(4096, 'x'));
  const ProcessResult r = run_in(dir.path(), {"doc", "check", "x.hula"});
  EXPECT_EQ(r.exit_code, 3);
  const Json report = Json::parse(r.out);
  EXPECT_FALSE(report["ok"].get<bool>());
  ASSERT_EQ(report["problems"].size(), 1u);
  EXPECT_NE(report["problems"][0].get<std::string>().find("not a HulaHoops document"), std::string::npos);
  EXPECT_EQ(io::read_text_file(dir / "x.hula"), std::string(4096, 'x'));
}

}  // namespace
}  // namespace hula
