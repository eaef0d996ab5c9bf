// SPDX-License-Identifier: MIT
// Runs the examples of docs/modules/oli.md: the test body below is the
// section's code blocks verbatim (checked by DocsExample.MatchesTheDocs), so
// the page cannot drift from code that compiles and passes.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>

#include "hula/curve/curve.hpp"
#include "hula/oli/document.hpp"
#include "hula/oli/variables.hpp"
#include "hula/testing/temp_dir.hpp"

namespace hula {
namespace {

std::string read(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Checks the page's example code runs and its expectations hold (the values the example states).
TEST(DocsExample, OliExamplesRun) {
  hula::testing::TempDir dir;
  // --- begin docs/modules/oli.md examples
  oli::Document doc = oli::Document::create(dir / "part.hula");
  oli::Label spine;
  doc.transact("add spine", [&](oli::Edit& e) {
    const curve::Curve bezier = curve::Curve::bezier(
        {.control_points = {{0, 0, 0}, {1, 2, 0}, {3, 2, 0}, {4, 0, 0}}, .weights = {}, .dimension = 3});
    spine = e.add_curve(bezier, {.name = "spine"});
  });
  // A drag: the first position is a new step, the next ones continue it.
  doc.transact("drag", [&](oli::Edit& e) { e.move_point(spine, 1, {1, 2.5, 0}); });
  for (double y : {2.6, 2.7, 2.8})
    doc.transact(
        "drag",
        [&](oli::Edit& e) {
          e.move_point(spine, 1, {1, y, 0});
        },
        oli::TransactMode::Continue);
  EXPECT_EQ(doc.revision(), 2u);

  // Anything that throws inside a body rolls the whole transaction back.
  oli::Outcome bad = doc.transact("bad", [&](oli::Edit& e) {
    e.set_attribute(spine, "colour", "#ff0000");
    e.move_point(spine, 9, {0, 0, 0});  // there is no point 9
  });
  EXPECT_FALSE(bad.committed);
  EXPECT_EQ(bad.error_code, "InvalidArgument");
  EXPECT_EQ(doc.get(spine).attributes().colour, "#1f77b4");

  doc.undo();             // back to before the drag
  doc = oli::Document{};  // closes the file (an empty in-memory document)
  doc = oli::Document::open(dir / "part.hula");
  EXPECT_EQ(doc.revision(), 1u);
  EXPECT_TRUE(doc.can_redo());
  doc.redo();
  EXPECT_EQ(doc.get(spine).curve().nurbs().control_points()[1].y, 2.8);
  oli::VariableSet shape{"shape",
                         {{.label = spine,
                           .kind = oli::VariableKind::ControlPoints,
                           .indices = {1, 2},
                           .axes = "y",
                           .bounds = {oli::BoundMode::Relative, -0.5, 0.5}}}};
  oli::VariableValues v = oli::read_variables(doc, shape);  // names "1.control-points[1].y", ...
  optim::Problem problem = oli::make_problem(
      doc, shape, [](const auto& curves, std::span<double> f) { f[0] = curves.begin()->second.length(); });
  // ... solve it, then write the champion back as one undoable step:
  doc.transact("optimise", [&](oli::Edit& e) { oli::write_variables(e, shape, v.values); });
  std::vector<oli::Label> redraw;
  doc.observe([&](const oli::ChangeSet& c) {
    for (const auto* list : {&c.added, &c.changed, &c.attributes_changed})
      redraw.insert(redraw.end(), list->begin(), list->end());
  });
  doc.transact("hide", [&](oli::Edit& e) { e.set_attribute(spine, "visible", false); });
  EXPECT_EQ(redraw, std::vector<oli::Label>{spine});
  // --- end docs/modules/oli.md examples
}

// Checks every code block of the page's Examples section appears verbatim (re-indented) in this file.
TEST(DocsExample, MatchesTheDocs) {
  const std::string page = read("docs/modules/oli.md");
  const std::string self = read("tests/oli/docs_example_test.cpp");
  const std::string examples = page.substr(page.find("## Examples"), page.find("## Labels") - page.find("## Examples"));
  const std::regex block("```cpp\\n([\\s\\S]*?)```");
  int count = 0;
  for (std::sregex_iterator it(examples.begin(), examples.end(), block), end; it != end; ++it, ++count) {
    std::string code = (*it)[1];
    std::string indented;
    std::istringstream lines(code);
    for (std::string line; std::getline(lines, line);) indented += (line.empty() ? "" : "  " + line) + "\n";
    EXPECT_NE(self.find(indented), std::string::npos) << "block " << count << " of docs/modules/oli.md differs";
  }
  EXPECT_EQ(count, 3);
}

}  // namespace
}  // namespace hula
