#include "runtime/write_relay.h"

#include <spdlog/fmt/fmt.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <iterator>
#include <thread>

#include "core/error.h"

namespace maquette {
namespace {

// A message is a kind byte, then for kBatch a serialized batch.
constexpr char kBatch = 'B';
constexpr char kEnd = 'E';  // the sender's batches of this run() are all sent

}  // namespace

void WriteRelay::relay(std::string batch) {
  batch.insert(batch.begin(), kBatch);
  std::unique_lock lock(mutex_);
  room_.wait(lock, [&] { return queued_.size() < kMaxQueued || stopped_; });
  if (stopped_) throw Error("the batches can no longer be relayed to the other ranks");
  queued_.push_back(std::move(batch));
}

std::vector<std::string> WriteRelay::take_queued(size_t count) {
  std::vector<std::string> taken;
  {
    std::lock_guard lock(mutex_);
    const auto end = queued_.begin() + ptrdiff_t(std::min(count, queued_.size()));
    taken.assign(std::make_move_iterator(queued_.begin()), std::make_move_iterator(end));
    queued_.erase(queued_.begin(), end);
  }
  room_.notify_all();
  return taken;
}

size_t WriteRelay::queued() {
  std::lock_guard lock(mutex_);
  return queued_.size();
}

void WriteRelay::send_on(std::string message, int except) {
  if (!ranks_.root()) return ranks_.post({0}, std::move(message));
  if (message.front() == kBatch && !to_copies_) return;
  std::vector<int> to;
  for (int r = 1; r < ranks_.size(); ++r)
    if (r != except) to.push_back(r);
  if (!to.empty()) ranks_.post(to, std::move(message));
}

void WriteRelay::run(const std::function<void()>& work, bool to_copies) {
  to_copies_ = to_copies;
  stopped_ = false;
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
  std::exception_ptr write_failure;
  try {
    pass_messages(working, write_failure);
  } catch (...) {
    // Passing messages failed (out of memory, say): the work is stopped (relay() throws) and
    // joined. The other ranks wait for this rank's messages and would never reach the collective
    // that reports an error, so with other ranks the job ends here, naming the rank.
    {
      std::lock_guard lock(mutex_);
      stopped_ = true;
    }
    room_.notify_all();
    worker.join();
    if (ranks_.size() == 1) throw;
    std::string what = "an unknown error";
    try {
      throw;
    } catch (const std::exception& e) {
      what = e.what();
    } catch (...) {
    }
    ranks_.abort(fmt::format("rank {} of {}: passing the batches between the ranks failed: {}",
                             ranks_.rank(), ranks_.size(), what));
  }
  worker.join();
  if (failure) std::rethrow_exception(failure);
  if (write_failure) std::rethrow_exception(write_failure);
}

void WriteRelay::pass_messages(const std::atomic<bool>& working,
                               std::exception_ptr& write_failure) {
  // End marks: the writer waits for every other rank's, the others for the writer's, which it
  // sends after every other rank's, so after every batch it passes on (messages between two
  // ranks arrive in order).
  const int ends_expected = ranks_.root() ? ranks_.size() - 1 : 1;
  int ends = 0;
  bool ended = false;
  // Idle polls sleep 1 ms, doubling up to kMaxIdle while nothing comes: a rank waiting for the
  // others' cells costs next to nothing, and a batch waits at most that long (MPI buffers it).
  constexpr auto kMaxIdle = std::chrono::milliseconds(8);
  auto idle = std::chrono::milliseconds(1);
  most_held_ = 0;
  for (;;) {
    bool busy = false;
    const bool done = !working;  // read before the queue: work's last batch is queued by then
    // Back-pressure (write_relay.h): batches are posted, and the writer receives, only while
    // fewer than kMaxSending are being sent.
    const size_t sending = ranks_.sending();
    for (std::string& message : take_queued(kMaxSending - std::min(sending, kMaxSending))) {
      send_on(std::move(message), 0);
      busy = true;
    }
    bool full = ranks_.root() && ranks_.sending() >= kMaxSending;
    while (!full) {
      std::optional<Ranks::Message> m = ranks_.poll();
      if (!m) break;
      busy = true;
      most_held_ = std::max(most_held_, queued() + ranks_.sending() + 1);
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
      if (ranks_.root()) send_on(std::move(m->bytes), m->from);
      full = ranks_.root() && ranks_.sending() >= kMaxSending;
    }
    const size_t waiting = queued();
    most_held_ = std::max(most_held_, waiting + ranks_.sending());
    if (!ended && done && waiting == 0 && (!ranks_.root() || ends == ends_expected)) {
      send_on(std::string(1, kEnd), 0);
      ended = true;
      busy = true;
    }
    if (ended && ends == ends_expected && ranks_.sending() == 0) break;
    // Polling, not blocking: ranks sharing cores leave them to the threads computing. Batches
    // held back by the back-pressure are tried again after the shortest sleep.
    if (busy) {
      idle = std::chrono::milliseconds(1);
    } else {
      std::this_thread::sleep_for(idle);
      idle = waiting > 0 || full ? std::chrono::milliseconds(1) : std::min(2 * idle, kMaxIdle);
    }
  }
}

}  // namespace maquette
