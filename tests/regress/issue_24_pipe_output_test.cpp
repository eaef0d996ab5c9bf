// SPDX-License-Identifier: MIT
// Issue 24, item 2: `-o -` printed the curve and then the JSON summary on stdout
// for every `edit` subcommand, `approximate`, `fit` and `law --to-nurbs` (they
// called print_json where print_result is meant), so the next command of a pipe
// failed with "unexpected '{'"; `match` and `blend`, added later, did the same.
// The shell chain of every writer is tests/apps/pipe_test.sh.
#include "cli.hpp"

namespace hula::regress {
namespace {

// checks: with -o -, stdout is the written curve file alone, byte for byte what -o FILE writes.
TEST(Issue24PipeOutput, EveryWriterPrintsOnlyTheCurveOnStdout) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  // A scan fit needs at least 10 points: 24 on a parabola.
  std::string scan;
  for (int i = 0; i < 24; ++i) scan += std::to_string(i) + "," + std::to_string(0.05 * i * i) + "\n";
  write(dir / "scan.csv", scan);
  const std::string curve = (dir / "c.json").string();
  ASSERT_EQ(hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", curve}).exit_code, 0);
  // A second curve for match and blend, beyond the first one's end (6, 0, 2).
  write(dir / "next.csv", "8,0,2\n9,1,3\n11,0,2\n12,2,1\n");
  const std::string next = (dir / "next.json").string();
  ASSERT_EQ(hula({"interpolate", "--points", (dir / "next.csv").string(), "-o", next}).exit_code, 0);
  const std::vector<std::vector<std::string>> writers = {
      {"edit", "insert-knot", curve, "--at", "0.5", "-o"},
      {"edit", "refine", curve, "--knots", "0.25,0.75", "-o"},
      {"edit", "remove-knots", curve, "--tolerance", "1e-9", "-o"},
      {"edit", "elevate", curve, "-o"},
      {"edit", "reverse", curve, "-o"},
      {"edit", "reparam", curve, "--domain", "0,10", "-o"},
      {"edit", "rebuild", curve, "--control-points", "6", "-o"},
      {"edit", "to-law", curve, "-o"},
      {"approximate", "--points", (dir / "points.csv").string(), "--control-points", "4", "-o"},
      {"approximate", "--points", (dir / "points.csv").string(), "--tolerance", "0.5", "-o"},
      {"fit", "--points", (dir / "scan.csv").string(), "--ordered", "-o"},
      {"law", "vec(cos(t), sin(t), 0)", "--to-nurbs", "0,1", "-o"},
      {"match", curve, next, "--continuity", "G2", "-o"},
      {"blend", curve, next, "--continuity", "G2", "-o"},
  };
  for (std::vector<std::string> args : writers) {
    const std::string name = args[0] + (args[0] == "edit" ? " " + args[1] : std::string());
    std::vector<std::string> to_file = args;
    to_file.push_back((dir / "out.json").string());
    const ProcessResult file = hula(to_file);
    ASSERT_EQ(file.exit_code, 0) << name << ": " << file.err;
    args.push_back("-");
    const ProcessResult piped = hula(args);
    ASSERT_EQ(piped.exit_code, 0) << name << ": " << piped.err;
    EXPECT_EQ(piped.out, io::read_text_file(dir / "out.json")) << name;
    EXPECT_FALSE(fs::exists("-")) << name;
  }
}

// checks: split writes either part to stdout alone, and refuses both parts on stdout before any work.
TEST(Issue24PipeOutput, SplitSendsOnePartToStdout) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);
  const std::string curve = (dir / "c.json").string();
  ASSERT_EQ(hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", curve}).exit_code, 0);
  const std::string first = (dir / "first.json").string(), second = (dir / "second.json").string();
  ASSERT_EQ(hula({"edit", "split", curve, "--at", "0.4", "-o", first, "--second", second}).exit_code, 0);
  const ProcessResult a = hula({"edit", "split", curve, "--at", "0.4", "-o", "-", "--second", second});
  ASSERT_EQ(a.exit_code, 0) << a.err;
  EXPECT_EQ(a.out, io::read_text_file(first));
  const ProcessResult b = hula({"edit", "split", curve, "--at", "0.4", "-o", first, "--second", "-"});
  ASSERT_EQ(b.exit_code, 0) << b.err;
  EXPECT_EQ(b.out, io::read_text_file(second));
  const ProcessResult both = hula({"edit", "split", curve, "--at", "0.4", "-o", "-", "--second", "-"});
  EXPECT_EQ(both.exit_code, 3) << both.err;
  EXPECT_TRUE(both.out.empty()) << both.out;
  EXPECT_EQ(error_of(both)["error"]["where"]["field"], "second") << both.err;
}

}  // namespace
}  // namespace hula::regress
