// SPDX-License-Identifier: MIT
// Open documents of the server (documents.hpp).
#include "hula/server/documents.hpp"

#include <chrono>

#include "hula/server/security.hpp"

namespace hula::server {

namespace {

Json labels_json(const std::vector<oli::Label>& labels) {
  Json out = Json::array();
  for (const oli::Label& l : labels) out.push_back(l.value);
  return out;
}

std::string_view cause_name(oli::ChangeSet::Cause cause) noexcept {
  switch (cause) {
    case oli::ChangeSet::Cause::Commit:
      return "commit";
    case oli::ChangeSet::Cause::Undo:
      return "undo";
    case oli::ChangeSet::Cause::Redo:
      return "redo";
  }
  return "commit";
}

}  // namespace

Json change_set_to_json(const oli::ChangeSet& c) {
  Json j = Json::object();
  j["cause"] = std::string(cause_name(c.cause));
  j["name"] = c.name;
  j["revision"] = c.revision;
  j["added"] = labels_json(c.added);
  j["changed"] = labels_json(c.changed);
  j["removed"] = labels_json(c.removed);
  j["attributes_changed"] = labels_json(c.attributes_changed);
  return j;
}

OpenDocument::OpenDocument(std::string name, oli::Document document)
    : name_(std::move(name)), document_(std::move(document)) {
  document_->observe([events = events_](const oli::ChangeSet& c) { events->append("change", change_set_to_json(c)); });
}

void OpenDocument::throw_if_closed() const {
  if (!document_)
    throw Error(Errc::InvalidArgument,
                "document '" + name_ + "' was " + closed_why_ + " while in use: nothing was stored in it",
                ErrorWhere{.field = "document"});
}

void OpenDocument::close(std::string_view why) {
  std::unique_lock lock(mutex_);
  if (!document_) return;
  document_.reset();
  closed_why_ = why;
  events_->close();
}

DocumentRegistry::DocumentRegistry(std::filesystem::path workspace) : workspace_(std::move(workspace)) {}

Json DocumentRegistry::list() const {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(workspace_, ec)) {
    const std::string n = entry.path().filename().string();
    if (!entry.is_regular_file(ec) || entry.is_symlink(ec)) continue;
    try {
      validate_document_name(n);
    } catch (const Error&) {
      continue;  // not a document (a CSV, a hidden file, the trash)
    }
    names.push_back(n);
  }
  std::sort(names.begin(), names.end());
  std::lock_guard lock(mutex_);
  Json out = Json::array();
  for (const std::string& n : names) {
    Json d = Json::object();
    d["name"] = n;
    d["open"] = open_.count(n) > 0;
    out.push_back(std::move(d));
  }
  return out;
}

std::shared_ptr<OpenDocument> DocumentRegistry::create(const std::string& name, const std::string& backend) {
  const std::filesystem::path path = document_path(workspace_, name);
  std::lock_guard lock(mutex_);
  std::error_code ec;
  if (std::filesystem::exists(std::filesystem::symlink_status(path, ec)))
    throw HttpError(409, "Conflict", "document '" + name + "' already exists in the workspace");
  oli::DocumentOptions options;
  options.backend = backend;
  auto doc = std::make_shared<OpenDocument>(name, oli::Document::create(path, options));
  open_[name] = doc;
  return doc;
}

std::shared_ptr<OpenDocument> DocumentRegistry::get(const std::string& name) {
  const std::filesystem::path path = document_path(workspace_, name);
  std::lock_guard lock(mutex_);
  if (const auto it = open_.find(name); it != open_.end()) return it->second;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw HttpError(404, "NotFound", "no document '" + name + "' in the workspace");
  auto doc = std::make_shared<OpenDocument>(name, oli::Document::open(path));
  open_[name] = doc;
  return doc;
}

std::filesystem::path DocumentRegistry::trash(const std::string& name) {
  const std::filesystem::path path = document_path(workspace_, name);
  std::lock_guard lock(mutex_);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw HttpError(404, "NotFound", "no document '" + name + "' in the workspace");
  if (const auto it = open_.find(name); it != open_.end()) {
    // Closed before the file moves: a request or job still holding the document (a study between its
    // compute and its commit) can no longer write into the trashed file, and SQLite has folded its
    // WAL back into the file.
    it->second->close("deleted");
    open_.erase(it);
  }
  const std::filesystem::path dir = workspace_ / ".trash";
  std::filesystem::create_directories(dir, ec);
  if (ec) throw Error(Errc::IoError, "cannot create the trash folder '" + dir.string() + "': " + ec.message());
  const auto stamp =
      std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count();
  const std::filesystem::path target = dir / (std::to_string(stamp) + "-" + name);
  std::filesystem::rename(path, target, ec);
  if (ec) throw Error(Errc::IoError, "cannot move '" + path.string() + "' to the trash: " + ec.message());
  for (const char* suffix : {"-wal", "-shm"}) {
    const std::filesystem::path side = path.string() + suffix;
    if (std::filesystem::exists(side, ec)) std::filesystem::rename(side, target.string() + suffix, ec);
  }
  return target;
}

void DocumentRegistry::close_all() {
  std::lock_guard lock(mutex_);
  for (auto& [name, doc] : open_) doc->close("closed");
  open_.clear();
}

}  // namespace hula::server
