// A thin RAII layer over the SQLite C API: a connection that caches its prepared statements,
// and Query, one use of a cached statement (reset when it goes out of scope). Every failure
// throws sqlite::Failure (a maquette::Error) naming the database file.
#pragma once

#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>

#include "core/error.h"

struct sqlite3;
struct sqlite3_stmt;

namespace maquette::sqlite {

class Failure : public Error {
 public:
  Failure(const std::string& message, int code) : Error(message), code_(code) {}
  int code() const { return code_; }  // primary SQLite result code (SQLITE_NOTADB, ...)

 private:
  int code_;
};

class Connection;

class Query {
 public:
  Query(Connection& conn, sqlite3_stmt* stmt) : conn_(conn), stmt_(stmt) {}
  ~Query();
  Query(const Query&) = delete;
  Query& operator=(const Query&) = delete;

  // Parameters are numbered from 1, as in SQLite.
  Query& bind_int(int i, int64_t v);
  Query& bind_real(int i, double v);
  Query& bind_null(int i);
  Query& bind_text(int i, std::string_view v);
  Query& bind_blob(int i, std::span<const std::byte> v);

  bool step();  // true when a row is available
  void run();   // steps a statement that returns no rows

  // Columns are numbered from 0; blob/text spans stay valid until the next step.
  bool is_null(int i) const;
  int64_t int64(int i) const;
  double real(int i) const;
  std::string text(int i) const;
  std::span<const std::byte> blob(int i) const;

 private:
  Connection& conn_;
  sqlite3_stmt* stmt_;
};

class Connection {
 public:
  // `flags` are sqlite3_open_v2 flags. `immutable`: the file is read as one nobody changes
  // (SQLite's immutable=1: no locks, no -shm or -wal), for a store on a read-only file system.
  Connection(std::string path, int flags, bool immutable = false);
  ~Connection();
  Connection(const Connection&) = delete;
  Connection& operator=(const Connection&) = delete;

  void exec(const char* sql);
  Query query(const char* sql);  // prepared once per connection, then reused
  int64_t last_insert_rowid() const;
  int64_t changes() const;
  const std::string& path() const { return path_; }

  // Runs f inside BEGIN IMMEDIATE ... COMMIT; rolls back and rethrows if f or COMMIT throws.
  template <typename F>
  void transaction(F&& f) {
    exec("BEGIN IMMEDIATE");
    try {
      f();
      exec("COMMIT");
    } catch (...) {
      rollback();
      throw;
    }
  }

  // Replaces SQLite's automatic checkpoint: after each commit that has grown the WAL by `pages`
  // pages since the last call, calls `wal_full` (in the committing thread). `pages` 0 restores the
  // automatic checkpoint.
  void on_wal_pages(int pages, std::function<void()> wal_full);
  // Copies into the database what it can of the WAL without waiting for any lock (a passive
  // checkpoint); false if it could not run.
  bool checkpoint_passive() noexcept;

  [[noreturn]] void fail(int code) const;

 private:
  void rollback() noexcept;
  static int wal_hook(void* self, sqlite3*, const char*, int pages);

  std::string path_;
  sqlite3* db_ = nullptr;
  std::unordered_map<std::string, sqlite3_stmt*> statements_;
  int wal_pages_ = 0, wal_notified_ = 0;
  std::function<void()> wal_full_;
};

}  // namespace maquette::sqlite
