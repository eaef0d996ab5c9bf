// SPDX-License-Identifier: MIT
// The documents the server has open (oli::Document, one per workspace file).
// An oli::Document is not thread-safe, so each open document has one
// shared_mutex: a transaction, undo or redo holds it exclusively (one writer
// at a time), readers hold it shared and take immutable Entity snapshots,
// which they may read after releasing it — no reader sees a half-applied
// change, and a long analysis never blocks an edit. Every committed change
// set is appended to the document's event log (SSE of
// /api/documents/{name}/events), so every client sees every change.
// Deleting (trash) or closing a document closes it under the exclusive lock:
// a request or job still holding it (a study job between its compute and its
// commit) then fails with an error naming the document, and nothing reaches
// the file, which is closed before it moves to the trash.
#pragma once

#include <algorithm>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <shared_mutex>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hula/oli/document.hpp"
#include "hula/server/events.hpp"
#include "hula/server/http.hpp"

namespace hula::server {

/// A change set as JSON: {"cause": "commit"|"undo"|"redo", "name", "revision", "added", "changed",
/// "removed", "attributes_changed"} (labels as integers).
[[nodiscard]] Json change_set_to_json(const oli::ChangeSet& changes);

/// A change and snapshots of the entities it added or changed (data or attributes), in label order,
/// taken under the writer's lock right after it: what the reply of a change carries.
struct Change {
  oli::Outcome outcome{};
  std::vector<oli::Entity> entities{};
};

/// One open document.
class OpenDocument {
 public:
  OpenDocument(std::string name, oli::Document document);

  [[nodiscard]] const std::string& name() const noexcept { return name_; }
  [[nodiscard]] std::shared_ptr<EventLog> events() const noexcept { return events_; }

  /// Runs `read` under the shared lock.
  /// @throws hula::Error(Errc::InvalidArgument) naming the document once it was closed
  template <class F>
  auto read(F&& read) const {
    std::shared_lock lock(mutex_);
    throw_if_closed();
    return read(std::as_const(*document_));
  }

  /// Runs `write` (a transaction, undo or redo) under the exclusive lock; the change set of a
  /// committed outcome reaches the event log through the document's observer.
  /// @throws hula::Error(Errc::InvalidArgument) naming the document once it was closed (nothing written)
  template <class F>
  auto write(F&& write) {
    std::unique_lock lock(mutex_);
    throw_if_closed();
    return write(*document_);
  }

  /// Runs `write` (a transaction, undo or redo returning its oli::Outcome) under the exclusive lock, as
  /// write(), and snapshots the entities its change set added or changed.
  /// @throws as write()
  template <class F>
  Change change(F&& write) {
    std::unique_lock lock(mutex_);
    throw_if_closed();
    Change c;
    c.outcome = write(*document_);
    if (c.outcome.committed) {
      const oli::ChangeSet& s = c.outcome.changes;
      std::vector<oli::Label> labels = s.added;
      labels.insert(labels.end(), s.changed.begin(), s.changed.end());
      labels.insert(labels.end(), s.attributes_changed.begin(), s.attributes_changed.end());
      std::sort(labels.begin(), labels.end());
      labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
      for (const oli::Label l : labels)
        if (document_->contains(l)) c.entities.push_back(document_->get(l));
    }
    return c;
  }

  /// Closes the document once the reader or writer holding it is done: its file is closed (SQLite
  /// folds its WAL back in), and every later read or write throws, saying the document was `why`
  /// ("deleted", "closed"). Idempotent.
  void close(std::string_view why);

 private:
  // The error of a closed document (called under mutex_).
  void throw_if_closed() const;

  std::string name_;
  mutable std::shared_mutex mutex_;
  std::optional<oli::Document> document_;
  std::string closed_why_{};
  std::shared_ptr<EventLog> events_ = std::make_shared<EventLog>();
};

/// The open documents of a workspace.
class DocumentRegistry {
 public:
  explicit DocumentRegistry(std::filesystem::path workspace);

  /// The *.hula files of the workspace (sorted), with whether each is open.
  [[nodiscard]] Json list() const;

  /// Creates a new document file and opens it.
  /// @throws hula::Error(InvalidArgument) for a bad name (security.hpp), HttpError(409, "Conflict")
  ///   if the file exists, hula::Error(InvalidOption) for an unknown backend
  std::shared_ptr<OpenDocument> create(const std::string& name, const std::string& backend);

  /// The open document, opening the file on first use.
  /// @throws HttpError(404, "NotFound") if there is no such file; hula::Error(IoError) if it is
  ///   not a readable document or another process writes it
  std::shared_ptr<OpenDocument> get(const std::string& name);

  /// Closes the document and moves its file to the workspace's .trash folder (never unlinked).
  /// @returns the trash path
  /// @throws HttpError(404) as get
  std::filesystem::path trash(const std::string& name);

  /// Closes every document (on shutdown).
  void close_all();

 private:
  std::filesystem::path workspace_;
  mutable std::mutex mutex_;
  std::map<std::string, std::shared_ptr<OpenDocument>> open_;
};

}  // namespace hula::server
