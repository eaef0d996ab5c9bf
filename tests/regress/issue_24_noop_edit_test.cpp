// SPDX-License-Identifier: MIT
// Issue 24, item 4: an edit that changes nothing (an attribute set to its
// current value, a user attribute removed that is absent, a point moved to its
// own position) made an undo step and discarded the redo history, although the
// docs say a body that changes nothing makes no step. The rule is in oli
// (Document's journal), so the CLI and the server's PATCH both follow it.
#include "cli.hpp"

namespace hula::regress {
namespace {

json run_json(const std::vector<std::string>& args) {
  const ProcessResult r = hula(args);
  EXPECT_EQ(r.exit_code, 0) << args[1] << ": " << r.err;
  return r.exit_code == 0 ? json::parse(r.out) : json();
}

// checks: each no-op `doc set` keeps the revision, adds no history step and keeps the redo step, which still
// redoes; a real change after them does drop it.
TEST(Issue24NoopEdit, NoOpEditsMakeNoUndoStepAndKeepRedo) {
  TempDir dir;
  write(dir / "points.csv", kPointsCsv);  // its first point is 0,0,0
  ASSERT_EQ(hula({"interpolate", "--points", (dir / "points.csv").string(), "-o", (dir / "c.json").string()}).exit_code,
            0);
  const std::string doc = (dir / "d.hula").string();
  run_json({"doc", "new", doc});
  run_json({"doc", "add", doc, "--curve", (dir / "c.json").string(), "--name", "s"});  // revision 1
  EXPECT_EQ(run_json({"doc", "set", doc, "1", "--attribute", "name=\"t\""})["revision"], 2);
  EXPECT_EQ(run_json({"doc", "undo", doc})["revision"], 1);  // name "s" again; one redo step
  const std::vector<std::vector<std::string>> no_ops = {
      {"doc", "set", doc, "1", "--attribute", "name=\"s\""},
      {"doc", "set", doc, "1", "--attribute", "ghost=null"},
      {"doc", "set", doc, "1", "--attribute", "visible=true"},
      {"doc", "set", doc, "1", "--move-point", "0", "--to", "0,0,0"},
  };
  for (const auto& args : no_ops) {
    EXPECT_EQ(run_json(args)["revision"], 1) << args[4];
    const json history = run_json({"doc", "history", doc});
    EXPECT_EQ(history["transactions"].size(), 1U) << args[4];
    ASSERT_EQ(history["redo"].size(), 1U) << args[4];
    EXPECT_EQ(history["redo"][0]["name"], "set name") << args[4];
  }
  EXPECT_EQ(run_json({"doc", "redo", doc})["revision"], 2);
  EXPECT_EQ(run_json({"doc", "show", doc, "1"})["attributes"]["name"], "t");
  // A real change still makes its step and drops the redo history.
  EXPECT_EQ(run_json({"doc", "undo", doc})["revision"], 1);
  EXPECT_EQ(run_json({"doc", "set", doc, "1", "--move-point", "0", "--to", "0,0,0.5"})["revision"], 2);
  EXPECT_TRUE(run_json({"doc", "history", doc})["redo"].empty());
}

}  // namespace
}  // namespace hula::regress
