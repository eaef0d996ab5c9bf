// SPDX-License-Identifier: MIT
// Property tests of the document (STYLE.md "Oli: a random sequence of
// operations with injected failures leaves the document equal to a model, and
// undo^k ∘ redo^k = id"): random operation sequences with failures injected
// (invalid curves, NaN, exceptions thrown mid-transaction, undo/redo with
// nothing to do) end equal to replaying only the operations that succeeded;
// undoing every step gives the empty document and redoing every step the
// final one, in memory and after save/reopen; labels are never reused.
#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <limits>
#include <stdexcept>

#include "hula/core/rng.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/oli/document.hpp"
#include "hula/testing/temp_dir.hpp"
#include "oli_fixtures.hpp"

namespace hula::oli {
namespace {

using testing::cubic;
using testing::history_json;
using testing::observable;

enum class OpKind : int {
  AddCurve,
  AddPoints,
  Move,
  SetAttribute,
  Remove,
  Undo,
  Redo,
  Drag,
  FailNaN,
  FailInvalidCurve,
  FailThrow,
  Count,
};

struct Op {
  OpKind kind = OpKind::AddCurve;
  std::uint64_t seed = 0;
};

std::ostream& operator<<(std::ostream& os, const Op& op) {
  return os << "Op{" << static_cast<int>(op.kind) << ", " << op.seed << "}";
}

// The target of an operation: an entity chosen by the seed among the current ones (the same in a replay).
std::optional<Label> pick(const Document& doc, Rng& rng) {
  const std::vector<Label> labels = doc.labels();
  if (labels.empty()) return std::nullopt;
  return labels[rng.below(labels.size())];
}

std::size_t point_count(const Entity& e) {
  return e.kind() == EntityKind::Curve ? e.curve().nurbs().control_points().size() : e.point_set().points.size();
}

// Applies one operation; returns whether it succeeded and the labels it added.
bool apply(Document& doc, const Op& op, std::vector<Label>& added) {
  Rng rng(op.seed);
  const Vec3 to{rng.uniform(-5, 5), rng.uniform(-5, 5), rng.uniform(-5, 5)};
  switch (op.kind) {
    case OpKind::AddCurve: {
      Label l;
      const bool ok =
          doc.transact("add curve",
                       [&](Edit& e) {
                         l = e.add_curve(cubic(4 + rng.below(5), to.x), {.name = "c" + std::to_string(op.seed % 97)});
                       })
              .committed;
      if (ok) added.push_back(l);
      return ok;
    }
    case OpKind::AddPoints: {
      Label l;
      const bool ok = doc.transact("add points",
                                   [&](Edit& e) {
                                     l = e.add_point_set({{to, {to.y, to.z, to.x}, {1, 2, 3}}, 3});
                                   })
                          .committed;
      if (ok) added.push_back(l);
      return ok;
    }
    case OpKind::Move:
    case OpKind::SetAttribute:
    case OpKind::Remove:
    case OpKind::Drag: {
      const std::optional<Label> target = pick(doc, rng);
      if (!target) return doc.transact("nothing", [](Edit&) {}).committed;
      const std::size_t index = rng.below(point_count(doc.get(*target)));
      if (op.kind == OpKind::Move)
        return doc.transact("move", [&](Edit& e) { e.move_point(*target, index, to); }).committed;
      if (op.kind == OpKind::SetAttribute)
        return doc
            .transact("attribute",
                      [&](Edit& e) {
                        e.set_attribute(*target, "weight", static_cast<double>(op.seed % 13));
                        e.set_attribute(*target, "visible", op.seed % 2 == 0);
                      })
            .committed;
      if (op.kind == OpKind::Remove) return doc.transact("remove", [&](Edit& e) { e.remove(*target); }).committed;
      bool ok = doc.transact("drag", [&](Edit& e) { e.move_point(*target, index, to); }).committed;
      for (int k = 1; k <= 3 && ok; ++k)
        ok =
            doc.transact(
                   "drag", [&](Edit& e) { e.move_point(*target, index, to * (1.0 + 0.1 * k)); }, TransactMode::Continue)
                .committed;
      return ok;
    }
    case OpKind::Undo:
      return doc.undo().committed;
    case OpKind::Redo:
      return doc.redo().committed;
    case OpKind::FailNaN: {
      const std::optional<Label> target = pick(doc, rng);
      return doc
          .transact("nan",
                    [&](Edit& e) {
                      (void)e.add_curve(cubic(5));
                      if (target)
                        e.move_point(*target, 0, {std::numeric_limits<double>::quiet_NaN(), 0, 0});
                      else
                        e.move_point(Label{1u << 30}, 0, to);
                    })
          .committed;
    }
    case OpKind::FailInvalidCurve: {
      const std::optional<Label> target = pick(doc, rng);
      return doc
          .transact("invalid",
                    [&](Edit& e) {
                      if (target && doc.get(*target).kind() == EntityKind::PointSet) e.move_point(*target, 0, to);
                      // Decreasing knots: the curve codec refuses it, mid-transaction.
                      const Json bad = Json::parse(
                          R"({"kind": "nurbs", "degree": 1, "knots": [0, 0, 1, 0.5],
                          "control_points": [[0, 0, 0], [1, 0, 0]], "weights": null})");
                      (void)e.add_curve(io::curve_from_json(bad));
                    })
          .committed;
    }
    case OpKind::FailThrow: {
      const std::optional<Label> target = pick(doc, rng);
      return doc
          .transact("throw",
                    [&](Edit& e) {
                      if (target) e.remove(*target);
                      (void)e.add_point_set({{to}, 3});
                      throw std::runtime_error("injected");
                    })
          .committed;
    }
    case OpKind::Count:
      break;
  }
  return false;
}

rc::Gen<Op> gen_op() {
  return rc::gen::map(
      rc::gen::pair(rc::gen::inRange(0, static_cast<int>(OpKind::Count)), rc::gen::arbitrary<std::uint32_t>()),
      [](const std::pair<int, std::uint32_t>& p) {
        return Op{static_cast<OpKind>(p.first), p.second};
      });
}

// JSON equality without RapidCheck printing the values (it cannot show ordered_json).
bool same(const Json& a, const Json& b) {
  if (a == b) return true;
  RC_LOG() << "expected " << b.dump() << "\nactual   " << a.dump() << "\n";
  return false;
}

bool is_failure(OpKind k) { return k == OpKind::FailNaN || k == OpKind::FailInvalidCurve || k == OpKind::FailThrow; }

// Runs ops on `doc`, returns the successful ones; checks failures never succeed and labels only grow.
std::vector<Op> run(Document& doc, const std::vector<Op>& ops) {
  std::vector<Op> succeeded;
  std::vector<Label> added;
  for (const Op& op : ops) {
    const Json before = observable(doc);
    const Label next_before = doc.next_label();
    const bool ok = apply(doc, op, added);
    if (is_failure(op.kind)) {
      RC_ASSERT(!ok);
    }
    if (ok)
      succeeded.push_back(op);
    else
      RC_ASSERT(same(observable(doc), before) && doc.next_label() == next_before);
  }
  for (std::size_t i = 1; i < added.size(); ++i) RC_ASSERT(added[i - 1] < added[i]);
  return succeeded;
}

// Undoes every applied step (reaching the empty document) and redoes as many (reaching the final one).
void check_undo_all_redo_all(Document& doc) {
  const Json final_state = observable(doc);
  const std::uint64_t next = doc.next_label().value;
  std::size_t undone = 0;
  while (doc.can_undo()) {
    RC_ASSERT(doc.undo().committed);
    ++undone;
  }
  RC_ASSERT(doc.size() == 0u);
  RC_ASSERT(doc.revision() == 0u);
  RC_ASSERT(doc.next_label().value == next);
  for (std::size_t k = 0; k < undone; ++k) RC_ASSERT(doc.redo().committed);
  RC_ASSERT(same(observable(doc), final_state));
}

// Checks random operations with injected failures equal the replay of the successful ones, and undo/redo of all steps.
RC_GTEST_PROP(DocumentProperty, FailuresLeaveTheReplayOfSuccesses, ()) {
  const std::vector<Op> ops = *rc::gen::container<std::vector<Op>>(gen_op());
  Document doc;
  const std::vector<Op> succeeded = run(doc, ops);
  Document replay;
  std::vector<Label> added;
  for (const Op& op : succeeded) RC_ASSERT(apply(replay, op, added));
  RC_ASSERT(same(observable(replay), observable(doc)));
  RC_ASSERT(replay.next_label() == doc.next_label());
  RC_ASSERT(same(history_json(replay), history_json(doc)));
  check_undo_all_redo_all(doc);
}

// Checks the same on a file document, after closing and reopening it, and that the file passes the check.
RC_GTEST_PROP(DocumentProperty, FileDocumentReopensEqualAndUndoesEverything, ()) {
  const std::vector<Op> ops = *rc::gen::resize(40, rc::gen::container<std::vector<Op>>(gen_op()));
  hula::testing::TempDir dir;
  const auto path = dir / "p.hula";
  Json final_state, history;
  std::uint64_t applied = 0;
  {
    Document doc = Document::create(path);
    (void)run(doc, ops);
    final_state = observable(doc);
    history = history_json(doc);
  }
  RC_ASSERT(Document::check_file(path).ok);
  {
    Document doc = Document::open(path);
    RC_ASSERT(same(observable(doc), final_state));
    RC_ASSERT(same(history_json(doc), history));
    check_undo_all_redo_all(doc);
    applied = doc.revision();
    while (doc.can_undo()) RC_ASSERT(doc.undo().committed);
  }
  Document doc = Document::open(path);
  RC_ASSERT(doc.size() == 0u);
  for (std::uint64_t k = 0; k < applied; ++k) RC_ASSERT(doc.redo().committed);
  RC_ASSERT(same(observable(doc), final_state));
}

}  // namespace
}  // namespace hula::oli
