// SPDX-License-Identifier: MIT
// Issue 10, item 7 "output for people too": JSON arrays of numbers on one
// line (was: one number per line, 680 lines for the demo), no -0.0, errors as
// one readable line with --error-format text, plain `hula` prints help (was:
// ran the demo), a bash completion generated from the command definitions,
// and eval --format jsonl|csv|text.
#include <algorithm>

#include "cli.hpp"

namespace hula::regress {
namespace {

// checks: a written curve file holds each control point and the knot vector on one line each.
TEST(Issue10OutputForPeople, NumberArraysAreOnOneLine) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  ASSERT_EQ(hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "c.json").string()}).exit_code,
            0);
  const std::string text = io::read_text_file(dir / "c.json");
  const json c = json::parse(text);
  EXPECT_NE(text.find("\"knots\": ["), std::string::npos) << text;
  // Every line holding a number also holds its whole array: no line is a bare number.
  std::size_t pos = 0, lines = 0;
  while (pos < text.size()) {
    const std::size_t eol = text.find('\n', pos);
    const std::string line = text.substr(pos, eol - pos);
    const std::size_t first = line.find_first_not_of(' ');
    if (first != std::string::npos) {
      const char f = line[first];
      EXPECT_FALSE((f >= '0' && f <= '9') || f == '-') << "a bare number on a line: " << line;
    }
    ++lines;
    pos = eol + 1;
  }
  // kind, degree, dimension, knots, control_points (one line each) and weights, within braces.
  EXPECT_LT(lines, 20u + c["control_points"].size()) << text;
}

// checks: no -0.0 appears in printed coordinates (the demo's planarity normals and the curve files).
TEST(Issue10OutputForPeople, NoNegativeZero) {
  const ProcessResult r = hula({"demo"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* negative_zero : {"-0.0,", "-0.0]", "-0.0\n"})
    EXPECT_EQ(r.out.find(negative_zero), std::string::npos);
  TempDir dir;
  // A curve through points with x = -0.0 (a CSV can hold it).
  write(dir / "points.csv", "-0.0,0,0\n1,-0.0,0\n2,1,-0.0\n");
  const ProcessResult i = hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", "-"});
  ASSERT_EQ(i.exit_code, 0) << i.err;
  for (const char* negative_zero : {"-0.0,", "-0.0]", "-0.0\n"})
    EXPECT_EQ(i.out.find(negative_zero), std::string::npos) << i.out;
}

// checks: plain `hula` prints the help (usage and the command list) and exits 0 instead of running the demo.
TEST(Issue10OutputForPeople, PlainHulaPrintsHelp) {
  const ProcessResult r = hula({});
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("interpolate"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Exit codes"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("\"curves\""), std::string::npos) << "the demo ran";
}

// checks: --error-format text prints one line naming the code; json (the default off a terminal) the error JSON.
TEST(Issue10OutputForPeople, ErrorFormatTextIsOneLine) {
  const ProcessResult text = hula({"--error-format", "text", "info", "/nonexistent/curve.json"});
  EXPECT_EQ(text.exit_code, 3);
  EXPECT_EQ(text.err.rfind("hula: error: ", 0), 0u) << text.err;
  EXPECT_EQ(std::count(text.err.begin(), text.err.end(), '\n'), 1) << text.err;
  EXPECT_NE(text.err.find("[IoError]"), std::string::npos) << text.err;
  const ProcessResult js = hula({"info", "/nonexistent/curve.json", "--error-format", "json"});
  EXPECT_EQ(error_of(js)["error"]["code"], "IoError");
  const ProcessResult usage = hula({"--error-format", "text", "optimise", "--population", "x"});
  EXPECT_EQ(usage.exit_code, 2);
  EXPECT_EQ(usage.err.rfind("hula: error: ", 0), 0u) << usage.err;
}

// checks: the bash completion script lists every subcommand and an option of one, taken from the CLI definition.
TEST(Issue10OutputForPeople, BashCompletionIsGenerated) {
  const ProcessResult r = hula({"completion", "bash"});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* word : {"interpolate", "analyse", "optimise", "fair-knots", "--population", "--points",
                           "complete -o filenames -F _hula hula"})
    EXPECT_NE(r.out.find(word), std::string::npos) << word;
  const ProcessResult syntax = testing::run_process("/bin/bash", {"-n", "-c", r.out});
  EXPECT_EQ(syntax.exit_code, 0) << syntax.err;
}

// checks: eval --format jsonl prints one record per line, csv rows that match the JSON values, text one line each.
TEST(Issue10OutputForPeople, EvalFormats) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  ASSERT_EQ(hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "c.json").string()}).exit_code,
            0);
  const std::string c = (dir / "c.json").string();
  const json doc = json::parse(hula({"eval", c, "--at", "0,0.5,1"}).out);
  const ProcessResult jl = hula({"eval", c, "--at", "0,0.5,1", "--format", "jsonl"});
  ASSERT_EQ(jl.exit_code, 0) << jl.err;
  EXPECT_EQ(std::count(jl.out.begin(), jl.out.end(), '\n'), 3);
  EXPECT_EQ(json::parse(jl.out.substr(0, jl.out.find('\n'))), doc["results"][0]);
  const ProcessResult csv = hula({"eval", c, "--at", "0,0.5,1", "--format", "csv"});
  ASSERT_EQ(csv.exit_code, 0) << csv.err;
  EXPECT_EQ(csv.out.substr(0, csv.out.find('\n')), "# t x y z");
  const std::string row = csv.out.substr(csv.out.find('\n') + 1);
  const double y = std::stod(row.substr(row.find(',', row.find(',') + 1) + 1));
  EXPECT_DOUBLE_EQ(y, doc["results"][0]["derivatives"][0][1].get<double>());
  const ProcessResult text = hula({"eval", c, "--at", "0.5", "--format", "text"});
  EXPECT_EQ(text.out.rfind("t = 0.5: [", 0), 0u) << text.out;
}

// checks: an out-of-domain eval names the flags to use, not the library's Domain:: identifiers.
TEST(Issue10OutputForPeople, MessagesNameFlagsNotIdentifiers) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  ASSERT_EQ(hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "c.json").string()}).exit_code,
            0);
  const ProcessResult r = hula({"eval", (dir / "c.json").string(), "--at", "5"});
  EXPECT_EQ(r.exit_code, 3) << r.err;
  EXPECT_NE(message_of(r).find("--extrapolate or --clamp"), std::string::npos) << r.err;
  EXPECT_EQ(message_of(r).find("Domain::"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace hula::regress
