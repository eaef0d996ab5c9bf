// SPDX-License-Identifier: MIT
// The SQLite plugin (libhula_sqlite.so): the table of libsqlite3's functions the document store calls
// (sqlite_api.hpp), loaded by store.cpp through hula/core/plugin.hpp on the first document opened.
#include "hula/oli/store/sqlite_api.hpp"

HULA_PLUGIN_EXPORT const hula::oli::store::detail::SqliteApi* hula_sqlite_api() {
  static const hula::oli::store::detail::SqliteApi api{
      .bind_blob64 = &::sqlite3_bind_blob64,
      .bind_int = &::sqlite3_bind_int,
      .bind_int64 = &::sqlite3_bind_int64,
      .bind_null = &::sqlite3_bind_null,
      .bind_text64 = &::sqlite3_bind_text64,
      .busy_timeout = &::sqlite3_busy_timeout,
      .clear_bindings = &::sqlite3_clear_bindings,
      .close = &::sqlite3_close,
      .column_blob = &::sqlite3_column_blob,
      .column_bytes = &::sqlite3_column_bytes,
      .column_int = &::sqlite3_column_int,
      .column_int64 = &::sqlite3_column_int64,
      .column_text = &::sqlite3_column_text,
      .column_type = &::sqlite3_column_type,
      .db_readonly = &::sqlite3_db_readonly,
      .errmsg = &::sqlite3_errmsg,
      .errstr = &::sqlite3_errstr,
      .exec = &::sqlite3_exec,
      .extended_result_codes = &::sqlite3_extended_result_codes,
      .finalize = &::sqlite3_finalize,
      .free = &::sqlite3_free,
      .open_v2 = &::sqlite3_open_v2,
      .prepare_v2 = &::sqlite3_prepare_v2,
      .reset = &::sqlite3_reset,
      .step = &::sqlite3_step,
      .system_errno = &::sqlite3_system_errno,
      .wal_checkpoint_v2 = &::sqlite3_wal_checkpoint_v2,
      .wal_hook = &::sqlite3_wal_hook,
  };
  return &api;
}
