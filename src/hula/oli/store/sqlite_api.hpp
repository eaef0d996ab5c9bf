// SPDX-License-Identifier: MIT
// The SQLite functions the document store calls (store.cpp), as one table the SQLite plugin
// (libhula_sqlite.so, sqlite_plugin.cpp, the only code of HulaHoops that links libsqlite3) hands out. Debian's
// libsqlite3 is linked with -z now: a program linking it binds its ~1,600 symbols at every start, which was
// about a seventh of `hula --version` (docs/benchmarks.md, "Command-line start-up"); behind the plugin only
// the commands that open a document load it. The header sqlite3.h gives the types only.
#pragma once

#include <sqlite3.h>

namespace hula::oli::store::detail {

/// Pointers to the sqlite3_<name> functions of the same names.
struct SqliteApi {
  decltype(&::sqlite3_bind_blob64) bind_blob64;
  decltype(&::sqlite3_bind_int) bind_int;
  decltype(&::sqlite3_bind_int64) bind_int64;
  decltype(&::sqlite3_bind_null) bind_null;
  decltype(&::sqlite3_bind_text64) bind_text64;
  decltype(&::sqlite3_busy_timeout) busy_timeout;
  decltype(&::sqlite3_clear_bindings) clear_bindings;
  decltype(&::sqlite3_close) close;
  decltype(&::sqlite3_column_blob) column_blob;
  decltype(&::sqlite3_column_bytes) column_bytes;
  decltype(&::sqlite3_column_int) column_int;
  decltype(&::sqlite3_column_int64) column_int64;
  decltype(&::sqlite3_column_text) column_text;
  decltype(&::sqlite3_column_type) column_type;
  decltype(&::sqlite3_db_readonly) db_readonly;
  decltype(&::sqlite3_errmsg) errmsg;
  decltype(&::sqlite3_errstr) errstr;
  decltype(&::sqlite3_exec) exec;
  decltype(&::sqlite3_extended_result_codes) extended_result_codes;
  decltype(&::sqlite3_finalize) finalize;
  decltype(&::sqlite3_free) free;
  decltype(&::sqlite3_open_v2) open_v2;
  decltype(&::sqlite3_prepare_v2) prepare_v2;
  decltype(&::sqlite3_reset) reset;
  decltype(&::sqlite3_step) step;
  decltype(&::sqlite3_system_errno) system_errno;
  decltype(&::sqlite3_wal_checkpoint_v2) wal_checkpoint_v2;
  decltype(&::sqlite3_wal_hook) wal_hook;
};

/// The plugin's entry point: returns the table (static, valid for the life of the process).
inline constexpr const char* kSqliteApiSymbol = "hula_sqlite_api";
using SqliteApiFunction = const SqliteApi* (*)();

}  // namespace hula::oli::store::detail
