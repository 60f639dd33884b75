// Decoded input tiles shared by the threads of one step, so that the halos of neighbouring cells
// do not read and decode the same tile up to 9 times: a mutex-protected LRU of at most `capacity`
// entries (absent tiles included). Entries in use by a thread outlive their eviction, so memory
// is bounded by `capacity` plus the tiles the threads are assembling (9 per thread).
#pragma once

#include <cstddef>
#include <functional>
#include <list>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>

#include "core/cell_id.h"
#include "core/tile.h"

namespace maquette {

class TileCache {
 public:
  using Value = std::shared_ptr<const std::optional<Tile<float>>>;
  using Load = std::function<std::optional<Tile<float>>()>;

  explicit TileCache(size_t capacity) : capacity_(capacity) {}

  // The cached tile of (layer, cell), or else load() (called without the lock: two threads missing
  // the same tile at once both load it, with the same result) and cached.
  Value get(const std::string& layer, CellId cell, const Load& load);

 private:
  using Key = std::pair<std::string, CellId>;
  using Entries = std::list<std::pair<Key, Value>>;  // most recently used first

  std::mutex mutex_;
  size_t capacity_;
  Entries entries_;
  std::map<Key, Entries::iterator> index_;
};

}  // namespace maquette
