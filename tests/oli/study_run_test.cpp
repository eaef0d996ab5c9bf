// SPDX-License-Identifier: MIT
// Study runs stored in the document: the study entity keeps setup, seed, run
// log and result; the result curve is a new entity with provenance; a rerun
// from what the document stored (also after reopening the file) gives the
// same curve bit for bit (the first run's stored curve is the reference).
#include "hula/oli/study_run.hpp"

#include <gtest/gtest.h>

#include "hula/io/json_curve.hpp"
#include "hula/testing/temp_dir.hpp"

namespace hula::oli {
namespace {

// Thesis 8.2.1 Example 1 (examples/studies/match-curvature-example1.json) with its points taken from
// a point-set entity and a small GA, so the test is fast.
Json study_on(Label points) {
  Json s = Json::parse(R"({"format": "hula-study", "version": 1, "study": "match-curvature", "seed": 5,
    "lower": [[0, 0], [30, 30], [0, 0]], "upper": [[0, 0], [35, 30], [0, 0]],
    "samples": 50, "method": "ga",
    "ga": {"algorithm": "binary", "population": 12, "generations": 6, "boost_start": 3, "boost_end": 5,
           "crossover_probability": 1.0, "mutation_probability": 0.01, "precision": 0.001}})");
  s["points"] = Json::object({{"entity", points.value}});
  s["target"] = Json::object({{"of_points", Json::object({{"entity", points.value}})}, {"mirror", true}});
  return s;
}

Label add_points(Document& doc) {
  Label p;
  doc.transact("points",
               [&](Edit& e) {
                 p = e.add_point_set({{{0, 0, 0}, {5, 20, 0}, {40, 0, 0}}, 2});
               })
      .throw_if_failed();
  return p;
}

// Checks one run adds the study and its result curve with provenance, and a rerun repeats it bit-exactly.
TEST(StudyRun, RunIsStoredWithProvenanceAndRepeatsBitExactly) {
  hula::testing::TempDir dir;
  const auto path = dir / "s.hula";
  StudyRunResult first;
  {
    Document doc = Document::create(path);
    const Label p = add_points(doc);
    doc.transact("run", [&](Edit& e) { first = run_study(e, study_on(p), dir.path()); }).throw_if_failed();
    ASSERT_EQ(first.curves.size(), 1u);
    const Entity study = doc.get(first.study);
    ASSERT_EQ(study.study().runs.size(), 1u);
    EXPECT_EQ(study.study().runs[0].seed, 5u);
    EXPECT_FALSE(study.study().runs[0].log.empty());
    EXPECT_EQ(study.study().setup["points"]["entity"], p.value);
    const Entity curve = doc.get(first.curves[0]);
    ASSERT_TRUE(curve.provenance().has_value());
    EXPECT_EQ(curve.provenance()->operation, "study:match-curvature");
    EXPECT_EQ(curve.provenance()->inputs, (std::vector<Label>{first.study, p}));
    EXPECT_EQ(curve.provenance()->seed, 5u);
    EXPECT_EQ(io::curve_to_json(curve.curve()), first.result["curve"]);
  }
  Document doc = Document::open(path);
  StudyRunResult again;
  doc.transact("rerun", [&](Edit& e) { again = rerun_study(e, first.study, dir.path()); }).throw_if_failed();
  const std::string a = io::curve_to_json(doc.get(first.curves[0]).curve()).dump();
  const std::string b = io::curve_to_json(doc.get(again.curves[0]).curve()).dump();
  EXPECT_EQ(a, b);
  EXPECT_EQ(doc.get(first.study).study().runs.size(), 2u);
  const Study& stored = doc.get(first.study).study();
  EXPECT_EQ(stored.runs[0].result["curve"].dump(), stored.runs[1].result["curve"].dump());
  EXPECT_EQ(stored.runs[0].result["after"].dump(), stored.runs[1].result["after"].dump());
}

// Checks a failing study (unknown kind, bad reference) rolls the whole transaction back.
TEST(StudyRun, FailingStudyRollsBack) {
  Document doc;
  const Label p = add_points(doc);
  Json bad = study_on(p);
  bad["study"] = "fair-knots";
  Outcome out = doc.transact("run", [&](Edit& e) { (void)run_study(e, bad, "."); });
  EXPECT_EQ(out.error_code, "InvalidArgument");
  EXPECT_NE(out.error_message.find("fair-knots"), std::string::npos);
  Json missing = study_on(Label{99});
  out = doc.transact("run", [&](Edit& e) { (void)run_study(e, missing, "."); });
  EXPECT_EQ(out.error_code, "InvalidArgument");
  EXPECT_NE(out.error_message.find("99"), std::string::npos);
  EXPECT_EQ(doc.size(), 1u);
  EXPECT_EQ(doc.revision(), 1u);
}

}  // namespace
}  // namespace hula::oli
