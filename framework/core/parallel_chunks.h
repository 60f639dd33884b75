// A parallel for over [0, n) by chunks of consecutive indices, whose failure does not depend on
// the threads.
#pragma once

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cstddef>
#include <exception>
#include <vector>

namespace maquette {

// f(first, last) for the chunks [0, chunk), [chunk, 2 chunk), ... of [0, n) (the last one
// shorter), in parallel (TBB); when n <= chunk, one call f(0, n) on the calling thread (a small
// job pays no task).
// Exceptions: a chunk that throws stops; the others run to their end; then the exception of the
// lowest-index chunk that threw is rethrown. With an f that works through its indices in order
// and stops at its first failure, that is the failure of the lowest failing index: the same error
// for any thread count.
// Precondition: chunk > 0; f may run concurrently on disjoint chunks.
template <typename F>
void parallel_chunks(size_t n, size_t chunk, const F& f) {
  if (n <= chunk) return f(size_t(0), n);
  std::vector<std::exception_ptr> failed((n + chunk - 1) / chunk);
  tbb::parallel_for(size_t(0), failed.size(), [&](size_t c) {
    try {
      f(c * chunk, std::min(n, (c + 1) * chunk));
    } catch (...) {
      failed[c] = std::current_exception();
    }
  });
  for (const std::exception_ptr& e : failed)
    if (e) std::rethrow_exception(e);
}

}  // namespace maquette
