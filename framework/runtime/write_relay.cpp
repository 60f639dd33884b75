#include "runtime/write_relay.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <thread>

namespace maquette {
namespace {

// A message is a kind byte, then for kBatch a serialized batch.
constexpr char kBatch = 'B';
constexpr char kEnd = 'E';  // the sender's batches of this run() are all sent

}  // namespace

void WriteRelay::relay(std::string batch) {
  std::unique_lock lock(mutex_);
  room_.wait(lock, [&] { return queued_.size() < kMaxQueued; });
  queued_.push_back(kBatch + batch);
}

std::vector<std::string> WriteRelay::take_queued() {
  std::vector<std::string> taken;
  {
    std::lock_guard lock(mutex_);
    taken.swap(queued_);
  }
  room_.notify_all();
  return taken;
}

void WriteRelay::send_on(const std::string& message, int except) {
  if (!ranks_.root()) return ranks_.post(0, message);
  if (message.front() == kBatch && !to_copies_) return;
  for (int r = 1; r < ranks_.size(); ++r)
    if (r != except) ranks_.post(r, message);
}

void WriteRelay::run(const std::function<void()>& work, bool to_copies) {
  to_copies_ = to_copies;
  std::exception_ptr failure;
  std::atomic<bool> working{true};
  std::thread worker([&] {
    try {
      work();
    } catch (...) {
      failure = std::current_exception();
    }
    working = false;
  });
  // End marks: the writer waits for every other rank's, the others for the writer's, which it
  // sends after every other rank's, so after every batch it passes on (messages between two
  // ranks arrive in order).
  const int ends_expected = ranks_.root() ? ranks_.size() - 1 : 1;
  int ends = 0;
  bool ended = false;
  std::exception_ptr write_failure;
  // Idle polls sleep 1 ms, doubling up to kMaxIdle while nothing comes: a rank waiting for the
  // others' cells costs next to nothing, and a batch waits at most that long (MPI buffers it).
  constexpr auto kMaxIdle = std::chrono::milliseconds(8);
  auto idle = std::chrono::milliseconds(1);
  for (;;) {
    bool busy = false;
    const bool done = !working;  // read before the queue: work's last batch is queued by then
    for (const std::string& message : take_queued()) {
      send_on(message, 0);
      busy = true;
    }
    while (std::optional<Ranks::Message> m = ranks_.poll()) {
      busy = true;
      if (m->bytes.front() == kEnd) {
        ++ends;
        continue;
      }
      try {
        Store::Batch batch(store_);
        batch.add_serialized(std::string_view(m->bytes).substr(1));
        batch.commit();
      } catch (...) {
        if (!write_failure) write_failure = std::current_exception();
      }
      if (ranks_.root()) send_on(m->bytes, m->from);
    }
    if (!ended && done && (!ranks_.root() || ends == ends_expected)) {
      send_on(std::string(1, kEnd), 0);
      ended = true;
      busy = true;
    }
    if (ended && ends == ends_expected && !ranks_.posting()) break;
    // Polling, not blocking: ranks sharing cores leave them to the threads computing.
    if (busy) {
      idle = std::chrono::milliseconds(1);
    } else {
      std::this_thread::sleep_for(idle);
      idle = std::min(2 * idle, kMaxIdle);
    }
  }
  worker.join();
  if (failure) std::rethrow_exception(failure);
  if (write_failure) std::rethrow_exception(write_failure);
}

}  // namespace maquette
