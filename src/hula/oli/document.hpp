// SPDX-License-Identifier: MIT
// The Oli document (thesis 9.5.3, DESIGN.md "oli"): the one stateful layer of
// HulaHoops. A Document holds entities — curves, point sets and studies —
// under labels that are stable for their whole life (across undo, redo, save
// and reopen) and never reused after deletion; applications hold labels, never
// pointers (9.5.3 "Labels"). Every change goes through a named transaction:
//
//   oli::Document doc = oli::Document::create("part.hula");
//   oli::Label l;
//   oli::Outcome done = doc.transact("add spine", [&](oli::Edit& e) {
//     l = e.add_curve(curve, {.name = "spine"});
//   });
//   doc.transact("move point", [&](oli::Edit& e) { e.move_point(l, 3, {1, 2, 0}); });
//   doc.undo();
//
// A transaction applies all or nothing, as ACIS API functions do (9.2): any
// exception thrown inside the body (an invalid curve, a NaN, a failed study,
// anything) rolls the document back to exactly its prior state — entities,
// attributes and the next label alike — and the Outcome names the error. A
// transaction started inside another one folds into it (like a SQLite
// savepoint: its own failure undoes only its own part and is reported to the
// enclosing body through its Outcome). The "continue" form replaces the last
// step, so a drag through many positions is one undo step.
//
// Each committed transaction is one undo step recording, per entity it
// touched, the state before and after (O(size of the change), the immutable
// entity states are shared, never copied whole). Observers receive one
// ChangeSet per committed transaction, undo and redo. A document opened from a
// file (SQLite, store/) writes each committed step as one SQLite transaction,
// undo history included, so tomorrow's session can undo today's steps.
//
// Threads: a Document is not thread-safe; one thread (or one strand of the
// server) owns it. Entity values handed out are immutable and may be read from
// any thread.
#pragma once

#include <chrono>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hula/core/error.hpp"
#include "hula/core/vec.hpp"
#include "hula/io/json_curve.hpp"
#include "hula/io/points_file.hpp"
#include "hula/oli/constraints.hpp"
#include "hula/optim/run_log.hpp"

namespace hula::curve {
class Curve;  // the one curve value type (hula/curve/curve.hpp)
}  // namespace hula::curve

namespace hula::oli {

using Json = io::Json;

/// A stable entity label: a positive integer, unique in its document for the
/// document's whole life (never reused after the entity is removed, even when
/// the removal is undone and redone). 0 is never a label.
struct Label {
  std::uint64_t value = 0;

  [[nodiscard]] constexpr bool valid() const noexcept { return value != 0; }
  friend constexpr auto operator<=>(const Label&, const Label&) = default;
};

/// What an entity is (9.5.3: curves are objects; their representations are attributes).
enum class EntityKind : std::uint8_t {
  Curve,     ///< a curve::Curve (NURBS, Bézier, interpolated, Hermite, law, natural equations)
  PointSet,  ///< an ordered set of points in model units
  Study,     ///< a study: its setup and the runs made from it
};

/// "curve", "point-set" or "study".
[[nodiscard]] std::string_view entity_kind_name(EntityKind kind) noexcept;

/// The system attributes every entity has, plus user attributes.
/// Schema (docs/modules/oli.md "Attributes"):
///   name     string, any UTF-8, default "" (unnamed); not required to be unique
///   colour   "#rrggbb" (lower-case hex), default "#1f77b4"
///   visible  bool, default true
///   layer    string, default "default"
///   locked   bool, default false: a locked entity refuses changes of its
///            data and its removal (attributes may still change, to unlock it)
///   user     key → any JSON value; keys are non-empty strings that do not
///            start with '$' (reserved)
struct Attributes {
  std::string name{};
  std::string colour = "#1f77b4";
  bool visible = true;
  std::string layer = "default";
  bool locked = false;
  std::map<std::string, Json> user{};

  /// @throws hula::Error(Errc::InvalidArgument) naming the field (colour not
  ///   "#rrggbb", empty layer, an empty or '$'-prefixed user key)
  void validate() const;
  friend bool operator==(const Attributes&, const Attributes&) = default;
};

/// What made an entity, when an operation made it (a study result, an import, a split).
struct Provenance {
  /// The operation, e.g. "study:match-curvature", "import:json", "split".
  std::string operation{};
  /// The labels of the entities it read (the study, the source curve, ...).
  std::vector<Label> inputs{};
  /// The seed of a stochastic operation.
  std::optional<std::uint64_t> seed{};
  /// The HulaHoops version that ran it.
  std::string tool_version{};
  /// Anything else the operation records (run index, source file name, ...).
  Json details = Json::object();

  friend bool operator==(const Provenance&, const Provenance&) = default;
};

/// A point set entity's data: the io module's point set (points in model
/// units, dimension 2 for planar [x, y] data, else 3).
using PointSet = io::PointSet;

/// One run of a study, stored in the study entity.
struct StudyRun {
  /// The seed the run used (the setup's, or the one it was asked for).
  std::uint64_t seed = 1;
  /// The study's result document as `hula <study>` prints it (champion, fitness, termination ...).
  Json result = Json::object();
  /// The run log: every individual of every generation of the study's optimisers (shared, never copied;
  /// shown as `--log` writes it). None for the studies without generations (shown as []).
  std::shared_ptr<const optim::RunLog> log{};
  /// The result curves, added as entities with provenance naming the study.
  std::vector<Label> result_curves{};

  /// Equal seeds, results, result curves and logs (the same log, or logs equal bit for bit).
  friend bool operator==(const StudyRun& a, const StudyRun& b) {
    return a.seed == b.seed && a.result == b.result && a.result_curves == b.result_curves &&
           (a.log == b.log || (a.log && b.log && *a.log == *b.log));
  }
};

/// A study entity's data: the study file's setup (curves it names resolved to
/// entity labels are recorded as such) and the runs made from it.
struct Study {
  /// The study file, as a "hula-study" document.
  Json setup = Json::object();
  /// The runs, oldest first.
  std::vector<StudyRun> runs{};

  friend bool operator==(const Study&, const Study&) = default;
};

namespace detail {
struct EntityState;
}  // namespace detail

/// A read-only view of one entity at one revision. Cheap to copy (one shared
/// pointer); it stays valid and unchanged when the document changes later, so
/// it is a snapshot, not a live handle.
class Entity {
 public:
  Entity() = default;
  explicit Entity(Label label, std::shared_ptr<const detail::EntityState> state);

  [[nodiscard]] Label label() const noexcept { return label_; }
  [[nodiscard]] EntityKind kind() const;
  [[nodiscard]] const Attributes& attributes() const;
  [[nodiscard]] const std::optional<Provenance>& provenance() const;
  /// The constraints stored with a curve (empty for other kinds).
  [[nodiscard]] const std::vector<Constraint>& constraints() const;
  /// The curve of a Curve entity.
  /// @throws hula::Error(Errc::InvalidArgument) naming the label if the entity is not a curve
  [[nodiscard]] const curve::Curve& curve() const;
  /// The points of a PointSet entity.
  /// @throws hula::Error(Errc::InvalidArgument) naming the label if the entity is not a point set
  [[nodiscard]] const PointSet& point_set() const;
  /// The study of a Study entity.
  /// @throws hula::Error(Errc::InvalidArgument) naming the label if the entity is not a study
  [[nodiscard]] const Study& study() const;

  /// The shared immutable state (for the store and the tests' equality checks).
  [[nodiscard]] const std::shared_ptr<const detail::EntityState>& state() const noexcept { return state_; }

 private:
  Label label_{};
  std::shared_ptr<const detail::EntityState> state_{};
};

/// What one committed transaction (or undo, or redo) changed. Labels are in
/// ascending order and each appears in at most one of added / changed /
/// removed; `attributes_changed` lists the entities (added ones excluded)
/// whose attributes differ, whether or not their data changed too.
struct ChangeSet {
  /// Why the document changed.
  enum class Cause : std::uint8_t { Commit, Undo, Redo };
  Cause cause = Cause::Commit;
  /// The transaction's name (for undo/redo, the name of the step undone or redone).
  std::string name{};
  /// The document's revision after the change.
  std::uint64_t revision = 0;
  std::vector<Label> added{};
  std::vector<Label> changed{};
  std::vector<Label> removed{};
  std::vector<Label> attributes_changed{};

  /// True when nothing changed.
  [[nodiscard]] bool empty() const noexcept {
    return added.empty() && changed.empty() && removed.empty() && attributes_changed.empty();
  }
};

/// The result of a transaction, undo or redo: committed with its change set,
/// or rolled back with the error that caused it.
struct Outcome {
  /// True when the change is applied (and, for a file document, on disk).
  bool committed = false;
  /// The document's revision after the call (unchanged when not committed).
  std::uint64_t revision = 0;
  /// What changed (empty when not committed).
  ChangeSet changes{};
  /// The error's stable code (errc_name, or "InternalError" for an exception
  /// that is not a hula::Error); empty when committed.
  std::string error_code{};
  /// The error's message; empty when committed.
  std::string error_message{};
  /// The exception that rolled the transaction back (null when committed).
  std::exception_ptr error{};

  explicit operator bool() const noexcept { return committed; }
  /// Rethrows the exception that rolled the transaction back; does nothing when committed.
  void throw_if_failed() const;
};

/// One undo step as listed by Document::history.
struct HistoryEntry {
  /// The revision the document has once this step is applied.
  std::uint64_t revision = 0;
  /// The transaction's name.
  std::string name{};
  /// When it was committed (UTC, ISO 8601 with milliseconds, "2026-12-01T18:30:00.123Z").
  std::string time{};
  /// The labels of the entities it added, changed or removed, ascending.
  std::vector<Label> changed{};
  /// True when the step is applied (revision ≤ the document's revision), false when it can be redone.
  bool applied = true;
};

/// How a transaction relates to the previous step.
enum class TransactMode : std::uint8_t {
  /// A new undo step (the usual case).
  New,
  /// Replaces the last step (a drag's intermediate positions): the document
  /// goes back to the state before the last step, runs the body there, and the
  /// result becomes that step, so undo goes back to before the drag began. It
  /// continues only a step with the same name that is the latest applied one
  /// and has not been undone; otherwise it makes a new step. If the body fails
  /// the last step stays as it was.
  Continue,
};

/// Options of a document.
struct DocumentOptions {
  /// Keep at most this many undo steps (the oldest are dropped, from memory
  /// and from the file, when a new step exceeds it). Empty = unbounded (the default).
  std::optional<std::size_t> undo_limit{};
  /// The geometry kernel recorded in the document: "native" (default) or "occt".
  std::string backend = "native";

  /// @throws hula::Error(Errc::InvalidOption) for an undo_limit of 0 or an unknown backend
  void validate() const;
};

/// How Document::open may use the file.
enum class OpenMode : std::uint8_t {
  /// Read and write; takes the file's writer lock (a second writer is refused).
  ReadWrite,
  /// Read only; no lock, no write, works beside a writer.
  ReadOnly,
};

/// One result of Document::check_file.
struct CheckReport {
  /// True when every check passed.
  bool ok = true;
  /// The file's schema version.
  int schema_version = 0;
  /// The revision stored in the file.
  std::uint64_t revision = 0;
  /// The number of entities that loaded.
  std::size_t entities = 0;
  /// The number of undo steps, applied and redoable.
  std::size_t steps = 0;
  /// What failed, one sentence each (empty when ok).
  std::vector<std::string> problems{};
};

class Edit;

/// An observer's callback: one ChangeSet per committed transaction, undo or redo.
using Observer = std::function<void(const ChangeSet&)>;
/// A registration handle for Document::unobserve.
using ObserverId = std::uint64_t;

/// The curve document. Movable, not copyable.
class Document {
 public:
  /// An empty in-memory document (not backed by a file).
  explicit Document(DocumentOptions options = {});
  /// Creates a new document file (SQLite, WAL) and opens it read-write.
  /// @param path the file to create
  /// @param overwrite replace an existing file (otherwise an existing file is refused)
  /// @throws hula::Error(Errc::IoError) naming the path if it exists (and !overwrite) or cannot be written
  /// @throws hula::Error(Errc::InvalidOption) from options.validate()
  [[nodiscard]] static Document create(const std::filesystem::path& path, DocumentOptions options = {},
                                       bool overwrite = false);
  /// Opens a document file: loads every entity and the undo history.
  /// @throws hula::Error(Errc::IoError) naming the path when it is missing, not a HulaHoops
  ///   document or written by a newer schema (the message names both versions)
  /// @throws hula::Error(Errc::DocumentCorrupt) naming the path when it is truncated, its pages are
  ///   corrupt, a stored entity does not decode or its history does not fit together (the file is
  ///   never written then)
  /// @throws hula::Error(Errc::DocumentLocked) for ReadWrite when it is already open for writing by
  ///   another process or another Document
  [[nodiscard]] static Document open(const std::filesystem::path& path, OpenMode mode = OpenMode::ReadWrite,
                                     std::optional<std::size_t> undo_limit = std::nullopt);
  /// Checks a document file without changing it: schema, every entity decodes,
  /// the undo history is consistent (undoing every step from the stored state
  /// reaches the empty document, steps are contiguous, labels below the next label).
  [[nodiscard]] static CheckReport check_file(const std::filesystem::path& path);

  Document(Document&&) noexcept;
  Document& operator=(Document&&) noexcept;
  Document(const Document&) = delete;
  Document& operator=(const Document&) = delete;
  ~Document();

  /// Runs `body` as one transaction named `name` (see the file comment).
  /// Never throws for a failure inside the body: the Outcome reports it.
  /// @returns committed with its change set, or rolled back with the error
  Outcome transact(std::string_view name, const std::function<void(Edit&)>& body,
                   TransactMode mode = TransactMode::New);
  /// Undoes the latest applied step. Returns a not-committed Outcome with
  /// error_code "InvalidArgument" when there is none.
  Outcome undo();
  /// Redoes the earliest undone step; fails as undo when there is none.
  Outcome redo();
  [[nodiscard]] bool can_undo() const noexcept;
  [[nodiscard]] bool can_redo() const noexcept;

  /// The number of applied steps since the document was created (0 for an
  /// empty new document). Undo lowers it by one, redo raises it by one.
  [[nodiscard]] std::uint64_t revision() const noexcept;
  /// The label the next added entity will get.
  [[nodiscard]] Label next_label() const noexcept;
  /// The undo steps, oldest first: applied ones then redoable ones.
  [[nodiscard]] std::vector<HistoryEntry> history() const;

  /// All labels, ascending.
  [[nodiscard]] std::vector<Label> labels() const;
  [[nodiscard]] std::size_t size() const noexcept;
  [[nodiscard]] bool contains(Label label) const noexcept;
  /// The entity with this label.
  /// @throws hula::Error(Errc::InvalidArgument) naming the label when there is none
  [[nodiscard]] Entity get(Label label) const;
  /// The entity with this label, or nullopt.
  [[nodiscard]] std::optional<Entity> find(Label label) const;

  /// Registers an observer; it is called after each committed transaction, undo and redo.
  /// An exception thrown by an observer is caught and does not undo anything.
  ObserverId observe(Observer observer);
  void unobserve(ObserverId id);

  /// The file behind the document (empty for an in-memory one).
  [[nodiscard]] const std::filesystem::path& path() const noexcept;
  /// True when opened with OpenMode::ReadOnly (transactions then fail with IoError).
  [[nodiscard]] bool read_only() const noexcept;
  [[nodiscard]] const DocumentOptions& options() const noexcept;

  /// The whole document as JSON: {"format": "hula-document", "version": 1,
  /// "revision", "next_label", "entities": [entity_to_json ...]} (history excluded).
  [[nodiscard]] Json to_json() const;

  struct Impl;

 private:
  friend class Edit;
  explicit Document(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

/// The editing handle passed to a transaction body. It exists only inside
/// the body; every method throws hula::Error on bad input, which rolls the
/// whole transaction back.
class Edit {
 public:
  /// Adds a curve; returns its new label.
  /// @throws hula::Error(Errc::InvalidArgument) from attributes.validate()
  Label add_curve(const curve::Curve& curve, Attributes attributes = {},
                  std::optional<Provenance> provenance = std::nullopt);
  /// Adds a point set. @throws hula::Error(Errc::NonFiniteInput) naming the point for a NaN or infinity
  Label add_point_set(PointSet points, Attributes attributes = {}, std::optional<Provenance> provenance = std::nullopt);
  /// Adds a study. @throws hula::Error(Errc::InvalidArgument) if the setup is not a JSON object
  Label add_study(Study study, Attributes attributes = {}, std::optional<Provenance> provenance = std::nullopt);

  /// Replaces a curve entity's curve.
  /// @throws hula::Error(Errc::InvalidArgument) for a missing label, another kind, or a locked entity
  void set_curve(Label label, const curve::Curve& curve);
  /// Replaces a point set entity's points (errors as set_curve, plus NonFiniteInput).
  void set_point_set(Label label, PointSet points);
  /// Replaces a study entity's data (errors as set_curve).
  void set_study(Label label, Study study);
  /// Moves point `index` of an entity: a control point of a NURBS or Bézier
  /// curve, a data point of an interpolated or Hermite curve, a point of a point set.
  /// @throws hula::Error(Errc::InvalidArgument) naming the index when out of range, or for a
  ///   law / natural-equation curve (no points); NonFiniteInput for a NaN or infinity in `to`;
  ///   the curve's own errors when the moved curve is invalid
  void move_point(Label label, std::size_t index, Vec3 to);
  /// Replaces all attributes. @throws as Attributes::validate, and for a missing label
  void set_attributes(Label label, Attributes attributes);
  /// Sets one attribute by key: a system key (name, colour, visible, layer, locked) with a
  /// value of its type, or any other key as a user attribute; a null value removes a user attribute.
  /// @throws hula::Error(Errc::InvalidArgument) naming the key for a value of the wrong type
  void set_attribute(Label label, std::string_view key, const Json& value);
  /// Replaces a curve's constraints. @throws hula::Error(Errc::InvalidArgument) as Constraint::validate
  void set_constraints(Label label, std::vector<Constraint> constraints);
  /// Removes an entity; its label is never given again.
  /// @throws hula::Error(Errc::InvalidArgument) for a missing label or a locked entity
  void remove(Label label);

  // Geometric operations, computed by the document's kernel backend
  // (DocumentOptions::backend, make_kernel). A NURBS, Bézier, interpolated or Hermite curve is
  // operated on as its exact NURBS and the entity becomes a NURBS curve; a law or
  // natural-equation curve (whose NURBS is an approximation) is refused. Kernel errors
  // (OutOfDomain, InvalidKnots, Unsupported, ...) keep their code and field, with the entity
  // and the operation named in the message; they roll the transaction back.

  /// Inserts knot u `times` times (the curve is unchanged as a point set and parametrisation).
  /// @throws hula::Error(Errc::InvalidArgument) for a missing label, another kind, a locked
  ///   entity or a law / natural-equation curve; as Kernel::insert_knot
  void insert_knot(Label label, double u, int times = 1);
  /// Raises the degree by `times` without changing the curve.
  /// @throws as insert_knot, and as Kernel::elevate_degree
  void elevate_degree(Label label, int times = 1);
  /// Reverses the direction of traversal on the same domain.
  /// @throws as insert_knot
  void reverse(Label label);
  /// Splits a curve at t: removes the entity and adds its pieces on [a, t] and [t, b], named
  /// "<name> (1)" and "<name> (2)", with provenance {"split", [label], details {"t"}}.
  /// @returns the labels of the two pieces
  /// @throws as insert_knot, and as Kernel::split (OutOfDomain unless a < t < b)
  std::pair<Label, Label> split(Label label, double t);

  /// The document as the body sees it so far (its own changes included).
  [[nodiscard]] const Document& document() const noexcept { return *document_; }
  [[nodiscard]] Entity get(Label label) const { return document_->get(label); }

 private:
  friend class Document;
  explicit Edit(Document* document) : document_(document) {}
  Document* document_;
};

/// An entity as JSON: its data in its own file format (a curve as its curve
/// file, a point set as a points file, a study as its setup and runs) plus
/// "label", "kind", "attributes", "provenance" (null when none) and "constraints".
[[nodiscard]] Json entity_to_json(const Entity& entity);
/// Attributes as JSON: {"name", "colour", "visible", "layer", "locked", "user": {...}}.
[[nodiscard]] Json attributes_to_json(const Attributes& attributes);
/// Parses attributes; absent members keep their defaults.
/// @throws hula::Error(Errc::ParseError) naming the member of the wrong type or an unknown one
[[nodiscard]] Attributes attributes_from_json(const Json& json);
[[nodiscard]] Json provenance_to_json(const Provenance& provenance);
/// @throws hula::Error(Errc::ParseError) naming the member
[[nodiscard]] Provenance provenance_from_json(const Json& json);

}  // namespace hula::oli

template <>
struct std::hash<hula::oli::Label> {
  std::size_t operator()(const hula::oli::Label& label) const noexcept {
    return std::hash<std::uint64_t>{}(label.value);
  }
};
