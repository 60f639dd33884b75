#include "store/sqlite.h"

#include <spdlog/spdlog.h>
#include <sqlite3.h>

#include <chrono>
#include <cstdio>
#include <thread>

namespace maquette::sqlite {

Query::~Query() {
  sqlite3_reset(stmt_);
  sqlite3_clear_bindings(stmt_);
}

Query& Query::bind_int(int i, int64_t v) {
  if (int rc = sqlite3_bind_int64(stmt_, i, v); rc != SQLITE_OK) conn_.fail(rc);
  return *this;
}

Query& Query::bind_real(int i, double v) {
  if (int rc = sqlite3_bind_double(stmt_, i, v); rc != SQLITE_OK) conn_.fail(rc);
  return *this;
}

Query& Query::bind_null(int i) {
  if (int rc = sqlite3_bind_null(stmt_, i); rc != SQLITE_OK) conn_.fail(rc);
  return *this;
}

Query& Query::bind_text(int i, std::string_view v) {
  if (int rc = sqlite3_bind_text64(stmt_, i, v.data(), v.size(), SQLITE_TRANSIENT, SQLITE_UTF8);
      rc != SQLITE_OK)
    conn_.fail(rc);
  return *this;
}

Query& Query::bind_blob(int i, std::span<const std::byte> v) {
  // A zero-length blob must still be a BLOB, not NULL: pass a non-null pointer.
  static const std::byte empty{};
  if (int rc =
          sqlite3_bind_blob64(stmt_, i, v.empty() ? &empty : v.data(), v.size(), SQLITE_TRANSIENT);
      rc != SQLITE_OK)
    conn_.fail(rc);
  return *this;
}

bool Query::step() {
  const int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  conn_.fail(rc);
}

void Query::run() {
  while (step()) {
  }
}

bool Query::is_null(int i) const { return sqlite3_column_type(stmt_, i) == SQLITE_NULL; }
int64_t Query::int64(int i) const { return sqlite3_column_int64(stmt_, i); }
double Query::real(int i) const { return sqlite3_column_double(stmt_, i); }

std::string Query::text(int i) const {
  const auto* p = reinterpret_cast<const char*>(sqlite3_column_text(stmt_, i));
  return p ? std::string(p, size_t(sqlite3_column_bytes(stmt_, i))) : std::string();
}

std::span<const std::byte> Query::blob(int i) const {
  const auto* p = static_cast<const std::byte*>(sqlite3_column_blob(stmt_, i));
  return {p, p ? size_t(sqlite3_column_bytes(stmt_, i)) : 0};
}

namespace {

constexpr auto kLockWait = std::chrono::seconds(60);
constexpr auto kLockNotice = std::chrono::seconds(2);

// Waits for another connection's lock by polling every 0.2 ms, for up to kLockWait, saying so
// once after kLockNotice (a wait without a word looked like a hang). SQLite's own busy_timeout
// backs off to sleeps of up to 100 ms, which left processes writing the same store (MPI ranks)
// idle for much of a run. `path`: the store's, a std::string.
int wait_for_lock(void* path, int attempts) {
  using Clock = std::chrono::steady_clock;
  thread_local Clock::time_point since;  // a busy wait runs on one thread, start to end
  thread_local bool told = false;
  if (attempts == 0) since = Clock::now(), told = false;
  const auto waited = Clock::now() - since;
  if (waited >= kLockWait) return 0;
  if (!told && waited >= kLockNotice) {
    told = true;
    spdlog::warn("{}: another connection holds its lock; waiting for it (up to {} s)",
                 *static_cast<const std::string*>(path), kLockWait.count());
  }
  std::this_thread::sleep_for(std::chrono::microseconds(200));
  return 1;
}

// A URI naming `path` with `query` ("immutable=1"): '?', '#' and '%' are escaped.
std::string file_uri(const std::string& path, const char* query) {
  std::string uri = "file:";
  for (const char c : path) {
    if (c == '?' || c == '#' || c == '%') {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", static_cast<unsigned char>(c));
      uri += hex;
    } else {
      uri += c;
    }
  }
  return uri + "?" + query;
}

}  // namespace

Connection::Connection(std::string path, int flags, bool immutable) : path_(std::move(path)) {
  const std::string name = immutable ? file_uri(path_, "immutable=1") : path_;
  if (immutable) flags |= SQLITE_OPEN_URI;
  const int rc = sqlite3_open_v2(name.c_str(), &db_, flags | SQLITE_OPEN_EXRESCODE, nullptr);
  if (rc != SQLITE_OK) {
    const std::string msg = db_ ? sqlite3_errmsg(db_) : sqlite3_errstr(rc);
    sqlite3_close_v2(db_);
    throw Failure("cannot open " + path_ + ": " + msg, rc & 0xff);
  }
  sqlite3_busy_handler(db_, &wait_for_lock, &path_);
}

Connection::~Connection() {
  for (auto& [sql, stmt] : statements_) sqlite3_finalize(stmt);
  sqlite3_close_v2(db_);
}

void Connection::exec(const char* sql) {
  if (int rc = sqlite3_exec(db_, sql, nullptr, nullptr, nullptr); rc != SQLITE_OK) fail(rc);
}

Query Connection::query(const char* sql) {
  auto [it, inserted] = statements_.try_emplace(sql, nullptr);
  if (inserted) {
    const int rc =
        sqlite3_prepare_v3(db_, sql, -1, SQLITE_PREPARE_PERSISTENT, &it->second, nullptr);
    if (rc != SQLITE_OK) {
      statements_.erase(it);
      fail(rc);
    }
  }
  return Query(*this, it->second);
}

int64_t Connection::last_insert_rowid() const { return sqlite3_last_insert_rowid(db_); }
int64_t Connection::changes() const { return sqlite3_changes64(db_); }

void Connection::on_wal_pages(int pages, std::function<void()> wal_full) {
  wal_pages_ = pages;
  wal_notified_ = 0;
  wal_full_ = std::move(wal_full);
  if (pages > 0)
    sqlite3_wal_hook(db_, &Connection::wal_hook, this);
  else
    sqlite3_wal_autocheckpoint(db_, 1000);  // SQLite's default
}

int Connection::wal_hook(void* self, sqlite3*, const char*, int pages) {
  auto& c = *static_cast<Connection*>(self);
  // `pages` counts the frames in the WAL since it last restarted from its beginning, checkpointed
  // or not: call again once it has grown by wal_pages_ more, or restarted.
  if (pages < c.wal_notified_ || pages - c.wal_notified_ >= c.wal_pages_) {
    c.wal_notified_ = pages;
    // The commit has succeeded whatever happens here: nothing may unwind through SQLite, and a
    // checkpoint missed now is made by a later one or at close.
    try {
      c.wal_full_();
    } catch (...) {
    }
  }
  return SQLITE_OK;
}

bool Connection::checkpoint_passive() noexcept {
  return sqlite3_wal_checkpoint_v2(db_, nullptr, SQLITE_CHECKPOINT_PASSIVE, nullptr, nullptr) ==
         SQLITE_OK;
}

void Connection::fail(int code) const {
  if (code == SQLITE_BUSY)  // the busy handler gave up (not SQLITE_BUSY_SNAPSHOT and the like)
    throw Failure(path_ + ": another connection kept it locked for more than " +
                      std::to_string(kLockWait.count()) + " s (" + sqlite3_errmsg(db_) + ")",
                  code & 0xff);
  throw Failure(path_ + ": " + sqlite3_errmsg(db_), code & 0xff);
}

void Connection::rollback() noexcept {
  if (!sqlite3_get_autocommit(db_)) sqlite3_exec(db_, "ROLLBACK", nullptr, nullptr, nullptr);
}

}  // namespace maquette::sqlite
