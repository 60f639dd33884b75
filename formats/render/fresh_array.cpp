#include "render/fresh_array.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <list>
#include <mutex>
#include <new>
#include <unordered_map>

namespace maquette {

void poison_fresh(void* p, size_t bytes) {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
  static std::atomic<uint64_t> allocations{0};
  uint64_t z = (uint64_t(std::chrono::steady_clock::now().time_since_epoch().count()) +
                allocations.fetch_add(1, std::memory_order_relaxed)) *
               0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  auto* out = static_cast<unsigned char*>(p);
  for (size_t at = 0; at < bytes; at += sizeof z)
    std::memcpy(out + at, &z, std::min(sizeof z, bytes - at));
#else
  (void)p, (void)bytes;
#endif
}

namespace {

// The blocks of kKeptBlockBytes or more: those in use, by address, with their sizes, and those
// freed and kept, oldest first.
class KeptBlocks {
 public:
  void* allocate(size_t bytes) {
    {
      std::lock_guard lock(mutex_);
      // The smallest kept block that holds `bytes` and is at most twice as large.
      auto best = kept_.end();
      for (auto it = kept_.begin(); it != kept_.end(); ++it)
        if (it->bytes >= bytes && it->bytes <= 2 * bytes &&
            (best == kept_.end() || it->bytes < best->bytes))
          best = it;
      if (best != kept_.end()) {
        const Block b = *best;
        kept_.erase(best);
        kept_bytes_ -= b.bytes;
        in_use_[b.p] = b.bytes;
        return b.p;
      }
    }
    void* p = ::operator new(bytes);
    std::lock_guard lock(mutex_);
    in_use_[p] = bytes;
    return p;
  }
  // False for a block not allocated here (nothing done).
  bool deallocate(void* p) {
    std::vector<void*> given_back;
    {
      std::lock_guard lock(mutex_);
      const auto it = in_use_.find(p);
      if (it == in_use_.end()) return false;
      kept_.push_back({p, it->second});
      kept_bytes_ += it->second;
      in_use_.erase(it);
      while (kept_bytes_ > kKeptBytes) {
        given_back.push_back(kept_.front().p);
        kept_bytes_ -= kept_.front().bytes;
        kept_.pop_front();
      }
    }
    for (void* q : given_back) ::operator delete(q);
    return true;
  }

 private:
  struct Block {
    void* p;
    size_t bytes;
  };
  std::mutex mutex_;
  std::unordered_map<void*, size_t> in_use_;
  std::list<Block> kept_;
  size_t kept_bytes_ = 0;
};

// Never destroyed: an array freed during the static objects' destruction still finds it.
KeptBlocks& kept_blocks() {
  static auto* blocks = new KeptBlocks;
  return *blocks;
}

}  // namespace

void* fresh_allocate(size_t bytes) {
  if (bytes < kKeptBlockBytes) return ::operator new(bytes);
  return kept_blocks().allocate(bytes);
}

void fresh_deallocate(void* p, size_t bytes) {
  if (bytes < kKeptBlockBytes || !kept_blocks().deallocate(p)) ::operator delete(p);
}

}  // namespace maquette
