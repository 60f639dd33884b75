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
  struct Failure {
    size_t index;
    std::string what;
  };
  std::atomic<bool> stop{false};
  std::mutex mutex;
  std::optional<Failure> failure;
  arena.execute([&] {
    tbb::parallel_for(
        tbb::blocked_range<size_t>(0, cells.chunk_count(), 1),
        [&](const tbb::blocked_range<size_t>& chunks) {
          for (size_t c = chunks.begin(); c != chunks.end(); ++c) {
            const size_t first = cells.chunk_begin(c);
            const auto chunk = cells.chunk(c);
            for (size_t k = 0; k < chunk.size(); ++k) {
              if (stop.load()) return;
              try {
                fn(first + k, chunk[k]);
              } catch (const std::exception& e) {
                std::lock_guard lock(mutex);
                if (!failure || first + k < failure->index) failure = Failure{first + k, e.what()};
                stop = true;
              }
            }
          }
        },
        tbb::simple_partitioner());
  });
  if (failure)
    throw Error(label + " failed on cell " + cells.cells()[failure->index].ToText() + ": " +
                failure->what);
}

}  // namespace maquette
