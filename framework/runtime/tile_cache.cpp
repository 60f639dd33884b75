#include "runtime/tile_cache.h"

namespace maquette {

TileCache::Value TileCache::get(const std::string& layer, CellId cell, const Load& load) {
  Key key(layer, cell);
  {
    std::lock_guard lock(mutex_);
    if (const auto it = index_.find(key); it != index_.end()) {
      entries_.splice(entries_.begin(), entries_, it->second);
      return it->second->second;
    }
  }
  auto value = std::make_shared<const std::optional<Tile<float>>>(load());
  std::lock_guard lock(mutex_);
  if (index_.count(key)) return value;  // loaded by another thread meanwhile
  entries_.emplace_front(key, value);
  index_.emplace(std::move(key), entries_.begin());
  if (entries_.size() > capacity_) {
    index_.erase(entries_.back().first);
    entries_.pop_back();
  }
  return value;
}

}  // namespace maquette
