// `maquette run --store-copies`: rank 0, the writer, alone opens the pipeline's store; every other
// rank reads its own copy of the store (on its machine) and writes there only what the run
// computes. Each rank's batches (StepIO::write), once committed to its own store, are relayed: a
// rank's to the writer, which commits them to the store and passes them on, as it does its own,
// to every other rank, which commits them to its copy. So the store gets every cell once, with
// its run record, and every copy holds what the run's steps wrote, for the next steps to read
// (halos, artifacts). Batches travel as Store::Batch::serialize gives them: tiles compressed by
// the rank that computed them, so the writer only commits.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "runtime/ranks.h"
#include "store/store.h"

namespace maquette {

class WriteRelay {
 public:
  // `store`: the pipeline's store on the writer, this rank's copy of it on the others.
  WriteRelay(Ranks& ranks, Store& store) : ranks_(ranks), store_(store) {}

  // From any thread, within run(): a batch this rank committed to its store (serialized), for
  // the other ranks. Waits while kMaxQueued batches wait to be sent.
  void relay(std::string batch);

  // Runs `work` on a thread of its own while this thread, the one that made the Ranks, passes
  // batches between the ranks; every rank calls it at the same point of the run, with the same
  // `to_copies`: whether the batches go to the copies too (false when no later step reads them
  // there: the writer alone writes them). Returns once every rank's work has ended and every
  // batch is written where it goes; then rethrows what `work` threw, or else the first error
  // writing a batch received.
  void run(const std::function<void()>& work, bool to_copies);
  // Whether this rank commits its own batches to its store (the writer's, or a copy that keeps
  // them): StepIO commits, serializes and relays; otherwise it only serializes and relays.
  bool commits_here() const { return ranks_.root() || to_copies_; }

 private:
  static constexpr size_t kMaxQueued = 64;

  std::vector<std::string> take_queued();
  // Sends `message` to the writer, or from the writer to every other rank but `except`.
  void send_on(const std::string& message, int except);

  Ranks& ranks_;
  Store& store_;
  std::mutex mutex_;
  std::condition_variable room_;
  std::vector<std::string> queued_;
  bool to_copies_ = false;  // of the current run()
};

}  // namespace maquette
