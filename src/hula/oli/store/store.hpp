// SPDX-License-Identifier: MIT
// The SQLite store of a .hula document (STYLE.md "Front ends and state": SQL
// lives here and nowhere else). One Store owns one connection. It knows rows
// and byte strings, not curves: the document encodes each entity state to
// bytes (oli/detail/entity_codec) and the store keeps them.
//
// The file: SQLite in WAL mode with synchronous=NORMAL. Each Store::apply is
// one SQLite transaction, so a crash or kill -9 at any moment leaves the file
// at the last applied batch. synchronous=NORMAL in WAL mode syncs the WAL at
// checkpoints only: a committed transaction survives the process being killed
// (its pages are in the operating system's cache) but the last few may be lost
// if the machine itself loses power; the file is never corrupted either way
// (sqlite.org/pragma.html#pragma_synchronous). Those syncs happen at
// checkpoints, which a writer runs on a thread of its own (PASSIVE, with its
// own connection, once a commit leaves 1,000 pages in the WAL), not inside
// the commit that crosses the threshold, as SQLite's automatic checkpoint
// would: a commit costs no fsync, whatever the disk's latency. The guarantee is
// the same: a commit is in the WAL before apply returns; closing the store
// checkpoints what is left.
//
// Schema: numbered, append-only migrations (store/migrations/NNNN_*.sql), each
// run inside one transaction, the version kept in PRAGMA user_version and the
// file tagged with PRAGMA application_id 'HULA'. A writer holds an exclusive
// flock(2) on the file for its whole life, so a second writer (another process
// or another Store) is refused at open instead of interleaving its writes;
// readers take no lock and see the last committed state (WAL).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace hula::oli::store {

/// The schema version this build writes and the newest it reads.
inline constexpr int kSchemaVersion = 1;
/// PRAGMA application_id of a .hula file: 'HULA'.
inline constexpr std::int32_t kApplicationId = 0x48554C41;

/// Bytes of an encoded entity state.
using Blob = std::string;

/// The document row.
struct DocumentRow {
  std::uint64_t revision = 0;
  std::uint64_t next_label = 1;
  std::string backend = "native";
  std::string created{};
  std::string tool_version{};
};

/// One undo step as stored.
struct StepRow {
  std::uint64_t revision = 0;
  std::string name{};
  std::string time{};
  bool applied = true;
  /// (label, state) pairs: the state before the step when applied, after it when not;
  /// nullopt when the entity does not exist then. Ascending labels.
  std::vector<std::pair<std::uint64_t, std::optional<Blob>>> entities{};
};

/// Everything in a file.
struct Snapshot {
  int schema_version = 0;
  DocumentRow document{};
  /// (label, state), ascending labels.
  std::vector<std::pair<std::uint64_t, Blob>> entities{};
  /// Ascending revisions.
  std::vector<StepRow> steps{};
};

/// One atomic change of the file: applied as one SQLite transaction, in the order listed.
struct Batch {
  /// Delete the steps with revision ≥ this (redo history dropped by a new change).
  std::optional<std::uint64_t> delete_steps_from{};
  /// Delete the steps with revision ≤ this (the oldest, over the undo limit).
  std::optional<std::uint64_t> delete_steps_through{};
  /// Entity states to write (nullopt deletes the row).
  std::vector<std::pair<std::uint64_t, std::optional<Blob>>> entities{};
  /// Steps to insert or replace whole (their entity rows replaced too).
  std::vector<StepRow> steps{};
  /// Steps whose applied flag and entity states change (undo/redo swap): replaces
  /// the listed entity rows and the flag, leaves the name and time.
  std::vector<StepRow> step_updates{};
  /// The new revision and next label.
  std::uint64_t revision = 0;
  std::uint64_t next_label = 1;
};

/// How to open a file.
enum class Access : std::uint8_t { ReadWrite, ReadOnly };

/// A connection to one .hula file.
class Store {
 public:
  /// Creates a new file with the current schema and the given document row, and
  /// opens it read-write (locked).
  /// @param overwrite replace an existing file: the new file is built beside it
  ///   and renamed over it, so a failure leaves the old one as it was
  /// @throws hula::Error(Errc::IoError) naming the path: exists (without overwrite),
  ///   locked by a writer, directory not writable, disk full
  [[nodiscard]] static Store create(const std::filesystem::path& path, const DocumentRow& row, bool overwrite);
  /// Opens an existing file. ReadWrite migrates an older schema forward.
  /// @throws hula::Error(Errc::IoError) naming the path: missing, not a regular file,
  ///   not a HulaHoops document, corrupt or truncated, newer schema (both versions
  ///   named), older schema opened read-only, locked by another writer
  [[nodiscard]] static Store open(const std::filesystem::path& path, Access access);

  Store(Store&&) noexcept;
  Store& operator=(Store&&) noexcept;
  Store(const Store&) = delete;
  Store& operator=(const Store&) = delete;
  ~Store();

  /// Reads the whole file.
  /// @throws hula::Error(Errc::IoError) naming the path when a read fails (corruption)
  [[nodiscard]] Snapshot load() const;
  /// Applies a batch as one SQLite transaction; on failure nothing of it is in the file.
  /// @throws hula::Error(Errc::IoError) naming the path and SQLite's reason (disk full, I/O error)
  void apply(const Batch& batch);
  /// SQLite's PRAGMA integrity_check: empty when the file is sound, else its messages.
  [[nodiscard]] std::vector<std::string> integrity_check() const;

  [[nodiscard]] const std::filesystem::path& path() const noexcept;
  [[nodiscard]] Access access() const noexcept;

  struct Impl;

 private:
  explicit Store(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace hula::oli::store
