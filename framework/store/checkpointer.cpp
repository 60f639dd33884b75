#include "store/checkpointer.h"

#include <fcntl.h>
#include <sqlite3.h>
#include <sys/stat.h>
#include <unistd.h>

namespace maquette {

Checkpointer::Checkpointer(sqlite::Connection& writer, std::string path, Journal journal)
    : writer_(writer), path_(std::move(path)), journal_(journal) {
  if (journal_ == Journal::Wal) writer_.on_wal_pages(kCheckpointPages, [this] { request(); });
}

Checkpointer::~Checkpointer() {
  if (journal_ == Journal::Wal) writer_.on_wal_pages(0, nullptr);
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  if (thread_.joinable()) thread_.join();
}

void Checkpointer::request() {
  {
    std::lock_guard lock(mutex_);
    requested_ = true;
    if (!thread_.joinable()) thread_ = std::thread([this] { run(); });
  }
  wake_.notify_one();
}

void Checkpointer::committed() {
  struct stat st {};
  if (::stat(path_.c_str(), &st) != 0) return;
  {
    std::lock_guard lock(mutex_);
    if (st.st_size - synced_size_ < kCheckpointBytes) return;
    synced_size_ = st.st_size;
  }
  request();
}

void Checkpointer::run() {
  // A checkpoint that fails (the disk, another process's checkpoint running) is left to the
  // next one and to the close, which checkpoints whatever remains.
  std::unique_ptr<sqlite::Connection> conn;
  if (journal_ == Journal::Wal) try {
      conn =
          std::make_unique<sqlite::Connection>(path_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_NOMUTEX);
      configure_connection(*conn, true);  // synchronous = NORMAL: the WAL is synced before copying
    } catch (const Error&) {
    }
  // SQLite syncs the database only when a checkpoint reaches the end of the WAL, which one
  // racing the writers seldom does: syncing it after each checkpoint too writes it out as it
  // grows, instead of all at the close.
  const int db = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
  std::unique_lock lock(mutex_);
  while (true) {
    wake_.wait(lock, [this] { return requested_ || stopping_; });
    if (stopping_) break;
    requested_ = false;
    lock.unlock();
    const bool copied = journal_ == Journal::Rollback || (conn && conn->checkpoint_passive());
    if (copied && db >= 0) ::fdatasync(db);
    lock.lock();
  }
  if (db >= 0) ::close(db);
}

}  // namespace maquette
