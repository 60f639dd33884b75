// Background checkpoints for a writing store: copying the WAL into the database file, and
// syncing the file, from a thread of its own.
//
// SQLite's automatic checkpoint runs in the thread that commits, which then waits for two fsyncs
// (the WAL, then the database) while it holds the store's write lock, and whatever is left of the
// WAL is checkpointed when the store closes. A Checkpointer instead copies the WAL into the
// database from its own thread and connection (passive checkpoints, which never block writers)
// whenever commits have grown the WAL by `kCheckpointPages`, so that the disk writes overlap
// the work of the writing threads and the close finds little left to copy.
//
// A store filled in bulk (rollback journal, no syncs: Store::Mode::CreateBulk) has no WAL, and
// its close syncs the whole file: there the thread syncs the file whenever commits have grown it
// by as much, so that the close's sync finds little left to write.
#pragma once

#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "store/schema.h"
#include "store/sqlite.h"

namespace maquette {

class Checkpointer {
 public:
  // 4 MiB of 16 KiB pages: a few checkpoints per second of ingest, each two fsyncs.
  static constexpr int kCheckpointPages = 256;
  static constexpr int64_t kCheckpointBytes = int64_t(kCheckpointPages) * kStorePageSize;

  enum class Journal { Wal, Rollback };

  // Installs itself on `writer` (Wal: replacing the automatic checkpoint). `path`: the store,
  // opened by the thread, which starts on the first request. Must be destroyed before `writer`.
  Checkpointer(sqlite::Connection& writer, std::string path, Journal journal);
  ~Checkpointer();
  Checkpointer(const Checkpointer&) = delete;
  Checkpointer& operator=(const Checkpointer&) = delete;

  // Wakes the thread (starting it the first time) for a checkpoint: called from the writer's
  // commits, and by a writer done with a run of writes, so that the copy overlaps what it does
  // next instead of the close.
  void request();
  // Rollback journal: to be called after each commit; requests a sync when the file has grown by
  // kCheckpointBytes since the last one.
  void committed();

 private:
  void run();

  sqlite::Connection& writer_;
  const std::string path_;
  const Journal journal_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool requested_ = false, stopping_ = false;
  int64_t synced_size_ = 0;  // file size at the last requested sync (Rollback)
  std::thread thread_;
};

}  // namespace maquette
