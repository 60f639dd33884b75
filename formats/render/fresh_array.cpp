#include "render/fresh_array.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstring>

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

}  // namespace maquette
