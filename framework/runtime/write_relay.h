// `maquette run --store-copies`: rank 0, the writer, alone opens the pipeline's store; every other
// rank reads its own copy of the store (on its machine) and writes there only what the run
// computes. Each rank's batches (StepIO::write), once committed to its own store, are relayed: a
// rank's to the writer, which commits them to the store and passes them on, as it does its own,
// to every other rank, which commits them to its copy. So the store gets every cell once, with
// its run record, and every copy holds what the run's steps wrote, for the next steps to read
// (halos, artifacts). Batches travel as Store::Batch::serialize gives them: tiles compressed by
// the rank that computed them, so the writer only commits.
//
// Memory is bounded by back-pressure: a rank holds at most kMaxQueued batches waiting to be
// sent (relay() waits while the queue is full), kMaxSending batches being sent (posted to MPI:
// a large message is sent only once its receiver takes it) and one received batch being
// committed, so at most kMaxHeld batches whatever the step's size. The writer receives only
// while it sends fewer than kMaxSending (it passes batches on to the copies), so a slow copy
// slows the ranks sending to the writer instead of piling up their batches there; the copies
// always receive (the writer's sends to them must complete).
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <exception>
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

  static constexpr size_t kMaxQueued = 32;
  static constexpr size_t kMaxSending = 16;
  static constexpr size_t kMaxHeld = kMaxQueued + kMaxSending + 1;

  // From any thread, within run(): a batch this rank committed to its store (serialized), for
  // the other ranks. Waits while kMaxQueued batches wait to be sent.
  void relay(std::string batch);

  // Runs `work` on a thread of its own while this thread, the one that made the Ranks, passes
  // batches between the ranks; every rank calls it at the same point of the run, with the same
  // `to_copies`: whether the batches go to the copies too (false when no later step reads them
  // there: the writer alone writes them). Returns once every rank's work has ended and every
  // batch is written where it goes; then rethrows what `work` threw, or else the first error
  // writing a batch received. When passing the messages itself fails (out of memory receiving a
  // batch, say), the other ranks would wait for this rank forever: with other ranks the job is
  // ended (Ranks::abort) with a message naming this rank and the error.
  void run(const std::function<void()>& work, bool to_copies);
  // Whether this rank commits its own batches to its store (the writer's, or a copy that keeps
  // them), and whether it relays them (to the writer, or from the writer to the copies): StepIO
  // serializes a batch only for the relay.
  bool commits_here() const { return ranks_.root() || to_copies_; }
  bool relays() const { return !ranks_.root() || to_copies_; }
  // The most batches this rank held at once in its last run(): queued, being sent, or received
  // and being committed, counted on each pass of run()'s loop (for tests of the bound).
  size_t most_held() const { return most_held_; }

 private:
  // run()'s loop on the thread that made the Ranks, until every rank's batches are written where
  // they go; the first error committing a received batch is kept in `write_failure`.
  void pass_messages(const std::atomic<bool>& working, std::exception_ptr& write_failure);
  // The queued batches, at most `count`, oldest first.
  std::vector<std::string> take_queued(size_t count);
  size_t queued();
  // Sends `message` to the writer, or from the writer to every other rank but `except`.
  void send_on(std::string message, int except);

  Ranks& ranks_;
  Store& store_;
  std::mutex mutex_;
  std::condition_variable room_;
  std::vector<std::string> queued_;
  bool to_copies_ = false;  // of the current run()
  bool stopped_ = false;    // run() failed: relay() throws
  size_t most_held_ = 0;
};

}  // namespace maquette
