#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <mutex>
#include <optional>

#include "core/error.h"
#include "runtime/step_exec.h"

namespace maquette {

void for_each_cell(const CellPlan& cells, tbb::task_arena& arena, const std::string& label,
                   const std::function<void(size_t, CellId)>& fn) {
  // The lowest failing index so far: cells above it are skipped, cells below it still run, so
  // the failure reported is that of the lowest failing cell whatever the thread count.
  std::atomic<size_t> lowest{SIZE_MAX};
  std::mutex mutex;
  std::string what;
  auto record = [&](size_t index, std::string message) {
    std::lock_guard lock(mutex);
    if (index < lowest) {
      lowest = index;
      what = std::move(message);
    }
  };
  arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, cells.chunk_count(), 1),
        [&](const tbb::blocked_range<size_t>& chunks) {
          for (size_t c = chunks.begin(); c != chunks.end(); ++c) {
            const size_t first = cells.chunk_begin(c);
            const auto chunk = cells.chunk(c);
            for (size_t k = 0; k < chunk.size(); ++k) {
              if (first + k > lowest.load()) return;
              try {
                fn(first + k, chunk[k]);
              } catch (const std::exception& e) {
                record(first + k, e.what());
              } catch (...) {
                record(first + k, "unknown exception");
              }
            }
          }
        },
        tbb::simple_partitioner());
  });
  if (const size_t index = lowest.load(); index != SIZE_MAX)
    throw Error(label + " failed on cell " + cells.cells()[index].ToText() + ": " + what);
}

}  // namespace maquette
