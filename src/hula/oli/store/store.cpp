// SPDX-License-Identifier: MIT
// The SQLite store (store.hpp). Every statement is prepared once with bound
// parameters and its result checked; the migrations are the static SQL files
// of store/migrations/, compiled in by CMake (migrations.inc).
#include "hula/oli/store/store.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <condition_variable>
#include <cstring>
#include <memory>
#include <mutex>
#include <string_view>
#include <thread>
#include <utility>

#include "hula/core/error.hpp"
#include "hula/core/plugin.hpp"
#include "hula/io/owned_files.hpp"
#include "hula/oli/store/sqlite_api.hpp"

namespace hula::oli::store {
namespace {

// libsqlite3's functions, from the SQLite plugin (sqlite_api.hpp), loaded by the first document opened.
const detail::SqliteApi& sqlite() {
  static const detail::SqliteApi* const api =
      reinterpret_cast<detail::SqliteApiFunction>(plugin_symbol("sqlite", detail::kSqliteApiSymbol))();
  return *api;
}

// The migrations, oldest first; migration i (0-based) brings the schema to version i + 1.
constexpr std::array kMigrations = {
#include "hula/oli/store/migrations.inc"
};
static_assert(kMigrations.size() == kSchemaVersion, "one migration per schema version");

// How long a reader or writer waits for SQLite's own short-lived locks (WAL
// recovery, checkpoints) before reporting the file busy.
constexpr int kBusyTimeoutMs = 2000;

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what, Errc code = Errc::IoError) {
  throw Error(code, path.string() + ": " + what, {.field = "path"});
}

// True when an SQLite I/O failure is the disk running out of space (or quota, or the file-size limit):
// SQLite reports ENOSPC while growing the -shm file (SQLITE_IOERR_SHMSIZE) or the WAL as a plain I/O
// error, not SQLITE_FULL; the OS error it saw tells them apart.
bool out_of_space(sqlite3* db, int rc) {
  if ((rc & 0xff) == SQLITE_FULL) return true;
  if ((rc & 0xff) != SQLITE_IOERR || db == nullptr) return false;
  const int e = sqlite().system_errno(db);
  return e == ENOSPC || e == EDQUOT || e == EFBIG;
}

// The code of an SQLite failure: locked or busy, corrupt, full, or another I/O error.
Errc sqlite_errc(sqlite3* db, int rc) {
  if (out_of_space(db, rc)) return Errc::StorageFull;
  switch (rc & 0xff) {
    case SQLITE_BUSY:
    case SQLITE_LOCKED:
      return Errc::DocumentLocked;
    case SQLITE_CORRUPT:
    case SQLITE_NOTADB:
      return Errc::DocumentCorrupt;
    default:
      return Errc::IoError;
  }
}

std::string sqlite_reason(sqlite3* db, int rc) {
  std::string reason = db != nullptr ? sqlite().errmsg(db) : sqlite().errstr(rc);
  const int primary = rc & 0xff;
  if (primary == SQLITE_CORRUPT || primary == SQLITE_NOTADB) return "the file is corrupt or truncated (" + reason + ")";
  if (out_of_space(db, rc)) return "the disk is full or the file size limit was reached (" + reason + ")";
  if (primary == SQLITE_CANTOPEN)
    return reason + " (a writer creates the -wal and -shm files beside the document: is its directory writable?)";
  if (primary == SQLITE_READONLY) return reason + " (is the file or its directory write-protected?)";
  return reason;
}

// A file descriptor holding the writer's flock; closed last, after SQLite's
// connection, because closing any descriptor of the file drops this process's
// POSIX locks, SQLite's included.
class LockFd {
 public:
  LockFd() = default;
  explicit LockFd(int fd) : fd_(fd) {}
  LockFd(LockFd&& o) noexcept : fd_(std::exchange(o.fd_, -1)) {}
  LockFd& operator=(LockFd&& o) noexcept {
    if (this != &o) {
      reset();
      fd_ = std::exchange(o.fd_, -1);
    }
    return *this;
  }
  ~LockFd() { reset(); }
  void reset() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }
  [[nodiscard]] int get() const { return fd_; }

 private:
  int fd_ = -1;
};

// Takes the writer lock on `path` (exclusive, non-blocking).
LockFd lock_for_writing(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail(path, std::string("cannot open: ") + std::strerror(errno));
  LockFd lock(fd);
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    if (errno == EWOULDBLOCK)
      fail(path,
           "the document is open for writing by another process (or another document in this one); "
           "close it there first",
           Errc::DocumentLocked);
    fail(path, std::string("cannot lock: ") + std::strerror(errno));
  }
  return lock;
}

// Reads SQLite's 100-byte header to refuse what is not a .hula file before
// SQLite touches it (it would otherwise treat an empty file as a new database).
void check_header(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail(path, std::string("cannot open: ") + std::strerror(errno));
  std::array<unsigned char, 100> header{};
  const ssize_t got = ::pread(fd, header.data(), header.size(), 0);
  ::close(fd);
  if (got < 0) fail(path, std::string("cannot read: ") + std::strerror(errno));
  if (got < static_cast<ssize_t>(header.size()))
    fail(path, "not a HulaHoops document (the file is truncated: " + std::to_string(got) + " bytes)",
         Errc::DocumentCorrupt);
  if (std::memcmp(header.data(), "SQLite format 3", 16) != 0) fail(path, "not a HulaHoops document (not SQLite)");
  auto be32 = [&](std::size_t at) {
    return static_cast<std::uint32_t>(header[at]) << 24 | static_cast<std::uint32_t>(header[at + 1]) << 16 |
           static_cast<std::uint32_t>(header[at + 2]) << 8 | static_cast<std::uint32_t>(header[at + 3]);
  };
  if (be32(68) != static_cast<std::uint32_t>(kApplicationId))
    fail(path, "not a HulaHoops document (an SQLite database of another application)");
  const auto version = static_cast<std::int32_t>(be32(60));
  if (version > kSchemaVersion)
    fail(path, "written by a newer HulaHoops (document schema version " + std::to_string(version) +
                   "); this hula reads schema versions up to " + std::to_string(kSchemaVersion));
}

}  // namespace

// WAL pages after a commit from which a checkpoint is due (SQLite's own default for its
// automatic checkpoint, which this replaces).
constexpr int kCheckpointPages = 1000;

// Checkpoints a writer's WAL on a thread of its own, with a connection of its own (store.hpp): a
// checkpoint syncs the WAL and then the database file, tens of milliseconds each on a busy disk,
// which SQLite's automatic checkpoint spends inside the commit that crosses kCheckpointPages.
// PASSIVE: it copies what no reader still needs and never blocks the writer; whatever it cannot
// copy waits for the next round, and closing the last connection checkpoints the rest.
class Checkpointer {
 public:
  explicit Checkpointer(std::filesystem::path path) : path_(std::move(path)), thread_([this] { run(); }) {}
  ~Checkpointer() {
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_one();
    thread_.join();
  }
  Checkpointer(const Checkpointer&) = delete;
  Checkpointer& operator=(const Checkpointer&) = delete;

  // Called by the writer's commit (sqlite3_wal_hook) with the pages now in the WAL.
  void committed(int wal_pages) {
    if (wal_pages < kCheckpointPages) return;
    {
      std::lock_guard lock(mutex_);
      due_ = true;
    }
    wake_.notify_one();
  }

 private:
  void run() {
    sqlite3* db = nullptr;
    std::unique_lock lock(mutex_);
    while (true) {
      wake_.wait(lock, [this] { return stopping_ || due_; });
      if (stopping_) break;
      due_ = false;
      lock.unlock();
      if (db == nullptr &&
          sqlite().open_v2(path_.c_str(), &db, SQLITE_OPEN_READWRITE | SQLITE_OPEN_NOMUTEX, nullptr) == SQLITE_OK) {
        sqlite().busy_timeout(db, kBusyTimeoutMs);
        // A connection that has read nothing has not opened the WAL yet, and its checkpoint would
        // do nothing: read the schema once.
        sqlite().exec(db, "SELECT count(*) FROM sqlite_master", nullptr, nullptr, nullptr);
      }
      // A failure (busy, I/O) leaves the pages in the WAL, where they are as durable as before; the
      // next commit past the threshold asks again.
      if (db != nullptr) sqlite().wal_checkpoint_v2(db, nullptr, SQLITE_CHECKPOINT_PASSIVE, nullptr, nullptr);
      lock.lock();
    }
    lock.unlock();
    if (db != nullptr) sqlite().close(db);
  }

  std::filesystem::path path_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool due_ = false;
  bool stopping_ = false;
  std::thread thread_;  // last: starts once the members above exist
};

int on_wal_commit(void* checkpointer, sqlite3*, const char*, int wal_pages) {
  static_cast<Checkpointer*>(checkpointer)->committed(wal_pages);
  return SQLITE_OK;
}

// The connection, its prepared statements and the writer lock.
struct Store::Impl {
  std::filesystem::path path;
  Access access = Access::ReadWrite;
  sqlite3* db = nullptr;
  LockFd lock;
  // A writer's checkpoints (stopped and closed before the writer's own connection).
  std::unique_ptr<Checkpointer> checkpointer;

  // A prepared statement, finalised with the connection.
  struct Stmt {
    sqlite3_stmt* s = nullptr;
  };
  Stmt begin, commit, rollback;
  Stmt put_entity, delete_entity, delete_steps_from, delete_steps_through, put_step, delete_step_entities,
      put_step_entity, set_applied, put_document;
  bool prepared = false;

  ~Impl() {
    checkpointer.reset();
    for (Stmt* st : {&begin, &commit, &rollback, &put_entity, &delete_entity, &delete_steps_from, &delete_steps_through,
                     &put_step, &delete_step_entities, &put_step_entity, &set_applied, &put_document})
      if (st->s != nullptr) sqlite().finalize(st->s);
    if (db != nullptr) sqlite().close(db);
    // `lock` closes after the connection (member order).
  }

  void check(int rc, std::string_view what) const {
    if (rc != SQLITE_OK && rc != SQLITE_DONE && rc != SQLITE_ROW)
      fail(path, std::string(what) + ": " + sqlite_reason(db, rc), sqlite_errc(db, rc));
  }

  sqlite3_stmt* prepare(std::string_view sql) const {
    sqlite3_stmt* s = nullptr;
    check(sqlite().prepare_v2(db, sql.data(), static_cast<int>(sql.size()), &s, nullptr), "prepare");
    return s;
  }

  // Runs a statement without results, then resets it.
  void run(Stmt& st, std::string_view what) const {
    const int rc = sqlite().step(st.s);
    sqlite().reset(st.s);
    sqlite().clear_bindings(st.s);
    check(rc, what);
  }

  void exec(const char* sql, std::string_view what) const {
    char* message = nullptr;
    const int rc = sqlite().exec(db, sql, nullptr, nullptr, &message);
    if (rc != SQLITE_OK) {
      std::string reason = message != nullptr ? message : sqlite_reason(db, rc);
      sqlite().free(message);
      if ((rc & 0xff) == SQLITE_CORRUPT || (rc & 0xff) == SQLITE_NOTADB || out_of_space(db, rc))
        reason = sqlite_reason(db, rc);
      fail(path, std::string(what) + ": " + reason, sqlite_errc(db, rc));
    }
  }

  std::int64_t pragma_int(const char* sql) const {
    sqlite3_stmt* s = prepare(sql);
    const int rc = sqlite().step(s);
    const std::int64_t value = rc == SQLITE_ROW ? sqlite().column_int64(s, 0) : 0;
    sqlite().finalize(s);
    check(rc, sql);
    return value;
  }

  // Opens `path` for reading. In a directory this process cannot write (a read-only mount) SQLite cannot
  // create the -shm a WAL reader needs; no writer can create one there either, so, unless a -wal is left
  // over from a writer, the file cannot change and is opened immutable (no locks, no -shm).
  void connect_read_only() {
    const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
    std::error_code ec;
    const bool wal = std::filesystem::exists(path.string() + "-wal", ec);
    if (wal || ::access(dir.c_str(), W_OK) == 0) {
      connect(SQLITE_OPEN_READONLY);
      return;
    }
    std::string uri = "file:";
    for (const char c : std::filesystem::absolute(path, ec).string()) {
      if (c == '%' || c == '?' || c == '#') {
        constexpr char kHex[] = "0123456789ABCDEF";
        uri += '%';
        uri += kHex[(static_cast<unsigned char>(c) >> 4) & 0xF];
        uri += kHex[static_cast<unsigned char>(c) & 0xF];
      } else {
        uri += c;
      }
    }
    uri += "?immutable=1";
    connect(SQLITE_OPEN_READONLY | SQLITE_OPEN_URI, uri.c_str());
  }

  void connect(int flags, const char* name = nullptr) {
    const int rc = sqlite().open_v2(name != nullptr ? name : path.c_str(), &db, flags | SQLITE_OPEN_NOMUTEX, nullptr);
    if (rc != SQLITE_OK) fail(path, "cannot open: " + sqlite_reason(db, rc), sqlite_errc(db, rc));
    sqlite().extended_result_codes(db, 1);
    sqlite().busy_timeout(db, kBusyTimeoutMs);
  }

  void prepare_all() {
    begin.s = prepare("BEGIN IMMEDIATE");
    commit.s = prepare("COMMIT");
    rollback.s = prepare("ROLLBACK");
    put_entity.s = prepare("INSERT OR REPLACE INTO entities (label, state) VALUES (?1, ?2)");
    delete_entity.s = prepare("DELETE FROM entities WHERE label = ?1");
    delete_steps_from.s = prepare("DELETE FROM steps WHERE revision >= ?1");
    delete_steps_through.s = prepare("DELETE FROM steps WHERE revision <= ?1");
    put_step.s = prepare("INSERT OR REPLACE INTO steps (revision, name, time, applied) VALUES (?1, ?2, ?3, ?4)");
    delete_step_entities.s = prepare("DELETE FROM step_entities WHERE revision = ?1");
    put_step_entity.s = prepare("INSERT OR REPLACE INTO step_entities (revision, label, state) VALUES (?1, ?2, ?3)");
    set_applied.s = prepare("UPDATE steps SET applied = ?2 WHERE revision = ?1");
    put_document.s = prepare("UPDATE document SET revision = ?1, next_label = ?2 WHERE id = 1");
    prepared = true;
  }

  void configure_writer() {
    exec("PRAGMA foreign_keys = ON", "enable foreign keys");
    exec("PRAGMA synchronous = NORMAL", "set synchronous");
    // Replaces SQLite's automatic checkpoint (also a WAL hook) by the checkpointer's thread.
    checkpointer = std::make_unique<Checkpointer>(path);
    sqlite().wal_hook(db, on_wal_commit, checkpointer.get());
  }

  // Brings the schema from `from` to kSchemaVersion, one transaction per migration.
  void migrate(std::int64_t from) {
    for (auto v = static_cast<std::size_t>(from); v < kMigrations.size(); ++v) {
      exec("BEGIN IMMEDIATE", "begin migration");
      try {
        exec(kMigrations[v], "migrate to schema version " + std::to_string(v + 1));
        exec("COMMIT", "commit migration");
      } catch (...) {
        sqlite().exec(db, "ROLLBACK", nullptr, nullptr, nullptr);
        throw;
      }
    }
  }

  void bind_blob(sqlite3_stmt* s, int index, const std::optional<Blob>& blob) const {
    const int rc =
        blob ? sqlite().bind_blob64(s, index, blob->data(), blob->size(), SQLITE_STATIC) : sqlite().bind_null(s, index);
    check(rc, "bind");
  }
  void bind_u64(sqlite3_stmt* s, int index, std::uint64_t value) const {
    check(sqlite().bind_int64(s, index, static_cast<sqlite3_int64>(value)), "bind");
  }
  void bind_text(sqlite3_stmt* s, int index, const std::string& text) const {
    check(sqlite().bind_text64(s, index, text.data(), text.size(), SQLITE_STATIC, SQLITE_UTF8), "bind");
  }

  void write_step_entities(const StepRow& step) {
    for (const auto& [label, state] : step.entities) {
      bind_u64(put_step_entity.s, 1, step.revision);
      bind_u64(put_step_entity.s, 2, label);
      bind_blob(put_step_entity.s, 3, state);
      run(put_step_entity, "write an undo step");
    }
  }
};

Store::Store(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Store::Store(Store&&) noexcept = default;
Store& Store::operator=(Store&&) noexcept = default;
Store::~Store() = default;

const std::filesystem::path& Store::path() const noexcept { return impl_->path; }
Access Store::access() const noexcept { return impl_->access; }

Store Store::create(const std::filesystem::path& path, const DocumentRow& row, bool overwrite) {
  std::error_code ec;
  const auto status = std::filesystem::symlink_status(path, ec);
  const bool exists = !ec && std::filesystem::exists(status);
  if (exists && !overwrite) fail(path, "already exists (give --force to replace it)");
  if (exists && !std::filesystem::is_regular_file(status)) fail(path, "exists and is not a regular file");
  LockFd old_lock;
  if (exists) old_lock = lock_for_writing(path);

  // Build the new file under a temporary name in the same directory, then
  // rename it into place: a failure at any point leaves `path` as it was.
  const std::filesystem::path dir = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  // `.NAME.new-<pid>-XXXXXX` with its -wal/-shm/-journal: what a killed `doc new` left (its pid is gone) goes.
  const std::string temp_prefix = "." + path.filename().string() + ".new-";
  io::remove_orphaned(dir, temp_prefix);
  std::string pattern = (dir / (io::owned_name(temp_prefix) + "-XXXXXX")).string();
  const int fd = ::mkstemp(pattern.data());
  if (fd < 0)
    fail(path, std::string("cannot create the file: ") + std::strerror(errno),
         errno == ENOSPC || errno == EDQUOT ? Errc::StorageFull : Errc::IoError);
  ::close(fd);
  const std::filesystem::path temp(pattern);
  auto remove_temp = [&] {
    for (const char* suffix : {"", "-wal", "-shm", "-journal"}) ::unlink((temp.string() + suffix).c_str());
  };
  try {
    {
      auto impl = std::make_unique<Impl>();
      impl->path = temp;
      impl->connect(SQLITE_OPEN_READWRITE);
      // WAL from the start: the migration and the first row cost one sync at the final checkpoint.
      impl->exec("PRAGMA journal_mode = WAL", "switch to WAL");
      impl->exec("PRAGMA synchronous = NORMAL", "set synchronous");
      impl->migrate(0);
      sqlite3_stmt* s = impl->prepare(
          "INSERT INTO document (id, revision, next_label, backend, created, tool_version) "
          "VALUES (1, ?1, ?2, ?3, ?4, ?5)");
      Impl::Stmt st{s};
      impl->bind_u64(s, 1, row.revision);
      impl->bind_u64(s, 2, row.next_label);
      impl->bind_text(s, 3, row.backend);
      impl->bind_text(s, 4, row.created);
      impl->bind_text(s, 5, row.tool_version);
      try {
        impl->run(st, "write the document row");
      } catch (...) {
        sqlite().finalize(s);
        throw;
      }
      sqlite().finalize(s);
    }
    if (exists) {
      // The old file's WAL and shared memory belong to it, not to the new file.
      ::unlink((path.string() + "-wal").c_str());
      ::unlink((path.string() + "-shm").c_str());
    }
    if (std::rename(temp.c_str(), path.c_str()) != 0) fail(path, std::string("cannot create: ") + std::strerror(errno));
  } catch (const Error& e) {
    remove_temp();
    // Report the target's name, not the temporary one.
    std::string message = e.message();
    if (message.rfind(temp.string(), 0) == 0) message = path.string() + message.substr(temp.string().size());
    throw Error(e.code(), message, {.field = "path"});  // a full disk stays StorageFull (507), not IoError
  }
  remove_temp();
  old_lock.reset();
  return open(path, Access::ReadWrite);
}

Store Store::open(const std::filesystem::path& path, Access access) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (ec || !std::filesystem::exists(status)) fail(path, "no such document");
  if (!std::filesystem::is_regular_file(status)) fail(path, "not a regular file");
  auto impl = std::make_unique<Impl>();
  impl->path = path;
  impl->access = access;
  if (access == Access::ReadWrite) {
    impl->lock = lock_for_writing(path);
    // A writer also clears what a killed `doc new --force` of this name left beside it.
    io::remove_orphaned(path.has_parent_path() ? path.parent_path() : std::filesystem::path("."),
                        "." + path.filename().string() + ".new-");
  }
  check_header(path);
  if (access == Access::ReadWrite)
    impl->connect(SQLITE_OPEN_READWRITE);
  else
    impl->connect_read_only();
  // SQLite opens a write-protected file read-only without saying so: refuse it here instead.
  if (access == Access::ReadWrite && sqlite().db_readonly(impl->db, "main") == 1)
    fail(path, "cannot open for writing: the file is write-protected");
  const std::int64_t app = impl->pragma_int("PRAGMA application_id");
  if (app != kApplicationId) fail(path, "not a HulaHoops document (an SQLite database of another application)");
  const std::int64_t version = impl->pragma_int("PRAGMA user_version");
  if (version > kSchemaVersion)
    fail(path, "written by a newer HulaHoops (document schema version " + std::to_string(version) +
                   "); this hula reads schema versions up to " + std::to_string(kSchemaVersion));
  if (version < 1) fail(path, "not a HulaHoops document (no schema)");
  if (access == Access::ReadWrite) {
    impl->configure_writer();
    if (version < kSchemaVersion) impl->migrate(version);
    impl->prepare_all();
  } else if (version < kSchemaVersion) {
    fail(path, "document schema version " + std::to_string(version) + " needs upgrading to version " +
                   std::to_string(kSchemaVersion) + "; open it for writing once");
  }
  return Store(std::move(impl));
}

Snapshot Store::load() const {
  Impl& m = *impl_;
  Snapshot out;
  out.schema_version = static_cast<int>(m.pragma_int("PRAGMA user_version"));
  // One read transaction, so the snapshot is consistent beside a writer.
  m.exec("BEGIN", "begin read");
  try {
    auto each = [&](const char* sql, auto&& row_fn) {
      sqlite3_stmt* s = m.prepare(sql);
      int rc = SQLITE_OK;
      while ((rc = sqlite().step(s)) == SQLITE_ROW) row_fn(s);
      sqlite().finalize(s);
      m.check(rc, "read");
    };
    auto blob = [](sqlite3_stmt* s, int col) {
      const void* data = sqlite().column_blob(s, col);
      const int size = sqlite().column_bytes(s, col);
      return Blob(static_cast<const char*>(data), static_cast<std::size_t>(size));
    };
    auto text = [](sqlite3_stmt* s, int col) {
      const unsigned char* data = sqlite().column_text(s, col);
      return data != nullptr ? std::string(reinterpret_cast<const char*>(data)) : std::string();
    };
    bool have_row = false;
    each("SELECT revision, next_label, backend, created, tool_version FROM document WHERE id = 1",
         [&](sqlite3_stmt* s) {
           out.document.revision = static_cast<std::uint64_t>(sqlite().column_int64(s, 0));
           out.document.next_label = static_cast<std::uint64_t>(sqlite().column_int64(s, 1));
           out.document.backend = text(s, 2);
           out.document.created = text(s, 3);
           out.document.tool_version = text(s, 4);
           have_row = true;
         });
    if (!have_row) fail(m.path, "the file is corrupt or truncated (no document row)");
    each("SELECT label, state FROM entities ORDER BY label", [&](sqlite3_stmt* s) {
      out.entities.emplace_back(static_cast<std::uint64_t>(sqlite().column_int64(s, 0)), blob(s, 1));
    });
    each("SELECT revision, name, time, applied FROM steps ORDER BY revision", [&](sqlite3_stmt* s) {
      StepRow step;
      step.revision = static_cast<std::uint64_t>(sqlite().column_int64(s, 0));
      step.name = text(s, 1);
      step.time = text(s, 2);
      step.applied = sqlite().column_int(s, 3) != 0;
      out.steps.push_back(std::move(step));
    });
    std::size_t at = 0;
    each("SELECT revision, label, state FROM step_entities ORDER BY revision, label", [&](sqlite3_stmt* s) {
      const auto revision = static_cast<std::uint64_t>(sqlite().column_int64(s, 0));
      while (at < out.steps.size() && out.steps[at].revision < revision) ++at;
      if (at == out.steps.size() || out.steps[at].revision != revision)
        fail(m.path, "the file is corrupt (undo record of a missing step " + std::to_string(revision) + ")");
      std::optional<Blob> state;
      if (sqlite().column_type(s, 2) != SQLITE_NULL) state = blob(s, 2);
      out.steps[at].entities.emplace_back(static_cast<std::uint64_t>(sqlite().column_int64(s, 1)), std::move(state));
    });
    m.exec("COMMIT", "end read");
  } catch (...) {
    sqlite().exec(m.db, "ROLLBACK", nullptr, nullptr, nullptr);
    throw;
  }
  return out;
}

void Store::apply(const Batch& batch) {
  Impl& m = *impl_;
  if (m.access != Access::ReadWrite) fail(m.path, "opened read-only");
  m.run(m.begin, "begin a transaction");
  try {
    if (batch.delete_steps_from) {
      m.bind_u64(m.delete_steps_from.s, 1, *batch.delete_steps_from);
      m.run(m.delete_steps_from, "drop redo steps");
    }
    if (batch.delete_steps_through) {
      m.bind_u64(m.delete_steps_through.s, 1, *batch.delete_steps_through);
      m.run(m.delete_steps_through, "drop old undo steps");
    }
    for (const auto& [label, state] : batch.entities) {
      if (state) {
        m.bind_u64(m.put_entity.s, 1, label);
        m.bind_blob(m.put_entity.s, 2, state);
        m.run(m.put_entity, "write an entity");
      } else {
        m.bind_u64(m.delete_entity.s, 1, label);
        m.run(m.delete_entity, "remove an entity");
      }
    }
    for (const StepRow& step : batch.steps) {
      m.bind_u64(m.delete_step_entities.s, 1, step.revision);
      m.run(m.delete_step_entities, "replace an undo step");
      m.bind_u64(m.put_step.s, 1, step.revision);
      m.bind_text(m.put_step.s, 2, step.name);
      m.bind_text(m.put_step.s, 3, step.time);
      m.check(sqlite().bind_int(m.put_step.s, 4, step.applied ? 1 : 0), "bind");
      m.run(m.put_step, "write an undo step");
      m.write_step_entities(step);
    }
    for (const StepRow& step : batch.step_updates) {
      m.bind_u64(m.set_applied.s, 1, step.revision);
      m.check(sqlite().bind_int(m.set_applied.s, 2, step.applied ? 1 : 0), "bind");
      m.run(m.set_applied, "mark an undo step");
      m.write_step_entities(step);
    }
    m.bind_u64(m.put_document.s, 1, batch.revision);
    m.bind_u64(m.put_document.s, 2, batch.next_label);
    m.run(m.put_document, "write the revision");
    m.run(m.commit, "commit");
  } catch (...) {
    // ROLLBACK can itself fail only when SQLite already rolled back (disk full, I/O error).
    sqlite().step(m.rollback.s);
    sqlite().reset(m.rollback.s);
    throw;
  }
}

std::vector<std::string> Store::integrity_check() const {
  std::vector<std::string> problems;
  sqlite3_stmt* s = impl_->prepare("PRAGMA integrity_check");
  int rc = SQLITE_OK;
  while ((rc = sqlite().step(s)) == SQLITE_ROW) {
    const unsigned char* text = sqlite().column_text(s, 0);
    std::string line = text != nullptr ? reinterpret_cast<const char*>(text) : "";
    if (line != "ok") problems.push_back(std::move(line));
  }
  sqlite().finalize(s);
  if (rc != SQLITE_DONE) problems.push_back(sqlite_reason(impl_->db, rc));
  return problems;
}

}  // namespace hula::oli::store
