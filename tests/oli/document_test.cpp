// SPDX-License-Identifier: MIT
// The document's contract, case by case: labels, all-or-nothing transactions,
// nesting, the drag "continue" form, undo/redo, observers, attributes, locks,
// persistence across reopen, the undo limit and read-only documents. The
// references are the states captured before each operation (to_json, bit-exact
// doubles) and the values the tests put in.
#include "hula/oli/document.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "hula/io/atomic_file.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/run_report_json.hpp"
#include "hula/oli/detail/entity_codec.hpp"
#include "hula/testing/temp_dir.hpp"
#include "oli_fixtures.hpp"

namespace hula::oli {
namespace {

using testing::cubic;
using testing::observable;

Label add(Document& doc, const curve::Curve& c, std::string name = {}) {
  Label l;
  doc.transact("add", [&](Edit& e) { l = e.add_curve(c, {.name = std::move(name)}); }).throw_if_failed();
  return l;
}

// Checks labels start at 1, increase, and a removed label is never given again (even after undo/redo).
TEST(Document, LabelsAreStableAndNeverReused) {
  Document doc;
  const Label a = add(doc, cubic(5));
  const Label b = add(doc, cubic(6));
  EXPECT_EQ(a.value, 1u);
  EXPECT_EQ(b.value, 2u);
  doc.transact("remove", [&](Edit& e) { e.remove(a); }).throw_if_failed();
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.get(a).label(), a);
  ASSERT_TRUE(doc.redo());
  EXPECT_FALSE(doc.contains(a));
  const Label c = add(doc, cubic(7));
  EXPECT_EQ(c.value, 3u);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(add(doc, cubic(7)).value, 4u);
}

// Checks a body that throws after changes leaves the document exactly as before (to_json equal), next label included.
TEST(Document, FailedTransactionRollsBackEverything) {
  Document doc;
  const Label a = add(doc, cubic(5));
  const Json before = observable(doc);
  const Outcome out = doc.transact("half", [&](Edit& e) {
    e.move_point(a, 2, {9, 9, 9});
    e.set_attribute(a, "colour", "#ff0000");
    (void)e.add_curve(cubic(4));
    e.remove(a);
    throw std::runtime_error("boom");
  });
  EXPECT_FALSE(out.committed);
  EXPECT_EQ(out.error_code, "InternalError");
  EXPECT_EQ(out.error_message, "boom");
  EXPECT_EQ(observable(doc), before);
  EXPECT_EQ(doc.next_label().value, 2u);
  EXPECT_EQ(doc.history().size(), 1u);
  EXPECT_THROW(out.throw_if_failed(), std::runtime_error);
}

// Checks a NaN target and an out-of-range index are refused with their codes and change nothing.
TEST(Document, InvalidInputIsRefusedByCodeAndChangesNothing) {
  Document doc;
  const Label a = add(doc, cubic(5));
  const Json before = observable(doc);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  Outcome out = doc.transact("nan", [&](Edit& e) { e.move_point(a, 1, {0, nan, 0}); });
  EXPECT_EQ(out.error_code, "NonFiniteInput");
  EXPECT_NE(out.error_message.find("to[1]"), std::string::npos) << out.error_message;
  out = doc.transact("range", [&](Edit& e) { e.move_point(a, 5, {0, 0, 0}); });
  EXPECT_EQ(out.error_code, "InvalidArgument");
  EXPECT_NE(out.error_message.find("index 5"), std::string::npos) << out.error_message;
  out = doc.transact("label", [&](Edit& e) { e.remove(Label{42}); });
  EXPECT_NE(out.error_message.find("42"), std::string::npos) << out.error_message;
  out = doc.transact("colour", [&](Edit& e) { e.set_attribute(a, "colour", "red"); });
  EXPECT_EQ(out.error_code, "InvalidArgument");
  EXPECT_EQ(observable(doc), before);
}

// Checks a move changes exactly that control point (the curve's own data as the reference).
TEST(Document, MovePointChangesOnlyThatPoint) {
  Document doc;
  const Label a = add(doc, cubic(6));
  doc.transact("move", [&](Edit& e) { e.move_point(a, 3, {1.5, -2, 7}); }).throw_if_failed();
  const auto& cps = doc.get(a).curve().nurbs().control_points();
  const curve::Curve original = cubic(6);
  const auto orig = original.nurbs().control_points();
  for (std::size_t i = 0; i < cps.size(); ++i) {
    const Vec3 want = i == 3 ? Vec3{1.5, -2, 7} : orig[i];
    EXPECT_EQ(cps[i].x, want.x);
    EXPECT_EQ(cps[i].y, want.y);
    EXPECT_EQ(cps[i].z, want.z);
  }
}

// Checks a nested transaction folds into its parent (one step) and a failed nested one undoes only its part.
TEST(Document, NestedTransactionsFoldIntoTheParent) {
  Document doc;
  Label a, b;
  const Outcome out = doc.transact("outer", [&](Edit& e) {
    a = e.add_curve(cubic(5));
    const Outcome inner = doc.transact("inner ok", [&](Edit& f) { f.move_point(a, 0, {1, 1, 1}); });
    EXPECT_TRUE(inner.committed);
    const Outcome bad = doc.transact("inner bad", [&](Edit& f) {
      b = f.add_curve(cubic(4));
      f.move_point(a, 1, {5, 5, 5});
      throw Error(Errc::InvalidArgument, "no");
    });
    EXPECT_FALSE(bad.committed);
    EXPECT_EQ(bad.error_code, "InvalidArgument");
  });
  ASSERT_TRUE(out.committed);
  EXPECT_EQ(doc.revision(), 1u);
  EXPECT_EQ(doc.size(), 1u);
  EXPECT_FALSE(doc.contains(b));
  EXPECT_EQ(doc.get(a).curve().nurbs().control_points()[0].x, 1.0);
  EXPECT_EQ(doc.get(a).curve().nurbs().control_points()[1].x, 1.0);  // the failed inner move is gone
  EXPECT_EQ(doc.next_label().value, 2u);                             // and so is its label
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(doc.size(), 0u);
}

// Checks a drag of many positions is one undo step whose undo returns to before the drag.
TEST(Document, ContinueReplacesTheLastStep) {
  Document doc;
  const Label a = add(doc, cubic(5));
  const Json before_drag = observable(doc);
  doc.transact("drag", [&](Edit& e) { e.move_point(a, 2, {0, 0, 0}); }).throw_if_failed();
  for (int i = 1; i <= 20; ++i)
    doc.transact(
           "drag",
           [&](Edit& e) {
             e.move_point(a, 2, {0.1 * i, 0, 0});
           },
           TransactMode::Continue)
        .throw_if_failed();
  EXPECT_EQ(doc.revision(), 2u);
  EXPECT_EQ(doc.history().size(), 2u);
  EXPECT_EQ(doc.get(a).curve().nurbs().control_points()[2].x, 0.1 * 20);
  // A failing continuation keeps the last position.
  EXPECT_FALSE(doc.transact(
      "drag", [&](Edit&) { throw std::runtime_error("x"); }, TransactMode::Continue));
  EXPECT_EQ(doc.get(a).curve().nurbs().control_points()[2].x, 0.1 * 20);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(observable(doc), before_drag);
  // Continue after an undo, or under another name, starts a new step.
  doc.transact(
         "drag",
         [&](Edit& e) {
           e.move_point(a, 2, {3, 0, 0});
         },
         TransactMode::Continue)
      .throw_if_failed();
  EXPECT_EQ(doc.revision(), 2u);
  doc.transact(
         "other",
         [&](Edit& e) {
           e.move_point(a, 2, {4, 0, 0});
         },
         TransactMode::Continue)
      .throw_if_failed();
  EXPECT_EQ(doc.revision(), 3u);
}

// Checks undo/redo walk the states exactly and a new change drops the redo history.
TEST(Document, UndoRedoAndRedoDroppedByNewChange) {
  Document doc;
  std::vector<Json> states{observable(doc)};
  const Label a = add(doc, cubic(5));
  states.push_back(observable(doc));
  doc.transact("move", [&](Edit& e) { e.move_point(a, 0, {3, 3, 3}); }).throw_if_failed();
  states.push_back(observable(doc));
  doc.transact("name", [&](Edit& e) { e.set_attribute(a, "name", "spine"); }).throw_if_failed();
  states.push_back(observable(doc));
  for (int k = 3; k > 0; --k) {
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(observable(doc), states[static_cast<std::size_t>(k - 1)]) << k;
  }
  EXPECT_FALSE(doc.undo());
  EXPECT_EQ(doc.undo().error_code, "InvalidArgument");
  for (int k = 1; k <= 3; ++k) {
    ASSERT_TRUE(doc.redo());
    EXPECT_EQ(observable(doc), states[static_cast<std::size_t>(k)]) << k;
  }
  ASSERT_TRUE(doc.undo());
  ASSERT_TRUE(doc.undo());
  doc.transact("other", [&](Edit& e) { e.move_point(a, 1, {8, 8, 8}); }).throw_if_failed();
  EXPECT_FALSE(doc.can_redo());
  EXPECT_EQ(doc.revision(), 2u);
}

// Checks observers get one change set per commit, undo and redo, with the right lists.
TEST(Document, ObserversGetOneChangeSetPerCommit) {
  Document doc;
  std::vector<ChangeSet> seen;
  const ObserverId id = doc.observe([&](const ChangeSet& c) { seen.push_back(c); });
  Label a, b;
  doc.transact("two",
               [&](Edit& e) {
                 a = e.add_curve(cubic(5));
                 b = e.add_curve(cubic(6));
                 e.move_point(a, 0, {1, 2, 3});
               })
      .throw_if_failed();
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].added, (std::vector<Label>{a, b}));
  EXPECT_TRUE(seen[0].changed.empty());
  doc.transact("edit",
               [&](Edit& e) {
                 e.move_point(a, 1, {1, 2, 3});
                 e.set_attribute(b, "visible", false);
               })
      .throw_if_failed();
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_EQ(seen[1].changed, std::vector<Label>{a});
  EXPECT_EQ(seen[1].attributes_changed, std::vector<Label>{b});
  EXPECT_EQ(seen[1].revision, 2u);
  EXPECT_FALSE(doc.transact("fail", [&](Edit& e) {
    e.remove(a);
    throw std::runtime_error("x");
  }));
  EXPECT_EQ(seen.size(), 2u);  // nothing for a rollback
  doc.transact("remove", [&](Edit& e) { e.remove(a); }).throw_if_failed();
  EXPECT_EQ(seen.back().removed, std::vector<Label>{a});
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(seen.back().cause, ChangeSet::Cause::Undo);
  EXPECT_EQ(seen.back().added, std::vector<Label>{a});
  doc.unobserve(id);
  ASSERT_TRUE(doc.redo());
  EXPECT_EQ(seen.size(), 4u);
}

// Checks a locked entity refuses moves and removal, and can be unlocked.
TEST(Document, LockedEntitiesRefuseChanges) {
  Document doc;
  const Label a = add(doc, cubic(5));
  doc.transact("lock", [&](Edit& e) { e.set_attribute(a, "locked", true); }).throw_if_failed();
  const Outcome move = doc.transact("move", [&](Edit& e) { e.move_point(a, 0, {1, 1, 1}); });
  EXPECT_NE(move.error_message.find("locked"), std::string::npos) << move.error_message;
  EXPECT_FALSE(doc.transact("remove", [&](Edit& e) { e.remove(a); }));
  doc.transact("unlock", [&](Edit& e) { e.set_attribute(a, "locked", false); }).throw_if_failed();
  EXPECT_TRUE(doc.transact("move", [&](Edit& e) { e.move_point(a, 0, {1, 1, 1}); }));
}

// Checks the attribute schema: typed system keys, user keys with any JSON, null removes.
TEST(Document, AttributesFollowTheirSchema) {
  Document doc;
  const Label a = add(doc, cubic(5), "spine");
  doc.transact("attrs",
               [&](Edit& e) {
                 e.set_attribute(a, "colour", "#00ff00");
                 e.set_attribute(a, "layer", "styling");
                 e.set_attribute(a, "tolerance", Json::object({{"max", 0.01}}));
                 e.set_attribute(a, "note", "keep");
                 e.set_attribute(a, "note", nullptr);
               })
      .throw_if_failed();
  const Attributes& at = doc.get(a).attributes();
  EXPECT_EQ(at.name, "spine");
  EXPECT_EQ(at.colour, "#00ff00");
  EXPECT_EQ(at.layer, "styling");
  EXPECT_EQ(at.user.at("tolerance")["max"], 0.01);
  EXPECT_FALSE(at.user.contains("note"));
  EXPECT_EQ(attributes_from_json(attributes_to_json(at)), at);
  EXPECT_EQ(doc.transact("x", [&](Edit& e) { e.set_attribute(a, "visible", 1); }).error_code, "InvalidArgument");
  EXPECT_EQ(doc.transact("x", [&](Edit& e) { e.set_attribute(a, "$x", 1); }).error_code, "InvalidArgument");
}

// Checks a file document reopens with its entities, history and undo (yesterday's steps undone today).
TEST(Document, PersistsEntitiesAndUndoAcrossReopen) {
  hula::testing::TempDir dir;
  const auto path = dir / "a.hula";
  std::vector<Json> states;
  {
    Document doc = Document::create(path);
    states.push_back(observable(doc));
    const Label a = add(doc, cubic(5), "first");
    states.push_back(observable(doc));
    doc.transact("move", [&](Edit& e) { e.move_point(a, 4, {0.1, 0.2, 0.3}); }).throw_if_failed();
    states.push_back(observable(doc));
    const Label b = add(doc, cubic(7));
    doc.transact("remove", [&](Edit& e) { e.remove(b); }).throw_if_failed();
    ASSERT_TRUE(doc.undo());
    ASSERT_TRUE(doc.undo());
    EXPECT_EQ(observable(doc), states[2]);
  }
  Document doc = Document::open(path);
  EXPECT_EQ(observable(doc), states[2]);
  EXPECT_EQ(doc.history().size(), 4u);
  EXPECT_TRUE(doc.can_redo());
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(observable(doc), states[1]);
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(observable(doc), states[0]);
  EXPECT_TRUE(Document::check_file(path).ok);
}

// Checks the undo limit drops the oldest steps, in memory and in the file.
TEST(Document, UndoLimitDropsTheOldestSteps) {
  hula::testing::TempDir dir;
  const auto path = dir / "a.hula";
  {
    Document doc = Document::create(path, {.undo_limit = 3});
    const Label a = add(doc, cubic(5));
    // Five real moves (x = 1 … 5; a move to where the point already is would be no step at all).
    for (int i = 1; i <= 5; ++i)
      doc.transact("move", [&](Edit& e) { e.move_point(a, 0, {1.0 * i, 0, 0}); }).throw_if_failed();
    EXPECT_EQ(doc.history().size(), 3u);
    EXPECT_EQ(doc.history().front().revision, 4u);
  }
  Document doc = Document::open(path, OpenMode::ReadWrite, 3);
  EXPECT_EQ(doc.history().size(), 3u);
  EXPECT_EQ(doc.revision(), 6u);
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(doc.undo());
  EXPECT_FALSE(doc.can_undo());
  EXPECT_EQ(doc.get(Label{1}).curve().nurbs().control_points()[0].x, 2.0);  // after the second move
  const CheckReport report = Document::check_file(path);
  EXPECT_TRUE(report.ok) << (report.problems.empty() ? "" : report.problems[0]);
  EXPECT_EQ(DocumentOptions{.undo_limit = 0}.undo_limit, 0u);
  EXPECT_THROW(Document(DocumentOptions{.undo_limit = 0}), Error);
}

// Checks a read-only document refuses transactions and undo with IoError, and reads beside a writer.
TEST(Document, ReadOnlyRefusesChangesAndReadsBesideAWriter) {
  hula::testing::TempDir dir;
  const auto path = dir / "a.hula";
  Document writer = Document::create(path);
  add(writer, cubic(5));
  Document reader = Document::open(path, OpenMode::ReadOnly);
  EXPECT_EQ(reader.size(), 1u);
  EXPECT_EQ(reader.transact("x", [&](Edit& e) { (void)e.add_curve(cubic(4)); }).error_code, "IoError");
  EXPECT_EQ(reader.undo().error_code, "IoError");
  try {
    (void)Document::open(path);
    ADD_FAILURE() << "second writer opened";
  } catch (const Error& e) {
    EXPECT_NE(e.message().find("open for writing"), std::string::npos) << e.message();
  }
}

// Checks point sets and studies are entities too, with their data kept exactly.
TEST(Document, PointSetsAndStudiesAreEntities) {
  hula::testing::TempDir dir;
  const auto path = dir / "a.hula";
  Label p, s;
  {
    Document doc = Document::create(path);
    doc.transact("add",
                 [&](Edit& e) {
                   p = e.add_point_set({{{0.1, 0.2, 0}, {1, 2, 0}}, 2});
                   s = e.add_study({Json::object({{"format", "hula-study"}}), {}}, {.name = "study"},
                                   Provenance{"test", {p}, 7, "x", Json::object()});
                 })
        .throw_if_failed();
  }
  Document doc = Document::open(path, OpenMode::ReadOnly);
  EXPECT_EQ(doc.get(p).point_set().points[0].x, 0.1);
  EXPECT_EQ(doc.get(p).point_set().dimension, 2);
  EXPECT_EQ(doc.get(s).study().setup["format"], "hula-study");
  EXPECT_EQ(doc.get(s).provenance()->inputs, std::vector<Label>{p});
  EXPECT_EQ(doc.get(s).provenance()->seed, 7u);
  EXPECT_THROW((void)doc.get(p).curve(), Error);
}

// A run log with what a real one may hold besides finite numbers: NaN and infinite values, a failed
// individual, two objectives, and an empty generation.
std::shared_ptr<const optim::RunLog> awkward_log() {
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  optim::RunLog log;
  optim::GenerationLog g;
  g.generation = 0;
  g.evaluations = 3;
  g.dimension = 2;
  g.objectives = 2;
  g.variables = {0.1, -0.0, 1e-300, 3.5, -inf, 2.0};
  g.objective_values = {1.0, 2.0, nan, nan, 0.5, inf};
  g.violation = {0.0, nan, 0.25};
  g.fitness = {0.5, 0.0, 1.0 / 3.0};
  g.failed = {0, 1, 0};
  log.append(g);
  optim::GenerationLog empty;
  empty.generation = 1;
  empty.evaluations = 3;
  empty.dimension = 2;
  empty.objectives = 2;
  log.append(empty);
  return std::make_shared<const optim::RunLog>(std::move(log));
}

// Checks a study's run logs survive the store bit for bit (NaN, -0, ±inf, failed flags, an empty
// generation, a study without generations), in the entity and in the undo log, and are shown as before:
// as run_log_to_json writes them, `[]` for none.
TEST(Document, StudyRunLogsRoundTripBitExactly) {
  hula::testing::TempDir dir;
  const auto path = dir / "s.hula";
  Study study{Json::object({{"format", "hula-study"}}), {}};
  study.runs.push_back(StudyRun{3, Json::object({{"best", 1.5}}), awkward_log(), {}});
  study.runs.push_back(StudyRun{4, Json::object(), nullptr, {}});
  Label s;
  {
    Document doc = Document::create(path);
    doc.transact("add", [&](Edit& e) { s = e.add_study(study); }).throw_if_failed();
    doc.transact("rename", [&](Edit& e) { e.set_attributes(s, {.name = "renamed"}); }).throw_if_failed();
  }
  Document doc = Document::open(path);
  const Study& read = doc.get(s).study();
  EXPECT_EQ(read, study);
  ASSERT_NE(read.runs[0].log, nullptr);
  EXPECT_TRUE(std::isinf(read.runs[0].log->generations()[0].variables[4]));
  EXPECT_TRUE(std::signbit(read.runs[0].log->generations()[0].variables[1]));
  EXPECT_EQ(read.runs[1].log, nullptr);
  const Json shown = entity_to_json(doc.get(s));
  EXPECT_EQ(shown["runs"][0]["log"], io::run_log_to_json(*study.runs[0].log));
  EXPECT_EQ(shown["runs"][0]["log"]["generations"][0]["individuals"][1]["failed"], true);
  EXPECT_TRUE(shown["runs"][0]["log"]["generations"][0]["individuals"][2]["objectives"][1].is_null());
  EXPECT_EQ(shown["runs"][1]["log"], Json::array());
  ASSERT_TRUE(doc.undo());  // the state before the rename comes from the undo log
  EXPECT_EQ(doc.get(s).study(), study);
  EXPECT_EQ(doc.get(s).attributes().name, "");
}

// Checks a document written before run logs were stored as columns (tests/data/oli/study-runs-v1.hula,
// written by the `hula` of main at 479c32d; README there) loads, and every entity — two GA studies with
// their logs, their result curves, and an undone edit-projection study read back by redo — is shown
// exactly as that `hula doc show` showed it; entities rewritten in the current encoding still are.
TEST(Document, DocumentsOfCodecVersion1LoadWithTheSameAnswers) {
  const std::filesystem::path data = std::filesystem::path(std::getenv("HULA_TEST_DATA")) / "oli";
  hula::testing::TempDir dir;
  const auto path = dir / "old.hula";
  std::filesystem::copy_file(data / "study-runs-v1.hula", path);
  const Json shown = Json::parse(io::read_text_file(data / "study-runs-v1-shown.json"));
  {
    Document doc = Document::open(path);
    ASSERT_EQ(doc.size(), 4u);
    for (const std::uint64_t l : {1, 2, 3, 4})
      EXPECT_EQ(entity_to_json(doc.get(Label{l})), shown[std::to_string(l)]) << "entity " << l;
    ASSERT_EQ(doc.get(Label{1}).study().runs[0].log->generations().size(), 4u);
    ASSERT_TRUE(doc.redo());
    EXPECT_EQ(entity_to_json(doc.get(Label{5})), shown["5"]);
    EXPECT_EQ(doc.get(Label{5}).study().runs[0].log, nullptr);
    // Rewrites both GA studies in the current encoding (a rename; undone below, so no attribute changes).
    doc.transact("rename",
                 [&](Edit& e) {
                   e.set_attributes(Label{1}, {.name = "one"});
                   e.set_attributes(Label{3}, {.name = "three"});
                 })
        .throw_if_failed();
  }
  Document doc = Document::open(path);
  for (const std::uint64_t l : {1, 3}) {
    Json now = entity_to_json(doc.get(Label{l}));
    Json was = shown[std::to_string(l)];
    now.erase("attributes");
    was.erase("attributes");
    EXPECT_EQ(now, was) << "entity " << l;
  }
  ASSERT_TRUE(doc.undo());
  EXPECT_EQ(entity_to_json(doc.get(Label{3})), shown["3"]);
}

// Checks a stored run-log column block whose counts exceed its numbers, or whose failed flag is not 0/1,
// is refused as a corrupt entity state naming the run log (never read past its end).
TEST(Document, CorruptRunLogColumnsAreRefused) {
  const auto blob = [](const std::vector<double>& columns) {
    const std::string text =
        R"({"kind":"study","attributes":{},"provenance":null,"constraints":[],)"
        R"("data":{"kind":"study","setup":{},"runs":[{"seed":1,"result":{},"log":{"$log":0},"result_curves":[]}]}})";
    std::string out = "HLE2";
    const auto u32 = [&](std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    u32(static_cast<std::uint32_t>(text.size()));
    out += text;
    u32(1);
    const std::uint64_t n = columns.size();
    out.append(reinterpret_cast<const char*>(&n), 8);
    out.append(reinterpret_cast<const char*>(columns.data()), columns.size() * sizeof(double));
    return out;
  };
  const auto refusal = [&](const std::vector<double>& columns) {
    try {
      (void)detail::decode_state(blob(columns));
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), Errc::ParseError);
      return e.message();
    }
    return std::string("accepted");
  };
  // generation 0, 2 evaluations, 1 variable, 1 objective, 2 individuals: a header of 5 and 10 numbers.
  const std::vector<double> good{0, 2, 1, 1, 2, 0.5, 0.25, 1.0, 2.0, 0, 0, 0.1, 0.2, 0, 1};
  const detail::StatePtr state = detail::decode_state(blob(good));
  ASSERT_NE(state->study->runs[0].log, nullptr);
  EXPECT_EQ(state->study->runs[0].log->generations()[0].failed, (std::vector<std::uint8_t>{0, 1}));
  EXPECT_NE(refusal({0, 2, 1, 1, 1e15, 0.5}).find("run log generation 0: 1000000000000000 individuals exceed"),
            std::string::npos);
  EXPECT_NE(refusal({0, 2, 1, 1, 2.5}).find("run log count 2.5"), std::string::npos);
  std::vector<double> bad_flag = good;
  bad_flag.back() = 2;
  EXPECT_NE(refusal(bad_flag).find("run log failed flag 2"), std::string::npos);
  EXPECT_NE(refusal({0, 2, 1}).find("run log truncated"), std::string::npos);
}

}  // namespace
}  // namespace hula::oli
