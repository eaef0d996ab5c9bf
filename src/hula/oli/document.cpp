// SPDX-License-Identifier: MIT
// The document: transactions with rollback, undo/redo, observers and the
// mapping of each committed step onto one store batch (document.hpp).
//
// A transaction journals every entity write (label, state before). Rollback
// replays the journal backwards; commit folds it into one step holding, per
// label, the first "before" and the current "after". The store keeps for each
// step only one state per entity — the one the document does not currently
// show: "before" while the step is applied, "after" once it is undone — so a
// step costs one copy of what it changed, and an add costs nothing extra.
#include <algorithm>
#include <chrono>
#include <ctime>
#include <set>

#include "hula/core/error.hpp"
#include "hula/oli/detail/document_impl.hpp"
#include "hula/oli/detail/entity_codec.hpp"

#ifndef HULA_VERSION
#define HULA_VERSION "unknown"
#endif

namespace hula::oli {

using detail::Change;
using detail::StatePtr;
using detail::Step;

namespace {

std::string now_iso8601() {
  const auto now = std::chrono::system_clock::now();
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()).count();
  const std::time_t seconds = static_cast<std::time_t>(ms / 1000);
  std::tm tm{};
  gmtime_r(&seconds, &tm);
  char text[96];
  std::snprintf(text, sizeof text, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", tm.tm_year + 1900, tm.tm_mon + 1, tm.tm_mday,
                tm.tm_hour, tm.tm_min, tm.tm_sec, static_cast<int>(ms % 1000));
  return text;
}

std::optional<store::Blob> encode(const StatePtr& state) {
  if (!state) return std::nullopt;
  return detail::encode_state(*state);
}

// Equal shared values: the same pointer, or both present and equal.
template <class T>
bool same_shared(const std::shared_ptr<const T>& a, const std::shared_ptr<const T>& b) {
  return a == b || (a && b && *a == *b);
}

bool same_points(const std::shared_ptr<const PointSet>& a, const std::shared_ptr<const PointSet>& b) {
  return a == b || (a && b && a->dimension == b->dimension && a->points == b->points);
}

// True when two states hold the same value (kind, attributes, provenance, constraints and data).
bool same_value(const detail::EntityState& a, const detail::EntityState& b) {
  return a.kind == b.kind && a.attributes == b.attributes && a.provenance == b.provenance &&
         a.constraints == b.constraints && same_shared(a.curve, b.curve) && same_points(a.points, b.points) &&
         same_shared(a.study, b.study);
}

bool data_differs(const detail::EntityState& a, const detail::EntityState& b) {
  return a.kind != b.kind || a.curve != b.curve || a.points != b.points || a.study != b.study ||
         a.constraints != b.constraints || a.provenance != b.provenance;
}

// Adds `label` to the change set for a move from `from` to `to`.
void classify(ChangeSet& set, Label label, const StatePtr& from, const StatePtr& to) {
  if (from == to || (from && to && same_value(*from, *to))) return;
  if (!from) {
    set.added.push_back(label);
  } else if (!to) {
    set.removed.push_back(label);
  } else {
    if (data_differs(*from, *to)) set.changed.push_back(label);
    if (from->attributes != to->attributes) set.attributes_changed.push_back(label);
  }
}

Outcome failure(std::uint64_t revision, std::exception_ptr error) {
  Outcome out;
  out.committed = false;
  out.revision = revision;
  out.error = error;
  try {
    std::rethrow_exception(error);
  } catch (const Error& e) {
    out.error_code = std::string(errc_name(e.code()));
    out.error_message = e.message();
  } catch (const std::exception& e) {
    out.error_code = "InternalError";
    out.error_message = e.what();
  } catch (...) {
    out.error_code = "InternalError";
    out.error_message = "an exception that is not a std::exception";
  }
  return out;
}

Outcome failure(std::uint64_t revision, const Error& error) {
  return failure(revision, std::make_exception_ptr(error));
}

store::StepRow step_row(const Step& step, bool applied) {
  store::StepRow row;
  row.revision = step.revision;
  row.name = step.name;
  row.time = step.time;
  row.applied = applied;
  for (const Change& c : step.changes) row.entities.emplace_back(c.label.value, encode(applied ? c.before : c.after));
  return row;
}

}  // namespace

const StatePtr& Document::Impl::existing(Label label) const {
  const auto it = entities.find(label);
  if (it == entities.end())
    throw Error(Errc::InvalidArgument, "no entity with label " + std::to_string(label.value), {.field = "label"});
  return it->second;
}

void Document::Impl::put(Label label, StatePtr next) {
  HULA_ASSERT(depth > 0, "entity written outside a transaction");
  auto it = entities.find(label);
  // A write that leaves the entity's value as it is (the same attribute value, removing an absent
  // attribute, a point moved to where it is) is no change: not journalled, so a transaction made only
  // of such writes makes no undo step and keeps the redo history (docs/modules/oli.md).
  if (it != entities.end() && next && same_value(*it->second, *next)) return;
  journal.emplace_back(label, it == entities.end() ? nullptr : it->second);
  if (next) {
    if (it == entities.end())
      entities.emplace(label, std::move(next));
    else
      it->second = std::move(next);
  } else if (it != entities.end()) {
    entities.erase(it);
  }
}

void Document::Impl::rollback_to(std::size_t mark) {
  while (journal.size() > mark) {
    auto [label, before] = std::move(journal.back());
    journal.pop_back();
    if (before)
      entities[label] = std::move(before);
    else
      entities.erase(label);
  }
}

Document::Document(DocumentOptions options) : impl_(std::make_unique<Impl>()) {
  options.validate();
  impl_->options = std::move(options);
  impl_->created = now_iso8601();
}
Document::Document(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Document::Document(Document&&) noexcept = default;
Document& Document::operator=(Document&&) noexcept = default;
Document::~Document() = default;

Document Document::create(const std::filesystem::path& path, DocumentOptions options, bool overwrite) {
  options.validate();
  store::DocumentRow row;
  row.backend = options.backend;
  row.created = now_iso8601();
  row.tool_version = HULA_VERSION;
  auto impl = std::make_unique<Impl>();
  impl->store.emplace(store::Store::create(path, row, overwrite));
  impl->options = std::move(options);
  impl->path = path;
  impl->created = row.created;
  return Document(std::move(impl));
}

namespace {

// Rebuilds the in-memory state of a snapshot; throws naming the label or step that does not load. A stored
// state that does not decode, or a history that does not fit together, is a corrupt document
// (DocumentCorrupt: 422 from the server, like a damaged file; was IoError, 500).
std::unique_ptr<Document::Impl> load_snapshot(const store::Snapshot& snap, const std::filesystem::path& path) {
  auto impl = std::make_unique<Document::Impl>();
  impl->path = path;
  impl->revision = snap.document.revision;
  impl->next_label = snap.document.next_label;
  impl->options.backend = snap.document.backend;
  impl->created = snap.document.created;
  auto decode_at = [&](const store::Blob& blob, std::uint64_t label, const std::string& where) {
    try {
      return detail::decode_state(blob);
    } catch (const Error& e) {
      throw Error(Errc::DocumentCorrupt,
                  path.string() + ": " + where + " entity " + std::to_string(label) + " does not load: " + e.what(),
                  {.field = "path"});
    }
  };
  for (const auto& [label, blob] : snap.entities) {
    if (label >= impl->next_label)
      throw Error(Errc::DocumentCorrupt,
                  path.string() + ": entity " + std::to_string(label) + " is not below the next label " +
                      std::to_string(impl->next_label),
                  {.field = "path"});
    impl->entities.emplace(Label{label}, decode_at(blob, label, "the"));
  }
  std::vector<const store::StepRow*> applied, undone;
  for (const store::StepRow& s : snap.steps) (s.applied ? applied : undone).push_back(&s);
  auto corrupt = [&](const std::string& what) {
    throw Error(Errc::DocumentCorrupt, path.string() + ": the undo history is inconsistent (" + what + ")",
                {.field = "path"});
  };
  for (std::size_t i = 0; i < applied.size(); ++i)
    if (applied[i]->revision != impl->revision - (applied.size() - 1 - i))
      corrupt("applied step " + std::to_string(applied[i]->revision) + " at revision " +
              std::to_string(impl->revision));
  for (std::size_t i = 0; i < undone.size(); ++i)
    if (undone[i]->revision != impl->revision + 1 + i)
      corrupt("redoable step " + std::to_string(undone[i]->revision) + " after revision " +
              std::to_string(impl->revision));
  // Applied steps, latest first: the stored state is "before"; "after" is what the
  // document showed just after the step.
  std::map<Label, StatePtr> work = impl->entities;
  auto at = [&](Label l) {
    const auto it = work.find(l);
    return it == work.end() ? StatePtr{} : it->second;
  };
  auto set = [&](Label l, StatePtr s) {
    if (s)
      work[l] = std::move(s);
    else
      work.erase(l);
  };
  std::deque<Step> undo;
  for (auto it = applied.rbegin(); it != applied.rend(); ++it) {
    Step step{(*it)->revision, (*it)->name, (*it)->time, {}};
    for (const auto& [label, blob] : (*it)->entities) {
      StatePtr before = blob ? decode_at(*blob, label, "undo step " + std::to_string(step.revision) + ":") : nullptr;
      step.changes.push_back({Label{label}, before, at(Label{label})});
      set(Label{label}, std::move(before));
    }
    undo.push_front(std::move(step));
  }
  work = impl->entities;
  std::vector<Step> redo;
  for (const store::StepRow* row : undone) {
    Step step{row->revision, row->name, row->time, {}};
    for (const auto& [label, blob] : row->entities) {
      StatePtr after = blob ? decode_at(*blob, label, "redo step " + std::to_string(step.revision) + ":") : nullptr;
      step.changes.push_back({Label{label}, at(Label{label}), after});
      set(Label{label}, std::move(after));
    }
    redo.push_back(std::move(step));
  }
  std::reverse(redo.begin(), redo.end());
  impl->undo = std::move(undo);
  impl->redo = std::move(redo);
  return impl;
}

// The outcome of a committed step, after every observer has seen its change set.
// Observers cannot undo a commit; their failure is theirs (document.hpp).
Outcome committed(const Document::Impl& m, ChangeSet changes) {
  for (const auto& [id, observer] : m.observers) {
    try {
      observer(changes);
    } catch (...) {
    }
  }
  Outcome out;
  out.committed = true;
  out.revision = m.revision;
  out.changes = std::move(changes);
  return out;
}

}  // namespace

Document Document::open(const std::filesystem::path& path, OpenMode mode, std::optional<std::size_t> undo_limit) {
  store::Store st =
      store::Store::open(path, mode == OpenMode::ReadWrite ? store::Access::ReadWrite : store::Access::ReadOnly);
  std::unique_ptr<Impl> impl = load_snapshot(st.load(), path);
  impl->options.undo_limit = undo_limit;
  impl->options.validate();
  impl->read_only = mode == OpenMode::ReadOnly;
  impl->store.emplace(std::move(st));
  return Document(std::move(impl));
}

CheckReport Document::check_file(const std::filesystem::path& path) {
  CheckReport report;
  try {
    store::Store st = store::Store::open(path, store::Access::ReadOnly);
    for (std::string& problem : st.integrity_check()) report.problems.push_back("SQLite: " + problem);
    const store::Snapshot snap = st.load();
    report.schema_version = snap.schema_version;
    report.revision = snap.document.revision;
    report.steps = snap.steps.size();
    std::unique_ptr<Impl> impl = load_snapshot(snap, path);
    report.entities = impl->entities.size();
    // Undo every applied step from the stored state: when the history reaches back to
    // revision 1 (no undo limit dropped the oldest), the result is the empty document.
    std::map<Label, StatePtr> work = impl->entities;
    for (auto it = impl->undo.rbegin(); it != impl->undo.rend(); ++it)
      for (const Change& c : it->changes) {
        if (work[c.label] != c.after && !(c.after == nullptr && work[c.label] == nullptr)) {
          report.problems.push_back("undo step " + std::to_string(it->revision) + " does not match entity " +
                                    std::to_string(c.label.value));
        }
        if (c.before)
          work[c.label] = c.before;
        else
          work.erase(c.label);
      }
    std::erase_if(work, [](const auto& kv) { return kv.second == nullptr; });
    if (!impl->undo.empty() && impl->undo.front().revision == 1 && !work.empty())
      report.problems.push_back("undoing every step leaves " + std::to_string(work.size()) +
                                " entities instead of the empty document");
    if (impl->undo.empty() && impl->revision == 0 && !impl->entities.empty())
      report.problems.push_back("revision 0 holds entities");
  } catch (const Error& e) {
    report.problems.emplace_back(e.message());
  }
  report.ok = report.problems.empty();
  return report;
}

Outcome Document::transact(std::string_view name, const std::function<void(Edit&)>& body, TransactMode mode) {
  Impl& m = *impl_;
  Edit edit(this);
  if (m.depth > 0) {
    // Nested: a savepoint inside the enclosing transaction.
    const std::size_t mark = m.journal.size();
    const std::uint64_t saved_next = m.next_label;
    ++m.depth;
    try {
      body(edit);
    } catch (...) {
      --m.depth;
      m.rollback_to(mark);
      m.next_label = saved_next;
      return failure(m.revision, std::current_exception());
    }
    --m.depth;
    Outcome folded;
    folded.committed = true;
    folded.revision = m.revision;
    folded.changes.name = std::string(name);
    return folded;
  }
  if (m.read_only)
    return failure(m.revision, Error(Errc::IoError, m.path.string() + ": opened read-only", {.field = "path"}));

  const bool continuing =
      mode == TransactMode::Continue && !m.undo.empty() && m.redo.empty() && m.undo.back().name == name;
  // To continue, the document first goes back to the state before the last step (not journalled:
  // the step itself says how to come back).
  auto revert_last = [&] {
    for (const Change& c : m.undo.back().changes) {
      if (c.before)
        m.entities[c.label] = c.before;
      else
        m.entities.erase(c.label);
    }
  };
  auto reapply_last = [&] {
    for (const Change& c : m.undo.back().changes) {
      if (c.after)
        m.entities[c.label] = c.after;
      else
        m.entities.erase(c.label);
    }
  };
  if (continuing) revert_last();
  const std::uint64_t saved_next = m.next_label;
  m.journal.clear();
  auto abort = [&] {
    m.rollback_to(0);
    m.next_label = saved_next;
    if (continuing) reapply_last();
    m.depth = 0;
  };
  m.depth = 1;
  try {
    body(edit);
  } catch (...) {
    abort();
    return failure(m.revision, std::current_exception());
  }
  m.depth = 0;

  // Fold the journal (and, when continuing, the last step) into one step.
  std::map<Label, StatePtr> before;
  if (continuing)
    for (const Change& c : m.undo.back().changes) before.emplace(c.label, c.before);
  for (const auto& [label, prior] : m.journal) before.emplace(label, prior);  // keeps the first
  Step step;
  step.revision = continuing ? m.undo.back().revision : m.revision + 1;
  step.name = std::string(name);
  step.time = now_iso8601();
  for (const auto& [label, prior] : before) {
    StatePtr after = m.state(label);
    if (after != prior && !(after && prior && same_value(*after, *prior)))
      step.changes.push_back({label, prior, std::move(after)});
  }
  // What observers must redraw: from what they last saw to now.
  ChangeSet changes;
  changes.cause = ChangeSet::Cause::Commit;
  changes.name = step.name;
  {
    std::set<Label> touched;
    for (const auto& [label, prior] : before) touched.insert(label);
    for (Label label : touched) {
      StatePtr seen = before.at(label);
      if (continuing)
        for (const Change& c : m.undo.back().changes)
          if (c.label == label) seen = c.after;
      classify(changes, label, seen, m.state(label));
    }
  }
  if (step.changes.empty() && !continuing && m.next_label == saved_next) {
    // Nothing changed: no undo step, nothing written.
    m.journal.clear();
    Outcome out;
    out.committed = true;
    out.revision = m.revision;
    out.changes = std::move(changes);
    out.changes.revision = m.revision;
    return out;
  }

  // Steps over the undo limit (a document opened with a lower limit may hold several).
  const std::size_t excess = !continuing && m.options.undo_limit && m.undo.size() + 1 > *m.options.undo_limit
                                 ? m.undo.size() + 1 - *m.options.undo_limit
                                 : 0;
  if (m.store) {
    try {
      store::Batch batch;
      if (!m.redo.empty()) batch.delete_steps_from = m.revision + 1;
      if (excess > 0) batch.delete_steps_through = m.undo[excess - 1].revision;
      for (const Change& c : step.changes) batch.entities.emplace_back(c.label.value, encode(c.after));
      if (continuing)
        for (const Change& c : m.undo.back().changes)
          if (std::none_of(step.changes.begin(), step.changes.end(),
                           [&](const Change& n) { return n.label == c.label; }))
            batch.entities.emplace_back(c.label.value, encode(m.state(c.label)));
      batch.steps.push_back(step_row(step, true));
      batch.revision = step.revision;
      batch.next_label = m.next_label;
      m.store->apply(batch);
    } catch (...) {
      abort();
      return failure(m.revision, std::current_exception());
    }
  }
  m.journal.clear();
  m.redo.clear();
  if (continuing) {
    m.undo.back() = std::move(step);
  } else {
    m.undo.push_back(std::move(step));
    m.undo.erase(m.undo.begin(), m.undo.begin() + static_cast<std::ptrdiff_t>(excess));
    m.revision += 1;
  }
  changes.revision = m.revision;
  return committed(m, std::move(changes));
}

namespace {

// Moves the document across one step (undo: after → before; redo: before → after).
Outcome cross_step(Document::Impl& m, bool undoing) {
  const char* verb = undoing ? "undo" : "redo";
  if (m.depth > 0)
    return failure(m.revision, Error(Errc::InvalidArgument, std::string("cannot ") + verb + " inside a transaction"));
  if (m.read_only)
    return failure(m.revision, Error(Errc::IoError, m.path.string() + ": opened read-only", {.field = "path"}));
  if (undoing ? m.undo.empty() : m.redo.empty())
    return failure(m.revision, Error(Errc::InvalidArgument, std::string("nothing to ") + verb));
  Step& step = undoing ? m.undo.back() : m.redo.back();
  const std::uint64_t new_revision = undoing ? m.revision - 1 : m.revision + 1;
  if (m.store) {
    try {
      store::Batch batch;
      for (const Change& c : step.changes)
        batch.entities.emplace_back(c.label.value, encode(undoing ? c.before : c.after));
      batch.step_updates.push_back(step_row(step, !undoing));
      batch.revision = new_revision;
      batch.next_label = m.next_label;
      m.store->apply(batch);
    } catch (...) {
      return failure(m.revision, std::current_exception());
    }
  }
  ChangeSet changes;
  changes.cause = undoing ? ChangeSet::Cause::Undo : ChangeSet::Cause::Redo;
  changes.name = step.name;
  changes.revision = new_revision;
  for (const Change& c : step.changes) {
    const StatePtr& to = undoing ? c.before : c.after;
    classify(changes, c.label, undoing ? c.after : c.before, to);
    if (to)
      m.entities[c.label] = to;
    else
      m.entities.erase(c.label);
  }
  if (undoing) {
    m.redo.push_back(std::move(step));
    m.undo.pop_back();
  } else {
    m.undo.push_back(std::move(step));
    m.redo.pop_back();
  }
  m.revision = new_revision;
  return committed(m, std::move(changes));
}

}  // namespace

Outcome Document::undo() { return cross_step(*impl_, true); }
Outcome Document::redo() { return cross_step(*impl_, false); }
bool Document::can_undo() const noexcept { return !impl_->undo.empty(); }
bool Document::can_redo() const noexcept { return !impl_->redo.empty(); }
std::uint64_t Document::revision() const noexcept { return impl_->revision; }
Label Document::next_label() const noexcept { return Label{impl_->next_label}; }

std::vector<HistoryEntry> Document::history() const {
  std::vector<HistoryEntry> out;
  auto add = [&](const Step& s, bool applied) {
    HistoryEntry e{s.revision, s.name, s.time, {}, applied};
    for (const Change& c : s.changes) e.changed.push_back(c.label);
    out.push_back(std::move(e));
  };
  for (const Step& s : impl_->undo) add(s, true);
  for (auto it = impl_->redo.rbegin(); it != impl_->redo.rend(); ++it) add(*it, false);
  return out;
}

std::vector<Label> Document::labels() const {
  std::vector<Label> out;
  out.reserve(impl_->entities.size());
  for (const auto& [label, state] : impl_->entities) out.push_back(label);
  return out;
}
std::size_t Document::size() const noexcept { return impl_->entities.size(); }
bool Document::contains(Label label) const noexcept { return impl_->entities.contains(label); }
Entity Document::get(Label label) const { return Entity(label, impl_->existing(label)); }
std::optional<Entity> Document::find(Label label) const {
  if (StatePtr s = impl_->state(label)) return Entity(label, std::move(s));
  return std::nullopt;
}

ObserverId Document::observe(Observer observer) {
  const ObserverId id = impl_->next_observer++;
  impl_->observers.emplace_back(id, std::move(observer));
  return id;
}
void Document::unobserve(ObserverId id) {
  std::erase_if(impl_->observers, [&](const auto& o) { return o.first == id; });
}

const std::filesystem::path& Document::path() const noexcept { return impl_->path; }
bool Document::read_only() const noexcept { return impl_->read_only; }
const DocumentOptions& Document::options() const noexcept { return impl_->options; }

Json Document::to_json() const {
  Json out = Json::object();
  out["format"] = "hula-document";
  out["version"] = 1;
  out["revision"] = impl_->revision;
  out["next_label"] = impl_->next_label;
  out["backend"] = impl_->options.backend;
  Json entities = Json::array();
  for (const auto& [label, state] : impl_->entities) entities.push_back(entity_to_json(Entity(label, state)));
  out["entities"] = std::move(entities);
  return out;
}

}  // namespace hula::oli
