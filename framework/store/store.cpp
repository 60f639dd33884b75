// Opening a store, the connection pool, and whole-file queries.
#include "store/store.h"

#include <fcntl.h>
#include <spdlog/spdlog.h>
#include <sqlite3.h>
#include <sys/stat.h>
#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <optional>

#include "store/codec.h"
#include "store/schema.h"
#include "store/store_impl.h"

namespace maquette {
namespace {

constexpr int kReadFlags = SQLITE_OPEN_READONLY | SQLITE_OPEN_NOMUTEX;

// Root may write to any file, so the mode bits are checked as well as access(): a store
// made read-only (chmod a-w) is refused for writing whoever opens it.
bool writable(const std::string& path, const struct stat& st) {
  return ::access(path.c_str(), W_OK) == 0 && (st.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) != 0;
}

// Flushes a file's data to the disk; 0 or the errno of the failure.
int sync_file(const std::string& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  const int err = fd >= 0 && ::fdatasync(fd) == 0 ? 0 : errno;
  if (fd >= 0) ::close(fd);
  return err;
}

// Builds a new store under a temporary name and links it into place, so that a process killed
// at any moment never leaves a file at `path` without the schema (at worst an orphaned
// PATH.creating.PID next to it). In WAL mode unless `bulk` (Mode::CreateBulk).
bool create_store_file(const std::string& path, bool bulk) {
  const std::string tmp = path + ".creating." + std::to_string(::getpid());
  {
    sqlite::Connection conn(tmp, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX);
    // Nobody sees this file before it is linked, and a killed process leaves it orphaned: no
    // rollback journal and no syncs while it is built (they were ten fsyncs, 0.1-8 ms each), one
    // fsync of the finished file below.
    conn.exec("PRAGMA journal_mode = OFF");
    conn.exec("PRAGMA synchronous = OFF");
    create_schema(conn);
    if (!bulk) conn.exec("PRAGMA journal_mode = WAL");
  }  // closing the last connection checkpoints and removes the WAL
  // Whole on the disk before it is linked. link() rather than rename(): if another process
  // created the store meanwhile, keep theirs (and return false).
  int err = sync_file(tmp);
  if (err == 0 && ::link(tmp.c_str(), path.c_str()) != 0) err = errno;
  ::unlink(tmp.c_str());
  if (err != 0 && err != EEXIST)
    throw Error("cannot create store " + path + ": " + std::strerror(err));
  return err == 0;
}

// A writer killed during a commit in rollback-journal mode (a bulk fill) leaves a hot journal,
// which only a connection that may write can roll back: read-only connections fail on it
// ("attempt to write a readonly database"), those already open included. So before a read-only
// connection is lent, a hot journal of a writable store is rolled back by a connection that may
// write (a journal that is not hot, a live writer's, is left alone by it); on a file nobody may
// write the read reports SQLite's error.
void roll_back_hot_journal(const std::string& path) {
  struct stat journal {
  }, st{};
  if (::stat((path + "-journal").c_str(), &journal) != 0 || journal.st_size == 0) return;
  if (::stat(path.c_str(), &st) != 0 || !writable(path, st)) return;
  try {
    sqlite::Connection conn(path, SQLITE_OPEN_READWRITE | SQLITE_OPEN_NOMUTEX);
    conn.exec("SELECT count(*) FROM sqlite_schema");  // a read rolls a hot journal back
  } catch (const sqlite::Failure&) {  // the read-only connection reports what is wrong
  }
}

// Why a store cannot be written at `path` (an existing file, or a new one in its directory), or
// nothing. Root may write to any file, so the mode bits of an existing file are checked too: a
// store made read-only (chmod a-w) is refused for writing whoever opens it.
std::optional<std::string> write_problem(const std::string& path) {
  struct stat st {};
  const bool exists = ::stat(path.c_str(), &st) == 0;
  std::string dir = std::filesystem::path(path).parent_path().string();
  if (dir.empty()) dir = ".";
  struct statvfs fs {};
  if (::statvfs(exists ? path.c_str() : dir.c_str(), &fs) == 0 && (fs.f_flag & ST_RDONLY))
    return "it is on a read-only file system";
  if (exists && !writable(path, st))
    return "no write permission (open it read-only or make it writable)";
  if (::access(dir.c_str(), W_OK) != 0)
    return "its directory " + dir + " is not writable (" + std::strerror(errno) + ")";
  return std::nullopt;
}

// A store on a read-only file system (or in a directory this user may not write) cannot have the
// -shm file SQLite's WAL mode reads through; the file is then read as immutable: nobody can
// change it there. A WAL left with changes cannot be read so, which is said.
bool read_in_place_impossible(const std::string& path) {
  if (!write_problem(path + "-shm")) return false;
  struct stat wal {};
  if (::stat((path + "-wal").c_str(), &wal) == 0 && wal.st_size > 0)
    spdlog::warn(
        "{}-wal holds changes that cannot be read where the store is ({}): they are "
        "left out",
        path, *write_problem(path + "-shm"));
  return true;
}

// The journal mode a pragma leaves: "wal", "truncate", ...
std::string set_journal_mode(sqlite::Connection& conn, const std::string& mode) {
  auto q = conn.query(("PRAGMA journal_mode = " + mode).c_str());
  return q.step() ? q.text(0) : std::string();
}

// Starts the bulk fill of a store this open created; false if another process has switched it
// to WAL meanwhile (opening it for writing does), in which case it is written as usual.
bool start_bulk_fill(sqlite::Connection& writer) {
  try {
    // TRUNCATE: a commit empties the journal rather than deleting it (one file operation
    // fewer); the switch to WAL at the close deletes it.
    if (set_journal_mode(writer, "TRUNCATE") != "truncate") return false;
  } catch (const sqlite::Failure&) {  // leaving WAL needs the only connection: "locked"
    return false;
  }
  writer.exec("PRAGMA synchronous = OFF");
  return true;
}

// Ends the bulk fill: synchronous = NORMAL makes the switch to WAL (a commit in rollback mode)
// sync the file, and the switch deletes the rollback journal. The file and any WAL are synced
// whatever happened: another process may have switched the store to WAL already (then this
// writer's last commits went to the WAL unsynced), or the switch may fail (then the store stays
// valid in rollback mode, and its next writer switches it).
void finish_bulk_fill(sqlite::Connection& writer) noexcept {
  try {
    writer.exec("PRAGMA synchronous = NORMAL");
    if (const std::string mode = set_journal_mode(writer, "WAL"); mode != "wal")
      spdlog::warn("{}: left in {} journal mode", writer.path(), mode);
  } catch (const std::exception& e) {
    spdlog::warn("{}: left in rollback-journal mode: {}", writer.path(), e.what());
  }
  for (const std::string& file : {writer.path(), writer.path() + "-wal"})
    if (const int err = sync_file(file); err != 0 && err != ENOENT)
      spdlog::warn("{}: cannot sync: {}", file, std::strerror(err));
}

}  // namespace

std::string cell_text(CellId cell) {
  return cell.is_valid() ? "cell " + cell.ToText() : "cell id " + std::to_string(cell.id());
}

ReadPool::Lease ReadPool::borrow() {
  bool immutable = false;
  {
    std::lock_guard lock(mutex_);
    immutable = immutable_;
  }
  if (!immutable) roll_back_hot_journal(path_);  // an immutable file has no journal to read
  {
    std::lock_guard lock(mutex_);
    if (!idle_.empty()) {
      auto conn = std::move(idle_.back());
      idle_.pop_back();
      return Lease(*this, std::move(conn));
    }
  }
  auto conn = std::make_unique<sqlite::Connection>(path_, kReadFlags, immutable);
  configure_connection(*conn, false);
  return Lease(*this, std::move(conn));
}

void ReadPool::read_immutable() {
  std::lock_guard lock(mutex_);
  immutable_ = true;
  idle_.clear();
}

void ReadPool::give_back(std::unique_ptr<sqlite::Connection> conn) {
  std::lock_guard lock(mutex_);
  idle_.push_back(std::move(conn));
}

void Store::Impl::require_writable() const {
  if (read_only) throw Error(path + " is open read-only: cannot write to it");
}

LayerEntry Store::Impl::require_tiles(const std::string& name) const {
  LayerEntry e = require(name);
  if (holds_content(e.info.kind))
    throw Error("layer '" + name + "' in " + path + " holds " +
                std::string(layer_kind_name(e.info.kind)) + " content (" +
                (e.info.kind == LayerKind::Model ? "get_model" : "get_content") +
                "), not raster tiles");
  return e;
}

RawTile Store::Impl::decode(std::span<const std::byte> blob, const LayerEntry& layer,
                            CellId cell) const {
  const std::string where = "corrupt tile of layer '" + layer.info.name + "' at " +
                            cell_text(cell) + " in " + path + ": ";
  RawTile tile;
  try {
    tile = decode_tile(blob);
  } catch (const Error& e) {
    throw Error(where + e.what());
  }
  const LayerInfo& info = layer.info;
  if (tile.dtype != info.dtype || tile.size != info.tile_size || tile.channels != info.channels)
    throw Error(where + "blob holds " + std::to_string(tile.size) + "x" +
                std::to_string(tile.size) + "x" + std::to_string(tile.channels) + " " +
                std::string(dtype_name(tile.dtype)) + ", the layer " +
                std::to_string(info.tile_size) + "x" + std::to_string(info.tile_size) + "x" +
                std::to_string(info.channels) + " " + std::string(dtype_name(info.dtype)));
  return tile;
}

Store::Store(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Store::~Store() {
  if (impl_->bulk) {
    impl_->checkpointer.reset();
    finish_bulk_fill(*impl_->writer);
  }
}

std::unique_ptr<Store> Store::open(const std::string& path, Mode mode) {
  struct stat st {};
  const bool exists = ::stat(path.c_str(), &st) == 0;
  const bool create = mode == Mode::Create || mode == Mode::CreateBulk;
  if (!exists && !create) throw Error("no such store: " + path);
  if (exists && S_ISDIR(st.st_mode)) throw Error(path + " is a directory, not a Maquette store");
  if (mode != Mode::ReadOnly) check_writable(path);

  auto impl = std::make_unique<Impl>(path, mode == Mode::ReadOnly);
  try {
    if (!exists) impl->created = create_store_file(path, mode == Mode::CreateBulk);
    if (mode == Mode::ReadOnly) {
      try {
        check_schema(*impl->readers.borrow());
      } catch (const sqlite::Failure& e) {
        if (e.code() == SQLITE_NOTADB || !read_in_place_impossible(path)) throw;
        impl->readers.read_immutable();
        check_schema(*impl->readers.borrow());
      }
    } else {
      impl->writer =
          std::make_unique<sqlite::Connection>(path, SQLITE_OPEN_READWRITE | SQLITE_OPEN_NOMUTEX);
      configure_connection(*impl->writer, true);
      create_schema(*impl->writer);  // for an existing store: checks, migrates
      impl->bulk = impl->created && mode == Mode::CreateBulk && start_bulk_fill(*impl->writer);
      if (impl->bulk) {
        impl->checkpointer =
            std::make_unique<Checkpointer>(*impl->writer, path, Checkpointer::Journal::Rollback);
      } else {
        set_journal_mode(*impl->writer, "WAL");
        // A new store's first commit writes the WAL's header and syncs it and the directory
        // (~2 ms, 10-30 ms on a busy disk): a write of the same schema version does it here
        // instead, where the caller may overlap the opening with other work.
        if (!exists) set_version(*impl->writer);
        impl->checkpointer =
            std::make_unique<Checkpointer>(*impl->writer, path, Checkpointer::Journal::Wal);
      }
    }
  } catch (const sqlite::Failure& e) {
    if (e.code() == SQLITE_NOTADB) throw Error(path + " is not a Maquette store");
    throw;
  }
  return std::unique_ptr<Store>(new Store(std::move(impl)));
}

void Store::check_writable(const std::string& path) {
  if (const auto problem = write_problem(path))
    throw Error((std::filesystem::exists(path) ? path + " is read-only: "
                                               : "cannot create the store " + path + ": ") +
                *problem);
}

const std::string& Store::path() const { return impl_->path; }
bool Store::read_only() const { return impl_->read_only; }
bool Store::created() const { return impl_->created; }

int64_t Store::file_size() const {
  int64_t total = 0;
  for (const std::string& file : {impl_->path, impl_->path + "-wal"}) {
    struct stat st {};
    if (::stat(file.c_str(), &st) == 0) total += st.st_size;
  }
  return total;
}

bool Store::integrity_ok() const {
  auto conn = impl_->readers.borrow();
  auto q = conn->query("PRAGMA integrity_check");
  return q.step() && q.text(0) == "ok" && !q.step();
}

}  // namespace maquette
