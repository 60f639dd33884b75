// parallel_chunks (core/parallel_chunks.h): every index covered once, by chunks of the given
// size; a small job on the calling thread; and the lowest failing chunk's exception rethrown for
// one thread and for many, where later chunks fail first in time.
#include "core/parallel_chunks.h"

#include <gtest/gtest.h>
#include <oneapi/tbb/global_control.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

namespace maquette {
namespace {

TEST(ParallelChunks, EveryIndexOnceInChunksOfTheGivenSize) {
  constexpr size_t n = 10'007, chunk = 1000;
  std::vector<std::atomic<int>> seen(n);
  std::atomic<int> calls = 0;
  parallel_chunks(n, chunk, [&](size_t first, size_t last) {
    ++calls;
    EXPECT_EQ(first % chunk, 0u);
    EXPECT_EQ(last, std::min(n, first + chunk));
    for (size_t i = first; i < last; ++i) ++seen[i];
  });
  EXPECT_EQ(calls, 11);
  for (size_t i = 0; i < n; ++i) ASSERT_EQ(seen[i], 1) << i;
}

TEST(ParallelChunks, SmallJobRunsOnceOnTheCallingThread) {
  for (const size_t n : {size_t(0), size_t(1), size_t(64)}) {
    std::vector<std::pair<size_t, size_t>> calls;
    const std::thread::id caller = std::this_thread::get_id();
    parallel_chunks(n, 64, [&](size_t first, size_t last) {
      EXPECT_EQ(std::this_thread::get_id(), caller);
      calls.emplace_back(first, last);
    });
    ASSERT_EQ(calls.size(), 1u);
    EXPECT_EQ(calls[0], std::pair(size_t(0), n));
  }
}

// Indices 70,000 and 5,000 fail (in that order in time: the lower one waits), each chunk in
// order stopping at its first failure: the error is index 5,000's, whatever the threads.
TEST(ParallelChunks, LowestFailingChunkIsRethrownWhateverTheThreads) {
  const auto run = [] {
    std::atomic<bool> later_failed = false;
    try {
      parallel_chunks(100'000, 4096, [&](size_t first, size_t last) {
        for (size_t i = first; i < last; ++i) {
          if (i == 70'000) {
            later_failed = true;
            throw std::runtime_error("index 70000");
          }
          if (i == 5'000) {
            // Give a chunk on another thread the time to fail first (bounded: one thread runs
            // the chunks in order, and never reaches 70,000 before this one).
            for (int k = 0; k < 200 && !later_failed; ++k)
              std::this_thread::sleep_for(std::chrono::milliseconds(1));
            throw std::runtime_error("index 5000");
          }
        }
      });
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  {
    const tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
    EXPECT_EQ(run(), "index 5000");
  }
  const tbb::global_control many(tbb::global_control::max_allowed_parallelism, 4);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(run(), "index 5000");
}

}  // namespace
}  // namespace maquette
