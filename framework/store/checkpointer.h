// Background WAL checkpoints for a writing store.
//
// SQLite's automatic checkpoint runs in the thread that commits, which then waits for two fsyncs
// (the WAL, then the database) while it holds the store's write lock, and whatever is left of the
// WAL is checkpointed when the store closes. A Checkpointer instead copies the WAL into the
// database from its own thread and connection (passive checkpoints, which never block writers)
// whenever commits have grown the WAL by `kCheckpointPages`, so that the disk writes overlap
// the work of the writing threads and the close finds little left to copy.
#pragma once

#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "store/sqlite.h"

namespace maquette {

class Checkpointer {
 public:
  // 4 MiB of 16 KiB pages: a few checkpoints per second of ingest, each two fsyncs.
  static constexpr int kCheckpointPages = 256;

  // Installs itself on `writer`, replacing the automatic checkpoint. `path`: the store, for the
  // checkpoint connection, opened with the thread on the first request. Must be destroyed
  // before `writer`.
  Checkpointer(sqlite::Connection& writer, std::string path);
  ~Checkpointer();
  Checkpointer(const Checkpointer&) = delete;
  Checkpointer& operator=(const Checkpointer&) = delete;

  // Wakes the thread (starting it the first time) for a checkpoint: called from the writer's
  // commits, and by a writer done with a run of writes, so that the copy overlaps what it does
  // next instead of the close.
  void request();

 private:
  void run();

  sqlite::Connection& writer_;
  const std::string path_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool requested_ = false, stopping_ = false;
  std::thread thread_;
};

}  // namespace maquette
