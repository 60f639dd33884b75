// The panorama's big arrays (meshes, fragments, pictures, guides), resized without being
// initialised (core/tile.h's DefaultInitAllocator): the step that makes an array writes each
// element once, so its fresh pages are not written twice. Contract: that step must write EVERY
// element; one left unwritten holds whatever the memory held (zero on a fresh page, old bytes on a
// reused one). One exception, said where it is declared: a step's own scratch array read by that
// step alone, which writes every element it reads (the untouched pages cost nothing). Under
// AddressSanitizer or ThreadSanitizer builds (GCC and Clang define
// __SANITIZE_ADDRESS__ / __SANITIZE_THREAD__ under -fsanitize) each array's storage is filled at
// allocation with a pattern of its own (8 bytes from the clock and a count of allocations,
// repeated), so an element left unwritten differs between two renders, in one process or two, and
// the byte-identity tests (threads, strips, an infinite bend) catch it, as they cannot on fresh
// pages that are zero each time.
#pragma once

#include <cstddef>
#include <vector>

#include "core/tile.h"

namespace maquette {

// Under AddressSanitizer or ThreadSanitizer builds fills `bytes` bytes at `p` with a pattern of
// this allocation's own (splitmix64 of the clock and a count of allocations); nothing otherwise.
void poison_fresh(void* p, size_t bytes);

template <typename T>
struct FreshAllocator : DefaultInitAllocator<T> {
  template <typename U>
  struct rebind {
    using other = FreshAllocator<U>;
  };
  FreshAllocator() = default;
  template <typename U>
  FreshAllocator(const FreshAllocator<U>&) noexcept {}
  T* allocate(size_t n) {
    T* p = DefaultInitAllocator<T>::allocate(n);
    poison_fresh(p, n * sizeof(T));
    return p;
  }
};

template <typename T>
using FreshArray = std::vector<T, FreshAllocator<T>>;

// Resizes `a` to `n` elements for a step that writes every one (an array reused from one strip of
// a picture to the next): within its capacity nothing is allocated; beyond it the old storage is
// freed first and exactly `n` elements allocated, the old elements not copied (std::vector's
// resize would copy them into twice the capacity).
template <typename T>
void resize_fresh(FreshArray<T>& a, size_t n) {
  if (n > a.capacity()) {
    FreshArray<T>().swap(a);
    a.reserve(n);
  }
  a.resize(n);
}

}  // namespace maquette
